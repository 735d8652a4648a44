// A Matrix Market file must hold exactly the entries its size line
// announces: more, like fewer, is an error naming the file and the line
// (issue 21, fault 5: a header announcing 2 entries followed by 3 gave a
// different matrix without a word). Comments and blank lines after the
// last entry are fine.
#include "../application_test_tools.h"

using namespace application_test;

namespace
{
  // An LCP run on @p matrix with b = (1, 1) and u >= 0.
  Result
  run_lcp(const std::string &name, const std::string &matrix)
  {
    write(name + ".mtx", matrix);
    write("b.txt", "1\n1\n");
    write("c.txt", "1 0\n2 0\n");
    write(name + ".prm",
          "set Scene = lcp\n"
          "subsection Output\n  set Directory = results\n"
          "  set Print timings = false\n  set Progress = false\nend\n"
          "subsection LCP\n  set Matrix file = " +
            name +
            ".mtx\n  set Right-hand side file = b.txt\n"
            "  set Constraints file = c.txt\nend\n");
    return run({name + ".prm"});
  }

  const std::string header =
    "%%MatrixMarket matrix coordinate real symmetric\n";
} // namespace

int
main()
{
  expect_error("size line announces 2 entries, 3 follow",
               run_lcp("three_of_two",
                       header + "2 2 2\n1 1 2\n2 2 2\n2 1 -1\n"),
               {"three_of_two.mtx:5:", "more entries than the 2"});
  expect_error("the extra entry after a comment and a blank line",
               run_lcp("extra_after_comment",
                       header +
                         "2 2 2\n1 1 2\n2 2 2\n% more below\n\n2 1 -1\n"),
               {"extra_after_comment.mtx:7:"});
  expect_error("size line announces 3 entries, 2 follow",
               run_lcp("two_of_three", header + "2 2 3\n1 1 2\n2 2 2\n"),
               {"two_of_three.mtx:", "2 of 3 entries"});

  const Result trailing =
    run_lcp("trailing_comments",
            header + "2 2 3\n1 1 2\n2 1 -1\n2 2 2\n% end\n\n");
  std::cout << "exactly the announced entries, then comments: exit code 0: "
            << yes_no(trailing.code == 0)
            << ", error output empty: " << yes_no(trailing.err.empty()) << "\n";
}
