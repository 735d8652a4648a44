#include <unilateral/base/memory.h>
#include <unilateral/base/start_up.h>

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace unilateral::start_up
{
  bool
  launched_by_mpi()
  {
    for (const char *name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
      if (std::getenv(name) != nullptr)
        return true;
    return false;
  }

  bool
  one_blas_thread_under_address_space_limit()
  {
    if (!std::isfinite(memory::address_space_limit()))
      return false;
    // OpenBLAS's own order: OPENBLAS_NUM_THREADS, else OMP_NUM_THREADS;
    // unset, empty or 0 mean a thread per core.
    const char *const openblas = std::getenv("OPENBLAS_NUM_THREADS");
    const char *const omp      = std::getenv("OMP_NUM_THREADS");
    const char *const count    = openblas != nullptr ? openblas : omp;
    if (count != nullptr && std::strcmp(count, "1") == 0)
      return false;
    return setenv("OPENBLAS_NUM_THREADS", "1", 1) == 0;
  }

  bool
  huge_pages()
  {
    const char *const tunables = std::getenv("GLIBC_TUNABLES");
    if (tunables != nullptr &&
        std::strstr(tunables, "glibc.malloc.hugetlb") != nullptr)
      return false;
    std::string value = "glibc.malloc.hugetlb=1";
    if (tunables != nullptr && *tunables != '\0')
      value = std::string(tunables) + ":" + value;
    return setenv("GLIBC_TUNABLES", value.c_str(), 1) == 0;
  }

  std::string
  beside_this_executable(const std::string &name, const char *argv0)
  {
    std::vector<char> path(4096);
    const ssize_t     length =
      readlink("/proc/self/exe", path.data(), path.size() - 1);
    std::string executable;
    if (length > 0 && static_cast<std::size_t>(length) < path.size() - 1)
      executable.assign(path.data(), static_cast<std::size_t>(length));
    else if (argv0 != nullptr)
      executable = argv0; // a path if it holds a slash (else found on PATH)
    const std::size_t slash = executable.rfind('/');
    return slash == std::string::npos ? "" :
                                        executable.substr(0, slash + 1) + name;
  }
} // namespace unilateral::start_up
