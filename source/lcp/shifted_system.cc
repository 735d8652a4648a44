#include <unilateral/lcp/shifted_system.h>


namespace unilateral::lcp
{
  ShiftedSystem::ShiftedSystem(const SparseMatrix &A, Counters &counters)
    : A(A)
    , counters(counters)
    , shifted(A)
    , diagonal_position(diagonal_positions(A))
  {
    // One analysis serves every iteration: worth a second ordering where
    // AMD's is poor.
    cholesky.try_nested_dissection = true;
  }

  bool
  ShiftedSystem::factorise(const Vector &shift)
  {
    for (Index j = 0; j < A.rows(); ++j)
      shifted.valuePtr()[diagonal_position[j]] =
        A.valuePtr()[diagonal_position[j]] + shift[j];
    return cholesky.factorise(shifted, counters);
  }

  void
  ShiftedSystem::solve(const Vector &r, Vector &x) const
  {
    cholesky.solve(r, x);
    ++counters.triangular_solves;
  }
} // namespace unilateral::lcp
