#pragma once

#include <unilateral/base/input_error.h>

#include <string>
#include <vector>

namespace unilateral
{
  /**
   * The plugins of one family (solver methods, scenes), in registration
   * order, ASPECT-style: each plugin registers itself from its own file
   * through a static initialiser, and the parameter selection, its help text
   * and the tests are built from the registry. Adding a plugin touches one
   * file.
   *
   * A header-only template, instantiated once for each family in the
   * library (SolverRegistry in lcp/solver.cc, SceneRegistry in
   * scenes/scene.cc).
   *
   * @p Info has the fields `name` and `description`, and the static strings
   * `Info::parameter` (the parameter that selects a plugin: "Solver/Method")
   * and `Info::kind` ("method").
   */
  template <typename Info>
  class Registry
  {
  public:
    static bool
    add(Info info)
    {
      entries().push_back(std::move(info));
      return true;
    }

    /// Throws InputError naming the unknown plugin and the known ones.
    static const Info &
    get(const std::string &name)
    {
      for (const Info &info : entries())
        if (info.name == name)
          return info;
      throw InputError("parameter '" + std::string(Info::parameter) +
                       "' = " + name + ": unknown " + Info::kind +
                       "; choose one of " + selection());
    }

    static const std::vector<Info> &
    all()
    {
      return entries();
    }

    static std::vector<std::string>
    names()
    {
      std::vector<std::string> result;
      for (const Info &info : entries())
        result.push_back(info.name);
      return result;
    }

    /// "a|b|c", for Patterns::Selection.
    static std::string
    selection()
    {
      std::string result;
      for (const Info &info : entries())
        result += (result.empty() ? "" : "|") + info.name;
      return result;
    }

    /// One line per plugin, "  name: description", for help texts.
    static std::string
    documentation()
    {
      std::string result;
      for (const Info &info : entries())
        result += "  " + info.name + ": " + info.description + "\n";
      return result;
    }

  private:
    // A function-local static: registration runs from static initialisers
    // of other translation units, in an order C++ leaves open.
    static std::vector<Info> &
    entries()
    {
      static std::vector<Info> registered;
      return registered;
    }
  };
} // namespace unilateral
