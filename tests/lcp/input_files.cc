// Two ways a file of the lcp scene went wrong without a clear word (found
// by benchmarks/stress/bad_input.py, issue 21): a directory given as the
// matrix file was read as an empty file ("A.mtx:1: empty file"), and a
// lower bound of -inf, which lcp/io.h documents as not allowed (an index
// without a bound is simply not listed), was accepted.
#include "../application_test_tools.h"

#include <filesystem>

using namespace application_test;

namespace
{
  Result
  run_lcp(const std::string &name,
          const std::string &matrix,
          const std::string &constraints)
  {
    write(name + ".prm",
          "set Scene = lcp\n"
          "subsection Output\n  set Directory = results\n"
          "  set Print timings = false\n  set Progress = false\nend\n"
          "subsection LCP\n  set Matrix file = " +
            matrix +
            "\n  set Right-hand side file = b.txt\n"
            "  set Constraints file = " +
            constraints + "\nend\n");
    return run({name + ".prm"});
  }
} // namespace

int
main()
{
  write("A.mtx",
        "%%MatrixMarket matrix coordinate real symmetric\n2 2 3\n"
        "1 1 2\n2 1 -1\n2 2 2\n");
  write("b.txt", "1\n-2\n");
  write("c.txt", "1 0\n2 0\n");
  write("c_minus_inf.txt", "1 0\n2 -inf\n");
  std::filesystem::create_directories("folder.mtx");
  std::filesystem::create_directories("folder.txt");

  expect_error("a directory as the matrix file",
               run_lcp("matrix_folder", "folder.mtx", "c.txt"),
               {"folder.mtx", "a directory, not a file"});
  expect_error("a directory as the constraints file",
               run_lcp("constraints_folder", "A.mtx", "folder.txt"),
               {"folder.txt", "a directory, not a file"});
  expect_error("a lower bound of -inf",
               run_lcp("minus_inf", "A.mtx", "c_minus_inf.txt"),
               {"c_minus_inf.txt:2:", "not listed"});
  // Before cedf554 the matrix of the size line was allocated first (7 GB
  // after 24 s); now the mismatch is found at once.
  write("huge.mtx",
        "%%MatrixMarket matrix coordinate real symmetric\n"
        "2000000000 2000000000 1\n1 1 1\n");
  write("b_one.txt", "1\n");
  write("c_one.txt", "1 0\n");
  write("huge.prm",
        "set Scene = lcp\n"
        "subsection Output\n  set Directory = results\n"
        "  set Print timings = false\n  set Progress = false\nend\n"
        "subsection LCP\n  set Matrix file = huge.mtx\n"
        "  set Right-hand side file = b_one.txt\n"
        "  set Constraints file = c_one.txt\nend\n");
  expect_error("a size line of 2e9 rows with b of one entry",
               run({"huge.prm"}),
               {"dimension mismatch"});
}
