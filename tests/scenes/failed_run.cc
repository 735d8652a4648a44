// What a failed run leaves behind (issue 21: a failed run left a directory
// with only parameters.prm). Bad parameters, found while parsing or by the
// scene's constructor, leave no run directory at all; a run that fails
// later (an unreadable LCP file, a problem larger than 'Memory limit')
// writes a summary.json saying so: scene, run_name, status "error", the
// one-line message and converged = false. The memory message names
// 'Memory limit' first when the limit, not the machine, was the bound.
#include <unilateral/base/memory.h>

#include "../application_test_tools.h"

#include <filesystem>

using namespace application_test;
namespace fs = std::filesystem;

namespace
{
  Result
  run_prm(const std::string &name, const std::string &text)
  {
    write(name + ".prm",
          text + "subsection Output\n  set Directory = results\n"
                 "  set Write VTU = false\n  set Print timings = false\n"
                 "  set Progress = false\nend\n");
    return run({name + ".prm"});
  }

  void
  expect_no_directory(const std::string &what,
                      const std::string &name,
                      const Result      &result)
  {
    std::cout << what << ": exit code 1: " << yes_no(result.code == 1)
              << ", no run directory: "
              << yes_no(!fs::exists("results/" + name)) << "\n";
  }

  void
  expect_error_summary(const std::string &what,
                       const std::string &name,
                       const std::string &scene,
                       const Result      &result)
  {
    const std::string prefix  = "unilateral: error: ";
    std::string       message = result.err;
    if (message.rfind(prefix, 0) == 0)
      message = message.substr(prefix.size());
    if (!message.empty() && message.back() == '\n')
      message.pop_back();
    const std::string summary = read("results/" + name + "/summary.json");
    std::cout << what << ":\n  exit code 1: " << yes_no(result.code == 1)
              << "\n  one line on stderr: " << yes_no(one_line(result.err))
              << "\n  parameters.prm written: "
              << yes_no(fs::exists("results/" + name + "/parameters.prm"))
              << "\n";
    for (const std::string &entry : {"\"scene\": \"" + scene + "\"",
                                     "\"run_name\": \"" + name + "\"",
                                     std::string("\"status\": \"error\""),
                                     "\"message\": \"" + message + "\"",
                                     std::string("\"converged\": false")})
      std::cout << "  summary.json has " << entry.substr(0, 22)
                << (entry.size() > 22 ? "..." : "") << ": "
                << yes_no(summary.find(entry) != std::string::npos) << "\n";
  }
} // namespace

int
main()
{
  fs::remove_all("results");
  expect_no_directory("a misspelt parameter",
                      "misspelt",
                      run_prm("misspelt",
                              "set Scene = masonry\n"
                              "set Memory limt = 1\n"));
  expect_no_directory("m = 0 (refused by the scene's constructor)",
                      "zero_blocks",
                      run_prm("zero_blocks",
                              "set Scene = masonry\nsubsection Masonry\n"
                              "  set Blocks per side = 0\nend\n"));

  write("b.txt", "1\n");
  write("c.txt", "1 0\n");
  const Result missing = run_prm("missing_matrix",
                                 "set Scene = lcp\nsubsection LCP\n"
                                 "  set Matrix file = missing.mtx\n"
                                 "  set Right-hand side file = b.txt\n"
                                 "  set Constraints file = c.txt\nend\n");
  expect_error_summary("an LCP whose matrix file is missing",
                       "missing_matrix",
                       "lcp",
                       missing);
  std::cout << "  " << missing.err;

  // 1 MB is less than the test already holds: 'Memory limit' is the bound.
  const Result memory = run_prm("memory_limit",
                                "set Scene = masonry\nset Memory limit = "
                                "0.001\nsubsection Masonry\n"
                                "  set Blocks per side = 2\nend\n");
  expect_error_summary("a wall larger than 'Memory limit'",
                       "memory_limit",
                       "masonry",
                       memory);
  const auto raise = memory.err.find("raise 'Memory limit'");
  std::cout << "  the message suggests raising 'Memory limit' before "
               "shrinking m: "
            << yes_no(raise != std::string::npos &&
                      raise < memory.err.find("Blocks per side"))
            << "\n";

  std::cout << "Which bound a run meets:\n";
  for (const double gigabytes : {0.0, 0.001, 1e9})
    {
      unilateral::memory::set_limit(1e9 * gigabytes);
      std::cout << "  'Memory limit' = " << gigabytes << " GB is the bound: "
                << yes_no(unilateral::memory::limit_binds()) << "\n";
    }
}
