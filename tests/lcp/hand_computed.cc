// Small LCPs whose solutions are known by hand, solved with every method of
// both papers. Each problem is built from its solution: b = A u* - lambda*
// with u*, lambda* complementary, so the check is independent of the solvers.
#include "../lcp_test_tools.h"

using namespace test;

struct HandProblem
{
  std::string         name;
  DenseMatrix         A;
  std::vector<Index>  S;
  std::vector<double> lower;
  Vector              u_star, lambda_star;
  bool                semidefinite = false;
};

int
main()
{
  std::vector<HandProblem> problems;
  {
    HandProblem p{"two unknowns, one contact",
                  DenseMatrix(2, 2),
                  {0, 1},
                  {0, 0},
                  Vector(2),
                  Vector(2)};
    p.A << 2, -1, -1, 2;
    p.u_star << 0.5, 0;
    p.lambda_star << 0, 1.5;
    problems.push_back(p);
  }
  {
    HandProblem p{"mixed, nonzero bounds",
                  DenseMatrix(3, 3),
                  {0, 2},
                  {1, -1},
                  Vector(3),
                  Vector(3)};
    p.A << 4, -1, 0, -1, 4, -1, 0, -1, 4;
    p.u_star << 1, 0.5, 0;
    p.lambda_star << 2, 0, 0;
    problems.push_back(p);
  }
  {
    HandProblem p{"one unknown below its bound",
                  DenseMatrix(1, 1),
                  {0},
                  {-1},
                  Vector(1),
                  Vector(1)};
    p.A << 2;
    p.u_star << -1;
    p.lambda_star << 2;
    problems.push_back(p);
  }
  {
    HandProblem p{"degenerate (at bound, zero multiplier)",
                  DenseMatrix(2, 2),
                  {0, 1},
                  {0, 0},
                  Vector(2),
                  Vector(2)};
    p.A << 1, 0, 0, 1;
    p.u_star << 0, 1;
    p.lambda_star << 0, 0;
    problems.push_back(p);
  }
  {
    HandProblem p{
      "no contact", DenseMatrix(2, 2), {0, 1}, {0, 0}, Vector(2), Vector(2)};
    p.A << 2, 0, 0, 2;
    p.u_star << 1, 1;
    p.lambda_star << 0, 0;
    problems.push_back(p);
  }
  {
    HandProblem p{"all in contact",
                  DenseMatrix(2, 2),
                  {0, 1},
                  {0, 0},
                  Vector(2),
                  Vector(2)};
    p.A << 2, -1, -1, 2;
    p.u_star << 0, 0;
    p.lambda_star << 2, 1;
    problems.push_back(p);
  }
  {
    // A block on a floor under gravity, hanging a free mass by a spring: A is
    // singular (rigid translation), the solution is unique. Methods that need
    // a definite matrix get A + eps I and the projection step.
    HandProblem p{"semidefinite (floating body)",
                  DenseMatrix(2, 2),
                  {0},
                  {0},
                  Vector(2),
                  Vector(2)};
    p.A << 1, -1, -1, 1;
    p.u_star << 0, -1;
    p.lambda_star << 2, 0;
    p.semidefinite = true;
    problems.push_back(p);
  }

  for (const auto &p : problems)
    {
      const Vector  b       = p.A * p.u_star - p.lambda_star;
      const Problem problem = make_problem(p.A, b, p.S, p.lower);
      std::cout << p.name << " (n = " << problem.size()
                << ", |S| = " << problem.n_constrained() << ")\n";
      for (const Method &method :
           all_methods(problem.n_constrained() < problem.size()))
        {
          Vector       u;
          const Report report =
            solve_with(problem, method, u, p.semidefinite ? 1e-9 : -1);
          const Vector lambda = multiplier(problem, u);
          std::cout << "  " << std::setw(46) << std::left << method.label()
                    << to_string(report.status) << ", u exact: "
                    << yes_no(relative_difference(u, p.u_star) < 1e-10)
                    << ", lambda exact: "
                    << yes_no(
                         (lambda - p.lambda_star).lpNorm<Eigen::Infinity>() <
                         1e-10 * (1 + p.lambda_star.lpNorm<Eigen::Infinity>()))
                    << "\n";
        }
    }
}
