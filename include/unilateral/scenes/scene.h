#pragma once

#include <unilateral/base/json_writer.h>
#include <unilateral/base/registry.h>
#include <unilateral/lcp/solver.h>

#include <deal.II/base/timer.h>

#include <filesystem>
#include <functional>
#include <iosfwd>
#include <memory>
#include <optional>
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
   * file's "Output" and "Solver" subsections; tests build their own.
   */
  struct RunContext
  {
    std::string           parameter_file;
    std::string           run_name;
    std::filesystem::path output_directory; ///< created before run()
    bool                  write_vtu      = true;
    bool                  export_lcp     = false;
    bool                  write_solution = false;
    bool                  print_timings  = true;
    bool                  writes_files   = true; ///< false on ranks > 0
    lcp::SolverParameters solver;
    std::ostream         *out      = nullptr; ///< the screen, or null
    std::ostream         *progress = nullptr; ///< iteration lines, or null
    dealii::TimerOutput  *timer = nullptr; ///< one section per stage, or null

    /// A timer section named @p name while the result lives (nothing if
    /// there is no timer).
    std::optional<dealii::TimerOutput::Scope>
    section(const std::string &name) const;

    /// A line of progress ("  <scene>: <text>"), if progress is on.
    void
    stage(const std::string &scene, const std::string &text) const;
  };

  /**
   * A scene builds an LCP from its parameters, solves it through the solver
   * layer and writes its results. run() is the one pipeline of every scene,
   * in the deal.II tutorials' stages (each a timer section of the same name,
   * so summary.json has the same keys for every scene):
   *   make grid, setup system, assemble system (the scene's LCP, then
   *   checked), [export LCP], solve (from the scene's start), [write
   *   solution], postprocess, output results (with Output/Write VTU), then
   *   the one-screen summary and summary.json.
   * A scene fills in the stages it has. Each scene registers itself with
   * UNILATERAL_REGISTER_SCENE; the "Scene" selection is built from them.
   */
  class Scene
  {
  public:
    explicit Scene(std::string name);

    virtual ~Scene() = default;

    /**
     * Run end to end. Returns the solver's report; the application turns a
     * non-converged status into a nonzero exit code. Writes
     * output_directory/summary.json.
     */
    lcp::Report
    run(RunContext &context);

    /// make grid and setup system only, each in its timer section: the
    /// problem's sizes without assembling or solving.
    void
    set_up(RunContext &context);

    /// assemble system (the scene's LCP, then checked by
    /// lcp::check_and_normalise), in its timer section; after set_up().
    void
    assemble(RunContext &context);

    /**
     * The parameters that set the problem's size, with their values, for
     * the message of a run that does not fit into memory ("'Masonry/Blocks
     * per side' = 1000").
     */
    virtual std::string
    size_parameters() const = 0;

    /**
     * One line for the user when the solver did not converge (the
     * application prints it on stderr): what the status means for this
     * scene's problem, and the solver's message.
     */
    virtual std::string
    failure_description(const lcp::Report &report) const;

    /**
     * Whether every rank of an MPI run writes its own piece of the VTU
     * output (and rank 0 the PVTU record that joins them); false: rank 0
     * writes the whole output alone (every rank holds the whole answer).
     */
    virtual bool
    writes_output_in_parallel() const
    {
      return false;
    }

    /// The registered name ("masonry").
    const std::string &
    name() const
    {
      return scene_name;
    }

    /// After run(): the LCP that was solved.
    const lcp::Problem &
    problem() const
    {
      return lcp_problem;
    }

    /// After run(): its solution.
    const lcp::Solution &
    solution() const
    {
      return lcp_solution;
    }

  protected:
    /// @name The stages of run(), in order
    /// @{
    virtual void
    make_grid(RunContext &context);

    virtual void
    setup_system(RunContext &context);

    /// Build lcp_problem (run() then checks it with check_and_normalise).
    virtual void
    assemble_system(RunContext &context) = 0;

    /**
     * A proof from the scene's own data that its LCP has no solution, in
     * the scene's terms (default: none, the solver decides). Where there is
     * one, run() reports 'infeasible' with it and does not solve.
     */
    virtual std::string
    proof_of_no_solution();

    /// The start of the solve in lcp_solution (default: none, each method's
    /// own).
    virtual void
    initial_solution(RunContext &context);

    /// Quantities of the solution, in the scene's terms; may change what
    /// the report says in the scene's units.
    virtual void
    postprocess(const RunContext &context, lcp::Report &report);

    /// The VTU/PVD files (or the scene's other field output).
    virtual void
    output_results(const RunContext &context) const;

    /// The scene's lines of the one-screen summary, around the solver's.
    virtual void
    print_summary(std::ostream &out, const lcp::Report &report) const;

    /// The scene's own keys of summary.json.
    virtual void
    add_summary(JsonObject &summary) const;
    /// @}

    /**
     * Fault in @p bytes of memory on the second core while the scene builds
     * its problem, for a serial run (under mpirun the ranks take every
     * core): memory::pretouch_in_background() says why. A scene calls it as
     * soon as it knows its size, with less than its solve's peak memory, so
     * that the peak does not grow (below 1 GB nothing is touched: there the
     * peak did grow).
     */
    void
    pretouch(double bytes) const;

    /// The LCP the scene builds, and its solution.
    lcp::Problem  lcp_problem;
    lcp::Solution lcp_solution;

  private:
    const std::string scene_name;
  };

  struct SceneInfo
  {
    /// For the registry's messages.
    static constexpr const char *parameter = "Scene";
    static constexpr const char *kind      = "scene";

    std::string name;
    std::string description;
    /// Declares the scene's own subsection (all scenes are always declared,
    /// so one parameter listing documents everything).
    std::function<void(dealii::ParameterHandler &)> declare_parameters;
    /// Parses and validates (InputError on bad values) and builds the scene.
    std::function<std::unique_ptr<Scene>(dealii::ParameterHandler &)> create;
  };

  using SceneRegistry = Registry<SceneInfo>;

  /**
   * Register class @p classname, which must provide
   *   static constexpr const char *registered_name = "...";
   *   static void declare_parameters(dealii::ParameterHandler &);
   *   explicit classname(dealii::ParameterHandler &);   // parse + validate
   */
#define UNILATERAL_REGISTER_SCENE(classname, description) \
  namespace                                               \
  {                                                       \
    const bool registered_scene_##classname =             \
      ::unilateral::SceneRegistry::add(                   \
        {classname::registered_name,                      \
         description,                                     \
         [](dealii::ParameterHandler &prm) {              \
           classname::declare_parameters(prm);            \
         },                                               \
         [](dealii::ParameterHandler &prm)                \
           -> std::unique_ptr<::unilateral::Scene> {      \
           return std::make_unique<classname>(prm);       \
         }});                                             \
  }

  /// The deterministic part of the one-screen summary (no timings).
  void
  print_solver_summary(std::ostream       &out,
                       const lcp::Problem &problem,
                       const lcp::Report  &report);
} // namespace unilateral

namespace unilateral
{
  // One registry, in the core library (not one per translation unit).
  extern template class Registry<SceneInfo>;
} // namespace unilateral
