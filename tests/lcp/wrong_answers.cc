// No wrong answer leaves the solver layer as converged (issue 21's faults,
// at the LCP level, for every registered method and variant):
//  1. nonzero bounds: an exact answer at an active positive bound passes the
//     work check (its sign was wrong: u = 1 for A = 1, b = 0, u >= 1 was
//     'inaccurate');
//  2. a body that must settle by its gap under a load far smaller than the
//     stiffness: the exact answer, or no 'converged' (the regularisation
//     once held it up, and the relative KKT residuals passed);
//  3. data beyond double precision: never converged (no double holds the
//     answer, so a converged one, finite or not, is wrong);
//  4. an indefinite A is refused before any answer (it was solved: pdas gave
//     u = (1/3, 1/3), graves (0, 1));
//  5. unknowns whose stiffness differs by 1e24: right in each unknown's own
//     units, or not converged;
//  6. loads that differ by 1e13: each unknown right against its own load,
//     or not converged. (Without the projection step the interior point
//     ends 'converged' there with a contact a thousandth off, a relative
//     KKT residual of 1e-16 against the largest force, and its note that
//     it is only as accurate as its own tolerance: a check of each unknown
//     against its own row's forces, tried, refused correct answers too,
//     benchmarks/stress/README.md.)
#include <unilateral/base/input_error.h>

#include "../lcp_test_tools.h"

#include <cmath>
#include <limits>
#include <map>

using namespace test;

namespace
{
  // Every registered method on @p problem: the verdict of each, one line
  // per method that fails it, one summary line and how many ended with
  // each status (so that a method turning from 'inaccurate' to
  // 'converged' shows, even where the verdict accepts both).
  template <typename Verdict>
  void
  every_method(const std::string &what,
               const Problem     &problem,
               const Verdict     &verdict)
  {
    unsigned int                        runs = 0, failures = 0;
    std::map<std::string, unsigned int> statuses;
    for (const Method &method :
         all_methods(problem.n_constrained() < problem.size()))
      {
        Vector       u;
        const Report report = solve_with(problem, method, u);
        ++runs;
        ++statuses[to_string(report.status)];
        if (!verdict(report, u))
          {
            ++failures;
            std::cout << "  " << method.label() << ": "
                      << to_string(report.status) << ", " << report.message
                      << "\n";
          }
      }
    std::cout << what << ": " << yes_no(failures == 0) << " (" << runs
              << " methods)\n  statuses:";
    for (const auto &[status, count] : statuses)
      std::cout << " " << status << " " << count;
    std::cout << "\n";
  }
} // namespace

int
main()
{
  // 1. A = 1, b = 0, u >= 1: u = 1, lambda = 1 (pushed up by its bound).
  {
    DenseMatrix A(1, 1);
    A << 1;
    const Problem problem = make_problem(A, Vector::Zero(1), {0}, {1.0});
    every_method("bound 1 above the free position: converged, u = 1",
                 problem,
                 [](const Report &report, const Vector &u) {
                   return report.converged() && std::abs(u[0] - 1) < 1e-12;
                 });
  }
  // The same with one constrained and one free unknown coupled, bounds 0.5
  // and the free one following: u = (0.5, 0.25).
  {
    DenseMatrix A(2, 2);
    A << 2, -1, -1, 2;
    const Problem problem = make_problem(A, Vector::Zero(2), {0}, {0.5});
    every_method("coupled, bound 0.5 above: converged, u = (0.5, 0.25)",
                 problem,
                 [](const Report &report, const Vector &u) {
                   return report.converged() && std::abs(u[0] - 0.5) < 1e-12 &&
                          std::abs(u[1] - 0.25) < 1e-12;
                 });
  }

  // 2. A block of two nodes joined by a spring of stiffness 1e4, its base
  // u_0 >= -1 (a support one unit below), a load -1e-12 on its top: it
  // settles onto the support, u = (-1, -1 - 1e-16).
  {
    DenseMatrix A(2, 2);
    A << 1e4, -1e4, -1e4, 1e4;
    Vector b(2);
    b << 0, -1e-12;
    Problem problem         = make_problem(A, b, {0}, {-1.0});
    problem.floating_bodies = true;
    every_method("a block settling by a gap 1e16 times its deformation: "
                 "converged only onto its support",
                 problem,
                 [](const Report &report, const Vector &u) {
                   return !report.converged() || (std::abs(u[0] + 1) < 1e-12 &&
                                                  std::abs(u[1] + 1) < 1e-12);
                 });
  }

  // 3. A = 1e-300, b = 1e300: u = 1e600 is beyond double precision.
  {
    DenseMatrix A(1, 1);
    A << 1e-300;
    Vector b(1);
    b << 1e300;
    const Problem problem = make_problem(A, b, {0}, {0.0});
    every_method("u = 1e600 (beyond double): never converged",
                 problem,
                 [](const Report &report, const Vector &) {
                   return !report.converged();
                 });
  }

  // 5. Unknowns of very different units: A = S A0 S with A0 = tridiag(-1,
  // 3, -1) and S = diag(1e-6, 1, 1e6, ...), b = S b0, the second unknown
  // bounded by 0; u = S^-1 u0 for the answer u0 of (A0, b0). Every method
  // here is right or says it failed; the plate on elements of 1e-4 mm,
  // where the KKT residuals relative to the largest force once let tnnmg's
  // answer pass 3.7e-4 off, is tests/plate/extreme_scales.
  {
    const int   n  = 6;
    DenseMatrix A0 = DenseMatrix::Zero(n, n);
    Vector      b0(n), scale(n);
    for (int i = 0; i < n; ++i)
      {
        A0(i, i) = 3;
        if (i > 0)
          A0(i, i - 1) = A0(i - 1, i) = -1;
        b0[i]    = i % 2 == 0 ? 1.0 : -2.0;
        scale[i] = std::pow(10.0, 6 * (i % 3) - 6);
      }
    const DenseMatrix A        = scale.asDiagonal() * A0 * scale.asDiagonal();
    const Problem     unscaled = make_problem(A0, b0, {1}, {0.0});
    const Problem problem = make_problem(A, scale.cwiseProduct(b0), {1}, {0.0});
    Vector        u0;
    solve_with(unscaled, all_methods(true).front(), u0);
    const Vector expected = u0.cwiseQuotient(scale);
    every_method(
      "unknowns whose stiffness differs by 1e24: converged only with every "
      "unknown right to 1e-7 in its own units",
      problem,
      [&](const Report &report, const Vector &u) {
        // The error of each unknown in units of A's unit diagonal (u_i
        // sqrt(A_ii)), against the largest such unknown: at most the KKT
        // tolerance (1e-8) times the condition of the scaled A (5).
        const Vector root = A.diagonal().cwiseSqrt();
        return !report.converged() ||
               (u - expected).cwiseProduct(root).lpNorm<Eigen::Infinity>() <=
                 1e-7 * expected.cwiseProduct(root).lpNorm<Eigen::Infinity>();
      });
  }

  // 6. A = I, b = (1e10, 1e-3, -1e-3), u >= 0: u = (1e10, 1e-3, 0).
  {
    DenseMatrix A = DenseMatrix::Identity(3, 3);
    Vector      b(3);
    b << 1e10, 1e-3, -1e-3;
    every_method("loads differing by 1e13: converged only with each unknown "
                 "right against its own load",
                 make_problem(A, b, {0, 1, 2}, {0, 0, 0}),
                 [](const Report &report, const Vector &u) {
                   return !report.converged() ||
                          (std::abs(u[0] - 1e10) <= 1e-8 * 1e10 &&
                           std::abs(u[1] - 1e-3) <= 1e-8 * 1e-3 &&
                           std::abs(u[2]) <= 1e-8 * 1e-3);
                 });
  }

  // 7. Two uncoupled parts loaded 1e8 and 1e-6 (a review): A = [[1, 1], [1,
  // 1 + 1e-6]] + [1e8], b = A (1, -1, 1), u_1 >= 0: the contact is open by
  // 1. Block pivoting and LSSNN held it at 0, pulling with all of its
  // part's load, and passed: the relative residual of that pull against
  // the other part's load was 5e-11.
  {
    DenseMatrix A = DenseMatrix::Zero(3, 3);
    A << 1, 1, 0, 1, 1 + 1e-6, 0, 0, 0, 1e8;
    const Vector expected{{1.0, -1.0, 1.0}};
    every_method("a lightly loaded part beside a heavily loaded one: "
                 "converged only with its contact open",
                 make_problem(A, A * expected, {0}, {0.0}),
                 [&](const Report &report, const Vector &u) {
                   return !report.converged() ||
                          (u - expected).lpNorm<Eigen::Infinity>() <= 1e-6;
                 });
  }

  // 8. A semidefinite LCP of rank 2 with many solutions (a review's; every
  // solution's energy by enumeration of its active sets: -1.3316). PDAS
  // and the methods it finishes ended 'singular', the proximal point finish
  // taking its slow steps for a runaway (2 of 17 converged; the Schur
  // complement does not exist: A_EE is singular). A claim that there is no
  // solution would be a wrong answer; one of rank 3 whose Schur complement
  // was called infeasible is lcp/schur_round_off.
  {
    DenseMatrix A(6, 6);
    A << 2, 3, -2, -1, 1, -2, 3, 5, -3, -1, 1, -4, -2, -3, 2, 1, -1, 2, -1, -1,
      1, 1, -1, 0, 1, 1, -1, -1, 1, 0, -2, -4, 2, 0, 0, 4;
    const Vector b{{-2.08, -3.62, 2.08, 0.54, -0.54, 3.08}};
    every_method("rank 2 of 6, solutions exist: converged with their energy, "
                 "never 'infeasible'",
                 make_problem(A, b, {2, 5}, {-0.06, 0}),
                 [](const Report &report, const Vector &) {
                   return report.status != Status::infeasible &&
                          (!report.converged() ||
                           std::abs(report.energy + 1.3316) <= 1e-10);
                 });
  }
  // 9. No solution: a free pair, A = [[1, -1], [-1, 1]], pulled apart by
  // b = (-1, 1 + 1e-4) with u_1 >= 0, beside a part loaded 1e5 (a review).
  // The imbalance is 1e-9 of the loads, within the KKT tolerance, so an
  // answer that balances the loads to it may be given (MPRGP's proximal
  // finish moves the pair by 0.03); not one that moved the pair by the
  // imbalance over the regularisation: the projection's last continuation
  // stage took it 5e7 away, its residual, eps times that, passing the
  // checks, until a stage's answer had to be independent of eps.
  {
    DenseMatrix A = DenseMatrix::Zero(3, 3);
    A << 1, -1, 0, -1, 1, 0, 0, 0, 1;
    const Vector b{{-1.0, 1.0001, 1e5}};
    every_method("no solution (a free pair pulled apart by 1e-4 beside a "
                 "part loaded 1e5): not converged, or the pair within 1",
                 make_problem(A, b, {0}, {0.0}),
                 [](const Report &report, const Vector &u) {
                   return !report.converged() || std::abs(u[0]) < 1;
                 });
  }

  // 4. An indefinite A (eigenvalues 3 and -1).
  {
    DenseMatrix A(2, 2);
    A << 1, 2, 2, 1;
    const Problem problem = make_problem(A, Vector::Ones(2), {0, 1}, {0, 0});
    unsigned int  refused = 0, runs = 0;
    std::string   message;
    for (const Method &method : all_methods(false))
      {
        Vector u;
        ++runs;
        try
          {
            solve_with(problem, method, u);
            std::cout << "  " << method.label() << ": answered\n";
          }
        catch (const unilateral::InputError &error)
          {
            ++refused;
            message = error.what();
          }
      }
    std::cout << "indefinite A refused by every method: "
              << yes_no(refused == runs) << " (" << runs << " methods)\n"
              << "  " << message << "\n";
  }
}
