// The unilateral executable: everything lives in the core library.
#include <unilateral/application.h>
#include <unilateral/base/blas_threads.h>
#include <unilateral/base/memory.h>

#include <deal.II/base/mpi.h>

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <string>
#include <thread>

namespace
{
  /**
   * Every active-set iteration touches a few hundred MB afresh (the factor
   * of a new reduced matrix, the matrix itself, vectors of a million
   * entries). In 4 KiB pages that is hundreds of thousands of page faults
   * per run, each costing microseconds on a virtual machine; glibc backs
   * malloc's memory with transparent huge pages when its tunable
   * glibc.malloc.hugetlb=1 is set (stack bond m = 225: 22-23.5 s -> 16 s,
   * the same peak memory). glibc reads tunables only at start-up, so the
   * program restarts itself once with it set, when run_application has read
   * the parameter file and found the problem large enough to gain (the
   * restart costs 0.4 s: --help, bad input and small runs go without). A
   * GLIBC_TUNABLES that names glibc.malloc.hugetlb already (=0 to switch it
   * off) is left alone; if the restart fails, the run goes on as it is.
   */
  void
  restart_with_huge_pages(char **argv)
  {
    const char *const tunables = std::getenv("GLIBC_TUNABLES");
    if (tunables != nullptr &&
        std::strstr(tunables, "glibc.malloc.hugetlb") != nullptr)
      return;
    std::string value = "glibc.malloc.hugetlb=1";
    if (tunables != nullptr && *tunables != '\0')
      value = std::string(tunables) + ":" + value;
    if (setenv("GLIBC_TUNABLES", value.c_str(), 1) == 0)
      execv("/proc/self/exe", argv);
  }

  /**
   * OpenBLAS starts its worker threads as it is loaded, and each maps a
   * work buffer (128 MB in Debian's build) when it first needs one; if the
   * mapping fails, the thread retries for ever (0.3.21): under an
   * address-space limit ('ulimit -v') near the run's needs that is a core
   * spinning through the run and a process that never ends, as its exit
   * waits for the thread. So under such a limit the program restarts itself
   * once, before any thread is started, with OPENBLAS_NUM_THREADS=1 (one
   * buffer, in the main thread, which the run maps at its start:
   * blas::prepare_for_address_space_limit). A thread count the user set
   * is overridden too: any other than 1 would hang alike.
   */
  void
  restart_with_one_blas_thread_under_address_space_limit(char **argv)
  {
    if (!std::isfinite(unilateral::memory::address_space_limit()))
      return;
    // OpenBLAS's own order: OPENBLAS_NUM_THREADS, else OMP_NUM_THREADS;
    // unset, empty or 0 mean a thread per core.
    const char *const openblas = std::getenv("OPENBLAS_NUM_THREADS");
    const char *const omp      = std::getenv("OMP_NUM_THREADS");
    const char *const count    = openblas != nullptr ? openblas : omp;
    if (count != nullptr && std::strcmp(count, "1") == 0)
      return;
    if (setenv("OPENBLAS_NUM_THREADS", "1", 1) == 0)
      execv("/proc/self/exe", argv);
  }

  /// Started by an MPI launcher (mpirun, mpiexec, srun): Open MPI, MPICH's
  /// Hydra and PMIx say so in the environment.
  bool
  launched_by_mpi()
  {
    for (const char *name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
      if (std::getenv(name) != nullptr)
        return true;
    return false;
  }
} // namespace

/**
 * MPI is started only under a launcher, so that a serial run needs no
 * mpirun and may still restart itself with huge pages: an execv after
 * MPI_Init would start MPI twice in one process. Under a launcher there is
 * no restart (`mpirun -x GLIBC_TUNABLES=glibc.malloc.hugetlb=1` gives every
 * rank huge pages). Ranks sharing a machine run one BLAS thread each.
 * Every rank reads the same file and fails alike on bad input; rank 0
 * alone prints and writes. A failure during the run (after the file is
 * read) ends every rank through MPI_Abort, as it may be one rank's alone.
 */
int
main(int argc, char **argv)
{
  restart_with_one_blas_thread_under_address_space_limit(argv);
  if (!launched_by_mpi())
    return unilateral::run_application(
      argc, argv, std::cout, std::cerr, [argv]() {
        restart_with_huge_pages(argv);
      });
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  unilateral::blas::one_thread_per_rank(MPI_COMM_WORLD);
  const unsigned int rank =
    dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
  const unsigned int ranks =
    dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
  const bool    speaks = rank == 0;
  std::ofstream nowhere; // never opened: what is written to it is dropped
  // A run that fails on one rank may leave the others waiting in a
  // collective call for ever: the failing rank says why (whichever it is)
  // and ends them all, with the run's exit code. Most failures come from
  // the input, which every rank reads alike: the other ranks wait a moment
  // before they speak, so that rank 0 writes summary.json and says why
  // once before it ends them (all ranks aborting at once tore each
  // other's lines and could end rank 0 before it had written the file).
  const auto end_every_rank = [rank, ranks](const std::string &message,
                                            const int          code) {
    if (ranks == 1)
      return;
    if (rank != 0)
      std::this_thread::sleep_for(std::chrono::seconds(2));
    std::cerr << "unilateral (rank " << rank << " of " << ranks
              << "): " << message << std::endl;
    MPI_Abort(MPI_COMM_WORLD, code);
  };
  return unilateral::run_application(argc,
                                     argv,
                                     speaks ? std::cout : nowhere,
                                     speaks ? std::cerr : nowhere,
                                     {},
                                     end_every_rank);
}
