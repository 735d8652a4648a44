#pragma once

#include <cstdint>

namespace unilateral::openmp
{
  /**
   * Run every OpenMP parallel region of the process on the thread that
   * reaches it, from now on, without starting a team.
   *
   * Why: CHOLMOD 3 (SuiteSparse 5.12) runs small loops of every supernode
   * (clearing a map, copying a few columns) as OpenMP regions of a
   * compile-time 4 threads, whatever OMP_NUM_THREADS says. On 2 cores every
   * such region wakes threads that have almost nothing to do, so the
   * regions are made serial (OpenMP's max-active-levels set to 0). Even
   * then libgomp forms a team of one for each region and, at its end,
   * wakes the team's (absent) other threads by a system call: 1.8 million
   * of them in one stack bond wall of m = 225, each slow on a virtual
   * machine (figures: benchmarks/masonry_tables/README.md, "Design
   * measurements", "OpenMP regions without a team").
   *
   * So this library defines GOMP_parallel, the entry libgomp gives the
   * code a compiler generates for `#pragma omp parallel`, and the libraries
   * loaded after it (CHOLMOD) call ours: while max-active-levels is 0 it
   * calls the region's body once on the calling thread, which is the
   * region of one thread that OpenMP prescribes when no level may be
   * active (omp_get_thread_num() 0, omp_get_num_threads() 1, barriers
   * and work sharing of an orphaned construct); otherwise it hands the
   * region to libgomp's own. A departure from the usual (a library
   * interposing a runtime's symbol) made on purpose: CHOLMOD 3 has no
   * setting for its thread count, and libgomp none for the wake-up.
   * Process-wide, as the setting itself is: a program linking this library
   * that runs OpenMP regions of its own gets them serial once a
   * SparseCholesky exists.
   */
  void
  run_regions_serially();

  /// How many regions this library's GOMP_parallel has run on the calling
  /// thread so far: the tests' evidence that CHOLMOD's calls reach it.
  std::uint64_t
  regions_run_without_team();
} // namespace unilateral::openmp
