#include <unilateral/base/openmp_regions.h>

#include <dlfcn.h>
#include <omp.h>

#include <atomic>

namespace
{
  std::atomic<std::uint64_t> regions_without_team{0};

  using RegionBody = void (*)(void *);
  using Parallel   = void (*)(RegionBody, void *, unsigned int, unsigned int);
} // namespace

namespace unilateral::openmp
{
  std::uint64_t
  regions_run_without_team()
  {
    return regions_without_team.load(std::memory_order_relaxed);
  }

  void
  run_regions_serially()
  {
    omp_set_max_active_levels(0);
  }
} // namespace unilateral::openmp

/// libgomp's entry for `#pragma omp parallel` (GCC 4.9 on), interposed: see
/// unilateral::openmp::run_regions_serially().
extern "C" void
GOMP_parallel(const RegionBody   body,
              void *const        data,
              const unsigned int requested_threads,
              const unsigned int flags)
{
  static const auto next_in_load_order =
    reinterpret_cast<Parallel>(dlsym(RTLD_NEXT, "GOMP_parallel"));
  // Outside any team only: a body run inside another team's thread would
  // see that team's size and do its share of a loop alone. Cancellation
  // needs a team to cancel.
  if ((omp_get_max_active_levels() == 0 && omp_get_level() == 0 &&
       !omp_get_cancellation()) ||
      next_in_load_order == nullptr)
    {
      regions_without_team.fetch_add(1, std::memory_order_relaxed);
      body(data);
    }
  else
    next_in_load_order(body, data, requested_threads, flags);
}
