#include <unilateral/lcp/shifted_system.h>


namespace unilateral::lcp
{
  ShiftedSystem::ShiftedSystem(const SparseMatrix &A, Counters &counters)
    : A(A)
    , counters(counters)
  {
    // The shift goes to A's stored diagonal entries: all must be there.
    diagonal_positions(A);
    // One analysis serves every iteration: worth a second ordering where
    // AMD's is poor.
    cholesky.try_nested_dissection = true;
  }

  bool
  ShiftedSystem::factorise(const Vector &shift)
  {
    return cholesky.factorise_shifted(A, shift, counters);
  }

  void
  ShiftedSystem::solve(const Vector &r, Vector &x) const
  {
    cholesky.solve(r, x);
    ++counters.triangular_solves;
  }
} // namespace unilateral::lcp
