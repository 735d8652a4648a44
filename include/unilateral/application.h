#pragma once

#include <functional>
#include <iostream>
#include <string>

namespace unilateral
{
  /**
   * The whole command line program: `unilateral FILE.prm` runs a scene,
   * `unilateral --help` explains usage, `--print-parameters` documents every
   * parameter. Returns the exit code: 0 on a converged run, 1 on bad input
   * (one line on @p err), 2 if the solver did not converge, 3 on an
   * internal error (a defect of the program or a library's failure).
   *
   * @p after_failed_run, if given, is called with the message and the exit
   * code when the scene's run fails (after the parameter file was read),
   * before the failure is reported on @p err: under MPI the failure may be
   * this rank's alone while the others wait in a collective call, and
   * main() then ends every rank (MPI_Abort) instead of returning.
   */
  int
  run_application(
    int                                                  argc,
    char                                               **argv,
    std::ostream                                        &out = std::cout,
    std::ostream                                        &err = std::cerr,
    const std::function<void(const std::string &, int)> &after_failed_run = {});
} // namespace unilateral
