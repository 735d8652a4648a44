#include <unilateral/base/input_error.h>
#include <unilateral/base/ranks.h>

#include <string>

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

  void
  collectively(const std::function<void()> &work, const MPI_Comm &communicator)
  {
    std::string failure;
    bool        failed = false;
    try
      {
        work();
      }
    catch (const InputError &error)
      {
        failure = error.what();
        failed  = true;
      }
    const unsigned int size = n_ranks(communicator);
    if (size == 1)
      {
        if (failed)
          throw InputError(failure);
        return;
      }
    const unsigned int first =
      dealii::Utilities::MPI::min(failed ? this_rank(communicator) : size,
                                  communicator);
    if (first == size)
      return;
    const std::string message =
      dealii::Utilities::MPI::broadcast(communicator, failure, first);
    throw InputError(first == 0 ?
                       message :
                       "on rank " + std::to_string(first) + ": " + message);
  }
} // namespace unilateral::ranks
