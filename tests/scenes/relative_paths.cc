// One rule for paths in a parameter file (issue 21: 'Output/Directory' was
// relative to the working directory while the LCP files were relative to
// the parameter file): a relative path written in a parameter file is taken
// from the parameter file's folder, as deal.II users expect from includes.
// An empty 'Output/Directory' (the default) means output/ in the working
// directory. Every file and folder parameter says so in its help text.
#include "../application_test_tools.h"

#include <filesystem>

using namespace application_test;
namespace fs = std::filesystem;

namespace
{
  std::string
  lcp_prm(const std::string &directory_line)
  {
    return "set Scene = lcp\nsubsection Output\n" + directory_line +
           "  set Print timings = false\n  set Progress = false\nend\n"
           "subsection LCP\n  set Matrix file = A.mtx\n"
           "  set Right-hand side file = b.txt\n"
           "  set Constraints file = c.txt\nend\n";
  }

  void
  expect_written(const std::string &what,
                 const Result      &result,
                 const std::string &directory)
  {
    std::cout << what << ":\n  exit code 0: " << yes_no(result.code == 0)
              << "\n  written to " << directory << ": "
              << yes_no(fs::exists(directory + "/summary.json"))
              << "\n  and says so: "
              << yes_no(result.out.find("results in " + directory + "/") !=
                        std::string::npos)
              << "\n";
  }

  std::size_t
  count(const std::string &text, const std::string &fragment)
  {
    std::size_t n = 0;
    for (auto at = text.find(fragment); at != std::string::npos;
         at      = text.find(fragment, at + 1))
      ++n;
    return n;
  }
} // namespace

int
main()
{
  for (const std::string directory :
       {"cases", "results", "elsewhere", "in_cwd", "default_run"})
    fs::remove_all(directory);
  fs::create_directories("cases/sub");
  write("cases/sub/A.mtx",
        "%%MatrixMarket matrix coordinate real symmetric\n2 2 3\n"
        "1 1 2\n2 1 -1\n2 2 2\n");
  write("cases/sub/b.txt", "1\n-2\n");
  write("cases/sub/c.txt", "1 0\n2 0\n");

  write("cases/sub/relative.prm", lcp_prm("  set Directory = results\n"));
  expect_written("Directory = results, parameter file in cases/sub",
                 run({"cases/sub/relative.prm"}),
                 "cases/sub/results/relative");
  std::cout << "  nothing in results/ of the working directory: "
            << yes_no(!fs::exists("results")) << "\n";

  write("cases/sub/up.prm", lcp_prm("  set Directory = ../../elsewhere\n"));
  expect_written("Directory = ../../elsewhere",
                 run({"cases/sub/up.prm"}),
                 "elsewhere/up");

  write("cases/sub/absolute.prm",
        lcp_prm("  set Directory = " + fs::absolute("in_cwd").string() + "\n"));
  const Result absolute = run({"cases/sub/absolute.prm"});
  std::cout << "an absolute Directory: exit code 0: "
            << yes_no(absolute.code == 0) << ", used as it is: "
            << yes_no(fs::exists("in_cwd/absolute/summary.json")) << "\n";

  // The default writes into output/ of the working directory, where the
  // test harness keeps its file 'output': run it from a folder of its own.
  write("cases/sub/default.prm", lcp_prm(""));
  fs::create_directories("default_run");
  fs::current_path("default_run");
  expect_written("Directory empty (the default), run from default_run/",
                 run({"../cases/sub/default.prm"}),
                 "output/default");
  fs::current_path("..");

  const Result parameters = run({"--print-parameters", "json"});
  std::cout << "help texts of Directory and the three LCP files state the "
               "rule: "
            << yes_no(count(parameters.out,
                            "A relative path is taken from the folder of "
                            "the parameter file") == 4)
            << "\n";
}
