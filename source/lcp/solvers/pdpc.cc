/**
 * Primal-dual predictor-corrector method of Ainsworth & Mihai (Section 4,
 * "PDPC"; after Wright and Portugal et al.), on A itself (no
 * regularisation), with their diagonal scaling (A to unit diagonal).
 *
 * In our signs (lambda = -Sigma >= 0, slack s = u_S - l_S >= 0):
 *   Step 2: stop if s^T lambda / n_c < tol1 and ||b - A u + lambda||_2 < tol2;
 *   Step 3: mu = s^T lambda / n_c; sigma = 0 on odd iterations (predictor),
 *           0.99 on even ones (corrector);
 *   Step 4: the Newton system
 *             A du - dlambda = b - A u + lambda          (on S; = on E)
 *             lambda_i du_i + s_i dlambda_i = sigma mu - s_i lambda_i,
 *           solved as
 *             (A + diag_S(lambda / s)) du = r + (sigma mu / s - lambda);
 *           (the paper prints the right-hand side of the last equation with
 *           the opposite sign; this is the Newton direction towards
 *           s_i lambda_i = sigma mu, which the step rule of Step 5 assumes)
 *   Step 5: alpha_1, alpha_2 = largest steps in [0, 1] keeping s, lambda >= 0;
 *           if ds^T dlambda > 0 also alpha_3 = 0.99 (1 - sigma) s^T lambda /
 *           ds^T dlambda; alpha = min of them.
 * Default tol1 (parameter 'Complementarity tolerance' = 0): the paper's
 * n_c * machine epsilon bounds the mean product, so the total s^T lambda can
 * reach n_c^2 epsilon (1e-5 on the m = 225 running bond wall), which leaves
 * the iterate too far from the answer for the projection to finish it. We
 * bound the total by n_c epsilon (mean <= epsilon); once the paper's bound
 * is met, a mean that no longer halves in four iterations has reached its
 * rounding floor and stops the method too (the mean falls about twofold in
 * two iterations before that: every other step is a centring one).
 * Safeguard (parameter 'Step to boundary', default 0.9995): a step limited by
 * alpha_1 or alpha_2 < 1 is shortened by that factor, because landing exactly
 * on the boundary (the printed rule) makes the next Newton system singular,
 * the "unsolvable Step 4" the paper reports. 1 reproduces the printed rule.
 */
#include <unilateral/base/input_error.h>
#include <unilateral/lcp/active_set_system.h>
#include <unilateral/lcp/shifted_system.h>
#include <unilateral/lcp/solver.h>

#include <deal.II/base/parameter_handler.h>

#include <cmath>
#include <iomanip>
#include <limits>
#include <ostream>
#include <sstream>
#include <vector>

namespace unilateral::lcp
{
  namespace
  {
    /// Subsection "Solver/PDPC".
    class PdpcParameters : public MethodParametersBase<PdpcParameters>
    {
    public:
      double initial_point      = 1e-2; ///< u0 = eps e, Sigma0 = -eps e
      double tolerance_gap      = 0;    ///< tol1; 0: see its help
      double tolerance_residual = 0;    ///< tol2; 0: n * sqrt(epsilon)
      bool   diagonal_scaling   = true;
      /// Fraction of a step to the boundary that is taken (1: the paper).
      double step_to_boundary = 0.9995;

      void
      add_parameters(dealii::ParameterHandler &prm) override
      {
        using namespace dealii::Patterns;
        prm.add_parameter(
          "Initial point",
          initial_point,
          "u0 = eps e, Sigma0 = -eps e (slacks and multipliers of the scaled "
          "problem); Ainsworth & Mihai take eps in (1e-6, 1e-2). The upper "
          "end is the default: a smaller eps starts almost on the "
          "complementarity surface but far from feasibility, and every step "
          "is then cut short by a bound (on a 16129-unknown obstacle "
          "problem 1e-6 takes 185 iterations, 1e-2 takes 29).",
          Double(0));
        prm.add_parameter(
          "Complementarity tolerance",
          tolerance_gap,
          "tol1 on |Sigma_S^T u_S| / n_c; 0: the total |Sigma_S^T u_S| within "
          "n_c * machine epsilon (the paper's tol1 on the mean lets large "
          "walls stop too far from the answer for the projection), or the "
          "mean within the paper's n_c * machine epsilon once it no longer "
          "halves in four iterations (its rounding floor).",
          Double(0));
        prm.add_parameter("Residual tolerance",
                          tolerance_residual,
                          "tol2 on ||b - A u - Sigma||_2; 0 takes n * "
                          "sqrt(machine epsilon) (scaled problem).",
                          Double(0));
        prm.add_parameter("Diagonal scaling",
                          diagonal_scaling,
                          "Scale A to unit diagonal first, as Ainsworth & "
                          "Mihai do to keep Step 4 solvable.",
                          Bool());
        prm.add_parameter(
          "Step to boundary",
          step_to_boundary,
          "A step cut short by a bound (alpha_1 or alpha_2 < 1) is "
          "multiplied by this factor so the iterate stays strictly interior. "
          "1 is the printed rule, which can land exactly on the boundary and "
          "make Step 4 singular.",
          Double(0, 1));
      }

      void
      check(const std::string &section) const override
      {
        check_parameter(step_to_boundary > 0,
                        section,
                        "Step to boundary",
                        step_to_boundary,
                        "must be in (0, 1]");
        check_parameter(initial_point > 0,
                        section,
                        "Initial point",
                        initial_point,
                        "must be > 0 (interior start)");
      }
    };

    class Pdpc : public Solver
    {
    public:
      using Parameters = PdpcParameters;

      Pdpc(const SolverParameters &parameters, const Parameters &options)
        : Solver(parameters)
        , options(options)
      {}

      static SolverInfo
      properties()
      {
        SolverInfo info;
        info.name        = "pdpc";
        info.label       = "PDPC";
        info.description = "primal-dual predictor-corrector interior point "
                           "(Ainsworth & Mihai), with diagonal scaling";
        info.subsection  = "PDPC";
        info.default_iterations = "500";
        info.exact              = false;
        // Its Newton system turns singular where the solutions are not
        // unique (A = [1 1; 1 1], b = (1, 1): the segment u1 + u2 = 1) or
        // the iterate breaks down; that says nothing about the LCP, so
        // "singular" is checked by PDAS, which solves it or proves that
        // there is no solution (a review).
        FollowUp check;
        check.kind   = FollowUp::Kind::verification;
        check.when   = Status::singular;
        check.method = "pdas";
        info.follow_ups.push_back(check);
        return info;
      }

      void
      solve(const Problem &original,
            Solution      &solution,
            Report        &report,
            std::ostream  *progress) override;

    private:
      const Parameters options;
    };

    /// u = D u_hat with D = diag(A)^-1/2 (or I): the problem in u_hat.
    Problem
    scaled(const Problem &original, const Vector &scale)
    {
      Problem problem = original;
      problem.A       = scale.asDiagonal() * original.A * scale.asDiagonal();
      problem.A.makeCompressed();
      problem.b = scale.cwiseProduct(original.b);
      for (Index k = 0; k < original.n_constrained(); ++k)
        problem.lower_bound[k] /= scale[original.constrained[k]];
      return problem;
    }

    /**
     * The state of one PDPC solve on the scaled problem: u, the slacks s
     * and multipliers lambda on S, and the Newton system of Step 4. Each
     * step is one member function.
     */
    class PdpcIterate
    {
    public:
      PdpcIterate(const Problem        &problem,
                  const PdpcParameters &options,
                  Report               &report)
        : problem(problem)
        , options(options)
        , report(report)
        , n_c(problem.n_constrained())
        , default_gap(!(options.tolerance_gap > 0))
        , tol_gap(default_gap ? epsilon : options.tolerance_gap)
        , paper_gap(std::max(n_c, 1) * epsilon)
        , tol_residual(options.tolerance_residual > 0 ?
                         options.tolerance_residual :
                         problem.size() * std::sqrt(epsilon))
        , u(Vector::Constant(problem.size(), options.initial_point))
        , slack(Vector::Constant(n_c, options.initial_point))
        , lambda(Vector::Constant(n_c, options.initial_point))
        , newton(problem.A, report.counters)
        , shift(Vector::Zero(problem.size()))
        , du(problem.size())
        , dlambda(n_c)
      {
        // Starting point: u0 = eps e (slacks eps on S), lambda0 = eps e.
        for (Index k = 0; k < n_c; ++k)
          u[problem.constrained[k]] =
            problem.lower_bound[k] + options.initial_point;
      }

      /// r = b - A u + lambda (on S), s^T lambda, mu and ||r||_2.
      void
      residual()
      {
        const Vector Au = problem.A * u;
        r               = problem.b - Au;
        ++report.counters.matrix_vector_products;
        for (Index k = 0; k < n_c; ++k)
          r[problem.constrained[k]] += lambda[k];
        gap           = slack.dot(lambda);
        mu            = n_c > 0 ? gap / n_c : 0.0;
        residual_norm = r.norm();
        // tol2 is absolute; never ask for less than the rounding floor of
        // the residual (epsilon times the terms that cancel).
        floor = 100 * epsilon * (Au.norm() + problem.b.norm() + lambda.norm());
      }

      /// Step 2, with the default tol1 (see above): a mean that no longer
      /// halves in four iterations, below the paper's bound, is at its
      /// rounding floor.
      bool
      converged()
      {
        recent_mu.push_back(mu);
        const std::size_t seen  = recent_mu.size();
        const bool gap_at_floor = default_gap && mu <= paper_gap && seen > 4 &&
                                  mu > 0.5 * recent_mu[seen - 5];
        return (mu <= tol_gap || gap_at_floor) &&
               residual_norm <= std::max(tol_residual, floor);
      }

      /// Step 4: the Newton direction towards s_i lambda_i = sigma mu; false
      /// if its system is singular.
      bool
      newton_direction(const double sigma)
      {
        Vector rhs = r;
        for (Index k = 0; k < n_c; ++k)
          {
            const Index i = problem.constrained[k];
            shift[i]      = lambda[k] / slack[k];
            rhs[i] += sigma * mu / slack[k] - lambda[k];
          }
        if (!newton.factorise(shift))
          return false;
        newton.solve(rhs, du);
        for (Index k = 0; k < n_c; ++k)
          dlambda[k] = (sigma * mu - slack[k] * lambda[k] -
                        lambda[k] * du[problem.constrained[k]]) /
                       slack[k];
        return true;
      }

      /**
       * Step 5: alpha_1, alpha_2 keep s, lambda >= 0 (shortened by 'Step to
       * boundary' where they cut the step), alpha_3 where ds^T dlambda > 0;
       * the step taken, whose length is returned.
       */
      double
      step(const double sigma)
      {
        double       ds_dlambda = 0;
        const double unlimited  = std::numeric_limits<double>::infinity();
        double       alpha_1 = unlimited, alpha_2 = unlimited;
        for (Index k = 0; k < n_c; ++k)
          {
            const double ds = du[problem.constrained[k]];
            ds_dlambda += ds * dlambda[k];
            if (ds < 0)
              alpha_1 = std::min(alpha_1, -slack[k] / ds);
            if (dlambda[k] < 0)
              alpha_2 = std::min(alpha_2, -lambda[k] / dlambda[k]);
          }
        // Shortened wherever a bound limits the full step, the full step
        // too: a predictor that lands exactly on the boundary (alpha_1 = 1
        // for a contact whose Newton step closes it exactly, as where A is
        // diagonal) leaves a zero slack, and the next Newton system divides
        // by it (a review: NaN after 45 iterations on A = I, b = (1, 0, -1)).
        const double blocking = std::min(alpha_1, alpha_2);
        double       alpha =
          blocking <= 1 ? blocking * options.step_to_boundary : 1.0;
        if (ds_dlambda > 0)
          alpha = std::min(alpha, 0.99 * (1 - sigma) * gap / ds_dlambda);
        u += alpha * du;
        for (Index k = 0; k < n_c; ++k)
          {
            slack[k] += alpha * du[problem.constrained[k]];
            lambda[k] += alpha * dlambda[k];
          }
        return alpha;
      }

      /// The answer in the original variables, u consistent with the
      /// slacks, and the analysis of the Newton matrix for the projection's
      /// systems (they have A's pattern). Once, at the end: the Newton
      /// matrix is left without its factor.
      void
      finish(const Vector &scale, Solution &solution)
      {
        for (Index k = 0; k < n_c; ++k)
          u[problem.constrained[k]] = problem.lower_bound[k] + slack[k];
        solution.u      = scale.cwiseProduct(u);
        solution.factor = newton.hand_over_analysis();
      }

      /// Of the last residual(): s^T lambda / n_c and ||r||_2.
      double mu = 0, residual_norm = 0;

    private:
      static constexpr double epsilon = std::numeric_limits<double>::epsilon();

      const Problem        &problem;
      const PdpcParameters &options;
      Report               &report;
      const Index           n_c;
      const bool            default_gap;
      const double          tol_gap, paper_gap, tol_residual;
      Vector                u, slack, lambda;
      ShiftedSystem         newton;
      Vector                shift, r, du, dlambda;
      double                gap = 0, floor = 0;
      std::vector<double>   recent_mu; ///< the mean products so far
    };

    void
    Pdpc::solve(const Problem &original,
                Solution      &solution,
                Report        &report,
                std::ostream  *progress)
    {
      const Index n     = original.size();
      Vector      scale = Vector::Ones(n);
      if (options.diagonal_scaling)
        for (Index i = 0; i < n; ++i)
          if (original.A.coeff(i, i) > 0)
            scale[i] = 1.0 / std::sqrt(original.A.coeff(i, i));
      const Problem problem = scaled(original, scale);
      PdpcIterate   pdpc(problem, options, report);

      const unsigned int limit = iteration_limit(500);
      for (unsigned int iteration = 0;; ++iteration)
        {
          pdpc.residual();
          if (!std::isfinite(pdpc.residual_norm) || !std::isfinite(pdpc.mu))
            {
              report.status  = Status::singular;
              report.message = "PDPC broke down (non-finite iterate) at "
                               "iteration " +
                               std::to_string(iteration);
              break;
            }
          if (progress != nullptr && iteration > 0)
            *progress << "    pdpc iteration " << iteration << std::scientific
                      << std::setprecision(2) << ": mu " << pdpc.mu
                      << ", residual " << pdpc.residual_norm
                      << std::defaultfloat << std::endl;
          // Step 2.
          if (pdpc.converged())
            {
              report.status = Status::converged;
              break;
            }
          if (iteration >= limit)
            {
              report.status = Status::iteration_limit;
              std::ostringstream message;
              message << std::setprecision(3) << "PDPC reached " << limit
                      << " iterations (mu " << pdpc.mu << ", residual "
                      << pdpc.residual_norm << ")";
              report.message = message.str();
              break;
            }
          report.iterations = iteration + 1;

          // Step 3: odd iterations predict, even ones correct.
          const double sigma = ((iteration + 1) % 2 == 1) ? 0.0 : 0.99;
          // Step 4.
          if (!pdpc.newton_direction(sigma))
            {
              report.status  = Status::singular;
              report.message = "PDPC Step 4: the Newton system is singular "
                               "at iteration " +
                               std::to_string(iteration + 1) +
                               " (A_EE singular, or round-off; keep "
                               "'Diagonal scaling' on)";
              break;
            }
          // Step 5.
          const double alpha = pdpc.step(sigma);
          if (!(alpha > 0) || !std::isfinite(alpha))
            {
              report.status  = Status::singular;
              report.message = "PDPC Step 5: no progress possible (step " +
                               std::to_string(alpha) + ") at iteration " +
                               std::to_string(iteration + 1);
              break;
            }
        }
      pdpc.finish(scale, solution);
    }
  } // namespace

  UNILATERAL_REGISTER_SOLVER(Pdpc)
} // namespace unilateral::lcp
