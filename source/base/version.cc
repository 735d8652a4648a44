#include <unilateral/base/version.h>
// Generated in the build tree by cmake/revision.cmake.
#include <unilateral/revision.h>

#include <deal.II/base/config.h>

namespace unilateral::version
{
  std::string
  git_revision()
  {
    return UNILATERAL_GIT_REVISION;
  }

  bool
  local_changes()
  {
    return UNILATERAL_GIT_LOCAL_CHANGES;
  }

  std::string
  deal_ii()
  {
    return DEAL_II_PACKAGE_VERSION;
  }

  std::string
  describe()
  {
    return "unilateral, git " + git_revision() +
           (local_changes() ? ", uncommitted changes" : "") + ", deal.II " +
           deal_ii();
  }

  JsonObject
  summary()
  {
    JsonObject fields;
    fields.set("git_revision", git_revision())
      .set("local_changes", local_changes())
      .set("deal.II", deal_ii());
    return fields;
  }
} // namespace unilateral::version
