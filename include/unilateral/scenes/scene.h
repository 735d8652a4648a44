#pragma once

#include <unilateral/base/json_writer.h>
#include <unilateral/lcp/solver.h>

#include <deal.II/base/timer.h>

#include <filesystem>
#include <functional>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace unilateral
{
  /**
   * What every run shares: where it writes, what it writes, how it reports
   * and the solver options. Built by the application from the parameter
   * file's "Output" and "Solver" subsections.
   */
  struct RunContext
  {
    std::string           parameter_file;
    std::string           run_name;
    std::filesystem::path output_directory; ///< created before run()
    bool                  write_vtu    = true;
    bool                  export_lcp   = false;
    bool                  write_solution = false;
    bool                  print_timings = true;
    lcp::SolverParameters solver;
    std::ostream         *out      = nullptr; ///< the screen
    std::ostream         *progress = nullptr; ///< iteration lines, or null
    dealii::TimerOutput  *timer    = nullptr; ///< one section per stage
  };

  /**
   * A scene builds an LCP from its parameters, solves it through the solver
   * layer and writes its results. Each scene registers itself with
   * UNILATERAL_REGISTER_SCENE; the "Scene" selection is built from them.
   */
  class Scene
  {
  public:
    virtual ~Scene() = default;

    /**
     * Run end to end. Returns the solver's report; the application turns a
     * non-converged status into a nonzero exit code. Writes
     * output_directory/summary.json.
     */
    virtual lcp::Report
    run(RunContext &context) = 0;

    /**
     * The regularisation a "Regularisation = auto" means for this scene
     * (relative to the mean diagonal of A): 0 when A is definite.
     */
    virtual double
    auto_regularisation() const
    {
      return 0;
    }

    /**
     * What "Solver/PDAS/Start = auto" means for this scene: true for "all
     * active" (structures in contact almost everywhere), false for u0 = 0.
     */
    virtual bool
    auto_pdas_start_all_active() const
    {
      return false;
    }

    /**
     * The parameters that set the problem's size, with their values, for
     * the message of a run that does not fit into memory ("'Masonry/Blocks
     * per side' = 1000").
     */
    virtual std::string
    size_parameters() const = 0;
  };

  struct SceneInfo
  {
    std::string name;
    std::string description;
    /// Declares the scene's own subsection (all scenes are always declared,
    /// so one parameter listing documents everything).
    std::function<void(dealii::ParameterHandler &)> declare_parameters;
    /// Parses and validates (InputError on bad values) and builds the scene.
    std::function<std::unique_ptr<Scene>(dealii::ParameterHandler &)> create;
  };

  class SceneRegistry
  {
  public:
    static bool
    add(SceneInfo info);

    static const SceneInfo &
    get(const std::string &name);

    static const std::vector<SceneInfo> &
    all();

    static std::string
    selection();

  private:
    static std::vector<SceneInfo> &
    entries();
  };

  /**
   * Register class @p classname, which must provide
   *   static void declare_parameters(dealii::ParameterHandler &);
   *   explicit classname(dealii::ParameterHandler &);   // parse + validate
   */
#define UNILATERAL_REGISTER_SCENE(classname, name, description)                \
  namespace                                                                   \
  {                                                                           \
    const bool registered_scene_##classname =                                 \
      ::unilateral::SceneRegistry::add(                                       \
        {name,                                                                \
         description,                                                         \
         [](dealii::ParameterHandler &prm) {                                  \
           classname::declare_parameters(prm);                                \
         },                                                                   \
         [](dealii::ParameterHandler &prm)                                    \
           -> std::unique_ptr<::unilateral::Scene> {                          \
           return std::make_unique<classname>(prm);                           \
         }});                                                                 \
  }

  /**
   * A safeguard on a converged answer: at every solution of the LCP the work
   * W = b^T u - lambda_S^T l_S equals u^T A u >= 0. If W < -1e-6 (|b|^T |u|
   * + |lambda_S|^T |l_S|), @p report becomes 'inaccurate' with a message.
   * It catches what the relative KKT residuals cannot see: a body that
   * drifted far away as a rigid motion (A u small, |A| |u| huge).
   */
  void
  check_work(const lcp::Problem  &problem,
             const lcp::Solution &solution,
             lcp::Report         &report);

  /// The context's solver options with the scene's choices filled in (the
  /// PDAS start 'auto').
  lcp::SolverParameters
  solver_parameters(const RunContext &context, const Scene &scene);

  /**
   * Solve @p problem with the context's solver options, inside a timer
   * section "solve", with the scene's automatic regularisation, then
   * check_work().
   */
  lcp::Report
  solve(RunContext          &context,
        const Scene         &scene,
        const lcp::Problem  &problem,
        lcp::Solution       &solution);

  /**
   * The keys every summary.json has: scene, solver, n_unknowns,
   * n_constraints, n_active, iterations, converged, status, message, kkt,
   * energy, time (per phase: the solver's and the context timer's), calls
   * (how often each stage ran; solver phases that ran count 1) and counters
   * (the solver's work).
   * Scenes add their own keys and then call write_summary().
   */
  JsonObject
  summary_base(const RunContext   &context,
               const std::string  &scene,
               const lcp::Problem &problem,
               const lcp::Report  &report);

  void
  write_summary(const RunContext &context, const JsonObject &summary);

  /// The deterministic part of the one-screen summary (no timings).
  void
  print_solver_summary(std::ostream       &out,
                       const lcp::Problem &problem,
                       const lcp::Report  &report);

  /// With Output/Export LCP: write the LCP in the lcp scene's file format.
  void
  export_lcp_if_requested(const RunContext &context, const lcp::Problem &problem);

  /// With Output/Write solution: write u and lambda of the LCP (u.txt,
  /// lambda.txt, as the lcp scene does), in the unknowns of the exported LCP.
  void
  write_solution_if_requested(const RunContext    &context,
                              const lcp::Solution &solution);
} // namespace unilateral
