#pragma once

// What the .mpirun=N. tests share: every rank runs the same checks, rank 0
// alone prints them (the other ranks' output would interleave).

#include <deal.II/base/mpi.h>

#include <iostream>

namespace mpi_test
{
  /// This process's rank in MPI_COMM_WORLD, with std::cout silenced on
  /// every rank but 0. Call it after MPI_InitFinalize.
  inline unsigned int
  rank_0_prints()
  {
    const unsigned int rank =
      dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
    if (rank != 0)
      std::cout.setstate(std::ios::failbit);
    return rank;
  }

  inline unsigned int
  n_ranks()
  {
    return dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
  }
} // namespace mpi_test
