#include <unilateral/base/ranks.h>

namespace unilateral::ranks
{
  unsigned int
  this_rank(const MPI_Comm &communicator)
  {
    return dealii::Utilities::MPI::job_supports_mpi() ?
             dealii::Utilities::MPI::this_mpi_process(communicator) :
             0;
  }

  unsigned int
  n_ranks(const MPI_Comm &communicator)
  {
    return dealii::Utilities::MPI::job_supports_mpi() ?
             dealii::Utilities::MPI::n_mpi_processes(communicator) :
             1;
  }
} // namespace unilateral::ranks
