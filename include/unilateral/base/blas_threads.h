#pragma once

#include <deal.II/base/mpi.h>

namespace unilateral::blas
{
  /**
   * OpenBLAS's thread count, read and set at run time: Debian's
   * alternatives choose the BLAS, and another one has no such call (then
   * threads() is 0 and set_threads() does nothing).
   */
  int
  threads();

  void
  set_threads(int n);

  /**
   * OpenBLAS on @p n threads for the lifetime of this object, then as
   * before: for a phase whose BLAS calls are too small for threads to pay.
   */
  class ScopedThreads
  {
  public:
    explicit ScopedThreads(int n);
    ~ScopedThreads();
    ScopedThreads(const ScopedThreads &) = delete;
    ScopedThreads &
    operator=(const ScopedThreads &) = delete;

  private:
    const int before;
  };

  /**
   * Ready OpenBLAS for a run under an address-space limit ('ulimit -v'):
   * its work buffer mapped now. OpenBLAS maps a buffer (128 MB in Debian's
   * build) the first time a thread needs one and keeps it; if the mapping
   * fails it retries forever, without a message (0.3.21): a run would hang
   * in its first factorisation near the limit. The program runs OpenBLAS
   * on one thread under such a limit (base/start_up.h says why), whose
   * one buffer is mapped here while there is room. Returns false if there
   * is none (136 MB cannot be allocated). Does nothing with another BLAS.
   */
  bool
  prepare_for_address_space_limit();

  /**
   * One BLAS thread per rank where several ranks of @p communicator share a
   * machine, unless the user chose a count (OPENBLAS_NUM_THREADS or
   * OMP_NUM_THREADS set). OpenBLAS starts as many threads as the machine
   * has cores in every process; with a rank per core they compete for the
   * cores, and their waiting threads spin in the kernel (README.md, "On
   * several ranks (MPI)").
   */
  void
  one_thread_per_rank(const MPI_Comm &communicator);
} // namespace unilateral::blas
