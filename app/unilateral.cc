// The unilateral executable: everything lives in the core library.
#include <unilateral/application.h>

#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>

namespace
{
  /**
   * Every active-set iteration touches a few hundred MB afresh (the factor
   * of a new reduced matrix, the matrix itself, vectors of a million
   * entries). In 4 KiB pages that is hundreds of thousands of page faults
   * per run, each costing microseconds on a virtual machine; glibc backs
   * malloc's memory with transparent huge pages when its tunable
   * glibc.malloc.hugetlb=1 is set (stack bond m = 225: 22-23.5 s -> 16 s,
   * the same peak memory). glibc reads tunables only at start-up, so the
   * program restarts itself once with it set, when run_application has read
   * the parameter file and found the problem large enough to gain (the
   * restart costs 0.4 s: --help, bad input and small runs go without). A
   * GLIBC_TUNABLES that names glibc.malloc.hugetlb already (=0 to switch it
   * off) is left alone; if the restart fails, the run goes on as it is.
   */
  void
  restart_with_huge_pages(char **argv)
  {
    const char *const tunables = std::getenv("GLIBC_TUNABLES");
    if (tunables != nullptr &&
        std::strstr(tunables, "glibc.malloc.hugetlb") != nullptr)
      return;
    std::string value = "glibc.malloc.hugetlb=1";
    if (tunables != nullptr && *tunables != '\0')
      value = std::string(tunables) + ":" + value;
    if (setenv("GLIBC_TUNABLES", value.c_str(), 1) == 0)
      execv("/proc/self/exe", argv);
  }
} // namespace

int
main(int argc, char **argv)
{
  return unilateral::run_application(
    argc, argv, std::cout, std::cerr, [argv]() {
      restart_with_huge_pages(argv);
    });
}
