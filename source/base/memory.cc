#include <unilateral/base/memory.h>

#include <sys/resource.h>
#include <unistd.h>
#if defined(__GLIBC__)
#  include <malloc.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>

namespace unilateral::memory
{
  namespace
  {
    double limit = 0;

    // MemAvailable in bytes, or infinity if the kernel does not say.
    double
    machine_available()
    {
      std::ifstream meminfo("/proc/meminfo");
      std::string   key, unit;
      double        kilobytes = 0;
      while (meminfo >> key >> kilobytes)
        {
          std::getline(meminfo, unit);
          if (key == "MemAvailable:")
            return 1024 * kilobytes;
        }
      return std::numeric_limits<double>::infinity();
    }

    // Field @p field of /proc/self/statm (0: the address space, 1: the
    // resident set) in bytes; 0 if the kernel does not say.
    double
    statm_bytes(const unsigned int field)
    {
      std::ifstream statm("/proc/self/statm");
      double        pages = 0;
      for (unsigned int i = 0; i <= field; ++i)
        if (!(statm >> pages))
          return 0;
      return pages * static_cast<double>(sysconf(_SC_PAGESIZE));
    }
  } // namespace

  double
  resident()
  {
    return statm_bytes(1);
  }

  double
  address_space_limit()
  {
    rlimit limit_of_process{};
    if (getrlimit(RLIMIT_AS, &limit_of_process) != 0 ||
        limit_of_process.rlim_cur == RLIM_INFINITY)
      return std::numeric_limits<double>::infinity();
    return static_cast<double>(limit_of_process.rlim_cur);
  }

  double
  address_space()
  {
    return statm_bytes(0);
  }

  std::string
  address_space_in_use()
  {
    return "the address space is limited to " + format(address_space_limit()) +
           " by 'ulimit -v', " + format(address_space()) + " of it in use";
  }

  bool
  address_space_limit_binds()
  {
    return std::isfinite(address_space_limit()) &&
           address_space_limit() - address_space() < available();
  }

  double
  peak_resident()
  {
    std::ifstream status("/proc/self/status");
    std::string   key, unit;
    double        kilobytes = 0;
    while (status >> key)
      {
        if (key == "VmHWM:" && status >> kilobytes)
          return 1024 * kilobytes;
        std::getline(status, unit);
      }
    return 0;
  }

  void
  set_limit(const double bytes)
  {
    limit = bytes;
  }

  void
  release_free_heap()
  {
#if defined(__GLIBC__)
    malloc_trim(0);
#endif
  }

  double
  available()
  {
    const double machine = machine_available();
    if (limit > 0)
      return std::min(machine, std::max(0.0, limit - resident()));
    return machine;
  }

  bool
  limit_binds()
  {
    return limit > 0 && limit - resident() < machine_available();
  }

  bool
  fits(const double bytes, const bool after_freeing)
  {
    if (bytes <= available())
      return true;
    // Trimmed only where it matters (release_free_heap() says why).
    if (!after_freeing)
      return false;
    release_free_heap();
    return bytes <= available();
  }

  void
  require(const double bytes, const std::string &what, const bool after_freeing)
  {
    if (fits(bytes, after_freeing))
      return;
    const double       left = available();
    std::ostringstream message;
    message << what << " needs " << format(bytes) << " more memory, but only "
            << format(left) << " is left"
            << (limit > 0 ? " under 'Memory limit' = " + format(limit) :
                            std::string(" on this machine"));
    if (address_space_limit_binds())
      message << " (" << address_space_in_use() << ")";
    throw OutOfMemory(message.str());
  }

  std::string
  format(const double bytes)
  {
    const char *units[] = {"bytes", "kB", "MB", "GB", "TB"};
    double      value   = bytes;
    int         unit    = 0;
    while (value >= 1000 && unit < 4)
      {
        value /= 1000;
        ++unit;
      }
    char text[32];
    std::snprintf(text,
                  sizeof text,
                  value < 10 && unit > 0 ? "%.1f %s" : "%.0f %s",
                  value,
                  units[unit]);
    return text;
  }
} // namespace unilateral::memory
