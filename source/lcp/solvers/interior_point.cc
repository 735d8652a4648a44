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
 * (||C z|| + ||F|| + ||w||), which on the paper's plates in kg and mm lies
 * above eps_1 = 1e-10 already at 20 x 20 (benchmarks/plate_tables/README.md,
 * "Iterations and time"). The test (55) therefore accepts a residual
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
 * the step by 1 %. On the running bond walls a few badly centred
 * products cut the affine step short in nearly every iteration; the
 * correctors, one solve each with the iteration's factor, save
 * factorisations (benchmarks/masonry_tables/README.md, "Design
 * measurements").
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

namespace unilateral::lcp
{
  namespace
  {
    /// Subsection "Solver/Interior point".
    class InteriorPointParameters
      : public MethodParametersBase<InteriorPointParameters>
    {
    public:
      double centering                 = 0.1;     ///< delta in (42)
      double step_factor               = 0.99995; ///< beta in (50)
      double residual_tolerance        = 1e-10;   ///< epsilon_1 in (55)
      double complementarity_tolerance = 1e-8;    ///< epsilon_2 in (56)
      /// "basic" or "predictor-corrector".
      std::string variant = "basic";
      /// Gondzio's centrality correctors per predictor-corrector iteration.
      unsigned int centrality_correctors = 2;

      bool
      predictor_corrector() const
      {
        return variant == "predictor-corrector";
      }

      void
      add_parameters(dealii::ParameterHandler &prm) override
      {
        using namespace dealii::Patterns;
        prm.add_parameter("Centering",
                          centering,
                          "delta in (0, 1) of mu_k = delta gap / |J1| (eq. "
                          "42 of Fernandes et al., who do not state its "
                          "value).",
                          Double(0, 1));
        prm.add_parameter("Step factor",
                          step_factor,
                          "beta of the step alpha = min(1, beta alpha_max) "
                          "(eq. 50; the paper takes 0.99995).",
                          Double(0, 1));
        prm.add_parameter("Residual tolerance",
                          residual_tolerance,
                          "epsilon_1 on ||C z - F - w||_2 (eq. 55).",
                          Double(0));
        prm.add_parameter("Complementarity tolerance",
                          complementarity_tolerance,
                          "epsilon_2 on (z - psi)^T w (eq. 56).",
                          Double(0));
        prm.add_parameter(
          "Variant",
          variant,
          "basic: the method of Fernandes et al. (one Newton step per "
          "iteration, centring delta). predictor-corrector: Mehrotra's, which "
          "starts from his heuristic point (one more factorisation), chooses "
          "the centring from an affine step and corrects its second order "
          "term: two solves with one factorisation per iteration, and far "
          "fewer iterations where the solution is degenerate (running bond "
          "walls, where the basic method converges only linearly). The "
          "hand-over from cycling PDAS always uses predictor-corrector.",
          Selection("basic|predictor-corrector"));
        prm.add_parameter(
          "Centrality correctors",
          centrality_correctors,
          "Gondzio's multiple centrality correctors per predictor-corrector "
          "iteration (ignored by the basic variant): each is one more solve "
          "with the iteration's factor that pulls the complementarity "
          "products far from their mean back towards it, and is kept only if "
          "it lengthens the step by 1 %. Where the affine step is short "
          "(degenerate walls) they save factorisations: running bond m = "
          "100, 22 -> 18 iterations. 0: Mehrotra's method alone.",
          Integer(0, 10));
      }

      void
      check(const std::string &section) const override
      {
        check_parameter(centering > 0 && centering < 1,
                        section,
                        "Centering",
                        centering,
                        "must be in (0, 1)");
        check_parameter(step_factor > 0 && step_factor < 1,
                        section,
                        "Step factor",
                        step_factor,
                        "must be in (0, 1)");
      }
    };

    /**
     * The state of one interior-point solve: the iterate (z, its slack
     * gap = z - psi on J1, and w), the Newton matrix of (47) and the
     * direction. Each step of the method is one member function.
     */
    class InteriorPointIterate
    {
    public:
      InteriorPointIterate(const Problem                 &problem,
                           const InteriorPointParameters &options,
                           Report                        &report)
        : problem(problem)
        , options(options)
        , report(report)
        , n_c(problem.n_constrained())
        , z(Vector::Zero(problem.size()))
        , gap(n_c)
        , w(n_c)
        , newton(problem.A, report.counters)
        , shift(Vector::Zero(problem.size()))
        , du(problem.size())
        , dw(n_c)
      {}

      /**
       * Starting point (66): z0 = 0, w0_i = max(10, -F_i); where psi_i >= 0
       * z0 = 0 is not interior, z0_i = psi_i + max(1, |psi|_inf). With the
       * predictor-corrector variant, Mehrotra's point instead.
       */
      void
      start()
      {
        const Vector &psi = problem.lower_bound;
        const double  psi_size =
          n_c > 0 ? std::max(1.0, psi.lpNorm<Eigen::Infinity>()) : 1.0;
        for (Index k = 0; k < n_c; ++k)
          {
            const Index i = problem.constrained[k];
            if (!(psi[k] < 0))
              z[i] = psi[k] + psi_size;
            gap[k] = z[i] - psi[k];
            w[k]   = std::max(10.0, -problem.b[i]);
          }
        if (options.predictor_corrector())
          mehrotra_start(problem, newton, z, gap, w);
      }

      /// r = F - C z + w (minus the linear infeasibility (49)), its norm,
      /// the complementarity (z - psi)^T w, and the infeasibility's
      /// rounding floor.
      void
      residual()
      {
        const Vector Az = problem.A * z;
        r               = problem.b - Az;
        ++report.counters.matrix_vector_products;
        for (Index j = 0; j < n_c; ++j)
          r[problem.constrained[j]] += w[j];
        complementarity = gap.dot(w);
        infeasibility   = r.norm();
        floor           = 100 * std::numeric_limits<double>::epsilon() *
                (Az.norm() + problem.b.norm() + w.norm());
      }

      /**
       * (55)-(56), accepting an infeasibility at its rounding floor. At
       * that floor the infeasibility stops falling while the gap keeps
       * shrinking tenfold per step, down to 1e-300 and NaN: three steps in
       * a row that do not halve it, with the gap met, are that floor; the
       * driver's relative KKT check then judges the iterate.
       */
      bool
      converged()
      {
        const bool gap_met =
          complementarity <= options.complementarity_tolerance;
        if (gap_met && infeasibility > 0.5 * previous_infeasibility)
          ++steps_at_floor;
        else
          steps_at_floor = 0;
        previous_infeasibility = infeasibility;
        return gap_met &&
               (infeasibility <= std::max(options.residual_tolerance, floor) ||
                steps_at_floor >= 3);
      }

      /// The matrix of (47), K = C + diag_J1(w / (z - psi)), factorised;
      /// false if it is not positive definite.
      bool
      factorise_newton_matrix()
      {
        for (Index j = 0; j < n_c; ++j)
          shift[problem.constrained[j]] = w[j] / gap[j];
        return newton.factorise(shift);
      }

      /**
       * (47): K du = r + E (c / (z - psi) - w),
       *       dw = c / (z - psi) - w (1 + du_J1 / (z - psi)),
       * for the centring term c of the complementarity rows
       * (z - psi) w = c: mu_k in the paper's method.
       */
      void
      direction(const Vector &centring)
      {
        Vector rhs = r;
        for (Index j = 0; j < n_c; ++j)
          rhs[problem.constrained[j]] += centring[j] / gap[j] - w[j];
        newton.solve(rhs, du);
        for (Index j = 0; j < n_c; ++j)
          dw[j] = centring[j] / gap[j] -
                  w[j] * (1 + du[problem.constrained[j]] / gap[j]);
      }

      /// (51): the largest step keeping z - psi >= 0 and w >= 0.
      double
      largest_step() const
      {
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
      }

      /// (42): mu_k = delta (z - psi)^T w / |J1| on every row.
      Vector
      fixed_centring() const
      {
        return Vector::Constant(
          n_c, n_c > 0 ? options.centering * complementarity / n_c : 0.0);
      }

      /**
       * Mehrotra: the affine step (c = 0) measures how far the gap can
       * fall; the centring is sigma mu with sigma the cube of that
       * fraction, and the corrector subtracts the second-order term ds dw
       * the affine step ignores. Sets @p target to sigma mu.
       */
      Vector
      mehrotra_centring(double &target)
      {
        Vector centring = Vector::Zero(n_c);
        direction(centring);
        const double alpha_affine           = std::min(1.0, largest_step());
        double       affine_complementarity = 0;
        for (Index j = 0; j < n_c; ++j)
          affine_complementarity +=
            (gap[j] + alpha_affine * du[problem.constrained[j]]) *
            (w[j] + alpha_affine * dw[j]);
        const double sigma =
          std::min(1.0, std::pow(affine_complementarity / complementarity, 3));
        target = sigma * complementarity / n_c;
        for (Index j = 0; j < n_c; ++j)
          centring[j] = target - du[problem.constrained[j]] * dw[j];
        return centring;
      }

      /**
       * Gondzio's correctors to the direction of @p centring, whose step is
       * @p step: at the trial step min(1, 1.5 step) the products outside
       * [0.1, 10] @p target are aimed back into that band by one more solve
       * each; a corrector stays only if it lengthens the step by 1 %.
       * Returns the step of the direction kept.
       */
      double
      correct_centrality(Vector &centring, const double target, double step)
      {
        const double low = 0.1 * target, high = 10 * target;
        for (unsigned int c = 0; c < options.centrality_correctors && step < 1;
             ++c)
          {
            const double trial = std::min(1.0, 1.5 * step);
            for (Index j = 0; j < n_c; ++j)
              {
                const double product =
                  (gap[j] + trial * du[problem.constrained[j]]) *
                  (w[j] + trial * dw[j]);
                // Raise small products to the band, lower large ones by at
                // most its top.
                if (product < low)
                  centring[j] += low - product;
                else if (product > high)
                  centring[j] += std::max(high - product, -high);
              }
            Vector kept_du = du, kept_dw = dw;
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
      }

      /// (54): the step alpha along the direction.
      void
      take_step(const double alpha)
      {
        z += alpha * du;
        for (Index j = 0; j < n_c; ++j)
          {
            gap[j] += alpha * du[problem.constrained[j]];
            w[j] += alpha * dw[j];
          }
      }

      /// The answer: z with its slack exactly psi + gap on J1, and the
      /// analysis of the Newton matrix for the projection's systems (they
      /// have A's pattern). Once, at the end: the Newton matrix is left
      /// without its factor.
      void
      finish(Solution &solution)
      {
        solution.u = z;
        for (Index j = 0; j < n_c; ++j)
          solution.u[problem.constrained[j]] = problem.lower_bound[j] + gap[j];
        solution.factor = newton.hand_over_analysis();
      }

      /**
       * Mehrotra's starting point, for the LCP: z from the Newton matrix
       * with a shift of a hundredth of A's diagonal on S, pulled towards
       * psi there (A z - b = D (psi - z) on S, zero elsewhere: z near the
       * unconstrained minimiser). Its slack z - psi and multiplier
       * A z - b on S are moved into the positive orthant by 1.5 times their
       * most negative entries, then each by half the complementarity over
       * the other's sum, so that no product is tiny against the rest.
       * (66) starts the running bond walls far from feasible; this start
       * saves more iterations there than the one factorisation it costs
       * (benchmarks/masonry_tables/README.md, "Design measurements").
       * Keeps start (66) if that matrix is not positive definite.
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


      /// (z - psi)^T w and ||r||_2 of the last residual().
      double complementarity = 0;
      double infeasibility   = 0;

    private:
      const Problem                 &problem;
      const InteriorPointParameters &options;
      Report                        &report;
      const Index                    n_c;
      Vector                         z, gap, w;
      ShiftedSystem                  newton;
      Vector                         shift, r, du, dw;
      /// The rounding floor of the infeasibility.
      double floor = 0;
      /// For the floor test of converged().
      double previous_infeasibility = std::numeric_limits<double>::infinity();
      unsigned int steps_at_floor   = 0;
    };

    class InteriorPoint : public Solver
    {
    public:
      using Parameters = InteriorPointParameters;

      InteriorPoint(const SolverParameters &parameters,
                    const Parameters       &options)
        : Solver(parameters)
        , options(options)
      {}

      static SolverInfo
      properties()
      {
        SolverInfo info;
        info.name        = "interior_point";
        info.label       = "interior point";
        info.description = "interior-point method of Fernandes, Figueiredo "
                           "& Judice (eqs. 42-56, start 66)";
        info.subsection  = "Interior point";
        info.default_iterations = "500";
        info.exact              = false;
        info.variants           = {{"predictor-corrector",
                                    {{"Interior point/Variant", "predictor-corrector"}}}};
        // Near the end the Newton matrix spans many orders of magnitude
        // (lambda / s on the closed contacts); a factorisation may then meet
        // a pivot that rounding made zero or negative (MUMPS's pivoting LDL'
        // does on a 3D wall where CHOLMOD's LL' passes). That says nothing
        // about the LCP, so "singular" is checked by PDAS, an exact method,
        // rather than reported as a wall without equilibrium.
        FollowUp check;
        check.kind   = FollowUp::Kind::verification;
        check.when   = Status::singular;
        check.method = "pdas";
        info.follow_ups.push_back(check);
        // The projection's first active set is the interior indicators'
        // guess at the answer. Where blocks are far stiffer than their
        // weight makes them deform (a masonry wall in SI units: E = 1e10,
        // rho g = 2e4), contacts opened by the elastic deformation alone
        // have slacks of that size, and at a complementarity of 1e-8 their
        // products are not yet told from the closed ones': a third of the
        // guess was wrong on a running bond of m = 30, and the projection
        // cycled. Far below, they are (tests/masonry/stiff_blocks).
        FollowUp tighter;
        tighter.when                  = Status::iteration_limit;
        tighter.after_projection      = true;
        tighter.only_at_default_limit = true;
        tighter.method                = info.name;
        tighter.settings              = {
                       {"Interior point/Complementarity tolerance", "1e-14"}};
        info.follow_ups.push_back(tighter);
        return info;
      }

      void
      solve(const Problem &problem,
            Solution      &solution,
            Report        &report,
            std::ostream  *progress) override
      {
        InteriorPointIterate ip(problem, options, report);
        // Its start orders the Newton matrix and factorises it, seconds on
        // large problems before the first iteration's line.
        if (progress != nullptr)
          *progress << "    interior point: ordering and factorising the "
                       "Newton matrix for its start ("
                    << problem.size() << " unknowns)" << std::endl;
        ip.start();
        const unsigned int limit = iteration_limit(500);
        for (unsigned int k = 0;; ++k)
          {
            ip.residual();
            if (!std::isfinite(ip.infeasibility) ||
                !std::isfinite(ip.complementarity))
              {
                report.status  = Status::singular;
                report.message = "interior point broke down (non-finite "
                                 "iterate) at iteration " +
                                 std::to_string(k);
                break;
              }
            if (progress != nullptr && k > 0)
              *progress << "    interior point iteration " << k
                        << std::scientific << std::setprecision(2) << ": gap "
                        << ip.complementarity << ", infeasibility "
                        << ip.infeasibility << std::defaultfloat << std::endl;
            if (ip.converged())
              {
                report.status = Status::converged;
                break;
              }
            if (k >= limit)
              {
                report.status = Status::iteration_limit;
                report.message =
                  "interior point reached " + std::to_string(limit) +
                  " iterations (gap " + std::to_string(ip.complementarity) +
                  ", infeasibility " + std::to_string(ip.infeasibility) + ")";
                break;
              }
            report.iterations = k + 1;

            if (!ip.factorise_newton_matrix())
              {
                report.status  = Status::singular;
                report.message = "interior point: the matrix of (47) is not "
                                 "positive definite at iteration " +
                                 std::to_string(k + 1) + " (C_JfJf singular?)";
                break;
              }
            double target   = 0; // sigma mu of the predictor-corrector
            Vector centring = options.predictor_corrector() ?
                                ip.mehrotra_centring(target) :
                                ip.fixed_centring();
            ip.direction(centring);
            double step = ip.largest_step();
            if (options.predictor_corrector())
              step = ip.correct_centrality(centring, target, step);
            ip.take_step(std::min(1.0, options.step_factor * step)); // (50)
          }
        ip.finish(solution);
      }

    private:
      const Parameters options;
    };
  } // namespace

  UNILATERAL_REGISTER_SOLVER(InteriorPoint)
} // namespace unilateral::lcp
