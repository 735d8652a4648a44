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
   * it is one in double precision (its entries below 1e-12 of its largest
   * taken as zero): A's stiffness along it, d^T A d, below
   * 1e-15 of A's diagonal along it, sum A_ii d_i^2 (a proof for A plus a
   * regularisation, or plus the Schur complement's round-off shift n_c
   * eps, is one for A too: A is stiffer along no direction), its entries
   * on the constrained indices of one sign to 1e-8 of its largest, and the
   * loads' work along it at least 1e-6 of |b| |d|, at most 1e-3 of it done
   * where A resists the motion (a force (A d)_i beyond 1e-8 of
   * (|A| |d|)_i: a soft part of an otherwise free motion proves nothing):
   * the minimiser along such a ray, if A had one, would
   * lie at least 1e9 |b| / d away (on the paper's walls a millionfold of
   * the elastic displacements, as a review measured). Returns a
   * description for the failure message, empty where @p direction proves
   * nothing.
   */
  std::string
  unbounded_direction(const Problem &problem, Vector direction);
} // namespace unilateral::lcp
