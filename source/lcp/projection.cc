#include <unilateral/lcp/projection.h>

#include <algorithm>
#include <memory>
#include <ostream>
#include <streambuf>
#include <string>
#include <utility>

namespace unilateral::lcp
{
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

  namespace
  {
    /**
     * The progress lines of the projection step, labelled after their
     * indentation ("    projection: pdas iteration 1: ..."): the method's
     * own lines would repeat those of the solve before it word for word.
     */
    class LabelledLines : public std::streambuf
    {
    public:
      LabelledLines(std::ostream &out, std::string label)
        : out(out)
        , label(std::move(label))
      {}

    protected:
      int
      overflow(const int c) override
      {
        if (c == traits_type::eof())
          return c;
        if (at_line_start && c != ' ')
          {
            out << label;
            at_line_start = false;
          }
        if (c == '\n')
          at_line_start = true;
        out.put(static_cast<char>(c));
        return c;
      }

      int
      sync() override
      {
        out.flush();
        return 0;
      }

    private:
      std::ostream     &out;
      const std::string label;
      bool              at_line_start = true;
    };

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

    // A + eps I.
    Problem
    shifted(const Problem &problem, const double eps)
    {
      Problem result = problem;
      for (Index j = 0; j < result.size(); ++j)
        result.A.coeffRef(j, j) += eps;
      return result;
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
    PhaseTimer                     timer(report, "projection");
    std::unique_ptr<LabelledLines> labelled_buffer;
    std::unique_ptr<std::ostream>  labelled;
    if (progress != nullptr)
      {
        labelled_buffer =
          std::make_unique<LabelledLines>(*progress, "projection: ");
        labelled = std::make_unique<std::ostream>(labelled_buffer.get());
      }
    const double mean_diagonal =
      problem.size() > 0 && problem.A.diagonal().mean() > 0 ?
        problem.A.diagonal().mean() :
        1.0;
    const double last_eps = 1e-14 * mean_diagonal;
    double       eps_k    = first_eps;

    SolverParameters projection_parameters = parameters;
    Solution         start                 = solution;
    if (first_active_set == FirstActiveSet::test_on_u)
      start.active_set.clear(); // the test on u_eps decides, not a hint
    else if (first_active_set == FirstActiveSet::interior_point)
      start.active_set = interior_point_active_set(problem, solution.u);
    Report projection;
    for (;;)
      {
        const bool stage_left = eps_k * 1e-3 >= last_eps;
        // Wandering counts as failure while a continuation stage is left.
        projection_parameters.max_iterations =
          !stage_left ? parameters.max_iterations :
          parameters.max_iterations > 0 ?
                        std::min(parameters.max_iterations, 50u) :
                        50u;
        solution   = start;
        projection = run_projection_method(problem,
                                           projection_parameters,
                                           solution,
                                           labelled.get());
        report.projection_iterations += projection.iterations;
        report.counters += projection.counters;
        if (projection.converged() || !stage_left)
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
  }
} // namespace unilateral::lcp
