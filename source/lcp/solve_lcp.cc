#include <unilateral/base/input_error.h>
#include <unilateral/lcp/schur_complement.h>
#include <unilateral/lcp/solver.h>

#include <algorithm>
#include <iomanip>
#include <limits>
#include <memory>
#include <ostream>
#include <sstream>

namespace unilateral::lcp
{
  std::vector<SolverInfo> &
  SolverRegistry::entries()
  {
    static std::vector<SolverInfo> registered;
    return registered;
  }

  bool
  SolverRegistry::add(SolverInfo info)
  {
    entries().push_back(std::move(info));
    return true;
  }

  const SolverInfo &
  SolverRegistry::get(const std::string &name)
  {
    for (const auto &info : entries())
      if (info.name == name)
        return info;
    throw InputError("parameter 'Solver/Method' = " + name +
                     ": unknown method; choose one of " + selection());
  }

  std::vector<std::string>
  SolverRegistry::names()
  {
    std::vector<std::string> result;
    for (const auto &info : entries())
      result.push_back(info.name);
    return result;
  }

  std::string
  SolverRegistry::selection()
  {
    std::string result;
    for (const auto &info : entries())
      result += (result.empty() ? "" : "|") + info.name;
    return result;
  }

  std::string
  SolverRegistry::documentation()
  {
    std::string result;
    for (const auto &info : entries())
      result += "  " + info.name + ": " + info.description + "\n";
    return result;
  }

  namespace
  {
    void
    merge_counters(Counters &into, const Counters &from)
    {
      into.orderings += from.orderings;
      into.symbolic_analyses += from.symbolic_analyses;
      into.numeric_factorisations += from.numeric_factorisations;
      into.reused_factorisations += from.reused_factorisations;
      into.modified_factorisations += from.modified_factorisations;
      into.factor_row_modifications += from.factor_row_modifications;
      into.resolved_subsets += from.resolved_subsets;
      into.resolved_indices += from.resolved_indices;
      into.cg_iterations += from.cg_iterations;
      into.triangular_solves += from.triangular_solves;
      into.partial_forward_solves += from.partial_forward_solves;
      into.centrality_correctors += from.centrality_correctors;
      into.matrix_vector_products += from.matrix_vector_products;
    }

    void
    merge_times(Report &into, const Report &from, const std::string &prefix)
    {
      for (const auto &[phase, seconds] : from.phase_times)
        into.add_time(prefix + phase, seconds);
    }

    Report
    solve_full(const Problem          &problem,
               const SolverParameters &parameters,
               Solution               &solution,
               std::ostream           *progress,
               double                  auto_regularisation);

    // Another method as a user would run it, regularised if need be and
    // projected, for the checks and continuations below.
    Report
    solve_full_with(const std::string      &method,
                    const Problem          &problem,
                    const SolverParameters &parameters,
                    Solution               &solution,
                    std::ostream           *progress,
                    const double            auto_regularisation)
    {
      SolverParameters method_parameters = parameters;
      method_parameters.method           = method;
      method_parameters.projection       = true;
      solution                           = Solution();
      return solve_full(
        problem, method_parameters, solution, progress, auto_regularisation);
    }

    /**
     * A claim that the LCP has no solution is checked with PDAS, which
     * never makes one (it ends singular or at its limit instead). Graves
     * can enter its Case 2 through round-off, as Ainsworth & Mihai report:
     * running bond, m = 5, without load, where u = 0 solves it. If PDAS
     * solves the LCP, its answer is given and the note says why.
     */
    void
    check_infeasibility_claim(const Problem          &problem,
                              const SolverParameters &parameters,
                              Solution               &solution,
                              Report                 &report,
                              std::ostream           *progress,
                              const double            auto_regularisation)
    {
      Solution     check;
      const Report check_report = solve_full_with(
        "pdas", problem, parameters, check, progress, auto_regularisation);
      merge_counters(report.counters, check_report.counters);
      merge_times(report, check_report, "infeasibility check: ");
      if (!check_report.converged() ||
          !(kkt_residuals(problem, check.u).max() <= parameters.kkt_tolerance))
        {
          report.message += "; PDAS found none either (" +
                            to_string(check_report.status) + ")";
          return;
        }
      report.message += "; but PDAS solved it in " +
                        std::to_string(check_report.iterations +
                                       check_report.projection_iterations) +
                        " iterations, so the claim came from round-off: the "
                        "answer given is PDAS's";
      report.status = Status::converged;
      solution      = check;
    }

    /**
     * PDAS that cycles hands over to the interior point of Fernandes et
     * al., which converges whatever the start (in fewer iterations than
     * PDPC: 45 against 63 on the m = 100 running bond wall), then the
     * projection from its answer, which is PDAS again but near the
     * solution. The running bond walls need it from m = 30 on (g = H/2).
     * The answer is exact or the failure is reported; the note says what
     * happened.
     */
    Report
    continue_from_interior_point(const Problem          &problem,
                                 const SolverParameters &parameters,
                                 Solution               &solution,
                                 const Report           &pdas_report,
                                 std::ostream           *progress,
                                 const double            auto_regularisation)
    {
      if (progress != nullptr)
        *progress << "    " << pdas_report.message
                  << "; continuing from the interior point"
                  << std::endl;
      SolverParameters interior_parameters = parameters;
      interior_parameters.interior_point.predictor_corrector = true;
      Report report = solve_full_with(
        "interior_point", problem, interior_parameters, solution, progress,
        auto_regularisation);
      report.solver = pdas_report.solver;
      report.iterations += pdas_report.iterations;
      merge_counters(report.counters, pdas_report.counters);
      merge_times(report, pdas_report, "pdas (cycled): ");
      const std::string note = pdas_report.message + " after " +
                               std::to_string(pdas_report.iterations) +
                               " iterations; continued from the interior "
                               "point's answer";
      report.message =
        report.message.empty() ? note : note + "; " + report.message;
      return report;
    }

    /**
     * The first active set of the projection after an interior-point
     * method. Its iterate lies strictly inside, with slack s and multiplier
     * lambda both small on the indices that are nearly complementary. PDAS's
     * test s - tau lambda < 0 mixes their units, and on the running bond
     * walls it called open a few closed contacts that carry almost no force
     * (slack 5e-8, lambda 1e-5) but hold a brick against rotation: the first
     * system was singular. Compared in units of their own size, s / |s| <
     * lambda / |lambda| (Tapia's indicators, scale-free), it errs towards
     * closing contacts, which the next test reopens safely.
     */
    std::vector<Index>
    interior_point_active_set(const Problem &problem, const Vector &u)
    {
      const Vector lambda = multiplier(problem, u);
      double       slack_size = 0, lambda_size = 0;
      for (Index k = 0; k < problem.n_constrained(); ++k)
        {
          const Index i = problem.constrained[k];
          slack_size = std::max(slack_size, u[i] - problem.lower_bound[k]);
          lambda_size = std::max(lambda_size, lambda[i]);
        }
      std::vector<Index> active;
      for (Index k = 0; k < problem.n_constrained(); ++k)
        {
          const Index i = problem.constrained[k];
          if ((u[i] - problem.lower_bound[k]) * lambda_size <=
              lambda[i] * slack_size)
            active.push_back(i);
        }
      return active;
    }

    // The method alone on the problem as given (no regularisation).
    void
    run_method(const SolverInfo       &info,
               const Problem          &problem,
               const SolverParameters &parameters,
               Solution               &solution,
               Report                 &report,
               std::ostream           *progress)
    {
      if (info.dense &&
          static_cast<unsigned int>(problem.size()) > parameters.max_dense_size)
        throw InputError(
          "method '" + info.name + "' is dense and the LCP has " +
          std::to_string(problem.size()) +
          " unknowns, more than 'Solver/Maximum dense size' = " +
          std::to_string(parameters.max_dense_size) +
          ": use 'Schur complement = true' (graves works on S only) or a "
          "sparse method");
      auto solver = info.create(parameters);
      solver->solve(problem, solution, report, progress);
    }

    Report
    solve_full(const Problem          &problem,
               const SolverParameters &parameters,
               Solution               &solution,
               std::ostream           *progress,
               const double            auto_regularisation)
    {
      const SolverInfo &info = SolverRegistry::get(parameters.method);
      Report            report;
      report.solver = info.name;

      // 'auto': the scene's value, raised to the method's own preference
      // when the scene needs regularisation at all (PSOR converges at a rate
      // set by eps; the projection makes the answer exact anyway).
      const double relative_eps =
        parameters.regularisation >= 0 ?
          parameters.regularisation :
          (auto_regularisation > 0 ?
             std::max(auto_regularisation, info.preferred_regularisation) :
             0.0);
      const bool regularise = info.needs_definite_matrix && relative_eps > 0;

      // Stage 1: the method, on A + eps d I if it needs a definite matrix.
      if (!regularise)
        {
          const Solution start = solution;
          {
            PhaseTimer timer(report, "solve");
            run_method(info, problem, parameters, solution, report, progress);
          }
          if (report.status == Status::singular &&
              info.needs_definite_matrix && parameters.regularisation < 0 &&
              auto_regularisation == 0)
            {
              // 'auto' on a scene that expected A to be definite, but it is
              // not (an LCP read from files, from masonry: floating
              // blocks): regularise after all, as the masonry scene does
              // (1e-9), and project. The failed attempt's time and work
              // stay in the report.
              if (progress != nullptr)
                *progress << "    " << report.message
                          << "; regularising with eps = 1e-9 (auto)"
                          << std::endl;
              solution           = start;
              Report regularised = solve_full(
                problem, parameters, solution, progress, 1e-9);
              merge_counters(regularised.counters, report.counters);
              merge_times(regularised, report, "");
              return regularised;
            }
          if (report.status == Status::singular && info.needs_definite_matrix)
            report.message += "; regularise ('Solver/Regularisation' > 0)";
          if (report.status == Status::infeasible && info.name != "pdas")
            check_infeasibility_claim(problem,
                                      parameters,
                                      solution,
                                      report,
                                      progress,
                                      auto_regularisation);
        }
      else
        {
          Problem regularised;
          {
            PhaseTimer timer(report, "regularise");
            regularised = problem;
            const double mean_diagonal =
              problem.size() > 0 ? problem.A.diagonal().mean() : 1.0;
            report.regularisation =
              relative_eps * (mean_diagonal > 0 ? mean_diagonal : 1.0);
            for (Index j = 0; j < regularised.size(); ++j)
              regularised.A.coeffRef(j, j) += report.regularisation;
          }
          PhaseTimer timer(report, "solve");
          run_method(info, regularised, parameters, solution, report, progress);
        }
      if (info.name == "pdas" && report.status == Status::iteration_limit &&
          parameters.max_iterations == 0)
        return continue_from_interior_point(problem,
                                            parameters,
                                            solution,
                                            report,
                                            progress,
                                            auto_regularisation);
      if (regularise && !parameters.projection && report.converged())
        {
          // A small KKT residual of the answer to A + eps I against A bounds
          // the backward error only; nearly floating bodies turn it into a
          // forward error 1e4 times larger (laminae m = 10, eps = 1e-8: KKT
          // 2.6e-9, displacement 8e-5 off). Not the user's problem solved.
          std::ostringstream message;
          message << std::setprecision(3)
                  << "the answer solves the regularised LCP (A + eps I, eps = "
                  << relative_eps
                  << " times the mean diagonal), not the given one, and its "
                     "error is not bounded by the KKT residual; set "
                     "'Solver/Projection = true' for the exact solution";
          report.status  = Status::inaccurate;
          report.message = message.str();
        }
      // An exact method on A itself needs no projection, unless its answer
      // fails the KKT check: pivoting methods with an absolute tolerance
      // (block pivoting's 1e-6) can stop a few indices short on large
      // plates (n1 = 64: KKT 2e-6). PDAS from there finishes the job.
      const bool exact_answer =
        info.exact && !regularise && report.converged() &&
        solution.u.size() == problem.size() &&
        kkt_residuals(problem, solution.u).max() <= parameters.kkt_tolerance;
      if (!report.converged() || !parameters.projection || exact_answer)
        return report;

      // Stage 2: the projection, PDAS on A from the approximate solution.
      // If u_eps is far from the answer (a large eps), PDAS on A may meet an
      // active set that leaves a body unsupported (a singular system) or
      // wander without settling. Then continue in eps: PDAS on A + eps_k d I
      // with eps_k falling by 1e3 per stage, each warm-started from the
      // last, and A again after each stage. A projection that has not
      // settled in 50 iterations counts as wandering while a stage is left.
      auto projection_timer =
        std::make_unique<PhaseTimer>(report, "projection");
      const double mean_diagonal =
        problem.size() > 0 && problem.A.diagonal().mean() > 0 ?
          problem.A.diagonal().mean() :
          1.0;
      // A method that ran on A itself (pdpc, interior_point) continues from
      // the scene's regularisation.
      double eps_k = regularise ? report.regularisation :
                                  1e3 * std::max(auto_regularisation, 1e-12) *
                                    mean_diagonal;
      const double     last_eps = 1e-14 * mean_diagonal;
      SolverParameters projection_parameters = parameters;
      Solution         start                 = solution;
      start.active_set.clear(); // the test on u_eps decides, not a hint
      if (!regularise && !info.exact)
        start.active_set = interior_point_active_set(problem, solution.u);
      Report           projection;
      for (;;)
        {
          const bool stage_left = eps_k * 1e-3 >= last_eps;
          projection_parameters.max_iterations =
            !stage_left                    ? parameters.max_iterations :
            parameters.max_iterations > 0 ? std::min(parameters.max_iterations, 50u) :
                                            50u;
          projection = Report();
          solution   = start;
          run_method(SolverRegistry::get("pdas"),
                     problem,
                     projection_parameters,
                     solution,
                     projection,
                     progress);
          report.projection_iterations += projection.iterations;
          merge_counters(report.counters, projection.counters);
          if (projection.converged() || !stage_left)
            break;
          eps_k *= 1e-3;
          if (progress != nullptr)
            *progress << "    projection: " << projection.message
                      << "; continuing with eps = " << eps_k / mean_diagonal
                      << " (relative)" << std::endl;
          // One continuation stage on A + eps_k d I.
          Problem shifted = problem;
          for (Index j = 0; j < shifted.size(); ++j)
            shifted.A.coeffRef(j, j) += eps_k;
          Report stage;
          run_method(SolverRegistry::get("pdas"),
                     shifted,
                     parameters,
                     start,
                     stage,
                     progress);
          report.projection_iterations += stage.iterations;
          ++report.continuation_stages;
          merge_counters(report.counters, stage.counters);
          if (!stage.converged())
            {
              projection = stage;
              break;
            }
        }
      report.projected = true;
      if (!projection.converged())
        {
          report.status  = projection.status;
          report.message = "projection step: " + projection.message;
          if (projection.status == Status::singular)
            report.message +=
              ": without regularisation this LCP has no unique solution for "
              "that active set (check that every body can be supported), or "
              "set 'Solver/Projection = false' to keep the regularised one";
        }
      projection_timer.reset(); // records the time before the return
      return report;
    }
  } // namespace

  Report
  solve_lcp(const Problem          &problem,
            const SolverParameters &parameters,
            Solution               &solution,
            std::ostream           *progress,
            const double            auto_regularisation)
  {
    Report report;
    if (!parameters.schur_complement)
      report =
        solve_full(problem, parameters, solution, progress, auto_regularisation);
    else
      {
        report.solver = SolverRegistry::get(parameters.method).name + "_sc";
        std::unique_ptr<SchurComplement> schur;
        {
          PhaseTimer timer(report, "schur complement");
          schur = std::make_unique<SchurComplement>(problem,
                                                    parameters.max_dense_size,
                                                    report.counters);
        }
        if (schur->singular())
          {
            report.status  = Status::singular;
            report.message = "A_EE (the unconstrained block) is not positive "
                             "definite, so the Schur complement does not "
                             "exist; solve the full LCP instead";
            solution.u     = Vector::Zero(problem.size());
          }
        else
          {
            // Ainsworth & Mihai regularise the (scaled) Schur complement with
            // eps ~ n_c * machine epsilon.
            const double sc_eps =
              problem.n_constrained() * std::numeric_limits<double>::epsilon();
            Solution reduced_solution;
            if (solution.u.size() == problem.size())
              {
                reduced_solution.u.resize(problem.n_constrained());
                for (Index k = 0; k < problem.n_constrained(); ++k)
                  reduced_solution.u[k] = solution.u[problem.constrained[k]];
              }
            SolverParameters reduced_parameters = parameters;
            reduced_parameters.schur_complement = false;
            const Report reduced_report = solve_full(schur->reduced_problem(),
                                                     reduced_parameters,
                                                     reduced_solution,
                                                     progress,
                                                     sc_eps);
            report.status                = reduced_report.status;
            report.message               = reduced_report.message;
            report.iterations            = reduced_report.iterations;
            report.projected             = reduced_report.projected;
            report.projection_iterations = reduced_report.projection_iterations;
            report.regularisation        = reduced_report.regularisation;
            merge_counters(report.counters, reduced_report.counters);
            merge_times(report, reduced_report, "");
            PhaseTimer timer(report, "recover u_E");
            solution.u = schur->recover(reduced_solution.u);
          }
      }

    // Release the last factorisation (it can be large) before returning.
    solution.factor.reset();

    // The final check, always against the original problem.
    {
      PhaseTimer timer(report, "kkt check");
      if (solution.u.size() != problem.size())
        solution.u = Vector::Zero(problem.size());
      solution.lambda = multiplier(problem, solution.u);
      // An index is active if u sits exactly at its bound (active-set and
      // pivoting methods put it there) or, for interior-point iterates that
      // never reach a bound, if its slack is smaller than its multiplier in
      // the same units (slack times the diagonal of A).
      solution.active_set.clear();
      for (Index k = 0; k < problem.n_constrained(); ++k)
        {
          const Index  i     = problem.constrained[k];
          const double slack = solution.u[i] - problem.lower_bound[k];
          const double scale =
            problem.A.coeff(i, i) > 0 ? problem.A.coeff(i, i) : 1.0;
          if (slack == 0 || slack * scale < solution.lambda[i])
            solution.active_set.push_back(i);
        }
      report.n_active = static_cast<unsigned int>(solution.active_set.size());
      report.kkt      = kkt_residuals(problem, solution.u);
      report.energy   = energy(problem, solution.u);
      ++report.counters.matrix_vector_products;
    }
    if (report.status == Status::converged &&
        !(report.kkt.max() <= parameters.kkt_tolerance))
      {
        std::ostringstream message;
        message << std::setprecision(3)
                << "the method's stopping test passed but the relative KKT "
                   "residual is "
                << report.kkt.max() << " > 'Solver/KKT tolerance' = "
                << parameters.kkt_tolerance;
        report.status  = Status::inaccurate;
        report.message = message.str();
      }
    return report;
  }
} // namespace unilateral::lcp
