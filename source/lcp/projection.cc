#include <unilateral/base/prefixed_lines.h>
#include <unilateral/lcp/answer_checks.h>
#include <unilateral/lcp/projection.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <ostream>
#include <sstream>
#include <string>
#include <utility>

namespace unilateral::lcp
{
  namespace
  {
    /// The rounding of row i's forces (A u - b)_i: a hundred times machine
    /// epsilon times the sizes of their terms, |b_i| + (|A| |u|)_i, with
    /// @p terms = absolute_product(A, u).
    double
    row_rounding(const Problem &problem, const Vector &terms, const Index i)
    {
      return 100 * std::numeric_limits<double>::epsilon() *
             (std::abs(problem.b[i]) + terms[i]);
    }
  } // namespace

  std::vector<Index>
  interior_point_active_set(const Problem &problem, const Vector &u)
  {
    const Vector lambda     = multiplier(problem, u);
    double       slack_size = 0, lambda_size = 0;
    for (Index k = 0; k < problem.n_constrained(); ++k)
      {
        const Index i = problem.constrained[k];
        slack_size    = std::max(slack_size, u[i] - problem.lower_bound[k]);
        lambda_size   = std::max(lambda_size, lambda[i]);
      }
    // A multiplier within the rounding of its own terms is no force the
    // arithmetic can tell from none: where nothing touches (a plate the
    // load lifts off its obstacle) every multiplier is such noise, and the
    // ratio test alone would close about half of them, for the projection
    // to reopen over many iterations.
    const Vector       terms = absolute_product(problem.A, u);
    std::vector<Index> active;
    for (Index k = 0; k < problem.n_constrained(); ++k)
      {
        const Index i = problem.constrained[k];
        if ((u[i] - problem.lower_bound[k]) * lambda_size <=
              lambda[i] * slack_size &&
            std::abs(lambda[i]) > row_rounding(problem, terms, i))
          active.push_back(i);
      }
    return active;
  }

  namespace
  {
    // The projection method alone on @p problem.
    Report
    run_projection_method(const Problem          &problem,
                          const SolverParameters &parameters,
                          Solution               &solution,
                          std::ostream           *progress)
    {
      const SolverInfo &info = projection_method();
      Report            report;
      info.create(parameters, parameters.of(info.name))
        ->solve(problem, solution, report, progress);
      return report;
    }

    // A += delta I.
    void
    shift_diagonal(Problem &problem, const double delta)
    {
      for (Index j = 0; j < problem.size(); ++j)
        problem.A.coeffRef(j, j) += delta;
    }

    // A + eps I.
    Problem
    shifted(const Problem &problem, const double eps)
    {
      Problem result = problem;
      shift_diagonal(result, eps);
      return result;
    }

    /**
     * The proximal point method (Rockafellar 1976) from @p solution: x_k+1
     * solves LCP(A + eps I, b + eps x_k), the energy plus eps/2 |x - x_k|^2,
     * a strictly convex problem for every k, warm-started from x_k. A fixed
     * point solves LCP(A, b), and the iterates converge to a solution even
     * where A is only semidefinite on the solution's free set and the
     * solutions form an unbounded set (a course of bricks free to slide
     * along its frictionless joints): the iteration keeps x_k's position
     * along such a motion and corrects the rest by about eps / (lambda +
     * eps) per step, lambda A's smallest nonzero eigenvalue there. Where
     * that is slow (a block held by contacts that carry almost no force:
     * lambda tiny), eps falls tenfold per step, down to @p smallest_eps:
     * each step starts nearer the answer, so a smaller eps is usually safe;
     * where the method fails on a step, eps goes back up tenfold and stays
     * there, and the step is taken again from the same iterate. Stops
     * once the KKT residual on A is below @p tolerance, or when three steps
     * together did not halve it (slower steps would not reach it within
     * the iterations a solve may take).
     *
     * Polish: once a step passes @p tolerance, at most four more steps
     * follow while each shrinks and at least halves the residual, until it
     * is below 1e-4 of @p tolerance; the first that does not (or fails)
     * ends the method with the iterate before it. Why: the residual a step
     * leaves is smooth along the free motion, of one sign over a body, so
     * the body's resultant sums it over its DOFs (a review: three blocks
     * free to slide on their beds, stopped at 2.8e-11 with the tolerance
     * 1e-8, had reactions 1e-7 off the loads and contact forces 3e-6 off
     * PDAS's). The polish never makes the finish fail where it passed;
     * its answer can pass later checks that the one before failed.
     *
     * Where the LCP has no solution (a load that drives a body away), each
     * step moves x by about as much as the one before along that motion,
     * and the KKT residual relative to the growing x falls as if
     * converging. Where a solution exists, the steps shrink towards it
     * (their lengths never grow for a fixed eps). So an answer is taken
     * only after a step at most half as long as the one before, and an
     * iterate that has moved from the start by more than the start's own
     * size ends the method as failed.
     */
    Report
    proximal_point(const Problem          &problem,
                   const SolverParameters &parameters,
                   const double            first_eps,
                   const double            smallest_eps,
                   const double            tolerance,
                   Solution               &solution,
                   std::ostream           *progress)
    {
      Problem    proximal = shifted(problem, first_eps);
      double     eps      = first_eps;
      double     floor    = smallest_eps;
      const auto set_eps  = [&](const double new_eps) {
        shift_diagonal(proximal, new_eps - eps);
        eps = new_eps;
      };
      // Where A is definite a solution exists: runaway steps are round-off.
      const std::string runaway =
        problem.definite ?
          "A is positive definite, so a solution exists: round-off?" :
          "no solution: a load that drives a body away?";
      Report              result;
      const Vector        start         = solution.u;
      double              previous_step = 0;
      std::vector<double> residuals{kkt_residuals(problem, solution.u).max()};
      // The iterate that passed, while the polish runs.
      std::optional<Solution> passed;
      double                  passed_residual = 0;
      unsigned int            polish_steps    = 0;
      const auto              polished        = [&]() {
        solution = std::move(*passed);
        return result;
      };
      for (unsigned int k = 1;
           residuals.size() < 4 ||
           residuals.back() < 0.5 * residuals[residuals.size() - 4];
           ++k)
        {
          proximal.b        = problem.b + eps * solution.u;
          Solution     next = solution;
          const Report step =
            run_projection_method(proximal, parameters, next, nullptr);
          result.iterations += step.iterations;
          result.counters += step.counters;
          if (!step.converged())
            {
              if (passed)
                return polished();
              if (eps >= first_eps || floor > smallest_eps)
                return step;
              floor = std::min(10 * eps, first_eps);
              set_eps(floor);
              continue;
            }
          const double step_length =
            (next.u - solution.u).lpNorm<Eigen::Infinity>();
          solution           = std::move(next);
          const double moved = (solution.u - start).lpNorm<Eigen::Infinity>();
          if (passed && moved > start.lpNorm<Eigen::Infinity>())
            return polished();
          if (moved > start.lpNorm<Eigen::Infinity>())
            {
              std::ostringstream message;
              message << "the proximal point iteration moved the answer by "
                      << moved << ", more than its own size (" << runaway
                      << ")";
              result.status  = Status::iteration_limit;
              result.message = message.str();
              return result;
            }
          const double residual = kkt_residuals(problem, solution.u).max();
          if (progress != nullptr)
            *progress << "    projection: proximal step " << k
                      << " (eps = " << eps << "): " << step.iterations
                      << " iterations, KKT residual " << residual << std::endl;
          const bool shrinking = step_length <= 0.5 * previous_step;
          if (passed)
            {
              if (!(shrinking && residual <= 0.5 * passed_residual))
                return polished();
              ++polish_steps;
            }
          if (passed || (residual <= tolerance && shrinking))
            {
              if (residual <= 1e-4 * tolerance || polish_steps == 4)
                return result;
              passed          = solution;
              passed_residual = residual;
            }
          previous_step = step_length;
          if (residual > 0.1 * residuals.back() && eps > floor)
            set_eps(std::max(0.1 * eps, floor));
          residuals.push_back(residual);
        }
      if (passed)
        return polished();
      std::ostringstream message;
      if (residuals.back() <= tolerance)
        message << "the proximal point steps do not shrink (the last moved "
                   "the answer by "
                << previous_step << "): " << runaway;
      else
        message << "the proximal point iteration stalled at a KKT residual "
                   "of "
                << residuals.back() << " after " << result.iterations
                << " iterations";
      result.status  = Status::iteration_limit;
      result.message = message.str();
      return result;
    }

    /**
     * Whether an unknown of @p later, the answer on A + @p eps I, exceeds a
     * hundred times its value in @p earlier by more than @p tolerance times
     * the largest of @p later, held there by a regularisation force eps
     * u_i beyond a hundred times the rounding of its row's forces: a load
     * drives it. A free motion that no load drives grows as much between
     * two stages, by the rounding of its loads over eps, but its
     * regularisation force is that rounding, and any position along it is
     * an answer.
     */
    bool
    grew(const Problem &problem,
         const Vector  &later,
         const double   eps,
         const Vector  &earlier,
         const double   tolerance)
    {
      const double floor = tolerance * later.lpNorm<Eigen::Infinity>();
      const Vector terms = absolute_product(problem.A, later);
      for (Eigen::Index i = 0; i < later.size(); ++i)
        if (std::abs(later[i]) > 100 * std::abs(earlier[i]) + floor &&
            eps * std::abs(later[i]) > row_rounding(problem, terms, i))
          return true;
      return false;
    }

    /// The answers of the continuation stages that converged: @p last on
    /// A + @p last_eps I (last_eps 0 if none did), @p previous at a
    /// thousand times that eps (at first the approximate answer).
    struct Stages
    {
      Vector previous;
      Vector last;
      double last_eps = 0;
    };

    /**
     * Where the projection onto A fails, A is singular on the answer's free
     * set or PDAS does not settle on it: finish by the proximal point method
     * instead, with the eps the @p approximate answer was computed with
     * (@p first_eps), so that its first problem lies next to that answer.
     * That fails where the approximate answer is far from A's: a method
     * whose own regularisation is large (PSOR, MPRGP: 1e-2 d) on a body
     * free to slide unloaded, whose elastic deflection the regularisation
     * held back; the first steps move by more than the answer's size and
     * look like a runaway. There the last continuation stage's answer (eps
     * down to 1e-14 ... 1e-11 d) may already solve the LCP on A (its free
     * motions unloaded, at no cost to the residuals): it is taken if it
     * passes the checks and does not depend on eps, i.e. no unknown that a
     * load drives grew by a hundred times from the stage before (grew).
     * Where the loads drive a free motion (an LCP without a solution) the
     * stage moves along it by the loads' work over eps, and its residual,
     * eps times that motion, passes the checks (a review); a proximal point
     * method from it with its eps moves by the loads' rounding over eps in
     * every step and cannot tell. The final judgement checks the answer
     * like any other. On success @p solution is the answer; the iterations
     * and counters go to @p report.
     */
    Report
    finish_without_projection(const Problem          &problem,
                              const SolverParameters &parameters,
                              const double            first_eps,
                              const double            last_eps,
                              Solution                approximate,
                              Stages                  stages,
                              Solution               &solution,
                              Report                 &report,
                              std::ostream           *progress)
    {
      const Report proximal = proximal_point(problem,
                                             parameters,
                                             first_eps,
                                             last_eps,
                                             parameters.kkt_tolerance,
                                             approximate,
                                             progress);
      report.projection_iterations += proximal.iterations;
      report.counters += proximal.counters;
      if (proximal.converged())
        solution = std::move(approximate);
      else if (stages.last_eps > 0 &&
               !grew(problem,
                     stages.last,
                     stages.last_eps,
                     stages.previous,
                     parameters.kkt_tolerance) &&
               passes_checks(problem, parameters.kkt_tolerance, stages.last))
        {
          if (progress != nullptr)
            *progress << "    projection: the last continuation stage's "
                         "answer solves the problem on A ("
                      << proximal.message << ")" << std::endl;
          solution   = Solution();
          solution.u = std::move(stages.last);
          return Report(); // converged
        }
      return proximal;
    }
  } // namespace

  void
  project(const Problem          &problem,
          const SolverParameters &parameters,
          const double            first_eps,
          const FirstActiveSet    first_active_set,
          Solution               &solution,
          Report                 &report,
          std::ostream           *progress)
  {
    PhaseTimer timer(report, "projection");
    // Its progress lines labelled after their indentation ("    projection:
    // pdas iteration 1: ..."): the method's own would repeat those of the
    // solve before it word for word.
    std::unique_ptr<PrefixedLines> labelled;
    if (progress != nullptr)
      labelled = std::make_unique<PrefixedLines>(
        *progress, [] { return std::string("projection: "); }, true);
    const double mean_diagonal = diagonal_scale(problem.A);
    const double last_eps      = 1e-14 * mean_diagonal;
    double       eps_k         = first_eps;

    SolverParameters projection_parameters = parameters;
    Solution         start                 = solution;
    if (first_active_set == FirstActiveSet::test_on_u)
      start.active_set.clear(); // the test on u_eps decides, not a hint
    else if (first_active_set == FirstActiveSet::interior_point)
      start.active_set = interior_point_active_set(problem, solution.u);
    // The approximate answer's factor goes to the first run on A only (its
    // systems are solved with it as a nearby factor); the copies kept for a
    // continuation stage or the proximal finish go without, so that it is
    // freed once the projection factorises its own: the largest walls
    // cannot hold two factors (benchmarks/tfeti/README.md, "The largest
    // walls").
    std::shared_ptr<const ActiveSetFactor> nearby = std::move(start.factor);
    const Solution                         approximate = start;
    Report                                 projection;
    // The continuation stages' answers, for the end of the finish below.
    Stages stages;
    stages.previous = approximate.u;
    for (;;)
      {
        const bool stage_left = eps_k * 1e-3 >= last_eps;
        // Wandering counts as failure while a continuation stage is left.
        projection_parameters.max_iterations =
          !stage_left ? parameters.max_iterations :
          parameters.max_iterations > 0 ?
                        std::min(parameters.max_iterations, 50u) :
                        50u;
        solution = start;
        if (nearby != nullptr)
          solution.factor = std::move(nearby);
        projection = run_projection_method(problem,
                                           projection_parameters,
                                           solution,
                                           labelled.get());
        report.projection_iterations += projection.iterations;
        report.counters += projection.counters;
        // A proof that there is no solution ends it (PDAS's free motion
        // along which the loads do work without bound).
        if (projection.converged() || !stage_left ||
            projection.status == Status::infeasible)
          break;

        // One continuation stage on A + eps_k d I, warm-started.
        eps_k *= 1e-3;
        if (progress != nullptr)
          *progress << "    projection: " << projection.message
                    << "; continuing with eps = " << eps_k / mean_diagonal
                    << " (relative)" << std::endl;
        const Report stage = run_projection_method(shifted(problem, eps_k),
                                                   parameters,
                                                   start,
                                                   labelled.get());
        report.projection_iterations += stage.iterations;
        ++report.continuation_stages;
        report.counters += stage.counters;
        if (!stage.converged())
          {
            projection = stage;
            break;
          }
        if (stages.last_eps > 0)
          stages.previous = std::move(stages.last);
        stages.last     = start.u;
        stages.last_eps = eps_k;
      }
    // Not where the projection proved that there is no answer.
    std::string proximal_failure;
    if (!projection.converged() && projection.status != Status::infeasible)
      {
        const Report finish = finish_without_projection(problem,
                                                        parameters,
                                                        first_eps,
                                                        last_eps,
                                                        approximate,
                                                        std::move(stages),
                                                        solution,
                                                        report,
                                                        progress);
        if (finish.converged())
          projection = finish;
        else
          proximal_failure = "; the proximal point finish: " + finish.message;
      }
    report.projected = true;
    if (!projection.converged())
      {
        report.status  = projection.status;
        report.message = "projection step: " + projection.message;
        if (projection.status == Status::singular && !problem.definite)
          report.message +=
            ": without regularisation this LCP has no unique solution for "
            "that active set (check that every body can be supported), or "
            "set 'Solver/Projection = false' to keep the regularised one";
        report.message += proximal_failure;
      }
  }
} // namespace unilateral::lcp
