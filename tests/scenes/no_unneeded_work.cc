// Stages a run does not need do not run, judged from the run's own records
// (summary.json: "calls" counts each timed stage, "counters" the linear
// algebra), never from times:
//  - no Schur complement unless an SC solver is chosen;
//  - no stress recovery and no output when output is off;
//  - no contact machinery (regularisation, projection, active-set
//    iterations) when a scene has no contact;
//  - no refactorisation when the matrix did not change: a plate without an
//    obstacle is one factorisation; with one, every active set reuses the
//    one AMD ordering (a restricted symbolic pass is cheap), and nearby
//    active sets reuse a factorisation.
#include <unilateral/application.h>

#include <fstream>
#include <iostream>
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

  bool
  ran(const std::string &summary, const std::string &stage)
  {
    return object(summary, "calls").find("\"" + stage + "\"") !=
           std::string::npos;
  }

  long
  counter(const std::string &summary, const std::string &name)
  {
    std::smatch       match;
    const std::string counters = object(summary, "counters");
    if (!std::regex_search(counters,
                           match,
                           std::regex("\"" + name + "\": ([0-9]+)")))
      return -1;
    return std::stol(match[1]);
  }

  void
  expect(const std::string &what, const bool holds)
  {
    std::cout << "  " << what << ": " << (holds ? "yes" : "NO") << std::endl;
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
    expect("masonry, VTU off: no output stage", !ran(s, "output results"));
    expect("no Schur complement", !ran(s, "solver: schur complement"));
    expect("contact machinery runs (regularise, projection)",
           ran(s, "solver: regularise") && ran(s, "solver: projection"));
    expect("at most one fill-reducing ordering for every active set",
           counter(s, "orderings") <= 1);
    expect("some active sets solved with a reused factorisation",
           counter(s, "reused_factorisations") > 0);
  }
  {
    const std::string s = run("masonry_schur",
                              masonry + "subsection Solver\n"
                                        "  set Schur complement = true\nend\n"
                                        "subsection Output\n"
                                        "  set Write VTU = true\nend\n");
    expect("masonry, Schur complement chosen: it runs",
           ran(s, "solver: schur complement"));
    expect("VTU on: the output stage runs", ran(s, "output results"));
  }
  {
    const std::string s =
      run("plate_free",
          with_obstacle("none") +
            "subsection Output\n  set Write VTU = false\nend\n");
    expect("plate without obstacle: no output stage",
           !ran(s, "output results"));
    expect("no regularisation, no projection",
           !ran(s, "solver: regularise") && !ran(s, "solver: projection"));
    expect("exactly one factorisation (the matrix never changes)",
           counter(s, "numeric_factorisations") == 1 &&
             counter(s, "symbolic_analyses") == 1);
  }
  {
    const std::string s =
      run("plate_psi3",
          with_obstacle("psi3") + "subsection Output\n"
                                  "  set Write VTU = false\nend\n");
    expect("plate on psi3: at most one ordering for every active set",
           counter(s, "orderings") <= 1);
    expect("no Schur complement, no regularisation",
           !ran(s, "solver: schur complement") &&
             !ran(s, "solver: regularise"));
  }
}
