#include <unilateral/lcp/shifted_system.h>

#include <stdexcept>

namespace unilateral::lcp
{
  ShiftedSystem::ShiftedSystem(const SparseMatrix &A, Counters &counters)
    : A(A)
    , counters(counters)
    , shifted(A)
    , diagonal_position(A.rows(), -1)
  {
    for (Index j = 0; j < A.outerSize(); ++j)
      for (Index k = A.outerIndexPtr()[j]; k < A.outerIndexPtr()[j + 1]; ++k)
        if (A.innerIndexPtr()[k] == j)
          diagonal_position[j] = k;
    for (const Index position : diagonal_position)
      if (position < 0)
        throw std::logic_error("ShiftedSystem: diagonal missing from pattern "
                               "(call check_and_normalise first)");
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
