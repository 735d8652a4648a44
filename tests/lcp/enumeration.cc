// Random SPD LCPs (n <= 12) against exhaustive enumeration of every
// complementary basis: the independent truth for every method. Mixed
// problems (some unknowns unconstrained), nonzero bounds, several seeds.
// Also PDAS's exact resolution of a subset (resolve_subset): with the side
// of every other constrained index kept, its answer on the subset against
// enumeration of every side the subset can take.
#include <unilateral/lcp/active_set_system.h>
#include <unilateral/lcp/subset_resolution.h>

#include "../lcp_test_tools.h"
#include "../test_tools.h"

#include <algorithm>

namespace
{
  using namespace test;

  // A = G G^T + 0.1 I (SPD with a spread of eigenvalues) and b, entries of
  // G and b from the suite's portable sequence in [-1, 1) (not <random>,
  // whose distributions differ between standard libraries).
  void
  random_spd_lcp(const Index           n,
                 test_tools::Sequence &uniform,
                 DenseMatrix          &A,
                 Vector               &b)
  {
    DenseMatrix G(n, n);
    for (Index i = 0; i < n; ++i)
      for (Index j = 0; j < n; ++j)
        G(i, j) = uniform.next();
    A = G * G.transpose() + 0.1 * DenseMatrix::Identity(n, n);
    b.resize(n);
    for (Index i = 0; i < n; ++i)
      b[i] = uniform.next();
  }

  /**
   * The answer on U by enumeration: every subset X' of U fixed with the
   * rest as given; the one whose u is feasible on U (u >= l off X',
   * lambda >= 0 on X') is the truth. Returns how many qualify.
   */
  int
  enumerate_subset(const DenseMatrix        &A,
                   const Vector             &b,
                   const Vector             &lower,
                   const std::vector<char>  &rest_active,
                   const std::vector<Index> &subset,
                   Vector                   &u_exact)
  {
    const Index k     = static_cast<Index>(subset.size());
    int         found = 0;
    for (long mask = 0; mask < (1L << k); ++mask)
      {
        std::vector<char> fixed = rest_active;
        for (Index r = 0; r < k; ++r)
          fixed[subset[r]] = (mask >> r) & 1;
        const Vector u        = equality_solution(A, b, fixed, lower);
        const Vector lambda   = A * u - b;
        bool         feasible = true;
        for (const Index i : subset)
          if (fixed[i] ? lambda[i] < -1e-12 :
                         u[i] < lower[i] - 1e-12 * (1 + std::abs(lower[i])))
            feasible = false;
        if (feasible && found++ == 0)
          u_exact = u;
      }
    return found;
  }
} // namespace

using namespace test;

int
main()
{
  test_tools::Sequence uniform(20061);

  const std::vector<Index> sizes    = {1, 2, 3, 5, 8, 10, 12};
  unsigned int             failures = 0, checks = 0, unique = 0, instances = 0;
  for (const Index n : sizes)
    for (unsigned int seed = 0; seed < 8; ++seed)
      {
        DenseMatrix A;
        Vector      b;
        random_spd_lcp(n, uniform, A, b);
        // Seeds 0, 1 (mod 4) constrain everything; 2, 3 leave about a third
        // free; odd seeds have nonzero bounds.
        std::vector<Index>  S;
        std::vector<double> lower;
        for (Index i = 0; i < n; ++i)
          if (seed % 4 < 2 || uniform.next() > -0.33)
            {
              S.push_back(i);
              lower.push_back(seed % 2 == 0 ? 0.0 : 0.5 * uniform.next());
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
            const bool   right  = report.converged() &&
                               relative_difference(u, u_exact) < 1e-8 &&
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
  // resolve_subset: random SPD A, a random subset U of S and random sides
  // for the rest of S.
  unsigned int subset_checks = 0, subset_right = 0;
  for (const Index n : sizes)
    for (unsigned int seed = 0; seed < 8; ++seed)
      {
        DenseMatrix A;
        Vector      b;
        random_spd_lcp(n, uniform, A, b);
        std::vector<Index>  S, subset;
        std::vector<double> lower;
        std::vector<char>   active(n, 0);
        for (Index i = 0; i < n; ++i)
          if (uniform.next() > -0.5)
            {
              S.push_back(i);
              lower.push_back(seed % 2 == 0 ? 0.0 : 0.5 * uniform.next());
              if (uniform.next() > 0 && subset.size() < 8)
                subset.push_back(i);
              else
                active[i] = uniform.next() > 0;
            }
        if (subset.empty())
          continue;
        const Problem problem    = make_problem(A, b, S, lower);
        const Vector  full_lower = problem.full_lower_bound();
        Vector        u_exact;
        const int     found =
          enumerate_subset(A, b, full_lower, active, subset, u_exact);
        Counters               counters;
        ActiveSetSystem        system(problem.A, counters);
        std::vector<char>      resolved = active;
        const SubsetResolution result =
          resolve_subset(problem, system, subset, resolved, counters);
        // The rest keeps its sides; U takes the answer's.
        bool rest_kept = true;
        for (Index i = 0; i < n; ++i)
          if (std::find(subset.begin(), subset.end(), i) == subset.end())
            rest_kept = rest_kept && resolved[i] == active[i];
        const Vector u   = equality_solution(A, b, resolved, full_lower);
        const bool right = found >= 1 && result == SubsetResolution::resolved &&
                           rest_kept && relative_difference(u, u_exact) < 1e-10;
        ++subset_checks;
        subset_right += right;
        if (!right)
          std::cout << "resolve_subset, n = " << n << ", seed " << seed
                    << ", |U| = " << subset.size() << ": found " << found
                    << ", difference " << relative_difference(u, u_exact)
                    << "\n";
      }
  // A subset LCP without solution (a body pulled off its only support) and
  // a singular base (a second body that no constraint holds).
  {
    DenseMatrix A(2, 2);
    A << 1, -1, -1, 1;
    Vector b(2);
    b << 1, 0; // lambda_0 = -1 whatever u is: nothing can hold the body
    const Problem     problem = make_problem(A, b, {0}, {0});
    Counters          counters;
    ActiveSetSystem   system(problem.A, counters);
    std::vector<char> active = {0, 0};
    std::cout << "resolve_subset, body pulled off its support: no solution: "
              << yes_no(
                   resolve_subset(problem, system, {0}, active, counters) ==
                   SubsetResolution::no_solution)
              << "\n";
    DenseMatrix two_bodies       = DenseMatrix::Zero(4, 4);
    two_bodies.block(0, 0, 2, 2) = A;
    two_bodies.block(2, 2, 2, 2) = A;
    Vector load(4);
    load << 0, -1, 0, -1;
    const Problem     loose = make_problem(two_bodies, load, {0}, {0});
    ActiveSetSystem   loose_system(loose.A, counters);
    std::vector<char> loose_active(4, 0);
    std::cout << "resolve_subset, a body no constraint holds: singular: "
              << yes_no(resolve_subset(
                          loose, loose_system, {0}, loose_active, counters) ==
                        SubsetResolution::singular)
              << "\n";
  }
  std::cout << "resolve_subset: " << subset_right << " of " << subset_checks
            << " subsets match enumeration to 1e-10\n";

  std::cout << "instances: " << instances
            << ", with a basis found by enumeration: " << unique << "\n"
            << "method runs: " << checks << "\n"
            << "runs matching enumeration to 1e-8 with KKT < 1e-10: "
            << checks - failures << "\n"
            << "all correct: "
            << yes_no(failures == 0 && unique == instances &&
                      subset_right == subset_checks)
            << "\n";
}
