#include <unilateral/base/input_error.h>
#include <unilateral/base/memory.h>
#include <unilateral/base/pretouch.h>
#include <unilateral/base/ranks.h>
#include <unilateral/base/text.h>
#include <unilateral/base/version.h>
#include <unilateral/lcp/io.h>
#include <unilateral/lcp/solve_lcp.h>
#include <unilateral/scenes/scene.h>

#include <deal.II/base/mpi.h>

#include <cmath>
#include <iomanip>
#include <ostream>
#include <sstream>

namespace unilateral
{
  template class Registry<SceneInfo>;

  std::optional<dealii::TimerOutput::Scope>
  RunContext::section(const std::string &name) const
  {
    if (timer == nullptr)
      return std::nullopt;
    return std::optional<dealii::TimerOutput::Scope>(std::in_place,
                                                     *timer,
                                                     name);
  }

  void
  RunContext::stage(const std::string &scene, const std::string &text) const
  {
    if (progress != nullptr)
      *progress << "  " << scene << ": " << text << std::endl;
  }

  namespace
  {
    /**
     * The keys every summary.json has: scene, run_name, version (the
     * commit built), solver, n_unknowns, n_constraints, n_active,
     * iterations, converged, status, message, kkt, energy, time (per stage
     * of the pipeline and per solver phase), calls (how often each stage
     * ran; solver phases that ran count 1) and counters (the solver's work).
     */
    JsonObject
    summary_base(const RunContext   &context,
                 const std::string  &scene,
                 const lcp::Problem &problem,
                 const lcp::Report  &report)
    {
      JsonObject summary;
      summary.set("scene", scene)
        .set("run_name", context.run_name)
        .set("version", version::summary())
        .set("solver", report.solver)
        .set("schur_complement", context.solver.schur_complement)
        .set("n_unknowns", problem.size())
        .set("n_constraints", problem.n_constrained())
        .set("n_active", report.n_active)
        .set("iterations", report.iterations)
        .set("projection_iterations", report.projection_iterations)
        .set("continuation_stages", report.continuation_stages)
        .set("regularisation", report.regularisation)
        .set("converged", report.converged())
        .set("solved", report.solved)
        .set("status", lcp::to_string(report.status))
        .set("message", report.message)
        .set("energy", report.energy);
      JsonObject &kkt = summary.object("kkt");
      kkt.set("stationarity", report.kkt.stationarity)
        .set("primal_feasibility", report.kkt.primal_feasibility)
        .set("dual_feasibility", report.kkt.dual_feasibility)
        .set("complementarity", report.kkt.complementarity)
        .set("max", report.kkt.max());

      JsonObject &time = summary.object("time");
      if (context.timer != nullptr)
        for (const auto &[section, seconds] : context.timer->get_summary_data(
               dealii::TimerOutput::total_wall_time))
          time.set(section, seconds);
      JsonObject &solver_time = time.object("solver");
      for (const auto &[phase, seconds] : report.phase_times)
        solver_time.set(phase, seconds);

      // How often each stage ran: tests check from these, not from times,
      // that a stage a run does not need never ran.
      JsonObject &calls = summary.object("calls");
      if (context.timer != nullptr)
        for (const auto &[section, n] :
             context.timer->get_summary_data(dealii::TimerOutput::n_calls))
          calls.set(section, static_cast<unsigned int>(n));
      for (const auto &[phase, seconds] : report.phase_times)
        calls.set("solver: " + phase, 1u);

      const lcp::Counters &work     = report.counters;
      JsonObject          &counters = summary.object("counters");
      counters.set("orderings", work.orderings)
        .set("symbolic_analyses", work.symbolic_analyses)
        .set("numeric_factorisations", work.numeric_factorisations)
        .set("reused_factorisations", work.reused_factorisations)
        .set("modified_factorisations", work.modified_factorisations)
        .set("factor_row_modifications", work.factor_row_modifications)
        .set("resolved_subsets", work.resolved_subsets)
        .set("resolved_indices", work.resolved_indices)
        .set("cg_iterations", work.cg_iterations)
        .set("triangular_solves", work.triangular_solves)
        .set("partial_forward_solves", work.partial_forward_solves)
        .set("centrality_correctors", work.centrality_correctors)
        .set("matrix_vector_products", work.matrix_vector_products);
      // Every rank's peak memory (a collective call: every rank is here).
      const std::vector<double> peaks =
        dealii::Utilities::MPI::all_gather(MPI_COMM_WORLD,
                                           memory::peak_resident());
      std::vector<JsonObject> ranks(peaks.size());
      for (std::size_t r = 0; r < peaks.size(); ++r)
        ranks[r]
          .set("rank", static_cast<unsigned int>(r))
          .set("peak_memory_gb", peaks[r] / 1e9);
      summary.set("ranks", ranks);
      if (context.progress != nullptr)
        for (std::size_t r = 0; r < peaks.size(); ++r)
          *context.progress
            << "  "
            << (peaks.size() > 1 ? "rank " + std::to_string(r) + ": " : "")
            << "peak memory " << memory::format(peaks[r]) << std::endl;
      if (!report.figures.empty())
        {
          JsonObject &method = summary.object("method");
          for (const auto &[name, value] : report.figures)
            method.set(name, value);
        }
      return summary;
    }

    /// With Output/Export LCP: the LCP in the lcp scene's file format.
    void
    export_lcp_if_requested(const RunContext   &context,
                            const lcp::Problem &problem)
    {
      if (!context.export_lcp)
        return;
      const auto timer = context.section("export LCP");
      lcp::write_problem(problem, context.output_directory.string());
    }

    /// With Output/Write solution: u and lambda of the LCP (u.txt,
    /// lambda.txt, as the lcp scene does), in the unknowns of the exported
    /// LCP.
    void
    write_solution_if_requested(const RunContext    &context,
                                const lcp::Solution &solution)
    {
      if (!context.write_solution)
        return;
      const auto        timer     = context.section("write solution");
      const std::string directory = context.output_directory.string();
      lcp::write_vector(solution.u, directory + "/u.txt");
      lcp::write_vector(solution.lambda, directory + "/lambda.txt");
    }

    /**
     * The report of an LCP that the scene proved to have no solution, not
     * solved: 'infeasible' with @p proof, and @p solution zero (the start,
     * whose residuals the report gives).
     */
    lcp::Report
    unsolved(const lcp::Problem          &problem,
             const lcp::SolverParameters &parameters,
             const std::string           &proof,
             lcp::Solution               &solution)
    {
      solution.u      = lcp::Vector::Zero(problem.size());
      solution.lambda = lcp::Vector::Zero(problem.size());
      solution.active_set.clear();
      lcp::Report report;
      report.solver =
        parameters.method + (parameters.schur_complement ? "_sc" : "");
      report.solved  = false;
      report.status  = lcp::Status::infeasible;
      report.message = proof;
      report.energy  = lcp::energy(problem, solution.u);
      report.kkt     = lcp::kkt_residuals(problem, solution.u);
      return report;
    }
  } // namespace

  Scene::Scene(std::string name)
    : scene_name(std::move(name))
  {}

  void
  Scene::set_up(RunContext &context)
  {
    {
      const auto timer = context.section("make grid");
      make_grid(context);
    }
    const auto timer = context.section("setup system");
    setup_system(context);
  }

  void
  Scene::assemble(RunContext &context)
  {
    const auto timer = context.section("assemble system");
    assemble_system(context);
    lcp::check_and_normalise(lcp_problem);
  }

  lcp::Report
  Scene::run(RunContext &context)
  {
    set_up(context);
    assemble(context);
    export_lcp_if_requested(context, lcp_problem);

    lcp::Report report;
    {
      // The scene's proof that there is no solution is part of the stage.
      const auto        timer = context.section("solve");
      const std::string proof = proof_of_no_solution();
      if (!proof.empty())
        {
          if (context.progress != nullptr)
            *context.progress << "  not solving: " << proof << std::endl;
          report = unsolved(lcp_problem, context.solver, proof, lcp_solution);
        }
      else
        {
          initial_solution(context);
          if (context.progress != nullptr)
            *context.progress
              << "  solving with " << context.solver.method
              << (context.solver.schur_complement ? " on the Schur complement" :
                                                    "")
              << std::endl;
          report = lcp::solve_lcp(lcp_problem,
                                  context.solver,
                                  lcp_solution,
                                  context.progress);
        }
    }
    write_solution_if_requested(context, lcp_solution);
    {
      const auto timer = context.section("postprocess");
      postprocess(context, report);
    }
    if (context.write_vtu)
      {
        const auto timer = context.section("output results");
        output_results(context);
      }

    if (context.out != nullptr)
      print_summary(*context.out, report);
    JsonObject summary = summary_base(context, name(), lcp_problem, report);
    add_summary(summary);
    if (context.writes_files)
      summary.write_file((context.output_directory / "summary.json").string());
    return report;
  }

  void
  Scene::pretouch(const double bytes) const
  {
    if (ranks::n_ranks() == 1)
      memory::pretouch_in_background(bytes);
  }

  std::string
  Scene::failure_description(const lcp::Report &report) const
  {
    switch (report.status)
      {
        case lcp::Status::infeasible: // the message says who proved it
          return report.message;
        case lcp::Status::singular:
          return "the solver met a singular system it could not resolve: " +
                 report.message;
        case lcp::Status::iteration_limit:
          return "the solver did not settle within its iteration limit: " +
                 report.message;
        case lcp::Status::inaccurate:
          return "the answer is not accurate enough to be given as "
                 "converged: " +
                 report.message;
        case lcp::Status::converged:
          break;
      }
    return "";
  }

  std::string
  Scene::proof_of_no_solution()
  {
    return "";
  }

  void
  Scene::make_grid(RunContext &)
  {}

  void
  Scene::setup_system(RunContext &)
  {}

  void
  Scene::initial_solution(RunContext &)
  {}

  void
  Scene::postprocess(const RunContext &, lcp::Report &)
  {}

  void
  Scene::output_results(const RunContext &) const
  {}

  void
  Scene::print_summary(std::ostream &out, const lcp::Report &report) const
  {
    print_solver_summary(out, lcp_problem, report);
  }

  void
  Scene::add_summary(JsonObject &) const
  {}

  void
  print_solver_summary(std::ostream       &out,
                       const lcp::Problem &problem,
                       const lcp::Report  &report)
  {
    const auto flags     = out.flags();
    const auto precision = out.precision();
    out << "  LCP: " << quantity(problem.size(), "unknown") << ", "
        << quantity(problem.n_constrained(), "constraint") << "\n"
        << "  solver " << report.solver << ": ";
    if (!report.solved)
      {
        out << "not run, " << lcp::to_string(report.status)
            << " (proved before solving)\n"
            << "  note: " << report.message << "\n";
        return;
      }
    out << lcp::to_string(report.status) << " after "
        << quantity(report.iterations, "iteration");
    if (report.projected)
      out << " + " << report.projection_iterations << " projection";
    out << ", " << report.n_active << " active\n";
    if (!report.message.empty())
      out << "  note: " << report.message << "\n";
    out << std::scientific << std::setprecision(6) << "  energy "
        << report.energy << "\n"
        << std::setprecision(1) << "  KKT residuals: stationarity "
        << report.kkt.stationarity << ", primal "
        << report.kkt.primal_feasibility << ", dual "
        << report.kkt.dual_feasibility << ", complementarity "
        << report.kkt.complementarity << "\n";
    out.flags(flags);
    out.precision(precision);
  }
} // namespace unilateral
