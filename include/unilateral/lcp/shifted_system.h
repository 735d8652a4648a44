#pragma once

#include <unilateral/lcp/sparse_cholesky.h>

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

    /// The factorisation, whose analysis a later stage on A's pattern may
    /// take over (ActiveSetFactor::analysis_of).
    SparseCholesky &
    factorisation()
    {
      return cholesky;
    }

  private:
    const SparseMatrix &A;
    Counters           &counters;
    SparseCholesky      cholesky;
  };
} // namespace unilateral::lcp
