#include <unilateral/base/blas_threads.h>

#include <dlfcn.h>

#include <cstdlib>
#include <vector>

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

  bool
  prepare_for_address_space_limit()
  {
    if (threads() == 0)
      return true;
    // Room for the buffer and 8 MB; freed, it stays in the heap (glibc's
    // trimming is off, see memory::release_free_heap), where OpenBLAS's
    // allocation below finds it.
    void *const room = std::malloc(std::size_t(136) << 20);
    if (room == nullptr)
      return false;
    std::free(room);
    using Gemm      = void (*)(const char *,
                          const char *,
                          const int *,
                          const int *,
                          const int *,
                          const double *,
                          const double *,
                          const int *,
                          const double *,
                          const int *,
                          const double *,
                          double *,
                          const int *);
    const auto gemm = reinterpret_cast<Gemm>(dlsym(RTLD_DEFAULT, "dgemm_"));
    if (gemm == nullptr)
      return true;
    // Large enough that OpenBLAS takes a buffer (and splits it over its
    // threads where the user asked for several).
    const int           n   = 256;
    const double        one = 1, zero = 0;
    std::vector<double> a(n * n, 1.0), c(n * n);
    gemm("N",
         "N",
         &n,
         &n,
         &n,
         &one,
         a.data(),
         &n,
         a.data(),
         &n,
         &zero,
         c.data(),
         &n);
    return true;
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
