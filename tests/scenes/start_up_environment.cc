// What the unilateral command sets before it starts the program proper
// (include/unilateral/base/start_up.h): glibc's huge pages unless the user
// named the tunable, one OpenBLAS thread under an address-space limit
// whatever count was set, and where the program lies. The command used to
// be the program itself, which restarted once to make these settings
// (issue 21: every start paid for it; then large runs did, 0.3-0.4 s).
#include <unilateral/base/start_up.h>

#include "../test_tools.h"

#include <sys/resource.h>
#include <unistd.h>

#include <cstdlib>
#include <string>
#include <vector>

using test_tools::verdict;
namespace start_up = unilateral::start_up;

namespace
{
  std::string
  variable(const char *name)
  {
    const char *value = std::getenv(name);
    return value == nullptr ? "(unset)" : value;
  }

  // GLIBC_TUNABLES before (nullptr: unset), and what huge_pages() must
  // leave.
  void
  check_tunables(const char *before, const std::string &after)
  {
    if (before == nullptr)
      unsetenv("GLIBC_TUNABLES");
    else
      setenv("GLIBC_TUNABLES", before, 1);
    const bool changed = start_up::huge_pages();
    verdict(std::string("GLIBC_TUNABLES ") +
              (before == nullptr ? "unset" : "'" + std::string(before) + "'") +
              " becomes '" + after + "', changed " + (changed ? "yes" : "no"),
            variable("GLIBC_TUNABLES") == after &&
              changed == (before == nullptr || after != before));
  }

  // OPENBLAS_NUM_THREADS and OMP_NUM_THREADS before (nullptr: unset), and
  // what one_blas_thread_under_address_space_limit() must leave.
  void
  check_blas(const char *openblas, const char *omp, const std::string &after)
  {
    for (const auto &[name, value] :
         std::vector<std::pair<const char *, const char *>>{
           {"OPENBLAS_NUM_THREADS", openblas}, {"OMP_NUM_THREADS", omp}})
      if (value == nullptr)
        unsetenv(name);
      else
        setenv(name, value, 1);
    const bool changed = start_up::one_blas_thread_under_address_space_limit();
    const std::string before = openblas == nullptr ? "(unset)" : openblas;
    verdict("OPENBLAS_NUM_THREADS " + before + ", OMP_NUM_THREADS " +
              (omp == nullptr ? "(unset)" : omp) + ": becomes " + after +
              ", changed " + (changed ? "yes" : "no"),
            variable("OPENBLAS_NUM_THREADS") == after &&
              changed == (after != before));
  }
} // namespace

int
main()
{
  check_tunables(nullptr, "glibc.malloc.hugetlb=1");
  check_tunables("", "glibc.malloc.hugetlb=1");
  check_tunables("glibc.malloc.hugetlb=0", "glibc.malloc.hugetlb=0");
  check_tunables("glibc.malloc.hugetlb=2", "glibc.malloc.hugetlb=2");
  check_tunables("glibc.malloc.arena_max=2",
                 "glibc.malloc.arena_max=2:glibc.malloc.hugetlb=1");

  // No address-space limit: nothing changes, whatever the counts.
  rlimit limit{};
  getrlimit(RLIMIT_AS, &limit);
  limit.rlim_cur = RLIM_INFINITY;
  if (setrlimit(RLIMIT_AS, &limit) != 0)
    std::cout << "the test could not lift its address-space limit\n";
  check_blas(nullptr, nullptr, "(unset)");
  check_blas("4", nullptr, "4");
  // Under a limit (far above this test's needs): one thread.
  limit.rlim_cur = rlim_t(1) << 40;
  verdict("an address-space limit of 1 TiB set",
          setrlimit(RLIMIT_AS, &limit) == 0);
  check_blas(nullptr, nullptr, "1");
  check_blas("4", nullptr, "1");
  check_blas("0", nullptr, "1");
  check_blas("1", nullptr, "1");
  check_blas(nullptr, "1", "(unset)"); // OpenBLAS takes OMP's count then
  check_blas(nullptr, "2", "1");

  for (const char *name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    unsetenv(name);
  verdict("not launched by MPI without its variables",
          !start_up::launched_by_mpi());
  for (const char *name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    {
      setenv(name, "2", 1);
      verdict(std::string("launched by MPI with ") + name,
              start_up::launched_by_mpi());
      unsetenv(name);
    }

  // The program lies beside the command: the folder of this executable.
  std::vector<char> path(4096);
  const ssize_t length = readlink("/proc/self/exe", path.data(), path.size());
  const std::string self(path.data(), length > 0 ? std::size_t(length) : 0);
  const std::string folder = self.substr(0, self.rfind('/') + 1);
  verdict("the program's path is in this executable's folder",
          !self.empty() &&
            start_up::beside_this_executable("unilateral-run", "x/y") ==
              folder + "unilateral-run");
}
