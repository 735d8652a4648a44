// The yardstick of benchmarks/external (our LCP reader and KKT residuals)
// linked from its list of sources alone, without the core library, and
// judging a hand-solved LCP: A = [2 -1; -1 2], b = (1, -2), u >= 0 has the
// solution u = (1/2, 0) with lambda = A u - b = (0, 3/2).
#include <unilateral/lcp/io.h>
#include <unilateral/lcp/problem.h>

#include "../test_tools.h"

#include <fstream>

using namespace unilateral::lcp;

int
main()
{
  std::ofstream("A.mtx") << "%%MatrixMarket matrix coordinate real symmetric\n"
                            "2 2 3\n1 1 2\n2 1 -1\n2 2 2\n";
  std::ofstream("b.txt") << "1\n-2\n";
  std::ofstream("c.txt") << "1 0\n2 0\n";
  const Problem problem = read_problem("A.mtx", "b.txt", "c.txt");
  test_tools::verdict("read: 2 unknowns, both constrained",
                      problem.size() == 2 && problem.n_constrained() == 2);

  Vector solution(2);
  solution << 0.5, 0;
  test_tools::verdict("the solution's KKT residual is zero",
                      kkt_residuals(problem, solution).max() == 0);

  // u = 0 leaves lambda_1 = -1: dual infeasible by 1 / sqrt 2 in the
  // scaled units, against the force scale f = ||D^-1/2 b||_inf = sqrt 2.
  const KktResiduals at_zero = kkt_residuals(problem, Vector::Zero(2));
  test_tools::verdict("u = 0: dual feasibility residual 1/2",
                      std::abs(at_zero.dual_feasibility - 0.5) < 1e-15 &&
                        at_zero.stationarity == 0 &&
                        at_zero.primal_feasibility == 0);
}
