// Stages a run does not need do not run, judged from the run's own records
// (summary.json: "calls" counts each timed stage, "counters" the linear
// algebra), never from times:
//  - no Schur complement unless an SC solver is chosen;
//  - no stress recovery and no output when output is off;
//  - no contact machinery (regularisation, projection, active-set
//    iterations) when a scene has no contact;
//  - no refactorisation when the matrix did not change: a plate without an
//    obstacle is one factorisation; with one, every active set reuses the
//    one AMD ordering (a restricted symbolic pass is cheap). On the masonry
//    wall some active sets are solved with a reused factorisation (the
//    plate on psi3 makes a new one for each: no reuse is claimed there).
// Missing records fail: every run must have written summary.json with
// status "converged", its "calls" and "counters"; a counter or stage record
// that is absent prints MISSING and fails its line, so that the negative
// checks ("no ...", "at most one ...") cannot hold on an empty summary. Each
// run has a positive control: the solve stage ran and at least one numeric
// factorisation was made.
#include <unilateral/application.h>

#include <fstream>
#include <iostream>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  // Run the application on @p text; return the summary.json it wrote.
  std::string
  run(const std::string &name, const std::string &text)
  {
    const std::string file = name + ".prm";
    std::ofstream(file) << "subsection Output\n  set Directory = results\n"
                           "  set Print timings = false\n"
                           "  set Progress = false\nend\n"
                        << text;
    std::vector<std::string> arguments = {"unilateral", file};
    char              *argv[] = {arguments[0].data(), arguments[1].data()};
    std::ostringstream out, err;
    const int          code = unilateral::run_application(2, argv, out, err);
    std::cout << name << ": exit code " << code << std::endl;
    std::ifstream      summary("results/" + name + "/summary.json");
    std::ostringstream text_of_summary;
    text_of_summary << summary.rdbuf();
    return text_of_summary.str();
  }

  // The JSON object under @p key (flat: no nested braces).
  std::string
  object(const std::string &summary, const std::string &key)
  {
    const auto begin = summary.find("\"" + key + "\": {");
    if (begin == std::string::npos)
      return "";
    return summary.substr(begin, summary.find('}', begin) - begin);
  }

  // A stage ran (its count in "calls" is present); std::nullopt, printed as
  // MISSING, if the summary has no "calls" at all.
  std::optional<bool>
  ran(const std::string &summary, const std::string &stage)
  {
    const std::string calls = object(summary, "calls");
    if (calls.empty())
      {
        std::cout << "  MISSING: \"calls\" in summary.json" << std::endl;
        return std::nullopt;
      }
    return calls.find("\"" + stage + "\"") != std::string::npos;
  }

  // The stage ran; false if the record is missing.
  bool
  runs(const std::string &summary, const std::string &stage)
  {
    const std::optional<bool> result = ran(summary, stage);
    return result.has_value() && *result;
  }

  // The stage did not run; false (not true) if the record is missing.
  bool
  skipped(const std::string &summary, const std::string &stage)
  {
    const std::optional<bool> result = ran(summary, stage);
    return result.has_value() && !*result;
  }

  // A counter; std::nullopt, printed as MISSING, if absent.
  std::optional<long>
  counter(const std::string &summary, const std::string &name)
  {
    std::smatch       match;
    const std::string counters = object(summary, "counters");
    if (!std::regex_search(counters,
                           match,
                           std::regex("\"" + name + "\": ([0-9]+)")))
      {
        std::cout << "  MISSING: counter \"" << name << "\" in summary.json"
                  << std::endl;
        return std::nullopt;
      }
    return std::stol(match[1]);
  }

  // The counter is present and meets @p condition.
  template <typename Condition>
  bool
  counted(const std::string &summary,
          const std::string &name,
          const Condition   &condition)
  {
    const std::optional<long> value = counter(summary, name);
    return value.has_value() && condition(*value);
  }

  void
  expect(const std::string &what, const bool holds)
  {
    std::cout << "  " << what << ": " << (holds ? "yes" : "NO") << std::endl;
  }

  // The positive control of every run: summary.json written with status
  // "converged", the solve stage ran, at least one numeric factorisation.
  void
  expect_a_solved_run(const std::string &summary)
  {
    const bool converged =
      summary.find("\"status\": \"converged\"") != std::string::npos;
    if (summary.empty())
      std::cout << "  MISSING: summary.json" << std::endl;
    const bool solved     = runs(summary, "solve");
    const bool factorised = counted(summary,
                                    "numeric_factorisations",
                                    [](const long n) { return n >= 1; });
    expect("summary.json: status converged, the solve stage ran, at least "
           "one numeric factorisation",
           converged && solved && factorised);
  }

  const std::string masonry = "set Scene = masonry\n"
                              "subsection Masonry\n"
                              "  set Geometry = running bond\n"
                              "  set Blocks per side = 5\n"
                              "end\n";
  const std::string plate   = "set Scene = plate\n"
                              "subsection Plate\n"
                              "  subsection Geometry\n"
                              "    set Elements x = 10\n"
                              "    set Elements y = 10\n"
                              "  end\n"
                              "  subsection Obstacle\n"
                              "    set Function = OBSTACLE\n"
                              "  end\n"
                              "end\n";

  std::string
  with_obstacle(const std::string &obstacle)
  {
    return std::regex_replace(plate, std::regex("OBSTACLE"), obstacle);
  }
} // namespace

int
main()
{
  {
    const std::string s =
      run("masonry_quiet",
          masonry + "subsection Output\n  set Write VTU = false\nend\n");
    expect_a_solved_run(s);
    expect("masonry, VTU off: no output stage", skipped(s, "output results"));
    expect("no Schur complement", skipped(s, "solver: schur complement"));
    expect("contact machinery runs (regularise, projection)",
           runs(s, "solver: regularise") && runs(s, "solver: projection"));
    expect("at most one fill-reducing ordering for every active set",
           counted(s, "orderings", [](const long n) { return n <= 1; }));
    expect("some active sets solved with a reused factorisation",
           counted(s, "reused_factorisations", [](const long n) {
             return n > 0;
           }));
  }
  {
    const std::string s = run("masonry_schur",
                              masonry + "subsection Solver\n"
                                        "  set Schur complement = true\nend\n"
                                        "subsection Output\n"
                                        "  set Write VTU = true\nend\n");
    expect_a_solved_run(s);
    expect("masonry, Schur complement chosen: it runs",
           runs(s, "solver: schur complement"));
    expect("VTU on: the output stage runs", runs(s, "output results"));
  }
  {
    const std::string s =
      run("plate_free",
          with_obstacle("none") +
            "subsection Output\n  set Write VTU = false\nend\n");
    expect_a_solved_run(s);
    expect("plate without obstacle: no output stage",
           skipped(s, "output results"));
    expect("no regularisation, no projection",
           skipped(s, "solver: regularise") &&
             skipped(s, "solver: projection"));
    expect("exactly one factorisation (the matrix never changes)",
           counted(s,
                   "numeric_factorisations",
                   [](const long n) { return n == 1; }) &&
             counted(s, "symbolic_analyses", [](const long n) {
               return n == 1;
             }));
  }
  {
    const std::string s =
      run("plate_psi3",
          with_obstacle("psi3") + "subsection Output\n"
                                  "  set Write VTU = false\nend\n");
    expect_a_solved_run(s);
    expect("plate on psi3: at most one ordering for every active set",
           counted(s, "orderings", [](const long n) { return n <= 1; }));
    expect("no Schur complement, no regularisation",
           skipped(s, "solver: schur complement") &&
             skipped(s, "solver: regularise"));
  }
}
