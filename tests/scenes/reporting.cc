// What a run says when it ends (issue 21, the weak answers):
//  - an LCP without a solution ends with exit code 2 and one line on
//    stderr in the scene's terms that says there is none and which method
//    proved it (it ended in a long note about bodies on stdout);
//  - 'KKT tolerance = 0' is refused (nothing floating-point passes it);
//  - counts are in the right number ("1 block", "after 1 iteration");
//  - the projection step's progress lines are labelled (they repeated the
//    solve's line word for word);
//  - with timings on, each progress line begins with the seconds since the
//    run started, and no other line does; with timings off, none does.
#include "../application_test_tools.h"

#include <regex>
#include <sstream>
#include <utility>

using namespace application_test;

namespace
{
  const std::string quiet = "subsection Output\n  set Directory = results\n"
                            "  set Print timings = false\n"
                            "  set Progress = false\nend\n";

  bool
  contains(const std::string &text, const std::string &fragment)
  {
    return text.find(fragment) != std::string::npos;
  }

  /// How many lines of @p text contain @p fragment, and how many of those
  /// begin with an elapsed time "[   0.1 s] ".
  std::pair<int, int>
  lines_with_times(const std::string &text, const std::string &fragment)
  {
    const std::regex    time_prefix(R"(^\[ *[0-9]+\.[0-9] s\] )");
    std::istringstream  lines(text);
    std::pair<int, int> counts{0, 0};
    for (std::string line; std::getline(lines, line);)
      if (contains(line, fragment))
        {
          ++counts.first;
          counts.second += std::regex_search(line, time_prefix);
        }
    return counts;
  }
} // namespace

int
main()
{
  // A = diag(1, 0), b = (1, 1), u >= 0: lambda_2 = -1 whatever u is.
  write("A.mtx",
        "%%MatrixMarket matrix coordinate real symmetric\n"
        "2 2 1\n1 1 1\n");
  write("b.txt", "1\n1\n");
  write("c.txt", "1 0\n2 0\n");
  for (const std::string method : {"pdas", "graves"})
    {
      write("no_solution.prm",
            "set Scene = lcp\nsubsection LCP\n  set Matrix file = A.mtx\n"
            "  set Right-hand side file = b.txt\n"
            "  set Constraints file = c.txt\nend\n"
            "subsection Solver\n  set Method = " +
              method + "\nend\n" + quiet);
      const Result result = run({"no_solution.prm"});
      std::cout << "LCP without a solution, " << method
                << ": exit code 2: " << yes_no(result.code == 2)
                << ", one line on stderr: "
                << yes_no(std::count(result.err.begin(),
                                     result.err.end(),
                                     '\n') == 1)
                << "\n  " << result.err;
    }

  write("zero_tolerance.prm",
        "subsection Solver\n  set KKT tolerance = 0\nend\n" + quiet);
  const Result zero = run({"zero_tolerance.prm"});
  std::cout << "KKT tolerance = 0: exit code 1: " << yes_no(zero.code == 1)
            << "\n  " << zero.err;

  write("one_block.prm",
        "subsection Masonry\n  set Blocks per side = 1\n"
        "  subsection Boundary conditions\n    set Relative gap = 0\n"
        "  end\nend\n" +
          quiet);
  const Result one = run({"one_block.prm"});
  std::cout << "one block: exit code 0: " << yes_no(one.code == 0)
            << ", says '1 block,': " << yes_no(contains(one.out, " 1 block,"))
            << ", no '1 blocks': " << yes_no(!contains(one.out, " 1 blocks"))
            << ", no '1 iterations': "
            << yes_no(!contains(one.out, " 1 iterations")) << "\n";

  write("progress.prm",
        "subsection Masonry\n  set Blocks per side = 3\nend\n"
        "subsection Output\n  set Directory = results\n"
        "  set Print timings = false\nend\n");
  const Result progress = run({"progress.prm"});
  std::cout << "progress: the projection's lines are labelled: "
            << yes_no(contains(progress.out, "    projection: pdas iteration"))
            << "\n";
  const auto untimed = lines_with_times(progress.out, "pdas iteration");
  std::cout << "progress with timings off: " << untimed.first
            << " iteration lines, " << untimed.second << " with a time\n";

  write("timed_progress.prm",
        "subsection Masonry\n  set Blocks per side = 3\nend\n"
        "subsection Output\n  set Directory = results\nend\n");
  const Result timed          = run({"timed_progress.prm"});
  const auto   progress_lines = lines_with_times(timed.out, "iteration ");
  const auto   all_lines      = lines_with_times(timed.out, "");
  std::cout << "progress with timings on: " << progress_lines.first
            << " iteration lines, all with a time: "
            << yes_no(progress_lines.second == progress_lines.first)
            << "; other lines with a time: "
            << all_lines.second - progress_lines.second
            << " (the set-up's and solve's progress lines), "
            << "the summary's and the timer table's without: "
            << yes_no(lines_with_times(timed.out, "energy").second == 0 &&
                      lines_with_times(timed.out, "Total wallclock").second ==
                        0)
            << "\n";
}
