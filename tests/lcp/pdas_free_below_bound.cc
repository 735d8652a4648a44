// PDAS's rounding test must not accept a free index that lies below its
// bound. Here A_00 tau = 2e6, so tau times the rounding error of lambda_0
// (the multiplier's share of the tolerance) is about 6e-6, while u_0 itself
// is known to 1e-15. The LCP is built from its solution: the unconstrained
// minimiser has u_0 = 1 - delta below the bound 1, which PDAS reaches after
// its first step (at the start u_0 is in tension and is freed); the answer
// has u_0 = 1 active with lambda_0 > 0. With the old test, delta = 1e-9
// ended "converged" at the free u_0 = 1 - delta (KKT residual 5e-10, within
// the driver's tolerance); delta = 1e-7 lies beyond that tolerance, which
// caught it.
#include "../lcp_test_tools.h"

using namespace test;

int
main()
{
  for (const double delta : {1e-7, 1e-9})
    {
      const double scale = 1e9;
      DenseMatrix  A(2, 2);
      A << 2 * scale, scale, scale, 2 * scale;
      // b = A (1 - delta, 1): the unconstrained minimiser.
      Vector b(2);
      b << scale * (3 - 2 * delta), scale * (3 - delta);
      const Problem problem = make_problem(A, b, {0}, {1.0});

      // The answer: u_0 = 1 active, u_1 from the second row.
      Vector u_exact(2);
      u_exact << 1, (b[1] - scale) / (2 * scale);
      const double lambda_0 = (A * u_exact - b)[0];

      Vector       u;
      const Report report = solve_with(problem, method("pdas"), u);
      std::cout << "delta = " << delta << " (n = 2, |S| = 1)\n"
                << "  exact answer has u_0 at its bound with lambda_0 > 0: "
                << yes_no(lambda_0 > 0) << "\n"
                << "  pdas: " << to_string(report.status)
                << ", u_0 on its bound: " << yes_no(u.size() == 2 && u[0] == 1)
                << ", u exact: "
                << yes_no(u.size() == 2 &&
                          relative_difference(u, u_exact) < 1e-14)
                << ", primal feasibility <= 1e-15: "
                << yes_no(report.kkt.primal_feasibility <= 1e-15)
                << ", KKT <= 1e-12: " << yes_no(report.kkt.max() <= 1e-12)
                << "\n";
    }
}
