#pragma once

// What the .mpirun=N. tests share: every rank runs the same checks, rank 0
// alone prints them (the other ranks' output would interleave). So that
// the other ranks' answers count too, every verdict goes through
// all_ranks() (it holds only if it holds on every rank), every measured
// error through max_over_ranks(), and a solution vector that every rank
// holds is compared with rank 0's (same_as_rank_0()).
//
// These are collective: every rank must call them, in the same order (as
// it does when all ranks run the same checks). Where MPI was never started
// (a serial test that shares these checks) they return the rank's own
// value.

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <vector>

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

  /// Whether @p condition holds on every rank (the minimum over the ranks).
  inline bool
  all_ranks(const bool condition)
  {
    return dealii::Utilities::MPI::min(condition ? 1 : 0, MPI_COMM_WORLD) == 1;
  }

  /// The largest @p value over the ranks; a NaN on any rank gives +infinity
  /// (MPI_MAX is not defined for NaN), so that "<= tolerance" fails.
  inline double
  max_over_ranks(const double value)
  {
    return dealii::Utilities::MPI::max(
      std::isnan(value) ? std::numeric_limits<double>::infinity() : value,
      MPI_COMM_WORLD);
  }

  /// Rank 0's @p values, on every rank.
  inline std::vector<double>
  from_rank_0(const std::vector<double> &values)
  {
    std::vector<double> result = values;
    if (!dealii::Utilities::MPI::job_supports_mpi())
      return result;
    unsigned long long size = result.size();
    MPI_Bcast(&size, 1, MPI_UNSIGNED_LONG_LONG, 0, MPI_COMM_WORLD);
    result.resize(size);
    if (size > 0)
      MPI_Bcast(
        result.data(), static_cast<int>(size), MPI_DOUBLE, 0, MPI_COMM_WORLD);
    return result;
  }

  /// Whether every rank's @p values equal rank 0's (broadcast) to
  /// @p tolerance times rank 0's largest |value|: the same length, every
  /// entry finite, max |v_rank - v_0| <= tolerance max |v_0|.
  inline bool
  same_as_rank_0(const std::vector<double> &values, const double tolerance)
  {
    const std::vector<double> reference = from_rank_0(values);
    double                    scale     = 0;
    for (const double v : reference)
      scale = std::max(scale, std::abs(v));
    double difference = values.size() == reference.size() ?
                          0 :
                          std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < values.size() && i < reference.size(); ++i)
      {
        const double d = std::abs(values[i] - reference[i]);
        difference     = std::isfinite(d) ? std::max(difference, d) :
                                            std::numeric_limits<double>::infinity();
      }
    return max_over_ranks(difference) <= tolerance * scale;
  }
} // namespace mpi_test
