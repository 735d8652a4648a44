#pragma once

#include <deal.II/base/mpi.h>

#include <functional>

namespace unilateral::ranks
{
  /**
   * deal.II's this_mpi_process and n_mpi_processes, also where MPI was never
   * started (a serial run without mpirun, see app/unilateral_run.cc): rank
   * 0 of 1 there.
   */
  unsigned int
  this_rank(const MPI_Comm &communicator = MPI_COMM_WORLD);

  unsigned int
  n_ranks(const MPI_Comm &communicator = MPI_COMM_WORLD);

  /**
   * Run @p work, a rank's own part of a step (writing its piece of the
   * output), on every rank; where it throws InputError on some ranks,
   * throw on every rank the first such rank's message. A failure of one
   * rank's own work then ends the run as a failure of the input does: rank
   * 0 writes summary.json and says why, and no rank is left waiting in a
   * later collective call until the failing one ends them all (a review:
   * a piece that could not be written on rank 1 left no summary.json).
   */
  void
  collectively(const std::function<void()> &work,
               const MPI_Comm              &communicator = MPI_COMM_WORLD);
} // namespace unilateral::ranks
