// The program proper (the unilateral command starts it: app/unilateral.cc);
// everything lives in the core library.
#include <unilateral/application.h>
#include <unilateral/base/blas_threads.h>
#include <unilateral/base/start_up.h>

#include <deal.II/base/mpi.h>

#include <unistd.h>

#include <chrono>
#include <fstream>
#include <iostream>
#include <string>
#include <thread>

/**
 * MPI is started only under an MPI launcher, so that a serial run needs no
 * mpirun. Ranks sharing a machine run one BLAS thread each. Started
 * directly rather than by the unilateral command, the program restarts
 * itself once under an address-space limit (start_up.h says why; the
 * command sets that before it starts the program), and runs without huge
 * pages unless GLIBC_TUNABLES asks for them. Every rank reads the same
 * file and fails alike on bad input; rank 0 alone prints and writes. A
 * failure during the run (after the file is read) ends every rank through
 * MPI_Abort, as it may be one rank's alone.
 */
int
main(int argc, char **argv)
{
  if (unilateral::start_up::one_blas_thread_under_address_space_limit())
    execv("/proc/self/exe", argv);
  if (!unilateral::start_up::launched_by_mpi())
    return unilateral::run_application(argc, argv, std::cout, std::cerr);
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
                                     end_every_rank);
}
