// CHOLMOD's OpenMP regions run on the factorising thread without a team
// (openmp::run_regions_serially): the core library's GOMP_parallel is the
// one the process's libraries call; it hands regions to libgomp's own on a
// thread that has not factorised, and inside another team; on a thread
// that has, it runs a region reached outside any team as a region of one
// thread without forming a team. A region that libgomp runs forms a team
// even of one thread (omp_get_level() 1) and wakes its absent threads by a
// system call at its end, 1.8 million times on a stack bond wall of
// m = 225 (benchmarks/masonry_tables/README.md, "Design measurements").
#include <unilateral/base/openmp_regions.h>
#include <unilateral/lcp/sparse_cholesky.h>

#include "../lcp_test_tools.h"
#include "../test_tools.h"

#include <dlfcn.h>
#include <omp.h>

#include <atomic>
#include <thread>

using namespace test;
using namespace unilateral;

namespace
{
  using RegionBody = void (*)(void *);
  using Parallel   = void (*)(RegionBody, void *, unsigned int, unsigned int);

  Parallel parallel = nullptr; // the GOMP_parallel the libraries bind to

  struct RegionRecord
  {
    std::atomic<int> runs{0};
    std::atomic<int> runs_on_caller{0};
    std::atomic<int> largest_team{0};
    std::atomic<int> smallest_level{1000};
    std::atomic<int> largest_level{0};
    std::thread::id  caller;
  };

  void
  record(void *data)
  {
    auto     &r     = *static_cast<RegionRecord *>(data);
    const int level = omp_get_level();
    ++r.runs;
    if (std::this_thread::get_id() == r.caller)
      ++r.runs_on_caller;
    int seen = r.largest_team;
    while (omp_get_num_threads() > seen &&
           !r.largest_team.compare_exchange_weak(seen, omp_get_num_threads()))
      ;
    seen = r.smallest_level;
    while (level < seen && !r.smallest_level.compare_exchange_weak(seen, level))
      ;
    seen = r.largest_level;
    while (level > seen && !r.largest_level.compare_exchange_weak(seen, level))
      ;
  }

  // A region of two threads requested, as `#pragma omp parallel
  // num_threads(2)` compiles to.
  void
  run_region(RegionRecord &r)
  {
    r.caller = std::this_thread::get_id();
    parallel(&record, &r, 2, 0);
  }

  // Each thread of a region of libgomp's sets its regions serial, then
  // starts a region of its own inside the team.
  RegionRecord nested;
  void
  start_nested_region(void *)
  {
    openmp::run_regions_serially();
    parallel(&record, &nested, 2, 0);
  }

  // The 7-point Laplacian on a 16 x 16 x 16 grid: its fronts are large, so
  // CHOLMOD factorises it by supernodes, in OpenMP regions.
  SparseMatrix
  laplacian_3d()
  {
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
    return A;
  }

  // Factorise and solve A x = b for x_i = i on the calling thread; true if
  // x is found to 1e-9 relative and the regions went through the core
  // library.
  bool
  factorise_and_solve(SparseCholesky &cholesky, const SparseMatrix &A)
  {
    Vector x_exact(A.rows());
    for (Index i = 0; i < A.rows(); ++i)
      x_exact[i] = i;
    const Vector        b = A * x_exact;
    Counters            counters;
    Vector              x(A.rows());
    const std::uint64_t regions_before = openmp::regions_run_without_team();
    bool                solved         = cholesky.factorise(A, counters);
    if (solved)
      cholesky.solve(b, x);
    solved = solved && (x - x_exact).norm() <= 1e-9 * x_exact.norm();
    return solved && openmp::regions_run_without_team() > regions_before;
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
  parallel = reinterpret_cast<Parallel>(dlsym(RTLD_DEFAULT, "GOMP_parallel"));
  const std::string file = defining_file(reinterpret_cast<void *>(parallel));
  test_tools::verdict("GOMP_parallel found", parallel != nullptr);
  test_tools::verdict("GOMP_parallel is the core library's",
                      file.find("unilateral_core") != std::string::npos);
  if (parallel == nullptr)
    return 0;

  // On a thread that has not factorised: libgomp's team (of up to two
  // threads, each running the body once, at level 1).
  RegionRecord before;
  run_region(before);
  test_tools::verdict("before: the region is libgomp's",
                      before.runs == before.largest_team &&
                        before.smallest_level == 1 &&
                        before.largest_level == 1);

  // Inside a team of libgomp's, a region of one of its threads is a team
  // of one nested in it (level 2), not the outer team's body again.
  RegionRecord outer;
  outer.caller = std::this_thread::get_id();
  parallel(&start_nested_region, &outer, 2, 0);
  test_tools::verdict("inside a team: each nested region a team of one",
                      nested.runs >= 1 && nested.largest_team == 1 &&
                        nested.smallest_level == 2);

  const SparseMatrix A = laplacian_3d();
  {
    // A factorisation on another thread sets that thread's regions serial.
    SparseCholesky cholesky;
    bool           solved = false;
    std::thread    other([&]() { solved = factorise_and_solve(cholesky, A); });
    other.join();
    test_tools::verdict(
      "another thread: CHOLMOD solves, its regions through the core library",
      solved);
  }
  SparseCholesky cholesky;
  test_tools::verdict(
    "this thread: CHOLMOD solves, its regions through the core library",
    factorise_and_solve(cholesky, A));

  RegionRecord after;
  run_region(after);
  test_tools::verdict("after: the body runs once, on the calling thread",
                      after.runs == 1 && after.runs_on_caller == 1);
  test_tools::verdict("after: as a region of one thread without a team",
                      after.largest_team == 1 && after.largest_level == 0);
  return 0;
}
