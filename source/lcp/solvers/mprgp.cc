/**
 * MPRGP, modified proportioning with reduced gradient projections (Dostal &
 * Schoberl, "Minimizing quadratic functions subject to bound constraints
 * with the rate of convergence and finite termination", Comput. Optim.
 * Appl. 30 (2005) 23-43; Dostal, "Optimal Quadratic Programming
 * Algorithms", 2009, ch. 5): conjugate gradients on the free set, with
 * projections, for min 1/2 u^T A u - b^T u subject to u_S >= l_S, A
 * symmetric positive definite. Matrix-free (one product with A per step),
 * the inner solver of FETI methods for contact (PERMON, PermonQP).
 *
 * With g = A u - b, the free set F = {i : i not in S or u_i > l_i}, the
 * free gradient phi (g on F, 0 elsewhere), the chopped gradient beta
 * (min(g_i, 0) on S \ F, 0 elsewhere), the reduced free gradient
 * phi~_i = min((u_i - l_i) / alpha_bar, phi_i) on F n S, and the projected
 * gradient g^P = phi + beta:
 *   while ||g^P|| > tolerance ||b||:
 *     if ||beta||^2 <= Gamma^2 phi~^T phi (the iterate is proportional):
 *       alpha_cg = g^T p / p^T A p, alpha_f = the largest feasible step;
 *       CG step (alpha_cg <= alpha_f): u -= alpha_cg p, p = phi - gamma p
 *         with gamma = phi^T A p / p^T A p;
 *       else expansion: u -= alpha_f p, then u = P(u - alpha_bar phi(u)),
 *         p = phi(u);
 *     else proportioning: u -= (g^T beta / beta^T A beta) beta, p = phi(u).
 * alpha_bar in (0, 2 / ||A||] (here 'Step length' / ||A||, ||A|| bounded by
 * the largest absolute row sum); Gamma = 1 as Dostal recommends. The rate
 * of convergence depends on the condition number of A (a first-order
 * method): the answer is approximate, and the projection step finishes it.
 */
#include <unilateral/base/input_error.h>
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

    class Mprgp : public Solver
    {
    public:
      using Parameters = MprgpParameters;

      Mprgp(const SolverParameters &parameters, const Parameters &options)
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

    /**
     * The state of one MPRGP solve: the iterate u, the gradient g = A u - b
     * and the conjugate direction p, and the parts of g the steps are
     * chosen by. Each step is one member function.
     */
    class MprgpIterate
    {
    public:
      MprgpIterate(const Problem &problem,
                   const double   alpha_bar,
                   Vector        &u,
                   Counters      &counters)
        : problem(problem)
        , lower(problem.full_lower_bound())
        , alpha_bar(alpha_bar)
        , counters(counters)
        , u(u)
      {
        if (u.size() != problem.size())
          u = Vector::Zero(problem.size());
        project(u);
        restart();
      }

      /// phi: the gradient on the free set.
      Vector
      free_gradient() const
      {
        Vector phi = g;
        for (const Index i : problem.constrained)
          if (!(u[i] > lower[i]))
            phi[i] = 0;
        return phi;
      }

      /// beta: min(g_i, 0) on the active set.
      Vector
      chopped_gradient() const
      {
        Vector beta = Vector::Zero(u.size());
        for (const Index i : problem.constrained)
          if (!(u[i] > lower[i]))
            beta[i] = std::min(g[i], 0.0);
        return beta;
      }

      /// phi~^T phi, with phi~_i = min((u_i - l_i) / alpha_bar, phi_i).
      double
      reduced_times_free(const Vector &phi) const
      {
        double result = 0;
        for (Index i = 0; i < u.size(); ++i)
          {
            const double reduced =
              std::isfinite(lower[i]) ?
                std::min((u[i] - lower[i]) / alpha_bar, phi[i]) :
                phi[i];
            result += reduced * phi[i];
          }
        return result;
      }

      /**
       * The iterate is proportional: a conjugate gradient step on the free
       * set, or an expansion where that would leave the feasible set (to
       * the boundary, then a projected gradient step of fixed length that
       * can add active constraints). False if p^T A p <= 0.
       */
      bool
      conjugate_gradient_or_expansion()
      {
        const Vector Ap  = product(p);
        const double pAp = p.dot(Ap);
        if (!(pAp > 0))
          return false;
        const double alpha_cg = g.dot(p) / pAp;
        const double alpha_f  = feasible_step();
        if (alpha_cg <= alpha_f)
          {
            u -= alpha_cg * p;
            g -= alpha_cg * Ap;
            const Vector phi = free_gradient();
            p                = phi - (phi.dot(Ap) / pAp) * p;
            return true;
          }
        u -= alpha_f * p;
        g -= alpha_f * Ap;
        u -= alpha_bar * free_gradient();
        project(u);
        restart();
        return true;
      }

      /// Proportioning: along the chopped gradient @p beta, releasing
      /// constraints whose multipliers are negative. False if
      /// beta^T A beta <= 0.
      bool
      proportioning(const Vector &beta)
      {
        const Vector Ad  = product(beta);
        const double dAd = beta.dot(Ad);
        if (!(dAd > 0))
          return false;
        const double alpha = g.dot(beta) / dAd;
        u -= alpha * beta;
        g -= alpha * Ad;
        p = free_gradient();
        return true;
      }

    private:
      Vector
      product(const Vector &d) const
      {
        ++counters.matrix_vector_products;
        return problem.A * d;
      }

      /// g from u, and p = phi.
      void
      restart()
      {
        g = problem.A * u - problem.b;
        ++counters.matrix_vector_products;
        p = free_gradient();
      }

      /// The largest alpha with u - alpha p feasible.
      double
      feasible_step() const
      {
        double alpha = std::numeric_limits<double>::infinity();
        for (const Index i : problem.constrained)
          if (p[i] > 0)
            alpha = std::min(alpha, (u[i] - lower[i]) / p[i]);
        return alpha;
      }

      /// u projected onto the feasible set.
      void
      project(Vector &v) const
      {
        for (const Index i : problem.constrained)
          v[i] = std::max(v[i], lower[i]);
      }

      const Problem &problem;
      const Vector   lower;
      const double   alpha_bar;
      Counters      &counters;
      Vector        &u;
      Vector         g, p;
    };

    void
    Mprgp::solve(const Problem &problem,
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
      const double alpha_bar = options.step_length / (norm_A > 0 ? norm_A : 1);
      MprgpIterate mprgp(problem, alpha_bar, solution.u, report.counters);

      const double       scale = problem.b.norm() > 0 ? problem.b.norm() : 1.0;
      const unsigned int limit = iteration_limit(100000);
      for (unsigned int iteration = 0;; ++iteration)
        {
          const Vector phi                = mprgp.free_gradient();
          const Vector beta               = mprgp.chopped_gradient();
          const double projected_gradient = (phi + beta).norm() / scale;
          if (progress != nullptr && iteration > 0 &&
              (iteration & (iteration - 1)) == 0)
            *progress << "    mprgp iteration " << iteration
                      << ": relative projected gradient " << projected_gradient
                      << std::endl;
          if (!std::isfinite(projected_gradient))
            {
              report.status  = Status::singular;
              report.message = "MPRGP diverged (non-finite iterate)";
              return;
            }
          if (projected_gradient <= options.tolerance)
            {
              report.status = Status::converged;
              return;
            }
          if (iteration >= limit)
            {
              report.status  = Status::iteration_limit;
              report.message = "MPRGP reached " + std::to_string(limit) +
                               " iterations with relative projected "
                               "gradient " +
                               std::to_string(projected_gradient);
              return;
            }
          report.iterations = iteration + 1;
          const bool proportional =
            beta.squaredNorm() <=
            options.gamma * options.gamma * mprgp.reduced_times_free(phi);
          if (!(proportional ? mprgp.conjugate_gradient_or_expansion() :
                               mprgp.proportioning(beta)))
            {
              report.status  = Status::singular;
              report.message = "MPRGP: a direction d with d^T A d <= 0, A "
                               "is not positive definite";
              return;
            }
        }
    }
  } // namespace

  UNILATERAL_REGISTER_SOLVER(Mprgp)
} // namespace unilateral::lcp
