#pragma once

#include <unilateral/base/json_writer.h>

#include <string>

/**
 * What the program was built from, so that a result can be traced to the
 * code that computed it: `unilateral --version` prints it and every
 * summary.json records it.
 */
namespace unilateral::version
{
  /// The git commit of the source tree at build time (12 hex digits), or
  /// "unknown" if it was not a git checkout.
  std::string
  git_revision();

  /// Whether tracked files differed from that commit at build time.
  bool
  local_changes();

  /// The deal.II release the program was compiled against.
  std::string
  deal_ii();

  /// "unilateral, git 5ebcf05a1b2c, deal.II 9.4.1" (with ", uncommitted
  /// changes" after the commit where there were any).
  std::string
  describe();

  /// git_revision, local_changes and deal.II, for summary.json.
  JsonObject
  summary();
} // namespace unilateral::version
