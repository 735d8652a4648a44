// 'Output/Run name' names a subdirectory of 'Output/Directory' and nothing
// else (issue 21: 'Run name = ../../escape' wrote outside Directory). A name
// with a path separator, or '.' or '..', is refused with one line naming the
// parameter, the value and the fix, before anything is written; a plain
// name, dots inside it included, is fine.
#include "../application_test_tools.h"

#include <filesystem>

using namespace application_test;

namespace
{
  Result
  run_named(const std::string &run_name)
  {
    write("named.prm",
          "set Scene = masonry\n"
          "subsection Output\n  set Directory = results/inner\n"
          "  set Run name = " +
            run_name +
            "\n  set Write VTU = false\n  set Print timings = false\n"
            "  set Progress = false\nend\n"
            "subsection Masonry\n  set Blocks per side = 2\nend\n");
    return run({"named.prm"});
  }
} // namespace

int
main()
{
  std::filesystem::remove_all("escape");
  std::filesystem::remove_all("results");
  for (const std::string name :
       {"../../escape", "../escape", "sub/run", "a\\b", "..", "."})
    {
      const Result result = run_named(name);
      expect_error("Run name = " + name,
                   result,
                   {"'Output/Run name' = " + name, "'Output/Directory'"});
    }
  std::cout << "nothing written outside results/inner: "
            << yes_no(!std::filesystem::exists("escape") &&
                      !std::filesystem::exists("results/escape") &&
                      !std::filesystem::exists("results/inner/sub"))
            << "\n";

  const Result plain = run_named("run 1.v2..final");
  std::cout << "Run name = run 1.v2..final: exit code 0: "
            << yes_no(plain.code == 0) << ", written where expected: "
            << yes_no(std::filesystem::exists(
                 "results/inner/run 1.v2..final/summary.json"))
            << "\n";
}
