#include <unilateral/base/memory.h>
#include <unilateral/base/pretouch.h>

#if defined(__GLIBC__)
#  include <malloc.h>
#endif

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <system_error>
#include <thread>
#include <vector>

namespace unilateral::memory
{
  namespace
  {
    // Small enough that the set-up's own allocations, made while the
    // thread works, find freed chunks to reuse; large enough that the
    // allocator's bookkeeping stays negligible.
    constexpr std::size_t chunk_bytes = std::size_t(64) << 20;
    constexpr std::size_t page_bytes  = 4096;
    // Below this the gain is lost in the noise, and the set-up's
    // allocations, placed above chunks still held, let the peak grow (the
    // figures: benchmarks/masonry_tables/README.md, "Pages faulted in on
    // the idle core").
    constexpr double smallest_bytes = 1e9;

    // The background thread and its chunks; joined when the process ends.
    class Pretouch
    {
    public:
      ~Pretouch()
      {
        stop = true;
        if (thread.joinable())
          thread.join();
      }

      bool
      started() const
      {
        return thread.joinable();
      }

      void
      start(const std::size_t n_chunks)
      {
        // Allocated here, by the main thread, so that the chunks belong to
        // the heap (glibc's main arena) that the run's allocations use.
        for (std::size_t i = 0; i < n_chunks; ++i)
          if (void *chunk = std::malloc(chunk_bytes))
            chunks.push_back(static_cast<char *>(chunk));
        try
          {
            thread = std::thread([this]() { touch_and_free(); });
          }
        catch (const std::system_error &)
          {
            // No thread to be had (a process or thread limit): the run
            // goes on without, as it would without glibc.
            for (char *chunk : chunks)
              std::free(chunk);
            chunks.clear();
          }
      }

    private:
      void
      touch_and_free()
      {
        for (char *chunk : chunks)
          {
            if (!stop)
              for (std::size_t offset = 0; offset < chunk_bytes;
                   offset += page_bytes)
                static_cast<volatile char *>(chunk)[offset] = 0;
            std::free(chunk);
          }
      }

      std::vector<char *> chunks;
      std::atomic<bool>   stop{false};
      std::thread         thread;
    };

    Pretouch &
    pretouch()
    {
      static Pretouch instance;
      return instance;
    }
  } // namespace

  void
  pretouch_in_background(const double bytes)
  {
#if defined(__GLIBC__)
    if (pretouch().started())
      return;
    // The address space the chunks take is reused by the run, but held
    // while the set-up allocates beside them: under 'ulimit -v' a quarter
    // of what is left, as of the memory.
    const double touched = std::min(
      {bytes, available() / 4, (address_space_limit() - address_space()) / 4});
    if (!(touched >= smallest_bytes))
      return;
    // Freed memory stays mapped, and large blocks come from the heap too:
    // otherwise the touched chunks would be returned to the system at once
    // and every factor mapped afresh.
    mallopt(M_MMAP_MAX, 0);
    mallopt(M_TRIM_THRESHOLD, -1);
    pretouch().start(static_cast<std::size_t>(touched / chunk_bytes));
#else
    (void)bytes;
#endif
  }
} // namespace unilateral::memory
