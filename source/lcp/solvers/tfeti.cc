/**
 * Total FETI (Dostal, Horak & Kucera, "Total FETI - an easier implementable
 * variant of the FETI method for numerical solution of elliptic PDE",
 * Commun. Numer. Meth. Engng 22 (2006) 1155-1162), with SMALBE-M and MPRGP
 * for contact (Dostal, "Optimal Quadratic Programming Algorithms", 2009,
 * ch. 5 and 6; PERMON's PermonQP, QPSSMALXE, is the public implementation
 * it was read against). It solves the problem torn into floating subdomains
 * (lcp/tearing.h),
 *     min 1/2 x^T K x - f^T x,  B_I x <= c_I,  B_E x = c_E,
 * through its dual: with K^+ a generalised inverse of K, R the rigid
 * motions, F = B K^+ B^T, G = R^T B^T, d = B K^+ f - c, e = R^T f,
 *     min 1/2 l^T F l - l^T d   subject to  l_I >= 0,  G l = e.
 * Steps:
 *  1. K_s^+ and G G^T, factorised (dual_operators.h: singular when a
 *     subdomain is held by nothing, refused);
 *  2. homogenisation: l = l0 + m with l0 = G^T (G G^T)^-1 e, so G m = 0 and
 *     the bounds of m are -l0_I;
 *  3. SMALBE-M on G m = 0 (Q = G^T (G G^T)^-1 G, P = I - Q, so ||Q m|| is
 *     ||G m|| in orthonormalised rows): with the multiplier q (= G^T mu),
 *     MPRGP minimises the augmented Lagrangian
 *       1/2 m^T (P F P + rho Q) m - m^T (P (d - F l0) - q)
 *     over the bounds until ||g^P|| <= min(M ||Q m||, eta) or the whole
 *     problem has converged; then q += rho Q m, and where the Lagrangian
 *     did not rise by rho/2 ||Q m||^2, M /= beta (SMALBE-M); rho grows by
 *     'Penalty growth' where ||Q m|| did not halve;
 *  4. the rigid motions alpha = (G G^T)^-1 G (F l - d - g), g the final
 *     gradient of step 3 (the bounds' multipliers: no active set needed),
 *     and x = K^+ (f - B^T l) + R alpha, the Problem's u = to_problem x,
 *     with the active set of the contacts whose multipliers are positive.
 * The answer is approximate (the dual's tolerance); the projection step
 * makes it exact on the Problem, starting from that active set.
 */
#include <unilateral/base/input_error.h>
#include <unilateral/base/text.h>
#include <unilateral/lcp/dual_operators.h>
#include <unilateral/lcp/mprgp.h>
#include <unilateral/lcp/solver.h>
#include <unilateral/lcp/tearing.h>

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <ostream>

namespace unilateral::lcp
{
  namespace
  {
    /// Subsection "Solver/TFETI".
    class TfetiParameters : public MethodParametersBase<TfetiParameters>
    {
    public:
      /// On ||g^P|| and ||P F P|| ||Q m||, relative to ||P (d - F l0)||.
      double tolerance = 1e-8;
      /// rho / ||P F P|| at the start.
      double penalty = 10;
      /// Factor of rho where ||Q m|| fails to halve (1: rho fixed).
      double penalty_growth = 2;
      /// M / ||P F P|| at the start (SMALBE's inner precision).
      double precision = 1;
      /// beta: M /= beta where the Lagrangian does not rise enough.
      double precision_update = 2;
      /// eta / ||P (d - F l0)||: the coarsest inner precision.
      double eta = 0.1;
      /// alpha_bar ||H|| of MPRGP's expansion steps.
      double step_length = 1.9;
      /// "fixed" or "adaptive".
      std::string expansion = "fixed";
      /// "none" or "lumped".
      std::string  preconditioner = "none";
      unsigned int max_outer      = 200;

      void
      add_parameters(dealii::ParameterHandler &prm) override;

      void
      check(const std::string &section) const override
      {
        // Beyond these the iteration drowns in round-off or overflows,
        // and the breakdown would read as a wall without equilibrium.
        check_parameter(penalty > 0 && penalty <= 1e8,
                        section,
                        "Penalty",
                        penalty,
                        "must be in (0, 1e8]");
        check_parameter(penalty_growth <= 1e3,
                        section,
                        "Penalty growth",
                        penalty_growth,
                        "must be in [1, 1e3]");
        check_parameter(precision >= 1e-14 && precision <= 1e8,
                        section,
                        "Inner precision",
                        precision,
                        "must be in [1e-14, 1e8]");
        check_parameter(eta >= 1e-14 && eta <= 1,
                        section,
                        "Eta",
                        eta,
                        "must be in [1e-14, 1]");
        check_parameter(step_length > 0,
                        section,
                        "Step length",
                        step_length,
                        "must be in (0, 2]");
      }
    };

    void
    TfetiParameters::add_parameters(dealii::ParameterHandler &prm)
    {
      using namespace dealii::Patterns;
      prm.add_parameter("Tolerance",
                        tolerance,
                        "Stop when the projected gradient of the dual and its "
                        "violation of G l = e (times ||P F P||) are at most "
                        "this times ||P (d - F l0)||. The projection step "
                        "then makes the answer exact.",
                        Double(0));
      prm.add_parameter("Penalty",
                        penalty,
                        "SMALBE's penalty rho at the start, relative to the "
                        "largest eigenvalue of P F P (estimated).",
                        Double(0));
      prm.add_parameter("Penalty growth",
                        penalty_growth,
                        "rho is multiplied by this whenever the violation of "
                        "G l = e fails to halve in an outer iteration; 1 "
                        "keeps it fixed (SMALBE-M).",
                        Double(1));
      prm.add_parameter("Inner precision",
                        precision,
                        "M of SMALBE-M at the start, relative to the largest "
                        "eigenvalue of P F P: an inner (MPRGP) solve stops at "
                        "a projected gradient of min(M ||Q l||, eta).",
                        Double(0));
      prm.add_parameter("Precision update",
                        precision_update,
                        "beta of SMALBE-M: M is divided by it whenever the "
                        "augmented Lagrangian fails to rise by rho/2 "
                        "||Q l||^2 in an outer iteration.",
                        Double(1));
      prm.add_parameter("Eta",
                        eta,
                        "The coarsest inner precision, relative to "
                        "||P (d - F l0)||.",
                        Double(0));
      prm.add_parameter("Step length",
                        step_length,
                        "alpha_bar ||H|| of MPRGP's expansion steps, in "
                        "(0, 2]; ||H|| = max(||P F P||, rho).",
                        Double(0, 2));
      prm.add_parameter(
        "Expansion step",
        expansion,
        "The length of MPRGP's projected step along the free gradient after "
        "it reaches the boundary: 'fixed', alpha_bar = 'Step length' / ||H||; "
        "'adaptive', the step that minimises the energy along that gradient "
        "(one product more), taken where the projected iterate's energy is "
        "below the boundary point's, else the fixed one. Adaptive takes "
        "fewer expansions but, on the walls measured, not fewer products "
        "except on laminae (benchmarks/tfeti/README.md).",
        Selection("fixed|adaptive"));
      prm.add_parameter(
        "Preconditioner",
        preconditioner,
        "MPRGP's conjugate gradient steps preconditioned in the face: 'none', "
        "or 'lumped', FETI's lumped preconditioner P B K B^T P (+ Q / rho on "
        "the penalised part), restricted to the free multipliers: one "
        "product with K and two coarse solves more per step. On the walls "
        "measured it saves at most a fifth of the products with F (blocks "
        "refined, where the faces' conjugate gradients run longest) and costs "
        "more than that (benchmarks/tfeti/README.md): the products go to "
        "the contacts that open and close, not to ill-conditioned faces.",
        Selection("none|lumped"));
      prm.add_parameter("Maximum outer iterations",
                        max_outer,
                        "SMALBE's iterations (updates of the equality "
                        "multiplier); 'Maximum iterations' bounds MPRGP's "
                        "steps, each one product with F, two for an "
                        "expansion, three for an adaptive one (besides "
                        "them, the estimate of ||P F P|| takes 30 and each "
                        "outer iteration one or two).",
                        Integer(1));
    }

    /// The homogenised dual: min 1/2 m^T P F P m - b^T m over m >= lower,
    /// G m = 0.
    struct HomogenisedDual
    {
      /// l0 = G^T (G G^T)^-1 e.
      Vector l0;
      /// d = B K^+ f - c.
      Vector d;
      /// b = P (d - F l0).
      Vector b;
      /// -l0 on the inequalities, -infinity on the equalities.
      Vector lower;
      /// ||b||, or 1 if b = 0: what the tolerances are relative to.
      double scale = 1;
    };

    HomogenisedDual
    homogenise(const DualOperators &dual)
    {
      const Tearing  &tearing = dual.tearing();
      HomogenisedDual h;
      h.l0 = dual.G().transpose() *
             dual.coarse_solve(dual.apply_rigid_motions_transposed(tearing.f));
      h.d     = tearing.B * dual.apply_pseudo_inverse(tearing.f) - tearing.c;
      h.b     = dual.apply_P(h.d - dual.apply_F(h.l0));
      h.lower = Vector::Constant(tearing.n_multipliers(),
                                 -std::numeric_limits<double>::infinity());
      h.lower.head(tearing.n_inequalities) = -h.l0.head(tearing.n_inequalities);
      h.scale                              = h.b.norm() > 0 ? h.b.norm() : 1.0;
      return h;
    }

    // The largest eigenvalue of P F P, by power iteration (an estimate from
    // below, raised by a tenth for MPRGP's step length).
    double
    largest_eigenvalue(const DualOperators &dual)
    {
      Vector x        = dual.apply_P(Vector::Ones(dual.n_multipliers()));
      double estimate = 0;
      for (unsigned int k = 0; k < 30 && x.norm() > 0; ++k)
        {
          x /= x.norm();
          const Vector y = dual.apply_P(dual.apply_F(dual.apply_P(x)));
          estimate       = x.dot(y);
          x              = y;
        }
      return 1.1 * estimate;
    }

    /**
     * SMALBE-M with MPRGP on the homogenised dual (step 3): its state and
     * its loop.
     */
    class Smalbe
    {
    public:
      Smalbe(const DualOperators   &dual,
             const HomogenisedDual &problem,
             const TfetiParameters &options)
        : m(Vector::Zero(dual.n_multipliers()))
        , dual(dual)
        , problem(problem)
        , options(options)
        , norm_pfp(largest_eigenvalue(dual))
        , rho(options.penalty * norm_pfp)
        , M(options.precision * norm_pfp)
        , initial_rho(rho)
        , q(Vector::Zero(dual.n_multipliers()))
      {}

      enum class Outcome
      {
        converged,
        outer_limit,
        product_limit,
        broke_down,
        infeasible
      };

      /// The outer loop; MPRGP may take as many steps as @p max_products
      /// less the products with F used so far.
      Outcome
      run(unsigned int max_products, std::ostream *progress);

      /// m, and the gradient of the last inner functional at it.
      Vector       m;
      Vector       gradient;
      unsigned int outer = 0, inner = 0, adaptive_expansions = 0;

    private:
      /// ||P F P|| ||Q m|| and ||g^P||, relative to the scale.
      bool
      converged(double projected_gradient, double violation) const
      {
        return projected_gradient <= options.tolerance * problem.scale &&
               norm_pfp * violation <= options.tolerance * problem.scale;
      }

      const DualOperators   &dual;
      const HomogenisedDual &problem;
      const TfetiParameters &options;
      const double           norm_pfp;
      double                 rho, M;
      /// rho at the start.
      const double initial_rho;

      /**
       * No equilibrium: where no compressive contact forces balance every
       * block (G l = e has no solution with l_I >= 0), the violation of
       * G l = e stalls and rho doubles at every outer iteration, without
       * end (the iterate then runs off to 1e29 while its residuals look
       * fine). Declared once rho has grown twenty times over its start
       * and to 1e12 ||P F P||: a wall in equilibrium converged long
       * before (8-17 outer iterations, benchmarks/tfeti/README.md) —
       * unless its 'Tolerance' is out of reach (0, or below what double
       * precision resolves), where rho grows alike while the violation
       * goes on falling far below any force (a review: 'Tolerance = 0'
       * called a stack bond of m = 4 without equilibrium at a violation of
       * 1e-24). So the violation must also have stalled at a size that
       * matters, 1e-10 of the scale; below, the run ends at its iteration
       * limit.
       */
      bool
      no_equilibrium(const double violation) const
      {
        return rho >= 1048576.0 * initial_rho && rho >= 1e12 * norm_pfp &&
               norm_pfp * violation > 1e-10 * problem.scale;
      }
      /// The equality multiplier, as G^T mu.
      Vector q;
    };

    Smalbe::Outcome
    Smalbe::run(const unsigned int max_products, std::ostream *progress)
    {
      const unsigned int first_product = dual.products_with_F();
      double previous_lagrangian = -std::numeric_limits<double>::infinity();
      double previous_violation  = std::numeric_limits<double>::infinity();
      // The coarse parts of the last product's input and of m.
      DualOperators::CoarseParts last, current;
      for (outer = 0; outer < options.max_outer; ++outer)
        {
          const Vector r = problem.b - q;
          Mprgp        mprgp(
            [&](const Vector &x, Vector &y) {
              y = dual.apply_penalised(x, rho, last);
            },
            r,
            problem.lower,
            options.step_length / std::max(norm_pfp, rho),
            1.0);
          mprgp.use_adaptive_expansion(options.expansion == "adaptive");
          if (options.preconditioner == "lumped")
            mprgp.precondition([&](const Vector &phi, Vector &z) {
              const Vector Q_phi = dual.apply_Q(phi);
              z = dual.apply_P(dual.apply_lumped(phi - Q_phi)) + Q_phi / rho;
            });
          // G m and (G G^T)^-1 G m follow m from the products' own.
          mprgp.observe([&](const double alpha) {
            if (std::isnan(alpha))
              current = last;
            else
              {
                current.Gx -= alpha * last.Gx;
                current.c -= alpha * last.c;
              }
          });
          // The inner precision, against the current violation ||Q m|| (m
          // is MPRGP's iterate); the whole problem converged stops too.
          bool       by_precision = false;
          double     violation    = 0;
          const auto stop         = [&](const double projected_gradient) {
            violation = std::sqrt(std::max(0.0, current.Gx.dot(current.c)));
            if (converged(projected_gradient, violation))
              return true;
            by_precision = projected_gradient <=
                           std::min(M * violation, options.eta * problem.scale);
            return by_precision;
          };
          const unsigned int   used = dual.products_with_F() - first_product;
          const Mprgp::Outcome outcome =
            mprgp.solve(m, stop, used < max_products ? max_products - used : 0);
          gradient = mprgp.gradient();
          inner += mprgp.steps();
          adaptive_expansions += mprgp.adaptive_expansions();
          if (outcome == Mprgp::Outcome::not_definite ||
              outcome == Mprgp::Outcome::diverged)
            return Outcome::broke_down;
          const double projected = mprgp.projected_gradient(m).norm();
          if (progress != nullptr)
            *progress << "    tfeti outer iteration " << outer + 1
                      << std::scientific << std::setprecision(2)
                      << ": projected gradient " << projected / problem.scale
                      << ", violation " << norm_pfp * violation / problem.scale
                      << ", " << mprgp.steps() << " inner iterations, rho "
                      << rho / norm_pfp << ", M " << M / norm_pfp
                      << std::defaultfloat << std::endl;
          if (converged(projected, violation))
            {
              ++outer;
              return Outcome::converged;
            }
          if (outcome == Mprgp::Outcome::iteration_limit)
            return Outcome::product_limit;

          // SMALBE-M: the Lagrangian of this inner solve, 1/2 m^T (g - r),
          // must rise by rho/2 ||Q m||^2 over the last one; where it does
          // not, the inner solves were too coarse, and M shrinks.
          const double lagrangian = 0.5 * m.dot(gradient - r);
          if (by_precision && lagrangian < previous_lagrangian +
                                             0.5 * rho * violation * violation)
            M /= options.precision_update;
          previous_lagrangian = lagrangian;
          q += rho * (dual.G().transpose() * current.c);
          if (violation > 0.5 * previous_violation)
            rho *= options.penalty_growth;
          previous_violation = violation;
          if (no_equilibrium(violation))
            return Outcome::infeasible;
        }
      return Outcome::outer_limit;
    }

    class Tfeti : public Solver
    {
    public:
      using Parameters = TfetiParameters;

      Tfeti(const SolverParameters &parameters, const Parameters &options)
        : Solver(parameters)
        , options(options)
      {}

      static SolverInfo
      properties()
      {
        SolverInfo info;
        info.name               = "tfeti";
        info.label              = "TFETI";
        info.description        = "total FETI (Dostal et al.): the dual of the "
                                  "problem torn into floating subdomains, by SMALBE "
                                  "and MPRGP; needs a scene that tears its problem "
                                  "(masonry)";
        info.subsection         = "TFETI";
        info.default_iterations = "100000 MPRGP steps";
        info.exact              = false;
        info.needs_tearing      = true;
        info.gives_active_set   = true;
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

    // Step 4: x = K^+ (f - B^T l) + R alpha with the rigid motions alpha
    // from the final gradient, u = to_problem x, and the active set of the
    // positive multipliers.
    void
    primal_answer(const DualOperators   &dual,
                  const HomogenisedDual &homogenised,
                  const Smalbe          &smalbe,
                  Solution              &solution)
    {
      const Tearing &tearing = dual.tearing();
      const Vector   l       = homogenised.l0 + smalbe.m;
      const Vector   alpha   = dual.coarse_solve(
        dual.G() * (dual.apply_F(l) - homogenised.d - smalbe.gradient));
      const Vector x =
        dual.apply_pseudo_inverse(tearing.f - tearing.B.transpose() * l) +
        dual.apply_rigid_motions(alpha);
      solution.u = tearing.to_problem * x;
      // MPRGP leaves the multipliers of open contacts exactly at their
      // bounds.
      solution.active_set.clear();
      for (Index i = 0; i < tearing.n_inequalities; ++i)
        if (smalbe.m[i] > homogenised.lower[i])
          solution.active_set.push_back(tearing.inequality_unknown[i]);
      std::sort(solution.active_set.begin(), solution.active_set.end());
    }

    void
    Tfeti::solve(const Problem &problem,
                 Solution      &solution,
                 Report        &report,
                 std::ostream  *progress)
    {
      const Tearing &tearing = *problem.tearing;
      check_tearing(tearing, problem);
      const DualOperators dual(tearing);
      dual.add_setup(report);
      // TFETI cannot take this input, whatever it holds: the user's choice
      // of method is what to change.
      if (!dual.pseudo_inverses_formed())
        throw InputError("parameter 'Solver/Method' = tfeti: " +
                         dual.coarse_failure());
      if (!dual.coarse_factorised())
        {
          report.status  = Status::singular;
          report.message = "TFETI: " + dual.coarse_failure();
          return;
        }
      const HomogenisedDual homogenised = homogenise(dual);
      Smalbe                smalbe(dual, homogenised, options);
      const Smalbe::Outcome outcome =
        smalbe.run(iteration_limit(100000), progress);
      primal_answer(dual, homogenised, smalbe, solution);

      report.iterations = smalbe.outer;
      report.counters.cg_iterations += smalbe.inner;
      dual.add_work(report);
      report.set_figure("outer_iterations", smalbe.outer);
      report.set_figure("inner_iterations", smalbe.inner);
      if (options.expansion == "adaptive")
        report.set_figure("adaptive_expansions", smalbe.adaptive_expansions);
      switch (outcome)
        {
          case Smalbe::Outcome::converged:
            report.status = Status::converged;
            return;
          case Smalbe::Outcome::broke_down:
            report.status  = Status::singular;
            report.message = "TFETI: the dual's inner solve (MPRGP) broke "
                             "down: P F P + rho Q is not positive definite";
            return;
          case Smalbe::Outcome::infeasible:
            report.status = Status::infeasible;
            report.message =
              "TFETI: no compressive contact forces balance every block "
              "(the violation of G l = e stalled while SMALBE's penalty grew "
              "to 1e12 times ||P F P||)";
            return;
          case Smalbe::Outcome::outer_limit:
            report.status  = Status::iteration_limit;
            report.message = "TFETI did not reach its tolerance in " +
                             quantity(smalbe.outer, "outer iteration") +
                             " ('Solver/TFETI/Maximum outer iterations') and " +
                             quantity(dual.products_with_F(), "product") +
                             " with F (its set-up's included)";
            return;
          // Within an outer iteration: that one counts (a review: "in 0
          // outer iterations" where the limit fell in the first).
          case Smalbe::Outcome::product_limit:
            report.status     = Status::iteration_limit;
            report.iterations = smalbe.outer + 1;
            report.message =
              "TFETI reached its limit of " +
              std::to_string(iteration_limit(100000)) +
              " MPRGP steps ('Solver/Maximum iterations') in outer "
              "iteration " +
              std::to_string(smalbe.outer + 1) + ", after " +
              quantity(dual.products_with_F(), "product") +
              " with F (its set-up's included)";
            return;
        }
    }
  } // namespace

  UNILATERAL_REGISTER_SOLVER(Tfeti)
} // namespace unilateral::lcp
