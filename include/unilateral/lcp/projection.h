#pragma once

#include <unilateral/lcp/problem.h>
#include <unilateral/lcp/report.h>
#include <unilateral/lcp/solver.h>

#include <iosfwd>
#include <vector>

namespace unilateral::lcp
{
  /**
   * The projection step of Ainsworth & Mihai (Section 4): the exact method
   * that finishes approximate answers (projection_method(), PDAS), run on A
   * itself from an approximate solution: the answer of A + eps I, or an
   * interior-point iterate. Near the solution it needs one or two
   * iterations.
   *
   * With eps-continuation: if the start is far from the answer (a large
   * eps), the method on A may meet an active set that leaves a body
   * unsupported (a singular system) or wander without settling. Then it
   * continues in eps: the method on A + eps_k d I with eps_k falling by 1e3
   * per stage, each warm-started from the last, and A again after each
   * stage. A projection that has not settled in 50 iterations counts as
   * wandering while a stage is left.
   *
   * Where even that fails, because A is singular on the answer's free set
   * (the solutions form an unbounded set: a course of bricks free to slide
   * along frictionless joints, which no load drives) or the method cycles
   * on A, the approximate answer is finished by the proximal point method
   * instead: LCP(A + eps I, b + eps x_k) for k = 0, 1, ..., each strictly
   * convex, whose fixed point solves LCP(A, b).
   *
   * @p solution: on entry the approximate answer (and the factor it
   * leaves), on exit the projected one. @p first_eps: the absolute eps the
   * continuation starts below (that of the regularised solve).
   * @p first_active_set: how the first active set is chosen: by the test
   * on u (PDAS's own), by interior_point_active_set() for an interior
   * iterate, or the one the method gave with its answer
   * (solution.active_set; SolverInfo::gives_active_set).
   * Adds its iterations, stages, work and time to @p report, and sets its
   * status and message if the projection failed.
   */
  enum class FirstActiveSet
  {
    test_on_u,
    interior_point,
    given
  };

  void
  project(const Problem          &problem,
          const SolverParameters &parameters,
          double                  first_eps,
          FirstActiveSet          first_active_set,
          Solution               &solution,
          Report                 &report,
          std::ostream           *progress);

  /**
   * The first active set of the projection after an interior-point method.
   * Its iterate lies strictly inside, with slack s and multiplier lambda
   * both small on the indices that are nearly complementary. PDAS's test
   * s - tau lambda < 0 mixes their units, and on the running bond walls it
   * called open a few closed contacts that carry almost no force but hold
   * a brick against rotation, their tiny slack larger than tau times their
   * tiny force (benchmarks/masonry_tables/README.md, "Design
   * measurements"): the first system was singular. Compared in units of
   * their own size, s / |s| < lambda / |lambda| (Tapia's indicators,
   * scale-free), it errs towards closing contacts, which the next test
   * reopens safely. A multiplier within the rounding of its own terms
   * counts as no force and leaves its contact open: where nothing touches,
   * every multiplier is such noise, and the ratio alone would close half
   * of them at random.
   */
  std::vector<Index>
  interior_point_active_set(const Problem &problem, const Vector &u);
} // namespace unilateral::lcp
