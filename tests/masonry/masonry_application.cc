// The masonry scene through the application, as a user runs it:
//  1. bad input gives exit code 1 and one line naming the parameter, the
//     value and the fix (printed here: code and message), and so does a
//     wall too large for 'Memory limit'; so do what deal.II's parser
//     refuses (the parameter's whole path, which deal.II does not name,
//     the nearest declared name for a misspelt one), in .prm, JSON and
//     XML files, and input refused where an earlier run's folder is
//     replaces its summary;
//  2. prescribed displacements far larger than the elastic ones end
//     'inaccurate' (exit 2) where double precision loses the energy, and
//     converge with the shift-independent answer where it does not;
//  3. two runs write VTU/PVD and summary.json, which read_masonry_vtu.py
//     reads back with VTK's XML reader (what ParaView sees) and checks
//     against the exact column solution (laminae, gap 0, P2) and for a
//     settling running bond with two materials (Q2).
#include <unilateral/application.h>
#include <unilateral/lcp/io.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  // "yes" if @p text holds @p fragment.
  const char *
  holds(const std::string &text, const std::string &fragment)
  {
    return text.find(fragment) != std::string::npos ? "yes" : "no";
  }

  // Run the application on a parameter file holding @p text; return the exit
  // code, keep the error stream (and the output stream, if asked).
  int
  run(const std::string &name,
      const std::string &text,
      std::string       &error,
      std::string       *output    = nullptr,
      const std::string &extension = ".prm")
  {
    const std::string file = name + extension;
    std::ofstream(file) << text;
    std::vector<std::string> arguments = {"unilateral", file};
    char              *argv[] = {arguments[0].data(), arguments[1].data()};
    std::ostringstream out, err;
    const int          code = unilateral::run_application(2, argv, out, err);
    error                   = err.str();
    if (output != nullptr)
      *output = out.str();
    return code;
  }

  std::string
  masonry_prm(const std::string &masonry_lines,
              const std::string &other_lines = "",
              const bool         vtu         = false)
  {
    return "set Scene = masonry\n"
           "subsection Output\n  set Directory = results\n"
           "  set Print timings = false\n  set Progress = false\n"
           "  set Write VTU = " +
           std::string(vtu ? "true" : "false") +
           "\nend\n"
           "subsection Masonry\n" +
           masonry_lines + "end\n" + other_lines;
  }

  void
  bad_input(const std::string &what,
            const std::string &text,
            const std::string &extension = ".prm")
  {
    std::string error;
    const int   code = run("bad_input", text, error, nullptr, extension);
    std::cout << what << ": exit code " << code << ", " << error;
    if (error.empty() || error.find('\n') != error.size() - 1)
      std::cout << "  (expected exactly one line)\n";
  }

  void
  check_vtu(const std::string &name, const std::string &mode)
  {
    const std::string command = "/usr/bin/python3 " SOURCE_DIR
                                "/read_masonry_vtu.py results/" +
                                name + " " + mode + " 2>&1";
    FILE *pipe = popen(command.c_str(), "r");
    if (pipe == nullptr)
      {
        std::cout << "cannot run " << command << "\n";
        return;
      }
    std::array<char, 512> line;
    while (fgets(line.data(), line.size(), pipe) != nullptr)
      std::cout << "  " << line.data();
    std::cout << "  read_masonry_vtu.py exit status " << pclose(pipe) << "\n";
  }
} // namespace

int
main()
{
  std::cout << "Bad input:\n";
  bad_input("m = 0", masonry_prm("  set Blocks per side = 0\n"));
  bad_input("m = -3", masonry_prm("  set Blocks per side = -3\n"));
  bad_input("r = -1", masonry_prm("  set Refinement = -1\n"));
  bad_input(
    "Factorisation = mumps without an MPI launcher",
    masonry_prm("  set Blocks per side = 2\n",
                "subsection Solver\n  set Factorisation = mumps\nend\n"));
  bad_input("g < 0",
            masonry_prm("  subsection Boundary conditions\n"
                        "    set Relative gap = -0.1\n  end\n"));
  // Accepted before ff1e49a: the support pushed the blocks up (exit 0).
  bad_input("Signorini gap < 0",
            masonry_prm("  set Blocks per side = 4\n"
                        "  subsection Boundary conditions\n"
                        "    set Signorini gap = -0.1\n  end\n"));
  // Boundary number 0 is what the joints between blocks carry: accepted
  // before ff1e49a, every joint was fixed (exit 0).
  bad_input("Fixed = 0",
            masonry_prm("  set Blocks per side = 4\n"
                        "  subsection Boundary conditions\n"
                        "    set Fixed = 0\n  end\n"));
  // Before 8c14f18: "entry 130 of b (counted from 1) is not a finite number".
  bad_input("Traction = 0; -1/0",
            masonry_prm("  set Blocks per side = 4\n"
                        "  subsection Boundary conditions\n"
                        "    set Traction = 0; -1/0\n  end\n"));
  bad_input("Largest aspect ratio = 0.5",
            masonry_prm("  subsection Tearing\n"
                        "    set Largest aspect ratio = 0.5\n  end\n"));
  bad_input("nu = 0.5",
            masonry_prm("  subsection Materials\n"
                        "    set Poisson's ratio = 0.5\n  end\n"));
  bad_input("nu = -1",
            masonry_prm("  subsection Materials\n"
                        "    set Poisson's ratio = -1\n  end\n"));
  bad_input("E = 0",
            masonry_prm("  subsection Materials\n"
                        "    set Young's modulus = 0\n  end\n"));
  bad_input("E < 0 in the second class",
            masonry_prm("  subsection Materials\n"
                        "    set Young's modulus = 4e3, -1\n"
                        "    set Poisson's ratio = 0.3, 0.3\n"
                        "    set Density = 1, 1\n"
                        "    set Assignment = cyclic\n  end\n"));
  bad_input("material lists of different lengths",
            masonry_prm("  subsection Materials\n"
                        "    set Young's modulus = 4e3, 2e3\n"
                        "    set Assignment = cyclic\n  end\n"));
  bad_input("two classes with rule 'single'",
            masonry_prm("  subsection Materials\n"
                        "    set Young's modulus = 4e3, 2e3\n"
                        "    set Poisson's ratio = 0.3, 0.3\n"
                        "    set Density = 1, 1\n  end\n"));
  bad_input("unknown geometry",
            masonry_prm("  set Geometry = herringbone bond\n"));
  bad_input("unknown solver",
            masonry_prm("",
                        "subsection Solver\n  set Method = simplex\nend\n"));
  // What deal.II's parser refuses, in the program's own form (before: its
  // message, "The entry value -1 for the entry named Tolerance does not
  // match the given pattern: [Double 0...MAX_DOUBLE (inclusive)]", named
  // neither the subsection nor a misspelt name's nearest).
  bad_input("PSOR's tolerance < 0",
            masonry_prm("",
                        "subsection Solver\n  subsection PSOR\n"
                        "    set Tolerance = -1\n  end\nend\n"));
  bad_input("m not an integer", masonry_prm("  set Blocks per side = 2.5\n"));
  bad_input("Write VTU = maybe",
            "subsection Output\n  set Write VTU = maybe\nend\n");
  bad_input("a misspelt name",
            masonry_prm("", "subsection Solver\n  set Metod = pdas\nend\n"));
  bad_input("a name of another subsection",
            masonry_prm("", "subsection Solver\n  set Tau = 1\nend\n"));
  bad_input("a misspelt subsection",
            masonry_prm("  subsection Boundary condition\n  end\n"));
  bad_input("a missing 'end'",
            "subsection Masonry\n  set Blocks per side = 2\n");
  // A setting the run would not read is refused, not ignored.
  bad_input("a mesh file with a built-in wall",
            masonry_prm("  set Mesh file = wall.msh\n"));
  bad_input("tags without 'Assignment = physical tag'",
            masonry_prm("  subsection Materials\n    set Tags = 1, 2\n"
                        "  end\n"));
  bad_input("a misspelt boundary of a built-in wall",
            masonry_prm("  subsection Boundary conditions\n"
                        "    set Fixed = rigth\n  end\n"));
  {
    // The run folder of a converged run, then bad input in the same file:
    // its summary.json said 'converged' until the next run that started.
    std::string error;
    run("rerun", masonry_prm("  set Blocks per side = 2\n"), error);
    const int         code = run("rerun",
                         masonry_prm("  set Blocks per side = 2\n"
                                             "  subsection Materials\n"
                                             "    set Young's modulus = 4e3, 2e3\n"
                                             "    set Poisson's ratio = 0.3, 0.3\n"
                                             "    set Density = 1, 1\n  end\n"),
                         error);
    std::ifstream     file("results/rerun/summary.json");
    std::stringstream summary;
    summary << file.rdbuf();
    std::cout << "bad input in an earlier run's folder: exit code " << code
              << ", its summary.json now says 'error': "
              << holds(summary.str(), "\"status\": \"error\"")
              << ", with the message: "
              << holds(summary.str(), "'single' uses one") << "\n";
    // The same where deal.II's parser refuses the file (a misspelt name).
    run("rerun", masonry_prm("  set Blocks per side = 2\n"), error);
    const int misspelt =
      run("rerun", masonry_prm("  set Blocks per sid = 2\n"), error);
    std::ifstream     again("results/rerun/summary.json");
    std::stringstream after;
    after << again.rdbuf();
    std::cout << "a misspelt name in an earlier run's folder: exit code "
              << misspelt << ", its summary.json now says 'error': "
              << holds(after.str(), "\"status\": \"error\"")
              << ", with the message: "
              << holds(after.str(), "did you mean 'Blocks per side'") << "\n";
  }
  // JSON and XML parameter files, in the same form (before: deal.II's
  // messages, "The string <2.5> does not match the given pattern
  // <[Integer range ...]>", "You can't ask for entry <Metod> you have not
  // yet declared", boost's "<unspecified file>(1): expected key string").
  const std::string json_masonry =
    "{ \"Scene\": \"masonry\", \"Output\": { \"Directory\": \"results\", "
    "\"Print timings\": \"false\", \"Progress\": \"false\", "
    "\"Write VTU\": \"false\" }, \"Masonry\": { \"Blocks per side\": ";
  bad_input("JSON: m not an integer", json_masonry + "\"2.5\" } }", ".json");
  bad_input("JSON: a misspelt name",
            json_masonry + "2 }, \"Solver\": { \"Metod\": \"pdas\" } }",
            ".json");
  bad_input("JSON: a name of another subsection",
            json_masonry + "2 }, \"Solver\": { \"Tau\": \"1\" } }",
            ".json");
  bad_input("JSON: a misspelt subsection",
            json_masonry +
              "2, \"Boundary condition\": { \"Relative gap\": \"0.1\" } } }",
            ".json");
  bad_input("JSON: a list for a value",
            json_masonry + "2, \"Refinement\": [1, 2] } }",
            ".json");
  bad_input("JSON: a subsection given a value",
            json_masonry + "2 }, \"Solver\": \"pdas\" }",
            ".json");
  bad_input("JSON: a missing '}'", json_masonry + "2 }", ".json");
  const std::string xml_start =
    "<?xml version=\"1.0\"?>\n<ParameterHandler><Scene><value>masonry</value>"
    "</Scene><Output><Directory><value>results</value></Directory>"
    "<Progress>false</Progress></Output>";
  bad_input("XML: m not an integer (a mangled name)",
            xml_start + "<Masonry><Blocks_20per_20side><value>2.5</value>"
                        "</Blocks_20per_20side></Masonry></ParameterHandler>\n",
            ".xml");
  bad_input("XML: a comment",
            xml_start + "<!-- m = 2 --></ParameterHandler>\n",
            ".xml");
  bad_input("XML: no <ParameterHandler>",
            "<?xml version=\"1.0\"?>\n<Parameters><Scene>masonry</Scene>"
            "</Parameters>\n",
            ".xml");
  bad_input("XML: not closed", xml_start, ".xml");
  bad_input("XML: a '<' in a value",
            xml_start +
              "<Masonry><Boundary_20conditions><Signorini><value>base where "
              "x < s</value></Signorini></Boundary_20conditions></Masonry>"
              "</ParameterHandler>\n",
            ".xml");
  bad_input("a file ending in .txt", masonry_prm(""), ".txt");
  {
    // Valid JSON and XML files run (names as the listing gives them, and
    // mangled); a misspelt name then marks the earlier run's summary as
    // not this run's, as for a .prm file (the folder read from the JSON).
    std::string error;
    const int   json =
      run("rerun_json", json_masonry + "2 } }", error, nullptr, ".json");
    std::cout << "a valid JSON file: exit code " << json
              << ", copied as parameters.json: "
              << (std::ifstream("results/rerun_json/parameters.json") ? "yes" :
                                                                        "no")
              << ", as parameters.prm: "
              << (std::ifstream("results/rerun_json/parameters.prm") ? "yes" :
                                                                       "no")
              << "\n"
              << error;
    const int xml =
      run("valid_xml",
          xml_start + "<Masonry><Blocks_20per_20side><value>2</value>"
                      "</Blocks_20per_20side></Masonry>"
                      "</ParameterHandler>\n",
          error,
          nullptr,
          ".xml");
    std::cout << "a valid XML file: exit code " << xml << "\n" << error;
    const int         misspelt = run("rerun_json",
                             json_masonry + "2, \"Refinment\": \"1\" } }",
                             error,
                             nullptr,
                             ".json");
    std::ifstream     file("results/rerun_json/summary.json");
    std::stringstream summary;
    summary << file.rdbuf();
    std::cout << "a misspelt name in JSON in an earlier run's folder: exit "
              << "code " << misspelt << ", its summary.json now says 'error': "
              << holds(summary.str(), "\"status\": \"error\"")
              << ", with the message: "
              << holds(summary.str(), "did you mean 'Refinement'") << "\n";
  }
  // A wall too large for the memory it may use: refused before its
  // matrix is built (1 MB is less than the test already holds).
  bad_input("memory limit 1 MB",
            "set Memory limit = 0.001\n" +
              masonry_prm("  set Blocks per side = 2\n"));
  {
    std::vector<std::string> arguments = {"unilateral", "no_such_file.prm"};
    char              *argv[] = {arguments[0].data(), arguments[1].data()};
    std::ostringstream out, err;
    const int          code = unilateral::run_application(2, argv, out, err);
    std::cout << "missing parameter file: exit code " << code << ", "
              << err.str();
  }

  std::string mistyped_note; // stdout of the next run
  {
    // A support whose region holds no node of its boundary (here a typo:
    // x > 2 on a unit wall) leaves the right half of the wall unsupported.
    // The run cannot succeed, and until 2026-11-27 it said only that the
    // wall has no equilibrium; now the set-up notes the support on stdout
    // and the failure line names it.
    std::string out, err;
    const int   code =
      run("nowhere",
          masonry_prm(
            "  set Blocks per side = 4\n"
            "  subsection Boundary conditions\n"
            "    set Normal displacement zero = left, right, base where x > 2\n"
            "  end\n"),
          err,
          &out);
    const std::string named =
      "'Normal displacement zero' = 'base where x > 2' acts on no node";
    mistyped_note = out;
    std::cout << "A support acting nowhere (base where x > 2): exit code "
              << code << "; noted on stdout: " << holds(out, named)
              << "; named in the failure line: " << holds(err, named) << "\n";
  }

  {
    // The whole base in Signorini contact ('Signorini part of the base' =
    // 1 puts s at its right end): the default 'base where x > s' is empty
    // by the user's choice, and the note says so instead of suggesting a
    // mistyped region (which the case above is told).
    std::string out, err;
    const int   code = run("nowhere_by_choice",
                         masonry_prm("  set Blocks per side = 4\n"
                                       "  subsection Boundary conditions\n"
                                       "    set Signorini part of the base = 1\n"
                                       "  end\n"),
                         err,
                         &out);
    std::cout << "The whole base Signorini: exit code " << code
              << "; the note on 'base where x > s' gives the reason: "
              << holds(out,
                       "'Normal displacement zero' = 'base where x > s' "
                       "acts on no node (as 'Signorini part of the base' = 1 "
                       "puts s at the structure's right end)")
              << "; the mistyped region's note says its region holds no "
                 "node: "
              << holds(mistyped_note,
                       "acts on no node (its region holds no node of that "
                       "boundary)")
              << "\n";
    // A region that s at the end does not explain (x > s + 1 holds no node
    // wherever s is) keeps the plain reason.
    run("nowhere_not_by_choice",
        masonry_prm("  set Blocks per side = 4\n"
                    "  subsection Boundary conditions\n"
                    "    set Signorini part of the base = 1\n"
                    "    set Normal displacement zero = left, right, base "
                    "where x > s + 1\n"
                    "  end\n"),
        err,
        &out);
    std::cout << "  and with 'base where x > s + 1' the note says its region "
                 "holds no node: "
              << holds(out,
                       "'base where x > s + 1' acts on no node (its region "
                       "holds no node of that boundary)")
              << "\n";
    // The same region written the other way round has the same reason.
    run("nowhere_by_choice_reversed",
        masonry_prm("  set Blocks per side = 4\n"
                    "  subsection Boundary conditions\n"
                    "    set Signorini part of the base = 1\n"
                    "    set Normal displacement zero = left, right, base "
                    "where s < x\n"
                    "  end\n"),
        err,
        &out);
    std::cout << "  and with 'base where s < x' the note gives the same "
                 "reason: "
              << holds(out,
                       "'base where s < x' acts on no node (as 'Signorini "
                       "part of the base' = 1 puts s at the structure's "
                       "right end)")
              << "\n";
  }

  {
    // A traction whose region holds no node of the top drops the load: the
    // run is right for the loads it has, and the set-up says which one
    // acts nowhere.
    std::string out, err;
    const int   code = run("traction_nowhere",
                         masonry_prm("  set Blocks per side = 4\n"
                                       "  subsection Boundary conditions\n"
                                       "    set Traction boundaries = top "
                                       "where x > 2\n"
                                       "    set Traction = 0; -100\n"
                                       "  end\n"),
                         err,
                         &out);
    std::cout << "A traction acting nowhere (top where x > 2): exit code "
              << code << "; noted on stdout: "
              << holds(out,
                       "'Traction boundaries' = 'top where x > 2' acts on "
                       "no node")
              << "\n";
  }

  std::string error;
  {
    // The right half of the base moved sideways by a shift s: for s >= 1
    // the joint opens and the answer does not depend on s. Before ff1e49a
    // s = 1e6 ended converged with energy -3 instead of -0.0625 (exit 0):
    // the share of the prescribed displacements, a difference of terms
    // 1e13 times larger, is lost in double precision.
    std::cout << "Prescribed displacement s; 0 on the base where x > s "
                 "(m = 4):\n";
    const auto shifted = [](const std::string &shift) {
      return masonry_prm("  set Blocks per side = 4\n"
                         "  subsection Boundary conditions\n"
                         "    set Normal displacement zero = left\n"
                         "    set Prescribed displacement boundaries = "
                         "base where x > s\n"
                         "    set Prescribed displacement = " +
                         shift + "; 0\n  end\n");
    };
    const auto number = [](const std::string &name, const std::string &key) {
      std::ifstream     in("results/" + name + "/summary.json");
      std::stringstream text;
      text << in.rdbuf();
      const std::string json  = text.str();
      const std::string label = "\"" + key + "\": ";
      const std::size_t at    = json.find(label);
      return at == std::string::npos ?
               std::nan("") :
               std::strtod(json.c_str() + at + label.size(), nullptr);
    };
    const auto energy = [&number](const std::string &name) {
      return number(name, "energy");
    };
    // The share's rounding, which the program bounds by epsilon times its
    // terms, grows as s^2: 6.4e-11 of the energy at s = 1, 2.6e-10 at 2,
    // 6.4e-9 at 10 (measured: the energies differ by 2.3e-10 and 2.4e-9).
    // Hence 1e-9 against s = 2, and against s = 10 the KKT tolerance
    // (1e-8), to which both runs were accepted as converged.
    bool all_converged = true;
    for (const std::string shift : {"1", "2", "10"})
      {
        all_converged = run("shift_" + shift, shifted(shift), error) == 0 &&
                        error.empty() && all_converged;
      }
    const double e_1 = energy("shift_1"), e_2 = energy("shift_2"),
                 e_10 = energy("shift_10");
    std::cout << "  s = 1, 2 and 10: exit code 0, stderr empty: "
              << (all_converged ? "yes" : "no")
              << "; energy of s = 1 equal to that of s = 2 to 1e-9: "
              << (std::abs(e_1 - e_2) <= 1e-9 * std::abs(e_2) ? "yes" : "no")
              << ", to that of s = 10 to 1e-8: "
              << (std::abs(e_1 - e_10) <= 1e-8 * std::abs(e_10) ? "yes" : "no")
              << "\n";
    // The exported LCP is in the solvers' force unit k (here E = 4e4:
    // k = 10) and leaves out the prescribed displacements' share e: its
    // energy times k plus e must be the scene's (summary.json names both).
    {
      const std::string name = "shift_exported";
      const std::string text = shifted("1") +
                               "subsection Masonry\n  subsection Materials\n"
                               "    set Young's modulus = 4e4\n  end\nend\n"
                               "subsection Output\n  set Export LCP = true\n"
                               "  set Write solution = true\nend\n";
      const int                      code      = run(name, text, error);
      const std::string              directory = "results/" + name + "/";
      const unilateral::lcp::Problem lcp =
        unilateral::lcp::read_problem(directory + "lcp_A.mtx",
                                      directory + "lcp_b.txt",
                                      directory + "lcp_constraints.txt");
      const unilateral::lcp::Vector u =
        unilateral::lcp::read_vector(directory + "u.txt");
      const double lcp_energy = unilateral::lcp::energy(lcp, u);
      const double unit       = number(name, "lcp_force_unit");
      const double offset     = number(name, "lcp_energy_offset");
      const double scene      = number(name, "energy");
      std::cout << "  exported LCP (E = 4e4): exit code " << code
                << "; lcp_force_unit " << unit
                << ", lcp_energy_offset nonzero: "
                << (offset != 0 ? "yes" : "no")
                << "; unit * LCP energy + offset = scene energy to 1e-12: "
                << (std::abs(unit * lcp_energy + offset - scene) <=
                        1e-12 * std::abs(scene) ?
                      "yes" :
                      "no")
                << "\n";
    }
    const int code_1e6 = run("shift_1e6", shifted("1e6"), error);
    std::cout << "  s = 1e6: exit code 2: " << (code_1e6 == 2 ? "yes" : "no")
              << "; stderr says 'the energy is resolved only to': "
              << (error.find("the energy is resolved only to") !=
                      std::string::npos ?
                    "yes" :
                    "no")
              << "\n";
  }

  // A run that fails shows its last iterate as such: Graves on the
  // Schur complement of a wall without side rollers (A_EE singular) ended
  // at its zero start, and the summary read "36 of 40 contacts closed"
  // and "18 contacts have zero gap and no force" (a review).
  {
    std::string output;
    const int   code =
      run("graves_singular",
          masonry_prm("  set Blocks per side = 3\n"
                      "  subsection Boundary conditions\n"
                      "    set Normal displacement zero = base where x > s\n"
                      "  end\n") +
            "subsection Solver\n  set Method = graves\n"
            "  set Schur complement = true\nend\n",
          error,
          &output);
    std::cout << "Graves on a singular Schur complement: exit code " << code
              << ", its zero start called the last iterate, not an answer: "
              << (output.find("the last iterate, not an answer") !=
                      std::string::npos ?
                    "yes" :
                    "no")
              << ", no note of degenerate contacts: "
              << (output.find("zero gap and no force") == std::string::npos ?
                    "yes" :
                    "no")
              << "\n";
  }

  std::cout << "Patch test output (laminae, m = 4, g = 0, P2):\n";
  std::cout << "  exit code "
            << run("patch",
                   masonry_prm("  set Geometry = laminae\n"
                               "  set Blocks per side = 4\n"
                               "  set Element = P2\n"
                               "  subsection Boundary conditions\n"
                               "    set Relative gap = 0\n  end\n",
                               "",
                               true),
                   error)
            << error << "\n";
  check_vtu("patch", "patch");

  std::cout << "Settling running bond (m = 4, g = H/2, two materials, Q2):\n";
  std::cout << "  exit code "
            << run("settle",
                   masonry_prm("  set Geometry = running bond\n"
                               "  set Blocks per side = 4\n"
                               "  subsection Materials\n"
                               "    set Young's modulus = 4e3, 1e3\n"
                               "    set Poisson's ratio = 0.3, 0.25\n"
                               "    set Density = 1, 2\n"
                               "    set Assignment = alternating courses\n"
                               "  end\n",
                               "",
                               true),
                   error)
            << error << "\n";
  check_vtu("settle", "settle");

  // The corners of quadratic triangles have int phi = 0 over their faces:
  // the pressure there was force / weight, round-off over round-off
  // (4.9e14 in this column, whose largest pressure is 1).
  std::cout << "3D column of P2 tetrahedra (stack bond m = 2, g = 0):\n";
  std::cout << "  exit code "
            << run("column3d",
                   masonry_prm("  set Dimension = 3\n"
                               "  set Blocks per side = 2\n"
                               "  set Blocks through the thickness = 2\n"
                               "  set Thickness = 2\n"
                               "  set Element = P2\n"
                               "  subsection Boundary conditions\n"
                               "    set Relative gap = 0\n"
                               "    set Normal displacement zero = left, "
                               "right, front, back, base where x > s\n"
                               "  end\n",
                               "",
                               true),
                   error)
            << error << "\n";
  check_vtu("column3d", "column3d");
}
