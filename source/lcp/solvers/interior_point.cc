/**
 * The interior-point method of Fernandes, Figueiredo & Judice (2002), Section
 * 3.1, for the MLCP (32)-(35): w = C z - F, z_J1 >= psi, w_J1 >= 0, w_Jf = 0.
 * In our notation z = u, w = lambda, psi = l, J1 = S, Jf = the rest.
 *   mu_k  = delta (z - psi)^T w / |J1|                                  (42)
 *   (C + diag_J1(w / (z - psi))) du = F - C z + mu_k / (z - psi)        (47)
 *   dw_i  = mu_k / (z_i - psi_i) - w_i (1 + du_i / (z_i - psi_i))
 *     (the printed (47) has w_J1 + F_J1 - C_J1 z on the right; eliminating
 *     v from the Newton system (46) with the printed dw gives no w there, and
 *     with it the iterates never become feasible: a typo, not repeated here)
 *   alpha = min(1, beta alpha_max), alpha_max the largest step keeping
 *           z - psi >= 0 and w >= 0                                  (50)-(51)
 *   stop when ||C z - F - w||_2 <= eps_1 and (z - psi)^T w <= eps_2 (55)-(56)
 * Starting point (66): z0 = 0, w0_i = max(10, -F_i) on J1. Where psi_i >= 0
 * the point z0 = 0 is not interior; there we start at psi_i + max(1, |psi|_inf)
 * (the paper's obstacles are all negative, so its runs are unaffected).
 * beta = 0.99995 as in the paper; delta is not stated there (default 0.1).
 *
 * eps_1 is absolute, and ||C z - F - w|| cannot fall below its rounding
 * floor, about machine epsilon times the size of the terms that cancel
 * (||C z|| + ||F|| + ||w||): 1.4e-10 for the paper's 20 x 20 steel plate in
 * kg and mm, above eps_1 = 1e-10. The test (55) therefore accepts a residual
 * at that floor (100 epsilon times those terms), or one that has stopped
 * falling for three steps with the gap met (the floor is higher on larger
 * meshes); the final KKT check of the driver still judges the answer. A
 * non-finite iterate ends the run as a breakdown instead of iterating on.
 *
 * Variant predictor-corrector (Mehrotra, as in Wright, "Primal-Dual
 * Interior-Point Methods", ch. 10, for the LCP): Mehrotra's starting point
 * instead of (66) (see mehrotra_start); per iteration, one
 * factorisation of the matrix of (47) and two solves, an affine step
 * (delta = 0) that sets delta = (gap after it / gap)^3, and a corrected
 * step with the affine step's second-order term. One step length for z and
 * w, as (50) (the LCP couples them). Then up to 'Centrality correctors' of
 * Gondzio ("Multiple centrality corrections in a primal-dual method for
 * linear programming", 1996): at the trial step min(1, 1.5 alpha) the
 * products (z - psi)_i w_i outside [0.1, 10] sigma mu are aimed back into
 * that band by one more solve each; a corrector stays only if it lengthens
 * the step by 1 %. On the running bond walls the affine step is cut to
 * 0.2-0.5 by a few badly centred products in every iteration, and the
 * correctors save a fifth of the factorisations (m = 100: 22 -> 18 from
 * Mehrotra's start, 28 -> 23 from (66)).
 */
#include <unilateral/lcp/active_set_system.h>
#include <unilateral/lcp/shifted_system.h>
#include <unilateral/lcp/solver.h>

#include <cmath>
#include <iomanip>
#include <limits>
#include <ostream>

namespace unilateral::lcp
{
  namespace
  {
    class InteriorPoint : public Solver
    {
    public:
      using Solver::Solver;

      /**
       * Mehrotra's starting point, for the LCP: z from the Newton matrix
       * with a shift of a hundredth of A's diagonal on S, pulled towards
       * psi there (A z - b = D (psi - z) on S, zero elsewhere: z near the
       * unconstrained minimiser). Its slack z - psi and multiplier
       * A z - b on S are moved into the positive orthant by 1.5 times their
       * most negative entries, then each by half the complementarity over
       * the other's sum, so that no product is tiny against the rest.
       * Running bond m = 100: 18 iterations instead of 23 (m = 225: 20
       * instead of 25), for the one factorisation it costs. Keeps start
       * (66) if that matrix is not positive definite.
       */
      static void
      mehrotra_start(const Problem &problem,
                     ShiftedSystem &newton,
                     Vector        &z,
                     Vector        &gap,
                     Vector        &w)
      {
        const Index   n_c = problem.n_constrained();
        const Vector &psi = problem.lower_bound;
        if (n_c == 0)
          return;
        Vector shift = Vector::Zero(problem.size());
        Vector rhs   = problem.b;
        for (Index k = 0; k < n_c; ++k)
          {
            const Index i = problem.constrained[k];
            shift[i]      = 1e-2 * problem.A.coeff(i, i);
            rhs[i] += shift[i] * psi[k];
          }
        Vector start;
        if (!newton.factorise(shift))
          return;
        newton.solve(rhs, start);
        const Vector multiplier = problem.A * start - problem.b;
        Vector       slack(n_c), lambda(n_c);
        for (Index k = 0; k < n_c; ++k)
          {
            slack[k]  = start[problem.constrained[k]] - psi[k];
            lambda[k] = multiplier[problem.constrained[k]];
          }
        slack.array() += std::max(0.0, -1.5 * slack.minCoeff());
        lambda.array() += std::max(0.0, -1.5 * lambda.minCoeff());
        const double products = slack.dot(lambda);
        if (!(products > 0) || !std::isfinite(products))
          return;
        gap = slack.array() + 0.5 * products / lambda.sum();
        w   = lambda.array() + 0.5 * products / slack.sum();
        z   = start;
        for (Index k = 0; k < n_c; ++k)
          z[problem.constrained[k]] = psi[k] + gap[k];
      }

      void
      solve(const Problem &problem,
            Solution      &solution,
            Report        &report,
            std::ostream  *progress) override
      {
        const Index n   = problem.size();
        const Index n_c = problem.n_constrained();
        const auto &options = parameters.interior_point;
        const Vector &psi   = problem.lower_bound;

        // Starting point (66).
        const double psi_size =
          n_c > 0 ? std::max(1.0, psi.lpNorm<Eigen::Infinity>()) : 1.0;
        Vector z = Vector::Zero(n);
        Vector gap(n_c), w(n_c);
        for (Index k = 0; k < n_c; ++k)
          {
            const Index i = problem.constrained[k];
            if (!(psi[k] < 0))
              z[i] = psi[k] + psi_size;
            gap[k] = z[i] - psi[k];
            w[k]   = std::max(10.0, -problem.b[i]);
          }

        ShiftedSystem newton(problem.A, report.counters);
        Vector        shift = Vector::Zero(n), rhs(n), du(n), dw(n_c);
        if (options.predictor_corrector)
          mehrotra_start(problem, newton, z, gap, w);
        const unsigned int limit = iteration_limit(500);
        double previous_infeasibility = std::numeric_limits<double>::infinity();
        unsigned int steps_at_floor   = 0;
        for (unsigned int k = 0;; ++k)
          {
            // r = F - C z + w: minus the linear infeasibility (49).
            const Vector Az = problem.A * z;
            Vector       r  = problem.b - Az;
            ++report.counters.matrix_vector_products;
            for (Index j = 0; j < n_c; ++j)
              r[problem.constrained[j]] += w[j];
            const double complementarity = gap.dot(w);
            const double infeasibility   = r.norm();
            // The rounding floor of the infeasibility (see above).
            const double floor =
              100 * std::numeric_limits<double>::epsilon() *
              (Az.norm() + problem.b.norm() + w.norm());
            if (!std::isfinite(infeasibility) || !std::isfinite(complementarity))
              {
                report.status  = Status::singular;
                report.message = "interior point broke down (non-finite "
                                 "iterate) at iteration " +
                                 std::to_string(k);
                break;
              }
            if (progress != nullptr && k > 0)
              *progress << "    interior point iteration " << k
                        << std::scientific << std::setprecision(2)
                        << ": gap " << complementarity << ", infeasibility "
                        << infeasibility << std::defaultfloat << std::endl;
            // At its floor the infeasibility stops falling while the gap
            // keeps shrinking tenfold per step, down to 1e-300 and NaN (90 x
            // 90 plate: stuck at 1.1e-9 from iteration 20 on, broke down at
            // 363). Three steps in a row that do not halve it, with the gap
            // met, are that floor: stop, and let the driver's relative KKT
            // check judge the iterate.
            if (complementarity <= options.complementarity_tolerance &&
                infeasibility > 0.5 * previous_infeasibility)
              ++steps_at_floor;
            else
              steps_at_floor = 0;
            previous_infeasibility = infeasibility;
            if ((infeasibility <= std::max(options.residual_tolerance, floor) ||
                 steps_at_floor >= 3) &&
                complementarity <= options.complementarity_tolerance)
              {
                report.status = Status::converged;
                break;
              }
            if (k >= limit)
              {
                report.status  = Status::iteration_limit;
                report.message = "interior point reached " +
                                 std::to_string(limit) + " iterations (gap " +
                                 std::to_string(complementarity) +
                                 ", infeasibility " +
                                 std::to_string(infeasibility) + ")";
                break;
              }
            report.iterations = k + 1;

            // (47): K du = r + E (c / (z - psi) - w),
            //       dw = c / (z - psi) - w (1 + du_J1 / (z - psi)),
            // with K = C + diag_J1(w / (z - psi)), for the centring term c of
            // the complementarity rows (z - psi) w = c: mu_k in the paper's
            // method.
            for (Index j = 0; j < n_c; ++j)
              shift[problem.constrained[j]] = w[j] / gap[j];
            if (!newton.factorise(shift))
              {
                report.status  = Status::singular;
                report.message = "interior point: the matrix of (47) is not "
                                 "positive definite at iteration " +
                                 std::to_string(k + 1) +
                                 " (C_JfJf singular?)";
                break;
              }
            const auto direction = [&](const Vector &centring) {
              rhs = r;
              for (Index j = 0; j < n_c; ++j)
                rhs[problem.constrained[j]] += centring[j] / gap[j] - w[j];
              newton.solve(rhs, du);
              for (Index j = 0; j < n_c; ++j)
                dw[j] = centring[j] / gap[j] -
                        w[j] * (1 + du[problem.constrained[j]] / gap[j]);
            };
            // (51): the largest step keeping z - psi >= 0 and w >= 0.
            const auto largest_step = [&]() {
              double alpha_max = std::numeric_limits<double>::infinity();
              for (Index j = 0; j < n_c; ++j)
                {
                  const double dz = du[problem.constrained[j]];
                  if (dz < 0)
                    alpha_max = std::min(alpha_max, gap[j] / -dz);
                  if (dw[j] < 0)
                    alpha_max = std::min(alpha_max, w[j] / -dw[j]);
                }
              return alpha_max;
            };
            // Gondzio's correctors to the direction of @p centring, whose
            // step is @p step; returns the step of the direction kept.
            const auto correct_centrality = [&](Vector      &centring,
                                                const double target,
                                                double       step) {
              // The band the products are aimed at.
              const double low = 0.1 * target, high = 10 * target;
              Vector       kept_du, kept_dw;
              for (unsigned int c = 0;
                   c < options.centrality_correctors && step < 1;
                   ++c)
                {
                  const double trial = std::min(1.0, 1.5 * step);
                  for (Index j = 0; j < n_c; ++j)
                    {
                      const double product =
                        (gap[j] + trial * du[problem.constrained[j]]) *
                        (w[j] + trial * dw[j]);
                      // Raise small products to the band, lower large ones
                      // by at most its top.
                      if (product < low)
                        centring[j] += low - product;
                      else if (product > high)
                        centring[j] += std::max(high - product, -high);
                    }
                  kept_du = du;
                  kept_dw = dw;
                  direction(centring);
                  const double corrected = largest_step();
                  if (corrected < 1.01 * step)
                    {
                      du = std::move(kept_du);
                      dw = std::move(kept_dw);
                      break;
                    }
                  ++report.counters.centrality_correctors;
                  step = corrected;
                }
              return step;
            };
            Vector centring(n_c);
            // sigma mu: the mean product the centring aims at.
            double target = 0;
            if (!options.predictor_corrector)
              // (42): mu_k = delta (z - psi)^T w / |J1|.
              centring.setConstant(
                n_c > 0 ? options.centering * complementarity / n_c : 0.0);
            else
              {
                // Mehrotra: the affine step (c = 0) measures how far the
                // gap can fall; the centring is the cube of that fraction,
                // and the corrector subtracts the second-order term ds dw
                // the affine step ignores.
                centring.setZero();
                direction(centring);
                const double alpha_affine = std::min(1.0, largest_step());
                double       affine_complementarity = 0;
                for (Index j = 0; j < n_c; ++j)
                  affine_complementarity +=
                    (gap[j] + alpha_affine * du[problem.constrained[j]]) *
                    (w[j] + alpha_affine * dw[j]);
                const double sigma = std::min(
                  1.0, std::pow(affine_complementarity / complementarity, 3));
                target = sigma * complementarity / n_c;
                for (Index j = 0; j < n_c; ++j)
                  centring[j] = target - du[problem.constrained[j]] * dw[j];
              }
            direction(centring);
            double step = largest_step();
            if (options.predictor_corrector)
              step = correct_centrality(centring, target, step);
            // (50).
            const double alpha = std::min(1.0, options.step_factor * step);

            // (54).
            z += alpha * du;
            for (Index j = 0; j < n_c; ++j)
              {
                gap[j] += alpha * du[problem.constrained[j]];
                w[j] += alpha * dw[j];
              }
          }
        for (Index j = 0; j < n_c; ++j)
          z[problem.constrained[j]] = psi[j] + gap[j];
        solution.u = z;
        // The projection's systems have A's pattern: order them as here.
        solution.factor = ActiveSetFactor::ordering_only(newton.ordering());
      }
    };
  } // namespace

  UNILATERAL_REGISTER_SOLVER(InteriorPoint,
                             "interior_point",
                             "interior-point method of Fernandes, Figueiredo "
                             "& Judice (eqs. 42-56, start 66)",
                             false,
                             false,
                             false,
                             0,
                             false)
} // namespace unilateral::lcp
