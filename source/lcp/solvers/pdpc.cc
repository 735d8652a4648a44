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
 *           solved as (A + diag_S(lambda / s)) du = r + (sigma mu / s - lambda);
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
#include <unilateral/lcp/active_set_system.h>
#include <unilateral/lcp/shifted_system.h>
#include <unilateral/lcp/solver.h>

#include <cmath>
#include <iomanip>
#include <limits>
#include <ostream>
#include <vector>

namespace unilateral::lcp
{
  namespace
  {
    class Pdpc : public Solver
    {
    public:
      using Solver::Solver;

      void
      solve(const Problem &original,
            Solution      &solution,
            Report        &report,
            std::ostream  *progress) override
      {
        const Index  n       = original.size();
        const Index  n_c     = original.n_constrained();
        const double epsilon = std::numeric_limits<double>::epsilon();

        // Diagonal scaling: u = D u_hat with D = diag(A)^-1/2.
        Vector scale = Vector::Ones(n);
        if (parameters.pdpc.diagonal_scaling)
          for (Index i = 0; i < n; ++i)
            if (original.A.coeff(i, i) > 0)
              scale[i] = 1.0 / std::sqrt(original.A.coeff(i, i));
        Problem problem = original;
        problem.A       = scale.asDiagonal() * original.A * scale.asDiagonal();
        problem.A.makeCompressed();
        problem.b = scale.cwiseProduct(original.b);
        for (Index k = 0; k < n_c; ++k)
          problem.lower_bound[k] /= scale[original.constrained[k]];

        const bool   default_gap = !(parameters.pdpc.tolerance_gap > 0);
        const double tol_gap     = default_gap ? epsilon :
                                                 parameters.pdpc.tolerance_gap;
        const double paper_gap   = std::max(n_c, 1) * epsilon;
        std::vector<double> recent_mu; // the mean products so far
        const double tol_residual =
          parameters.pdpc.tolerance_residual > 0 ?
            parameters.pdpc.tolerance_residual :
            n * std::sqrt(epsilon);
        const double to_boundary = parameters.pdpc.step_to_boundary;

        // Starting point: u0 = eps e (slacks eps on S), lambda0 = eps e.
        const double start = parameters.pdpc.initial_point;
        Vector       u     = Vector::Constant(n, start);
        Vector       slack(n_c), lambda(n_c);
        for (Index k = 0; k < n_c; ++k)
          {
            u[problem.constrained[k]] = problem.lower_bound[k] + start;
            slack[k]                  = start;
            lambda[k]                 = start;
          }

        ShiftedSystem newton(problem.A, report.counters);
        Vector        shift = Vector::Zero(n), rhs(n), du(n), dlambda(n_c);
        const unsigned int limit = iteration_limit(500);
        for (unsigned int iteration = 0;; ++iteration)
          {
            // r = b - A u + lambda (on S).
            const Vector Au = problem.A * u;
            Vector       r  = problem.b - Au;
            ++report.counters.matrix_vector_products;
            for (Index k = 0; k < n_c; ++k)
              r[problem.constrained[k]] += lambda[k];
            const double gap      = slack.dot(lambda);
            const double mu       = n_c > 0 ? gap / n_c : 0.0;
            const double residual = r.norm();
            // tol2 is absolute; never ask for less than the rounding floor
            // of the residual (epsilon times the terms that cancel).
            const double floor =
              100 * epsilon *
              (Au.norm() + problem.b.norm() + lambda.norm());
            if (!std::isfinite(residual) || !std::isfinite(gap))
              {
                report.status  = Status::singular;
                report.message = "PDPC broke down (non-finite iterate) at "
                                 "iteration " +
                                 std::to_string(iteration);
                break;
              }
            if (progress != nullptr && iteration > 0)
              *progress << "    pdpc iteration " << iteration
                        << std::scientific << std::setprecision(2)
                        << ": mu " << mu << ", residual " << residual
                        << std::defaultfloat << std::endl;
            recent_mu.push_back(mu);
            const std::size_t seen = recent_mu.size();
            const bool        gap_at_floor =
              default_gap && mu <= paper_gap && seen > 4 &&
              mu > 0.5 * recent_mu[seen - 5];
            if ((mu <= tol_gap || gap_at_floor) &&
                residual <= std::max(tol_residual, floor))
              {
                report.status = Status::converged;
                break;
              }
            if (iteration >= limit)
              {
                report.status  = Status::iteration_limit;
                report.message = "PDPC reached " + std::to_string(limit) +
                                 " iterations (mu " + std::to_string(mu) +
                                 ", residual " + std::to_string(residual) +
                                 ")";
                break;
              }
            report.iterations = iteration + 1;

            // Step 3: odd iterations predict, even ones correct.
            const double sigma = ((iteration + 1) % 2 == 1) ? 0.0 : 0.99;

            // Step 4.
            rhs = r;
            for (Index k = 0; k < n_c; ++k)
              {
                const Index i = problem.constrained[k];
                shift[i]      = lambda[k] / slack[k];
                rhs[i] += sigma * mu / slack[k] - lambda[k];
              }
            if (!newton.factorise(shift))
              {
                report.status  = Status::singular;
                report.message = "PDPC Step 4: the Newton system is singular "
                                 "at iteration " +
                                 std::to_string(iteration + 1) +
                                 " (A_EE singular, or round-off; keep "
                                 "'Diagonal scaling' on)";
                break;
              }
            newton.solve(rhs, du);
            double ds_dlambda = 0;
            double alpha_1 = 1, alpha_2 = 1;
            for (Index k = 0; k < n_c; ++k)
              {
                const double ds = du[problem.constrained[k]];
                dlambda[k] =
                  (sigma * mu - slack[k] * lambda[k] - lambda[k] * ds) /
                  slack[k];
                ds_dlambda += ds * dlambda[k];
                if (ds < 0)
                  alpha_1 = std::min(alpha_1, -slack[k] / ds);
                if (dlambda[k] < 0)
                  alpha_2 = std::min(alpha_2, -lambda[k] / dlambda[k]);
              }

            // Step 5.
            double alpha = std::min(alpha_1, alpha_2);
            if (alpha < 1)
              alpha *= to_boundary;
            if (ds_dlambda > 0)
              alpha = std::min(alpha,
                               0.99 * (1 - sigma) * gap / ds_dlambda);
            u += alpha * du;
            for (Index k = 0; k < n_c; ++k)
              {
                slack[k] += alpha * du[problem.constrained[k]];
                lambda[k] += alpha * dlambda[k];
              }
            if (!(alpha > 0) || !std::isfinite(alpha))
              {
                report.status  = Status::singular;
                report.message = "PDPC Step 5: no progress possible (step " +
                                 std::to_string(alpha) + ") at iteration " +
                                 std::to_string(iteration + 1);
                break;
              }
          }
        // Undo the scaling; keep u consistent with the slacks.
        for (Index k = 0; k < n_c; ++k)
          u[problem.constrained[k]] = problem.lower_bound[k] + slack[k];
        solution.u = scale.cwiseProduct(u);
        // The projection's systems have A's pattern: order them as here.
        solution.factor = ActiveSetFactor::ordering_only(newton.ordering());
      }
    };
  } // namespace

  UNILATERAL_REGISTER_SOLVER(Pdpc,
                             "pdpc",
                             "primal-dual predictor-corrector interior point "
                             "(Ainsworth & Mihai), with diagonal scaling",
                             false,
                             false,
                             false,
                             0,
                             false)
} // namespace unilateral::lcp
