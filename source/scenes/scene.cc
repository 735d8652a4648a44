#include <unilateral/base/input_error.h>
#include <unilateral/lcp/io.h>
#include <unilateral/scenes/scene.h>

#include <cmath>
#include <iomanip>
#include <sstream>
#include <ostream>

namespace unilateral
{
  std::vector<SceneInfo> &
  SceneRegistry::entries()
  {
    static std::vector<SceneInfo> registered;
    return registered;
  }

  bool
  SceneRegistry::add(SceneInfo info)
  {
    entries().push_back(std::move(info));
    return true;
  }

  const SceneInfo &
  SceneRegistry::get(const std::string &name)
  {
    for (const auto &info : entries())
      if (info.name == name)
        return info;
    throw InputError("parameter 'Scene' = " + name +
                     ": unknown scene; choose one of " + selection());
  }

  const std::vector<SceneInfo> &
  SceneRegistry::all()
  {
    return entries();
  }

  std::string
  SceneRegistry::selection()
  {
    std::string result;
    for (const auto &info : entries())
      result += (result.empty() ? "" : "|") + info.name;
    return result;
  }

  lcp::SolverParameters
  solver_parameters(const RunContext &context, const Scene &scene)
  {
    lcp::SolverParameters parameters = context.solver;
    if (parameters.pdas.start == lcp::SolverParameters::PdasStart::automatic)
      parameters.pdas.start =
        scene.auto_pdas_start_all_active() ?
          lcp::SolverParameters::PdasStart::all_active :
          lcp::SolverParameters::PdasStart::zero;
    return parameters;
  }

  lcp::Report
  solve(RunContext         &context,
        const Scene        &scene,
        const lcp::Problem &problem,
        lcp::Solution      &solution)
  {
    dealii::TimerOutput::Scope scope(*context.timer, "solve");
    if (context.progress != nullptr)
      *context.progress << "  solving with " << context.solver.method
                        << (context.solver.schur_complement ?
                              " on the Schur complement" :
                              "")
                        << std::endl;
    lcp::Report report = lcp::solve_lcp(problem,
                                        solver_parameters(context, scene),
                                        solution,
                                        context.progress,
                                        scene.auto_regularisation());
    check_work(problem, solution, report);
    return report;
  }

  void
  check_work(const lcp::Problem  &problem,
             const lcp::Solution &solution,
             lcp::Report         &report)
  {
    if (!report.converged() || solution.u.size() != problem.size())
      return;
    // At any solution u^T A u = b^T u + lambda^T u = b^T u + lambda_S^T l_S
    // (lambda_E = 0 and complementarity), and u^T A u >= 0: the work
    // W = b^T u - lambda_S^T l_S of the loads and the supports cannot be
    // negative. The relative KKT residuals are blind to a body that drifted
    // far away as a rigid motion (A u stays small where |A| |u| is huge),
    // and W is not: such an answer has W close to -|b|^T |u|.
    const lcp::Vector lambda = problem.A * solution.u - problem.b;
    double            work   = problem.b.dot(solution.u);
    double            scale  = problem.b.cwiseAbs().dot(solution.u.cwiseAbs());
    for (lcp::Index k = 0; k < problem.n_constrained(); ++k)
      {
        const double product =
          lambda[problem.constrained[k]] * problem.lower_bound[k];
        work -= product;
        scale += std::abs(product);
      }
    if (work < -1e-6 * scale)
      {
        std::ostringstream message;
        message << std::setprecision(3) << "the answer fails the work check: "
                << "b^T u - lambda_S^T l_S = " << work
                << " < 0, but it equals u^T A u >= 0 at every solution (a "
                   "body drifted away as a rigid motion?)";
        report.status  = lcp::Status::inaccurate;
        report.message = message.str() +
                         (report.message.empty() ? "" : "; " + report.message);
      }
  }

  JsonObject
  summary_base(const RunContext   &context,
               const std::string  &scene,
               const lcp::Problem &problem,
               const lcp::Report  &report)
  {
    JsonObject summary;
    summary.set("scene", scene)
      .set("run_name", context.run_name)
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

    // How often each stage ran: tests check from these, not from times, that
    // a stage a run does not need never ran.
    JsonObject &calls = summary.object("calls");
    if (context.timer != nullptr)
      for (const auto &[section, n] :
           context.timer->get_summary_data(dealii::TimerOutput::n_calls))
        calls.set(section, static_cast<unsigned int>(n));
    for (const auto &[phase, seconds] : report.phase_times)
      calls.set("solver: " + phase, 1u);

    JsonObject &counters = summary.object("counters");
    counters.set("orderings", report.counters.orderings)
      .set("symbolic_analyses", report.counters.symbolic_analyses)
      .set("numeric_factorisations", report.counters.numeric_factorisations)
      .set("reused_factorisations", report.counters.reused_factorisations)
      .set("modified_factorisations",
           report.counters.modified_factorisations)
      .set("factor_row_modifications",
           report.counters.factor_row_modifications)
      .set("resolved_subsets", report.counters.resolved_subsets)
      .set("resolved_indices", report.counters.resolved_indices)
      .set("cg_iterations", report.counters.cg_iterations)
      .set("triangular_solves", report.counters.triangular_solves)
      .set("partial_forward_solves",
           report.counters.partial_forward_solves)
      .set("centrality_correctors", report.counters.centrality_correctors)
      .set("matrix_vector_products", report.counters.matrix_vector_products);
    return summary;
  }

  void
  write_summary(const RunContext &context, const JsonObject &summary)
  {
    summary.write_file((context.output_directory / "summary.json").string());
  }

  void
  print_solver_summary(std::ostream       &out,
                       const lcp::Problem &problem,
                       const lcp::Report  &report)
  {
    const auto flags = out.flags();
    const auto precision = out.precision();
    out << "  LCP: " << problem.size() << " unknowns, "
        << problem.n_constrained() << " constraints\n"
        << "  solver " << report.solver << ": " << lcp::to_string(report.status)
        << " after " << report.iterations << " iterations";
    if (report.projected)
      out << " + " << report.projection_iterations << " projection";
    out << ", " << report.n_active << " active\n";
    if (!report.message.empty())
      out << "  note: " << report.message << "\n";
    out << std::scientific << std::setprecision(6)
        << "  energy " << report.energy << "\n"
        << std::setprecision(1) << "  KKT residuals: stationarity "
        << report.kkt.stationarity << ", primal "
        << report.kkt.primal_feasibility << ", dual "
        << report.kkt.dual_feasibility << ", complementarity "
        << report.kkt.complementarity << "\n";
    out.flags(flags);
    out.precision(precision);
  }

  void
  export_lcp_if_requested(const RunContext &context, const lcp::Problem &problem)
  {
    if (!context.export_lcp)
      return;
    dealii::TimerOutput::Scope scope(*context.timer, "export LCP");
    lcp::write_problem(problem, context.output_directory.string());
  }

  void
  write_solution_if_requested(const RunContext    &context,
                              const lcp::Solution &solution)
  {
    if (!context.write_solution)
      return;
    dealii::TimerOutput::Scope scope(*context.timer, "write solution");
    const std::string directory = context.output_directory.string();
    lcp::write_vector(solution.u, directory + "/u.txt");
    lcp::write_vector(solution.lambda, directory + "/lambda.txt");
  }
} // namespace unilateral
