#pragma once

#include <cstdint>

namespace unilateral::openmp
{
  /**
   * Run the OpenMP parallel regions that the calling thread starts outside
   * any team on this thread itself, from now on, without forming a team.
   * OpenMP keeps this setting per thread: SparseCholesky sets it on the
   * thread that factorises.
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
   * So this library defines GOMP_parallel, libgomp's entry for the code a
   * compiler generates for `#pragma omp parallel`, and the libraries loaded
   * after it (CHOLMOD; gmsh, SuperLU_DIST, LibRaw and muParser too) call
   * ours. Where the calling thread has max-active-levels 0, is in no team
   * (omp_get_level() 0) and cancellation is off, it calls the region's body
   * once on that thread: as libgomp's team of one would, the body sees thread
   * 0 of 1, and its barriers, work sharing and tasks take libgomp's path for
   * constructs outside a region. What differs: omp_get_level() is 0 inside,
   * not 1, the body sees the caller's ICVs (the outer level of a nested
   * OMP_NUM_THREADS list), and an ICV it sets (omp_set_num_threads) stays set
   * after it; CHOLMOD does none of this. Every other region goes to libgomp's
   * own GOMP_parallel, and so do the combined entries (`parallel for
   * schedule(dynamic)`, `parallel sections`), which CHOLMOD does not use.
   *
   * A departure from the usual (a library interposing a runtime's symbol)
   * made on purpose: CHOLMOD 3 has no setting for its thread count, and
   * libgomp none for the wake-up. The gain needs this library before
   * libgomp in the load order, as the executable and the tests have it; a
   * program that loads libgomp first (built with -fopenmp and loading this
   * library by dlopen, or linking -lgomp ahead of it) keeps libgomp's
   * regions, with the same results; so does a run with OMP_CANCELLATION
   * set to true.
   */
  void
  run_regions_serially();

  /// How many regions this library's GOMP_parallel has run without a team
  /// so far, on all threads: the tests' evidence that CHOLMOD's calls reach
  /// it.
  std::uint64_t
  regions_run_without_team();
} // namespace unilateral::openmp
