// CHOLMOD's OpenMP regions run on the calling thread without a team once a
// SparseCholesky exists (openmp::run_regions_serially): the core library's
// GOMP_parallel is the one the process's libraries call, it hands regions
// to libgomp's own until then, and runs them as a region of one thread
// without forming a team after. A region that libgomp runs forms a team
// even of one thread (omp_get_level() 1) and wakes its absent threads by a
// system call at its end, 1.8 million times on a stack bond wall of m = 225
// (benchmarks/masonry_tables/README.md, "Design measurements").
#include <unilateral/base/openmp_regions.h>
#include <unilateral/lcp/sparse_cholesky.h>

#include "../lcp_test_tools.h"
#include "../test_tools.h"

#include <dlfcn.h>
#include <omp.h>

#include <atomic>
#include <cstring>
#include <thread>

using namespace test;
using namespace unilateral;

namespace
{
  using RegionBody = void (*)(void *);
  using Parallel   = void (*)(RegionBody, void *, unsigned int, unsigned int);

  struct RegionRecord
  {
    std::atomic<int> runs{0};
    std::atomic<int> largest_level{0};
    std::atomic<int> largest_team{0};
    std::atomic<int> runs_on_caller{0};
    std::thread::id  caller;
  };

  void
  record(void *data)
  {
    auto &r = *static_cast<RegionRecord *>(data);
    ++r.runs;
    r.largest_level = std::max<int>(r.largest_level, omp_get_level());
    r.largest_team  = std::max<int>(r.largest_team, omp_get_num_threads());
    if (std::this_thread::get_id() == r.caller)
      ++r.runs_on_caller;
  }

  // A region of two threads requested, as `#pragma omp parallel
  // num_threads(2)` compiles to.
  void
  run_region(const Parallel parallel, RegionRecord &r)
  {
    r.caller = std::this_thread::get_id();
    parallel(&record, &r, 2, 0);
  }

  // The file that defines the address, as the dynamic loader names it.
  std::string
  defining_file(void *address)
  {
    Dl_info info;
    if (address == nullptr || dladdr(address, &info) == 0 ||
        info.dli_fname == nullptr)
      return "";
    return info.dli_fname;
  }
} // namespace

int
main()
{
  // What CHOLMOD's calls bind to: the first definition in load order.
  const auto parallel =
    reinterpret_cast<Parallel>(dlsym(RTLD_DEFAULT, "GOMP_parallel"));
  const std::string file = defining_file(reinterpret_cast<void *>(parallel));
  test_tools::verdict("GOMP_parallel found", parallel != nullptr);
  test_tools::verdict("GOMP_parallel is the core library's",
                      file.find("unilateral_core") != std::string::npos);
  if (parallel == nullptr)
    return 0;

  RegionRecord before;
  run_region(parallel, before);
  test_tools::verdict("before: libgomp's team of two runs the body twice",
                      before.runs == 2 && before.largest_team == 2 &&
                        before.largest_level == 1);

  {
    SparseCholesky cholesky; // sets the regions serial, process-wide
    RegionRecord   after;
    run_region(parallel, after);
    test_tools::verdict("after: the body runs once, on the calling thread",
                        after.runs == 1 && after.runs_on_caller == 1);
    test_tools::verdict("after: as a region of one thread without a team",
                        after.largest_team == 1 && after.largest_level == 0);

    // CHOLMOD's supernodal factorisation takes this path, and still gives
    // the answer: the 7-point Laplacian on a 16 x 16 x 16 grid (large
    // fronts, so CHOLMOD factorises by supernodes), b = A x for x_i = i.
    const Index                         k = 16, n = k * k * k;
    std::vector<Eigen::Triplet<double>> entries;
    for (Index i = 0; i < n; ++i)
      {
        entries.emplace_back(i, i, 6.0);
        for (const Index stride : {Index(1), k, k * k})
          if (i + stride < n && (stride != 1 || (i + 1) % k != 0) &&
              (stride != k || (i / k + 1) % k != 0))
            {
              entries.emplace_back(i, i + stride, -1.0);
              entries.emplace_back(i + stride, i, -1.0);
            }
      }
    SparseMatrix A(n, n);
    A.setFromTriplets(entries.begin(), entries.end());
    Vector x_exact(n);
    for (Index i = 0; i < n; ++i)
      x_exact[i] = i;
    const Vector        b = A * x_exact;
    Counters            counters;
    Vector              x(n);
    const std::uint64_t regions_before = openmp::regions_run_without_team();
    const bool          factorised     = cholesky.factorise(A, counters);
    if (factorised)
      cholesky.solve(b, x);
    test_tools::verdict("CHOLMOD's regions run through the core library",
                        openmp::regions_run_without_team() > regions_before);
    test_tools::verdict("CHOLMOD solves A x = b to 1e-9 relative",
                        factorised &&
                          (x - x_exact).norm() <= 1e-9 * x_exact.norm());
  }
  return 0;
}
