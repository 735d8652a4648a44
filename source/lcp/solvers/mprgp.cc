/**
 * The primal MPRGP (lcp/mprgp.h) as a method: min 1/2 u^T A u - b^T u
 * subject to u_S >= l_S with H = A, alpha_bar = 'Step length' / ||A|| (||A||
 * bounded by the largest absolute row sum), stopping when ||g^P|| <=
 * 'Tolerance' ||b||. Its rate of convergence depends on the condition
 * number of A: the answer is approximate, and the projection step finishes
 * it.
 */
#include <unilateral/base/input_error.h>
#include <unilateral/lcp/mprgp.h>
#include <unilateral/lcp/solver.h>

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>

namespace unilateral::lcp
{
  namespace
  {
    /// Subsection "Solver/MPRGP".
    class MprgpParameters : public MethodParametersBase<MprgpParameters>
    {
    public:
      /// On ||g^P|| relative to ||b||.
      double tolerance = 1e-10;
      /// Gamma, the proportioning constant.
      double gamma = 1;
      /// alpha_bar ||A||, in (0, 2].
      double step_length = 1.9;

      void
      add_parameters(dealii::ParameterHandler &prm) override
      {
        using namespace dealii::Patterns;
        prm.add_parameter("Tolerance",
                          tolerance,
                          "Stop when the projected gradient ||g^P||_2 is at "
                          "most this times ||b||_2. The projection step then "
                          "makes the answer exact.",
                          Double(0));
        prm.add_parameter("Proportioning",
                          gamma,
                          "Gamma > 0: a proportioning step (along the chopped "
                          "gradient, releasing active constraints) is taken "
                          "when ||beta||^2 > Gamma^2 phi~^T phi; Dostal's "
                          "choice is 1.",
                          Double(0));
        prm.add_parameter("Step length",
                          step_length,
                          "alpha_bar ||A|| of the expansion step, in (0, 2] "
                          "(the convergence proof's range); ||A|| is bounded "
                          "by the largest absolute row sum of A.",
                          Double(0, 2));
      }

      void
      check(const std::string &section) const override
      {
        check_parameter(
          gamma > 0, section, "Proportioning", gamma, "must be > 0");
        check_parameter(step_length > 0,
                        section,
                        "Step length",
                        step_length,
                        "must be in (0, 2]");
      }
    };

    class PrimalMprgp : public Solver
    {
    public:
      using Parameters = MprgpParameters;

      PrimalMprgp(const SolverParameters &parameters, const Parameters &options)
        : Solver(parameters)
        , options(options)
      {}

      static SolverInfo
      properties()
      {
        SolverInfo info;
        info.name        = "mprgp";
        info.label       = "MPRGP";
        info.description = "modified proportioning with reduced gradient "
                           "projections (Dostal & Schoberl), matrix-free "
                           "conjugate gradients with projections";
        info.subsection  = "MPRGP";
        info.default_iterations    = "100000 products with A";
        info.needs_definite_matrix = true;
        info.exact                 = false;
        info.warm_start            = true;
        // Its rate is set by the condition number of A + eps I; the
        // projection makes the answer exact anyway.
        info.preferred_regularisation = 1e-2;
        return info;
      }

      void
      solve(const Problem &problem,
            Solution      &solution,
            Report        &report,
            std::ostream  *progress) override;

    private:
      const Parameters options;
    };

    void
    PrimalMprgp::solve(const Problem &problem,
                       Solution      &solution,
                       Report        &report,
                       std::ostream  *progress)
    {
      // ||A|| <= the largest absolute row sum (A is symmetric).
      double norm_A = 0;
      for (Index j = 0; j < problem.size(); ++j)
        {
          double row_sum = 0;
          for (SparseMatrix::InnerIterator it(problem.A, j); it; ++it)
            row_sum += std::abs(it.value());
          norm_A = std::max(norm_A, row_sum);
        }
      unilateral::lcp::Mprgp mprgp([&](const Vector &x,
                                       Vector       &y) { y = problem.A * x; },
                                   problem.b,
                                   problem.full_lower_bound(),
                                   options.step_length /
                                     (norm_A > 0 ? norm_A : 1),
                                   options.gamma);

      const double       scale = problem.b.norm() > 0 ? problem.b.norm() : 1.0;
      const unsigned int limit = iteration_limit(100000);
      unsigned int       step  = 0;
      double             last  = 0;
      const auto         stop  = [&](const double projected_gradient) {
        last = projected_gradient / scale;
        if (progress != nullptr && step > 0 && (step & (step - 1)) == 0)
          *progress << "    mprgp iteration " << step
                    << ": relative projected gradient " << last << std::endl;
        ++step;
        return last <= options.tolerance;
      };
      if (solution.u.size() != problem.size())
        solution.u = Vector::Zero(problem.size());
      const unilateral::lcp::Mprgp::Outcome outcome =
        mprgp.solve(solution.u, stop, limit);
      report.iterations = mprgp.steps();
      report.counters.matrix_vector_products += mprgp.products();
      switch (outcome)
        {
          case unilateral::lcp::Mprgp::Outcome::converged:
            report.status = Status::converged;
            break;
          case unilateral::lcp::Mprgp::Outcome::iteration_limit:
            report.status  = Status::iteration_limit;
            report.message = "MPRGP reached " + std::to_string(limit) +
                             " iterations with relative projected gradient " +
                             std::to_string(last);
            break;
          case unilateral::lcp::Mprgp::Outcome::not_definite:
            report.status  = Status::singular;
            report.message = "MPRGP: a direction d with d^T A d <= 0, A is "
                             "not positive definite";
            break;
          case unilateral::lcp::Mprgp::Outcome::diverged:
            report.status = Status::singular;
            report.message =
              "MPRGP diverged (a non-finite iterate or curvature d^T A d: "
              "numbers beyond double precision, such as loads or bounds "
              "near 1e150; give them in units nearer to each other, or use "
              "'Solver/Method = pdas')";
            break;
        }
    }
  } // namespace

  UNILATERAL_REGISTER_SOLVER(PrimalMprgp)
} // namespace unilateral::lcp
