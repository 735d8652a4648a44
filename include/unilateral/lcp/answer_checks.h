#pragma once

#include <unilateral/lcp/problem.h>
#include <unilateral/lcp/report.h>

namespace unilateral::lcp
{
  /**
   * The final judgement of every answer solve_lcp gives, always from u alone
   * against the problem: lambda = A u - b, the active set, the relative KKT
   * residuals and the energy, then the checks below in turn. A method's
   * "converged" stands only if all of them pass; the first that fails makes
   * the report 'inaccurate' with a message that says what failed and why.
   * No wrong answer leaves the solver layer as converged.
   */
  void
  assess_answer(const Problem &problem,
                double         kkt_tolerance,
                Solution      &solution,
                Report        &report);

  /**
   * Whether @p u would pass assess_answer as converged: for the decisions
   * taken before the final judgement (whether an exact method's answer
   * needs the projection, whether a verifying method's answer replaces the
   * first), so that they apply the same checks as the final one.
   */
  bool
  passes_checks(const Problem &problem, double kkt_tolerance, const Vector &u);

  /**
   * @name The checks of assess_answer
   * Each leaves a report that is not 'converged' as it is.
   */
  /// @{

  /// u, lambda, the energy and the residuals are finite numbers: a NaN or an
  /// infinity in them means the data are beyond what double arithmetic
  /// holds (a stiffness of 1e-300 with a load of 1); the message gives
  /// their sizes.
  void
  check_finite(const Problem  &problem,
               const Solution &solution,
               Report         &report);

  /// The relative KKT residuals are at most @p kkt_tolerance (the method's
  /// own test can pass where they are not: a tolerance of its paper, an
  /// answer of a regularised problem).
  void
  check_kkt(double kkt_tolerance, Report &report);

  /**
   * The work identity: at every solution u^T A u = b^T u + lambda_S^T l_S
   * (lambda = A u - b vanishes off S, and complementarity puts u at l where
   * lambda is not zero), and u^T A u >= 0. So W = b^T u + lambda_S^T l_S
   * cannot be negative; an answer with W below -1e-6 (|b|^T |u| +
   * |lambda_S|^T |l_S|), less the rounding error of lambda_S^T l_S, is not
   * a solution. The relative KKT residuals are
   * blind to a body that drifted far away as a rigid motion (A u stays
   * small where |A| |u| is huge), and W is not: such an answer has W close
   * to -|b|^T |u|.
   */
  void
  check_work(const Problem &problem, const Solution &solution, Report &report);

  /**
   * The forces of the answer balance the loads, measured against the loads:
   * with F = max(|b|_inf, |lambda_S|_inf), the residuals of stationarity,
   * of dual feasibility, and in force units (times A_ii) of
   * complementarity, must be at most @p kkt_tolerance F plus ten times
   * their rounding error, epsilon |A| |u|_inf (a large motion elsewhere
   * hides a force on an open contact from the relative KKT residual); and
   * double precision must resolve the forces that finely: epsilon |A|
   * |u|_inf must be at most @p kkt_tolerance F too (it bounds the accuracy
   * of the contact forces and of the energy), unless A is definite
   * (Problem::definite: no rigid motion, |A| |u| / F is the conditioning).
   * Both
   * catch what the relative KKT residuals (measured against |A| |u|) miss
   * where the displacements are mostly rigid motions far larger than the
   * elastic ones: blocks that settle by a gap a billion times their elastic
   * deformation, or that hang in the air held by round-off. Without loads
   * and with contact forces at the round-off of A u there is nothing to
   * balance and the check passes.
   */
  void
  check_balance(const Problem  &problem,
                const Solution &solution,
                double          kkt_tolerance,
                Report         &report);

  /**
   * Each contact held exactly at its bound (as exact methods leave it)
   * against the terms its force is made of, r_i = |b_i| + (|A| |u|)_i: a
   * contact that pulls (lambda_i < 0) by more than @p kkt_tolerance r_i
   * plus ten times the rounding error of A u (epsilon |A| |u|_inf) is held
   * where it should open. check_balance measures the pull against the
   * largest force of the whole problem, and a heavily loaded body
   * elsewhere hides a wrong contact of a lightly loaded one (a review:
   * two uncoupled blocks loaded 1e8 and 1e-6, whose contact pulled with
   * all of the small block's load, passed block pivoting and LSSNN with
   * a relative residual of 5e-11). Not for contacts off their bound: an
   * approximate method's leftover slack there is measured against itself
   * (benchmarks/stress/README.md, a check of every row tried and
   * reverted), nor for a Schur complement (Problem::eliminated: its
   * rounding is the full problem's). Takes the multipliers from @p
   * solution (assess_answer sets them from u).
   */
  void
  check_contact_forces(const Problem  &problem,
                       const Solution &solution,
                       double          kkt_tolerance,
                       Report         &report);

  /**
   * The largest residual check_balance lets pass for @p u and its
   * multipliers @p lambda = A u - b: @p kkt_tolerance F plus ten times the
   * rounding error epsilon |A| |u|_inf, in force units; infinity where
   * there is nothing to balance (no loads, no contact force) or where the
   * forces are not resolved to @p kkt_tolerance (a floating body whose
   * rigid motion dwarfs them; check_balance says so). For a
   * method's own stopping test, so that it does not stop at an answer this
   * check refuses (PDAS keeping a contact that pulls).
   */
  double
  balance_allowance(const Problem &problem,
                    const Vector  &u,
                    const Vector  &lambda,
                    double         kkt_tolerance);
  /// @}
} // namespace unilateral::lcp
