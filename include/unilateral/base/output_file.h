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

  /**
   * @name Files written whole or not at all
   * A result file is written under a temporary name (@p name + ".partial")
   * and renamed when complete: a run ended half-way (another MPI rank's
   * failure, a kill) leaves no truncated file that reads like a whole one,
   * nor an earlier run's file half overwritten.
   */
  /// @{
  /// The stream to write @p name through; InputError if it cannot be made.
  std::ofstream
  open_for_writing(const std::string &name);

  /// Closes @p file (as close_written_file) and gives it its name @p name.
  void
  finish_writing(std::ofstream &file, const std::string &name);

  /// The name of the file that @p file_name, a file being written, will
  /// have; @p file_name itself for any other file.
  std::string
  name_when_written(const std::string &file_name);
  /// @}
} // namespace unilateral
