// The tests' one way to enumerate methods: every registered method and each
// of its registered variants, on the full LCP and on the Schur complement,
// from the registry (a new method is tested without touching any test).
#pragma once

#include <unilateral/lcp/solver.h>

#include <string>
#include <vector>

namespace registered_methods
{
  using namespace unilateral::lcp;

  /// A registered method as a user selects it.
  struct MethodRun
  {
    const SolverInfo *info;
    bool              schur_complement = false;
    /// One of the method's registered variants, or none.
    const Variant *variant = nullptr;

    const std::string &
    name() const
    {
      return info->name;
    }

    /// "name", "name (Schur)", "name (predictor-corrector)".
    std::string
    label() const
    {
      return info->name + (schur_complement ? " (Schur)" : "") +
             (variant != nullptr ? " (" + variant->name + ")" : "");
    }

    /// The variant's settings applied to @p parameters, and the method.
    void
    apply(SolverParameters &parameters) const
    {
      parameters.method           = info->name;
      parameters.schur_complement = schur_complement;
      if (variant != nullptr)
        for (const auto &[entry, value] : variant->settings)
          parameters.set(entry, value);
    }

    /// The same as lines of a parameter file's subsection Solver.
    std::string
    prm_lines() const
    {
      return "  set Method = " + info->name + "\n" + prm_settings();
    }

    /// Those lines but the method's name.
    std::string
    prm_settings() const
    {
      std::string lines = "  set Schur complement = " +
                          std::string(schur_complement ? "true" : "false") +
                          "\n";
      if (variant != nullptr)
        for (const auto &[entry, value] : variant->settings)
          {
            const auto slash = entry.rfind('/');
            lines += "  subsection " + entry.substr(0, slash) + "\n    set " +
                     entry.substr(slash + 1) + " = " + value + "\n  end\n";
          }
      return lines;
    }
  };

  /// What a scene's problem carries beyond A, b and the bounds.
  struct Carries
  {
    bool tearing   = false;
    bool hierarchy = false;
  };
  constexpr Carries a_tearing{true, false};
  constexpr Carries a_hierarchy{false, true};

  /**
   * Every registered method and variant, on the full LCP (first all of
   * these) and then on the Schur complement. A dense method takes the full
   * LCP only where every unknown is constrained (@p has_unconstrained
   * false), and then not its Schur complement. A method that works on the
   * problem torn into subdomains (needs_tearing) or on a hierarchy of meshes
   * (needs_hierarchy) takes only the full LCP of a scene whose problem
   * @p carries it (the masonry scene tears, the plate scene has levels):
   * the Schur complement has neither.
   */
  inline std::vector<MethodRun>
  all(const bool has_unconstrained, const Carries carries = {})
  {
    std::vector<MethodRun> runs;
    for (const bool schur_complement : {false, true})
      for (const SolverInfo &info : SolverRegistry::all())
        {
          if (info.dense && has_unconstrained != schur_complement)
            continue;
          if (info.needs_tearing && (!carries.tearing || schur_complement))
            continue;
          if (info.needs_hierarchy && (!carries.hierarchy || schur_complement))
            continue;
          runs.push_back({&info, schur_complement});
          for (const Variant &variant : info.variants)
            runs.push_back({&info, schur_complement, &variant});
        }
    return runs;
  }
} // namespace registered_methods
