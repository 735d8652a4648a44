// Random SPD LCPs (n <= 12) against exhaustive enumeration of every
// complementary basis: the independent truth for every method. Mixed
// problems (some unknowns unconstrained), nonzero bounds, several seeds.
#include "../lcp_test_tools.h"

#include <random>

using namespace test;

int
main()
{
  std::mt19937 generator(20061);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);

  const std::vector<Index> sizes = {1, 2, 3, 5, 8, 10, 12};
  unsigned int failures = 0, checks = 0, unique = 0, instances = 0;
  for (const Index n : sizes)
    for (unsigned int seed = 0; seed < 8; ++seed)
      {
        // A = G G^T + 0.1 I: SPD with a spread of eigenvalues.
        DenseMatrix G(n, n);
        for (Index i = 0; i < n; ++i)
          for (Index j = 0; j < n; ++j)
            G(i, j) = uniform(generator);
        const DenseMatrix A = G * G.transpose() + 0.1 * DenseMatrix::Identity(n, n);
        Vector b(n);
        for (Index i = 0; i < n; ++i)
          b[i] = uniform(generator);
        // Seeds 0, 1 (mod 4) constrain everything; 2, 3 leave about a third
        // free; odd seeds have nonzero bounds.
        std::vector<Index>  S;
        std::vector<double> lower;
        for (Index i = 0; i < n; ++i)
          if (seed % 4 < 2 || uniform(generator) > -0.33)
            {
              S.push_back(i);
              lower.push_back(seed % 2 == 0 ? 0.0 : 0.5 * uniform(generator));
            }
        const Problem problem = make_problem(A, b, S, lower);
        Vector        u_exact;
        const int     feasible = enumerate(A, b, S, lower, u_exact);
        ++instances;
        unique += (feasible >= 1);

        for (const Method &method :
             all_methods(problem.n_constrained() < problem.size()))
          {
            Vector       u;
            const Report report = solve_with(problem, method, u);
            const bool   right =
              report.converged() && relative_difference(u, u_exact) < 1e-8 &&
              report.kkt.max() < 1e-10;
            ++checks;
            if (!right)
              {
                ++failures;
                std::cout << "n = " << n << ", seed " << seed << ", "
                          << method.label() << ": " << to_string(report.status)
                          << ", difference " << relative_difference(u, u_exact)
                          << ", kkt " << report.kkt.max() << "\n";
              }
          }
      }
  std::cout << "instances: " << instances
            << ", with a basis found by enumeration: " << unique << "\n"
            << "method runs: " << checks << "\n"
            << "runs matching enumeration to 1e-8 with KKT < 1e-10: "
            << checks - failures << "\n"
            << "all correct: " << yes_no(failures == 0 && unique == instances)
            << "\n";
}
