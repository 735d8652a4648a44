#pragma once

#include <unilateral/lcp/problem.h>
#include <unilateral/lcp/report.h>
#include <unilateral/lcp/solver.h>

#include <iosfwd>

namespace unilateral::lcp
{
  /**
   * Solve @p problem with the method and options in @p parameters, as a
   * sequence of attempts:
   *  - an attempt runs a method as a user would: a method that needs a
   *    definite matrix gets A + eps I (eps relative to the mean diagonal;
   *    "auto" takes 1e-9 when Problem::floating_bodies, raised to the
   *    method's preferred eps, else none) and then the projection step
   *    (projection.h), which recovers the exact solution; approximate
   *    methods (PSOR, interior point) get the projection too;
   *  - what follows an attempt is declared by its method (SolverInfo::
   *    follow_ups: PDAS that cycles hands over to the interior point;
   *    Graves' claim that no solution exists is checked), and a method that
   *    needs a definite matrix, meeting a singular one where none was
   *    expected, is tried again regularised;
   *  - with schur_complement, the reduced LCP on S is formed (dense) and
   *    solved this way, and u_E recovered;
   *  - the report gets KKT residuals, energy and active set of the final u
   *    against the original problem, and the status is downgraded to
   *    "inaccurate" if the method's own test passed but the KKT residuals
   *    exceed kkt_tolerance.
   * @p problem must have passed check_and_normalise(); A is verified to be
   * positive semidefinite first (verify_semidefinite). A non-empty
   * solution.u of the right size is the start of the methods that take one.
   * The answer is judged by assess_answer (answer_checks.h).
   */
  /**
   * Throws InputError unless A is positive semidefinite (up to
   * semidefinite_shift of each row's diagonal), which every method assumes:
   * on an indefinite A they return points that solve nothing (a saddle).
   * One Cholesky factorisation of A + shift D, D the diagonal of A (so the
   * test does not depend on the units of each unknown); none where the
   * builder vouches for A (Problem::known_semidefinite).
   */
  void
  verify_semidefinite(const Problem &problem);

  /// The shift of verify_semidefinite, relative to each row's diagonal:
  /// round-off's share of a semidefinite A, far below any eigenvalue of an
  /// indefinite one.
  constexpr double semidefinite_shift = 1e-10;

  Report
  solve_lcp(const Problem          &problem,
            const SolverParameters &parameters,
            Solution               &solution,
            std::ostream           *progress = nullptr);
} // namespace unilateral::lcp
