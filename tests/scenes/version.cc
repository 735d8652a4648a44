// A result can be traced to the code that computed it: `unilateral
// --version` prints one line with the git commit built (12 hex digits, or
// "unknown" outside a git checkout) and the deal.II release, takes no
// argument after it, and every summary.json, a failed run's included,
// records the same commit.
#include "../application_test_tools.h"

#include <regex>

using namespace application_test;

namespace
{
  const std::string output = "subsection Output\n  set Directory = results\n"
                             "  set Write VTU = false\n"
                             "  set Print timings = false\n"
                             "  set Progress = false\nend\n";
} // namespace

int
main()
{
  const Result version = run({"--version"});
  std::smatch  parts;
  const bool   well_formed =
    std::regex_match(version.out,
                     parts,
                     std::regex("unilateral, git ([0-9a-f]{12}|unknown)"
                                "(, uncommitted changes)?, deal\\.II "
                                "[0-9]+\\.[0-9]+\\.[0-9]+\n"));
  const std::string revision = well_formed ? parts[1].str() : "";
  std::cout << "--version: exit code 0: " << yes_no(version.code == 0)
            << ", one line naming the commit and deal.II: "
            << yes_no(well_formed)
            << ", nothing on stderr: " << yes_no(version.err.empty()) << "\n";

  expect_error("--version with an argument",
               run({"--version", "extra"}),
               {"'extra'", "--version"});

  const auto records_commit = [&revision](const std::string &run_name) {
    const std::string recorded = "\"git_revision\": \"" + revision + "\"";
    return yes_no(
      !revision.empty() &&
      read("results/" + run_name + "/summary.json").find(recorded) !=
        std::string::npos);
  };
  write("converged.prm",
        "subsection Masonry\n  set Blocks per side = 2\nend\n" + output);
  const Result converged = run({"converged.prm"});
  std::cout << "a run: exit code 0: " << yes_no(converged.code == 0)
            << ", summary.json records the commit: "
            << records_commit("converged") << "\n";

  // A run that fails after its folder was made (a missing matrix file).
  write("b.txt", "1\n");
  write("c.txt", "1 0\n");
  write("failed.prm",
        "set Scene = lcp\nsubsection LCP\n  set Matrix file = missing.mtx\n"
        "  set Right-hand side file = b.txt\n"
        "  set Constraints file = c.txt\nend\n" +
          output);
  const Result failed = run({"failed.prm"});
  std::cout << "a failed run: exit code 1: " << yes_no(failed.code == 1)
            << ", its summary.json records the commit: "
            << records_commit("failed") << "\n";
}
