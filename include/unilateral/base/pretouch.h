#pragma once

namespace unilateral::memory
{
  /**
   * Fault in about @p bytes of heap memory on a background thread, so that
   * the run's later allocations (the factors of the solve) find their pages
   * already mapped instead of waiting while the kernel zeroes them.
   *
   * Why: a large run's factorisations spend much of their time in the
   * kernel, which zeroes each page on its first touch (slowly on virtual
   * machines), while the second core idles through the set-up and the
   * assembly. The memory is taken from glibc's main heap in chunks, each
   * written once a page and freed again at once; the freed chunks stay
   * mapped (malloc's trimming and its mmap of large blocks are switched off
   * here, as SuperLU_DIST, which PETSc loads, switches them off anyway), so
   * the next allocations reuse them. Memory checks count the touched free
   * heap as used, and release_free_heap() gives it back where memory runs
   * short. At most a quarter of the memory available is touched, and
   * nothing below 1 GB, once per process; the thread stops, and frees what
   * it has not touched, when the process ends; where no thread can be
   * started, nothing is touched. Measured:
   * benchmarks/masonry_tables/README.md, "Design measurements", "Pages
   * faulted in on the idle core". Does nothing without glibc.
   */
  void
  pretouch_in_background(double bytes);
} // namespace unilateral::memory
