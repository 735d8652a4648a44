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
    // AMD's is poor. CHOLMOD's own supernodes, not relaxed ones: with the
    // factorisation on two threads they are the faster (the walls'
    // interior point, benchmarks/masonry_tables/README.md, "Design
    // measurements"), and the projection that takes over this analysis
    // modifies its factor row by row, which relaxed supernodes slow down.
    cholesky.try_nested_dissection = true;
    cholesky.relaxed_supernodes    = false;
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
