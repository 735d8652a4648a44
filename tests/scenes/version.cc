// A result can be traced to the code that computed it: `unilateral
// --version` prints one line with the git commit built (12 hex digits, or
// "unknown" outside a git checkout) and the deal.II release, takes no
// argument after it, and every summary.json, a failed run's included,
// records the same commit.
//
// The commit is judged against git itself, not only against the program's
// other output (both come from the same compiled string): where git can be
// run on the source tree, the commit must be `git rev-parse --short=12
// HEAD`, and "uncommitted changes" (--version, "local_changes" in
// summary.json) must be said exactly when `git status --porcelain
// --untracked-files=no` lists a change; "unknown" is accepted only where
// that git command fails. The program's commit cannot legitimately lag HEAD
// here: cmake/revision.cmake runs at every build (target
// unilateral_revision, not at configure time), the core library depends on
// it, and ctest builds this test's target, and with it the core library,
// right before running it; so a commit made without reconfiguring is
// picked up. (Only running this executable by hand after a commit, without
// building, or committing while the test runs, could show an older commit.)
#include "../application_test_tools.h"

#include <array>
#include <cstdio>
#include <regex>

using namespace application_test;

namespace
{
  /// The standard output of a shell command and whether it exited with 0.
  std::pair<bool, std::string>
  shell(const std::string &command)
  {
    FILE *pipe = popen(command.c_str(), "r");
    if (pipe == nullptr)
      return {false, ""};
    std::string           text;
    std::array<char, 256> buffer;
    while (fgets(buffer.data(), buffer.size(), pipe) != nullptr)
      text += buffer.data();
    return {pclose(pipe) == 0, text};
  }

  /// What git says about the source tree: HEAD's commit (12 hex digits; ""
  /// if git fails) and whether tracked files differ from it, by the
  /// commands cmake/revision.cmake runs at build time.
  struct Git
  {
    std::string head;
    bool        local_changes = false;
  };

  Git
  git()
  {
    const std::string root = "'" SOURCE_DIR "/../..'";
    Git               result;
    const auto [head_ok, head] =
      shell("git -C " + root + " rev-parse --short=12 HEAD 2>/dev/null");
    if (!head_ok || !std::regex_match(head, std::regex("[0-9a-f]{12}\n")))
      return result;
    const auto [status_ok, status] =
      shell("git --no-optional-locks -C " + root +
            " status --porcelain --untracked-files=no 2>/dev/null");
    if (!status_ok)
      return result;
    result.head          = head.substr(0, 12);
    result.local_changes = !status.empty();
    return result;
  }

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
  const std::string revision     = well_formed ? parts[1].str() : "";
  const bool        says_changes = well_formed && parts[2].matched;
  std::cout << "--version: exit code 0: " << yes_no(version.code == 0)
            << ", one line naming the commit and deal.II: "
            << yes_no(well_formed)
            << ", nothing on stderr: " << yes_no(version.err.empty()) << "\n";

  const Git source_tree = git();
  std::cout << "--version: the commit is git's HEAD of the source tree "
               "('unknown' only where git fails): "
            << yes_no(
                 source_tree.head.empty() ?
                   revision == "unknown" ||
                     std::regex_match(revision, std::regex("[0-9a-f]{12}")) :
                   revision == source_tree.head)
            << ", uncommitted changes said exactly when git status lists "
               "changes to tracked files: "
            << yes_no(source_tree.head.empty() ?
                        well_formed :
                        says_changes == source_tree.local_changes)
            << "\n";

  expect_error("--version with an argument",
               run({"--version", "extra"}),
               {"'extra'", "--version"});

  // The commit, and "local_changes" as --version says it.
  const auto records_commit = [&revision,
                               says_changes](const std::string &run_name) {
    const std::string summary  = read("results/" + run_name + "/summary.json");
    const std::string recorded = "\"git_revision\": \"" + revision + "\"";
    const std::string changes =
      std::string("\"local_changes\": ") + (says_changes ? "true" : "false");
    return yes_no(!revision.empty() &&
                  summary.find(recorded) != std::string::npos &&
                  summary.find(changes) != std::string::npos);
  };
  write("converged.prm",
        "subsection Masonry\n  set Blocks per side = 2\nend\n" + output);
  const Result converged = run({"converged.prm"});
  std::cout << "a run: exit code 0: " << yes_no(converged.code == 0)
            << ", summary.json records the commit and local_changes: "
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
            << ", its summary.json records the commit and local_changes: "
            << records_commit("failed") << "\n";
}
