// Errors in an LCP read from files use the files' numbering (1-based, as
// Matrix Market and our constraints file count) and name the file, and the
// line where there is one (issue 21: messages quoted 0-based indices,
// "A(1,0) - A(0,1)", "constrained index 2 is outside 0..1", and index
// errors named no file). check_and_normalise on a problem built in code
// counts from 1 as well and says so.
#include <unilateral/base/input_error.h>
#include <unilateral/lcp/problem.h>

#include "../application_test_tools.h"

using namespace application_test;

namespace
{
  Result
  run_lcp(const std::string &name,
          const std::string &matrix,
          const std::string &rhs,
          const std::string &constraints)
  {
    write(name + "_A.mtx", matrix);
    write(name + "_b.txt", rhs);
    write(name + "_c.txt", constraints);
    write(name + ".prm",
          "set Scene = lcp\n"
          "subsection Output\n  set Directory = results\n"
          "  set Print timings = false\n  set Progress = false\nend\n"
          "subsection LCP\n  set Matrix file = " +
            name + "_A.mtx\n  set Right-hand side file = " + name +
            "_b.txt\n  set Constraints file = " + name + "_c.txt\nend\n");
    return run({name + ".prm"});
  }

  const std::string spd =
    "%%MatrixMarket matrix coordinate real symmetric\n2 2 3\n"
    "1 1 2\n2 1 -1\n2 2 2\n";

  // The message check_and_normalise gives for @p problem.
  std::string
  check(unilateral::lcp::Problem problem)
  {
    try
      {
        unilateral::lcp::check_and_normalise(problem);
      }
    catch (const unilateral::InputError &error)
      {
        return error.what();
      }
    return "(accepted)";
  }
} // namespace

int
main()
{
  expect_error("constrained index 3 of 2",
               run_lcp("range", spd, "1\n1\n", "1 0\n# comment\n3 0\n"),
               {"range_c.txt:3:", "index 3", "1..2"});
  expect_error("constrained index 2 twice",
               run_lcp("twice", spd, "1\n1\n", "2 0\n1 0\n2 0.5\n"),
               {"twice_c.txt:3:", "index 2", "line 1"});
  expect_error("non-symmetric A",
               run_lcp("unsymmetric",
                       "%%MatrixMarket matrix coordinate real general\n2 2 3\n"
                       "1 1 2\n2 1 -1\n2 2 2\n",
                       "1\n1\n",
                       "1 0\n"),
               {"unsymmetric_A.mtx",
                "row 2, column 1",
                "row 1, column 2",
                "counted from 1"});
  expect_error("negative diagonal",
               run_lcp("negative",
                       "%%MatrixMarket matrix coordinate real symmetric\n"
                       "3 3 3\n1 1 1\n2 2 1\n3 3 -1\n",
                       "1\n1\n1\n",
                       "1 0\n"),
               {"negative_A.mtx", "row 3", "counted from 1"});
  expect_error("b longer than A",
               run_lcp("mismatch", spd, "1\n1\n1\n", "1 0\n"),
               {"mismatch_A.mtx", "mismatch_b.txt", "2 x 2", "3 entries"});

  std::cout << "check_and_normalise on problems built in code:\n";
  unilateral::lcp::Problem problem;
  problem.A.resize(2, 2);
  problem.A.insert(0, 0) = 1;
  problem.A.insert(1, 1) = 1;
  problem.b              = unilateral::lcp::Vector::Zero(2);
  problem.constrained    = {1, 1};
  problem.lower_bound    = unilateral::lcp::Vector::Zero(2);
  std::cout << "  " << check(problem) << "\n";
  problem.constrained = {0, 2};
  std::cout << "  " << check(problem) << "\n";
  problem.constrained = {0};
  problem.lower_bound = unilateral::lcp::Vector::Zero(1);
  problem.b[1]        = std::numeric_limits<double>::quiet_NaN();
  std::cout << "  " << check(problem) << "\n";
}
