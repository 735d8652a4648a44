#pragma once

#include <stdexcept>
#include <string>

namespace unilateral
{
  /**
   * A run that does not fit into memory: thrown before the allocation that
   * would not fit (so that the kernel's out-of-memory killer does not end
   * the run without a word), or when an allocation has failed. The
   * application adds which parameters make the problem smaller.
   */
  class OutOfMemory : public std::runtime_error
  {
  public:
    explicit OutOfMemory(const std::string &message)
      : std::runtime_error(message)
    {}
  };

  namespace memory
  {
    /**
     * Cap what a run may use in total, in bytes ('Memory limit'); 0 leaves
     * only the machine's available memory as the bound.
     */
    void
    set_limit(double bytes);

    /**
     * What the run can still allocate, in bytes: the machine's available
     * memory (MemAvailable in /proc/meminfo, which counts reclaimable page
     * cache as free), or the limit less the run's resident memory if that
     * is smaller. Infinite where neither can be read. The run's freed heap
     * memory counts as used until release_free_heap().
     */
    double
    available();

    /// True if the limit is set and leaves the run less than the machine
    /// does: then raising 'Memory limit' is the first fix.
    bool
    limit_binds();

    /**
     * Whether @p bytes more fit. With @p after_freeing, for an estimate
     * that is the whole allocation (a factor, the ordering's workspace, a
     * copy of a factor), after release_free_heap() if they did not fit at
     * first. Not for an estimate that leaves out smaller temporaries (the
     * assembly's): there the freed heap is the margin they are taken from.
     */
    bool
    fits(double bytes, bool after_freeing);

    /**
     * Throw OutOfMemory naming @p what unless fits(@p bytes,
     * @p after_freeing).
     */
    void
    require(double bytes, const std::string &what, bool after_freeing = false);

    /**
     * Return the heap memory the run has freed to the system (glibc's
     * malloc_trim). SuperLU_DIST, which PETSc loads for deal.II, switches
     * off glibc's own trimming and its mmap of large blocks as it is
     * loaded, so without this everything a run frees stays resident:
     * factors of earlier active sets, copies of A_FF, the assembly's
     * temporaries. Called where memory runs short only: the pages given
     * back are faulted in and zeroed again by the next allocations, which
     * costs more than keeping them (benchmarks/tfeti/README.md, "The
     * largest walls").
     */
    void
    release_free_heap();

    /// The process's resident memory now, in bytes; 0 if the kernel does
    /// not say.
    double
    resident();

    /**
     * The soft limit on the process's address space ('ulimit -v',
     * RLIMIT_AS) in bytes; infinite if none is set. It is not part of
     * available(): the address space counts freed heap memory, which the
     * run reuses, so a check against it would refuse runs that fit. It is
     * named where an allocation fails, and bounds the pre-touch.
     */
    double
    address_space_limit();

    /// The address space the process has mapped now (VmSize), in bytes; 0
    /// if the kernel does not say.
    double
    address_space();

    /// True if an address-space limit is set and leaves the run less room
    /// than available() (the machine, or 'Memory limit'): then it is what a
    /// failed allocation ran into, and raising it is a fix.
    bool
    address_space_limit_binds();

    /// "the address space is limited to 2.0 GB by 'ulimit -v', 1.9 GB of it
    /// in use", for messages where the limit binds.
    std::string
    address_space_in_use();

    /// The process's peak resident memory so far (VmHWM), in bytes; 0 if
    /// the kernel does not say.
    double
    peak_resident();

    /// "1.2 GB", "350 MB", "12 kB".
    std::string
    format(double bytes);
  } // namespace memory
} // namespace unilateral
