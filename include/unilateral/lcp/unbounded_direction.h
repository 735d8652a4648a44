#pragma once

#include <unilateral/lcp/problem.h>

#include <string>

namespace unilateral::lcp
{
  /**
   * A proof that the LCP has no solution: a direction d with A d = 0,
   * d_i >= 0 on the constrained indices it moves, and b^T d > 0. From any
   * feasible u the ray u + t d stays feasible and the energy
   * 1/2 u^T A u - b^T u falls along it without bound, so the convex
   * problem has no minimiser (for semidefinite A such a ray exists exactly
   * when there is no solution). A load that drives a body away gives one:
   * the body's free motion.
   *
   * @p direction is a candidate from a singular system, zero on the
   * indices held at their bounds: the motion the loads drive there
   * (ActiveSetSystem::near_null_direction). It is taken as a proof only where
   * it is one in double precision: A's stiffness along it below 1e-15 of A's
   * mean diagonal d (an A regularised for floating bodies, by at least
   * 1e-14 d, never qualifies; the Schur complement's round-off shift
   * n_c eps d, below that for n_c <= 4, does, where the LCP without it has
   * no solution either), its entries on the constrained indices of one
   * sign to 1e-8 of its largest, and the loads' work along it at least
   * 1e-6 of |b| |d|: the minimiser along such a ray, if A had one, would
   * lie at least 1e9 |b| / d away (on the paper's walls a millionfold of
   * the elastic displacements, as a review measured). Returns a
   * description for the failure message, empty where @p direction proves
   * nothing.
   */
  std::string
  unbounded_direction(const Problem &problem, Vector direction);
} // namespace unilateral::lcp
