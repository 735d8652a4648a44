#pragma once

#include <unilateral/lcp/problem.h>
#include <unilateral/lcp/report.h>

#include <iosfwd>

namespace unilateral::lcp
{
  /**
   * Graves' principal pivoting simplex method, as given by Ainsworth & Mihai
   * (Section 4, "Graves"; Graves 1967, Murty ch. 4), for an LCP in which every
   * index is constrained, in practice the reduced Schur-complement LCP
   * (3.17)-(3.18) ('Solver/Schur complement = true').
   *
   * Tableau form: with z = u - l >= 0 and w = lambda >= 0,
   *     w = M z + q,   M = A (after diagonal scaling),  q = A l - b.
   * The tableau (M, q, B) starts with B = I (rows lexico-positive) and every
   * w basic. Each iteration:
   *   Step 2: if q >= 0 the basic variables equal q: stop.
   *   Step 3: t = the row with q_t < 0 whose B_t / q_t is lexicographically
   *           largest.
   *   Step 4, Case 1 (M_tt != 0): principal pivot on t, exchanging w_t, z_t.
   *   Case 2 (M_tt = 0): if M_it >= 0 for all i the LCP has no solution (stop);
   *           else s = the row with M_st < 0 maximising lexicographically
   *           (B_s - q_s B_t / q_t) / M_st, and a double principal pivot on
   *           {s, t}.
   * The pivots are the 1x1 and 2x2 principal pivot transforms written in block
   * form (the paper spells out their entries; its Case 1 update of B has a
   * typo, B_ij - A_it B_ij / A_tt for B_ij - A_it B_tj / A_tt, not repeated
   * here). Theorem 4.5: the lexicographic rule makes the method finite.
   *
   * Dense: for the reduced Schur-complement LCP (the 'graves' method) and
   * the small LCPs of PDAS's exact resolutions (subset_resolution.h).
   * Sets solution.u, report.status (infeasible when Case 2 proves that no
   * solution exists), .iterations and .message; stops at @p limit
   * iterations.
   */
  void
  principal_pivoting(const Problem &problem,
                     unsigned int   limit,
                     Solution      &solution,
                     Report        &report,
                     std::ostream  *progress);
} // namespace unilateral::lcp
