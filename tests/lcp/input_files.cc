// Ways a file of the lcp scene went wrong without a clear word (found
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

  // Found by a review (2026-11-27), each solved with exit 0 or crashing:
  // a column count beyond 32 bits wrapped (an entry in column 5 of a
  // "3 x 4294967299" matrix was added to A(1, 1));
  write("wide.mtx",
        "%%MatrixMarket matrix coordinate real symmetric\n2 4294967298 3\n"
        "1 1 2\n2 1 -1\n2 2 2\n");
  expect_error("a column count beyond 32-bit indices",
               run_lcp("wide", "wide.mtx", "c.txt"),
               {"wide.mtx:2:", "32-bit"});
  // a symmetric file with both triangles counted every off-diagonal entry
  // twice (Eigen sums repeated triplets), and so did a general file its
  // repeated entries;
  write("both.mtx",
        "%%MatrixMarket matrix coordinate real symmetric\n2 2 4\n"
        "1 1 2\n2 1 -1\n1 2 -1\n2 2 2\n");
  expect_error("a symmetric file listing both triangles",
               run_lcp("both", "both.mtx", "c.txt"),
               {"both.mtx:5:", "listed twice"});
  write("twice.mtx",
        "%%MatrixMarket matrix coordinate real general\n2 2 5\n"
        "1 1 2\n2 1 -1\n1 2 -1\n2 2 1\n2 2 1\n");
  expect_error("a general file listing an entry twice",
               run_lcp("twice", "twice.mtx", "c.txt"),
               {"twice.mtx:7:", "listed twice"});
  // an asymmetry of 0.4 beside an entry of 1e12 passed the symmetry test
  // (relative to the largest entry), and methods solved another problem;
  write("skew.mtx",
        "%%MatrixMarket matrix coordinate real general\n3 3 5\n"
        "1 1 1e12\n2 2 1\n3 3 1\n3 2 0.9\n2 3 0.5\n");
  write("b3.txt", "1\n-2\n1\n");
  write("skew.prm",
        "set Scene = lcp\n"
        "subsection Output\n  set Directory = results\n"
        "  set Print timings = false\n  set Progress = false\nend\n"
        "subsection LCP\n  set Matrix file = skew.mtx\n"
        "  set Right-hand side file = b3.txt\n"
        "  set Constraints file = c.txt\nend\n");
  expect_error("an asymmetry far below the largest entry",
               run({"skew.prm"}),
               {"not symmetric", "0.9", "0.5"});
  // a constraint index beyond 32 bits was called below 1, and a file with
  // a byte-order mark was refused without naming it.
  write("c_wide.txt", "4294967297 0\n");
  expect_error("a constraint index beyond 32 bits",
               run_lcp("c_wide", "A.mtx", "c_wide.txt"),
               {"c_wide.txt:1:", "beyond 32-bit"});
  write("bom.mtx",
        "\xEF\xBB\xBF%%MatrixMarket matrix coordinate real symmetric\n2 2 3\n"
        "1 1 2\n2 1 -1\n2 2 2\n");
  expect_error("a byte-order mark",
               run_lcp("bom", "bom.mtx", "c.txt"),
               {"bom.mtx", "byte-order mark"});
  // A size line "2 2 3.9" read as 3 entries, and a fourth token on an
  // entry's line (a complex part) was dropped: both solved with exit 0.
  write("size_fraction.mtx",
        "%%MatrixMarket matrix coordinate real symmetric\n2 2 3.9\n"
        "1 1 2\n2 1 -1\n2 2 2\n");
  expect_error("a size line with a fraction",
               run_lcp("size_fraction", "size_fraction.mtx", "c.txt"),
               {"size_fraction.mtx:2:", "three whole numbers", "3.9"});
  write("four_tokens.mtx",
        "%%MatrixMarket matrix coordinate real symmetric\n2 2 3\n"
        "1 1 2\n2 1 -1 0.5\n2 2 2\n");
  expect_error("an entry with a fourth token",
               run_lcp("four_tokens", "four_tokens.mtx", "c.txt"),
               {"four_tokens.mtx:4:", "'2 1 -1 0.5'"});
  // A right-hand side in Matrix Market array form had its size line
  // skipped: "2 2" (a matrix of two columns) with two values was solved.
  const auto run_with_b = [](const std::string &name) {
    write(name + ".prm",
          "set Scene = lcp\n"
          "subsection Output\n  set Directory = results\n"
          "  set Print timings = false\n  set Progress = false\nend\n"
          "subsection LCP\n  set Matrix file = A.mtx\n"
          "  set Right-hand side file = " +
            name +
            ".txt\n"
            "  set Constraints file = c.txt\nend\n");
    return run({name + ".prm"});
  };
  write("b_two_columns.txt",
        "%%MatrixMarket matrix array real general\n2 2\n1\n-2\n");
  expect_error("a vector whose size line announces two columns",
               run_with_b("b_two_columns"),
               {"b_two_columns.txt:2:", "2 columns"});
  write("b_short.txt",
        "%%MatrixMarket matrix array real general\n3 1\n1\n-2\n");
  expect_error("a vector with fewer values than its size line announces",
               run_with_b("b_short"),
               {"b_short.txt:2:", "announces 3 values", "holds 2"});

  // Files cut short inside their last number ("2" of "2.5", "-2" of
  // "-25") read as complete files with another last entry; only the
  // missing newline tells.
  write("b_cut.txt", "1\n-2");
  expect_error("a vector cut inside its last number",
               run_with_b("b_cut"),
               {"b_cut.txt:2:", "cut short", "newline"});
  write("A_cut.mtx",
        "%%MatrixMarket matrix coordinate real symmetric\n2 2 3\n"
        "1 1 2\n2 1 -1\n2 2 2");
  expect_error("a matrix cut inside its last number",
               run_lcp("matrix_cut", "A_cut.mtx", "c.txt"),
               {"A_cut.mtx:5:", "cut short"});
  write("c_cut.txt", "1 0\n2 0");
  expect_error("constraints cut inside the last bound",
               run_lcp("constraints_cut", "A.mtx", "c_cut.txt"),
               {"c_cut.txt:2:", "cut short"});
  // A last line of comment without a newline cuts no number.
  write("A_comment.mtx",
        "%%MatrixMarket matrix coordinate real symmetric\n2 2 3\n"
        "1 1 2\n2 1 -1\n2 2 2\n% the end");
  std::cout << "a matrix file ending in a comment without a newline: exit "
               "code "
            << run_lcp("matrix_comment", "A_comment.mtx", "c.txt").code << "\n";
}
