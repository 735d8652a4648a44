// memory::pretouch_in_background faults in heap memory on a thread of its
// own and leaves it to the run (base/pretouch.h): the process's resident
// memory grows by what was asked, without the caller touching anything, and
// a later allocation of that size reuses it instead of growing the process
// again. Below 1 GB nothing is touched; a second call does nothing (once per
// process).
#include <unilateral/base/memory.h>
#include <unilateral/base/pretouch.h>

#include "../test_tools.h"

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <thread>

namespace
{
  constexpr double megabyte = 1 << 20;

  // Wait (up to a minute) until the resident memory has grown by at least
  // @p growth over @p start; true if it has.
  bool
  grows_by(const double start, const double growth)
  {
    for (int i = 0; i < 600; ++i)
      {
        if (unilateral::memory::resident() - start >= growth)
          return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
      }
    return false;
  }
} // namespace

int
main()
{
  const double small = unilateral::memory::resident();
  unilateral::memory::pretouch_in_background(512 * megabyte);
  std::this_thread::sleep_for(std::chrono::seconds(2));
  test_tools::verdict("512 MB, below the 1 GB minimum: nothing is touched",
                      unilateral::memory::resident() - small < 32 * megabyte);

  const double start = unilateral::memory::resident();
  unilateral::memory::pretouch_in_background(1200 * megabyte);
  test_tools::verdict("the thread faults in 1200 MB",
                      grows_by(start, 1150 * megabyte));
  // The last chunk is freed right after it is touched.
  std::this_thread::sleep_for(std::chrono::seconds(1));

  const double      before = unilateral::memory::resident();
  const std::size_t bytes  = 1000 * megabyte;
  char *const       block  = static_cast<char *>(std::malloc(bytes));
  std::memset(block, 1, bytes);
  const double growth = unilateral::memory::resident() - before;
  test_tools::verdict("a 1000 MB allocation afterwards reuses it (the "
                      "process grows by less than 32 MB)",
                      growth < 32 * megabyte);
  std::free(block);

  const double again = unilateral::memory::resident();
  unilateral::memory::pretouch_in_background(1200 * megabyte);
  std::this_thread::sleep_for(std::chrono::seconds(2));
  test_tools::verdict("a second call touches nothing more",
                      unilateral::memory::resident() - again < 32 * megabyte);
}
