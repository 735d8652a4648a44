#pragma once

#include <functional>
#include <iostream>

namespace unilateral
{
  /**
   * The whole command line program: `unilateral FILE.prm` runs a scene,
   * `unilateral --help` explains usage, `--print-parameters` documents every
   * parameter. Returns the exit code: 0 on a converged run, 1 on bad input
   * (one line on @p err), 2 if the solver did not converge.
   *
   * @p before_large_run, if given, is called for a run large enough to gain
   * from glibc's huge pages (a wall of m 2^r >= 100 blocks per side, a plate
   * of 128 x 128 elements or more, an LCP file of 20 MB or more) once the
   * parameter file is read and the scene built, before anything is printed
   * or written: main() restarts the program there with huge pages on.
   */
  int
  run_application(int                          argc,
                  char                       **argv,
                  std::ostream                &out              = std::cout,
                  std::ostream                &err              = std::cerr,
                  const std::function<void()> &before_large_run = {});
} // namespace unilateral
