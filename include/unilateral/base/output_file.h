#pragma once

#include <fstream>
#include <string>

namespace unilateral
{
  /**
   * Close @p file, written as @p name, and throw InputError naming it if
   * any write or the close failed: a full disk shows only there, and a
   * result file that did not reach the disk must not end a run as
   * converged (scripts read the files and the exit code).
   */
  void
  close_written_file(std::ofstream &file, const std::string &name);
} // namespace unilateral
