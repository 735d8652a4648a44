#pragma once

#include <iostream>

namespace unilateral
{
  /**
   * The whole command line program: `unilateral FILE.prm` runs a scene,
   * `unilateral --help` explains usage, `--print-parameters` documents every
   * parameter. Returns the exit code: 0 on a converged run, 1 on bad input
   * (one line on @p err), 2 if the solver did not converge.
   */
  int
  run_application(int           argc,
                  char        **argv,
                  std::ostream &out = std::cout,
                  std::ostream &err = std::cerr);
} // namespace unilateral
