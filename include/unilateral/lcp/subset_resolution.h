#pragma once

#include <unilateral/lcp/active_set_system.h>
#include <unilateral/lcp/problem.h>
#include <unilateral/lcp/report.h>

#include <vector>

namespace unilateral::lcp
{
  /**
   * The indices an active-set method cannot settle, resolved exactly at once.
   *
   * PDAS moves every violated index to the other side in each iteration. On
   * a matrix that is not an M-matrix this can cycle among a few dozen
   * indices for ever (the running bond walls: contacts that hold a brick
   * against rotation with almost no force), and Judice & Pires' single
   * pivots then pay one factorisation per index. Instead, keep the side of
   * every index outside a subset U (active ones at their bounds, inactive
   * ones free, their bounds ignored) and solve the LCP in the variables of U
   * exactly:
   *     z = u_U - l_U >= 0,   w = lambda_U = q + M z >= 0,   z^T w = 0,
   * with M the Schur complement on U of A with the rest so fixed (positive
   * semidefinite: M = A_UU - A_UF A_FF^-1 A_FU) and q the multipliers with
   * all of U at its bounds. M costs |U| solves with one factor; the dense
   * LCP goes to Graves' principal pivoting, which is exact for semidefinite
   * M and finite by its lexicographic rule (Murty, ch. 4).
   *
   * The answer is the side of each index of U that is consistent with the
   * rest. The caller's next solve and test check it against the whole
   * problem: indices outside U may then be violated, never those in U.
   */
  enum class SubsetResolution
  {
    resolved,   ///< @p active holds the new sides of U
    singular,   ///< A_FF with all of U at its bounds is singular
    no_solution ///< the LCP on U has none (or Graves failed on round-off)
  };

  /**
   * Resolve @p subset (constrained indices) as above. @p active: one entry
   * per unknown, nonzero for the active indices; the entries of @p subset
   * are rewritten when the result is `resolved`, nothing otherwise.
   */
  SubsetResolution
  resolve_subset(const Problem            &problem,
                 ActiveSetSystem          &system,
                 const std::vector<Index> &subset,
                 std::vector<char>        &active,
                 Counters                 &counters);

  /// Largest subset resolve_subset is given: beyond it, M (|U| solves and
  /// O(|U|^3) pivoting) costs more than the single pivots it replaces.
  constexpr Index max_resolved_subset = 1000;
} // namespace unilateral::lcp
