#pragma once

#include <unilateral/lcp/active_set_system.h>
#include <unilateral/lcp/sparse_cholesky.h>

#include <memory>
#include <vector>

namespace unilateral::lcp
{
  /**
   * Systems (A + diag(shift)) x = r, the Newton systems of interior-point
   * methods: A plus a nonnegative diagonal that changes every iteration
   * (lambda_i / slack_i on S, zero elsewhere). The pattern never changes, so
   * the symbolic analysis runs once (the plate paper's "Analyse once").
   */
  class ShiftedSystem
  {
  public:
    ShiftedSystem(const SparseMatrix &A, Counters &counters);

    /// Factorise A + diag(shift); false if not positive definite.
    bool
    factorise(const Vector &shift);

    void
    solve(const Vector &r, Vector &x) const;

    /// The analysis of A's pattern, with the factor's storage, for a later
    /// stage on A's pattern (ActiveSetFactor::analysis_of); this system is
    /// left without a factor.
    std::shared_ptr<const ActiveSetFactor>
    hand_over_analysis()
    {
      return ActiveSetFactor::analysis_of(cholesky);
    }

  private:
    const SparseMatrix &A;
    Counters           &counters;
    SparseCholesky      cholesky;
  };
} // namespace unilateral::lcp
