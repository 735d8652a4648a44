#include <unilateral/base/blas_threads.h>

#include <dlfcn.h>

#include <cstdlib>

namespace unilateral::blas
{
  int
  threads()
  {
    using Get = int (*)();
    const auto get =
      reinterpret_cast<Get>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
    return get != nullptr ? get() : 0;
  }

  void
  set_threads(const int n)
  {
    using Set = void (*)(int);
    const auto set =
      reinterpret_cast<Set>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
    if (set != nullptr && n > 0)
      set(n);
  }

  ScopedThreads::ScopedThreads(const int n)
    : before(threads())
  {
    set_threads(n);
  }

  ScopedThreads::~ScopedThreads()
  {
    set_threads(before);
  }

  void
  one_thread_per_rank(const MPI_Comm &communicator)
  {
    if (std::getenv("OPENBLAS_NUM_THREADS") != nullptr ||
        std::getenv("OMP_NUM_THREADS") != nullptr)
      return;
    MPI_Comm on_this_machine;
    MPI_Comm_split_type(
      communicator, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &on_this_machine);
    int ranks_here = 1;
    MPI_Comm_size(on_this_machine, &ranks_here);
    MPI_Comm_free(&on_this_machine);
    if (ranks_here > 1)
      set_threads(1);
  }
} // namespace unilateral::blas
