#pragma once

#include <string>

/**
 * Settings that glibc and OpenBLAS read only as a process starts, made in
 * the environment before the program proper is started. Plain C++ and the
 * C library only (and memory.h, likewise): the launcher
 * (app/unilateral.cc) makes them and then starts the program
 * (app/unilateral_run.cc), so that deal.II's ~200 shared libraries are
 * loaded once, with the settings in force. A program that made them for
 * itself would have to start again after loading them (a restart cost
 * 0.3-0.4 s, more than a small run takes).
 */
namespace unilateral::start_up
{
  /// Started by an MPI launcher (mpirun, mpiexec, srun): Open MPI, MPICH's
  /// Hydra and PMIx say so in the environment.
  bool
  launched_by_mpi();

  /**
   * OpenBLAS starts its worker threads as it is loaded, and each maps a
   * work buffer (128 MB in Debian's build) when it first needs one; if the
   * mapping fails, the thread retries for ever (0.3.21): under an
   * address-space limit ('ulimit -v') near the run's needs that is a core
   * spinning through the run and a process that never ends, as its exit
   * waits for the thread. So under such a limit OPENBLAS_NUM_THREADS is set
   * to 1 (one buffer, in the main thread, which the run maps at its start:
   * blas::prepare_for_address_space_limit). A thread count the user set is
   * overridden too: any other than 1 would hang alike. True if the
   * environment was changed.
   */
  bool
  one_blas_thread_under_address_space_limit();

  /**
   * Every active-set iteration touches a few hundred MB afresh (the factor
   * of a new reduced matrix, the matrix itself, vectors of a million
   * entries). In 4 KiB pages that is hundreds of thousands of page faults
   * per run, each costing microseconds on a virtual machine; glibc backs
   * malloc's memory with transparent huge pages when its tunable
   * glibc.malloc.hugetlb=1 is set (stack bond m = 225: 22-23.5 s -> 16 s,
   * the same peak memory; small runs neither gain nor lose). Adds it to
   * GLIBC_TUNABLES unless that names glibc.malloc.hugetlb already (=0 to
   * switch it off). True if the environment was changed.
   */
  bool
  huge_pages();

  /// The path of @p name in the folder of the running executable: the one
  /// /proc/self/exe names (through symbolic links), or where there is no
  /// /proc the folder of @p argv0 if that is a path; empty if neither says.
  std::string
  beside_this_executable(const std::string &name, const char *argv0);
} // namespace unilateral::start_up
