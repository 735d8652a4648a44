#pragma once

#include <deal.II/base/mpi.h>

namespace unilateral::ranks
{
  /**
   * deal.II's this_mpi_process and n_mpi_processes, also where MPI was never
   * started (a serial run without mpirun, see app/unilateral.cc): rank 0 of
   * 1 there.
   */
  unsigned int
  this_rank(const MPI_Comm &communicator = MPI_COMM_WORLD);

  unsigned int
  n_ranks(const MPI_Comm &communicator = MPI_COMM_WORLD);
} // namespace unilateral::ranks
