/**
 * Linear least squares with selected nonnegativity constraints (Lawson &
 * Hanson's NNLS on the selected set S), as given by Ainsworth & Mihai,
 * Section 4 "LSSNN". The least-squares problem of Step 5,
 *   min_v || R_bar v - R^-T b ||  with the columns SZ of R removed,
 * is the equality-constrained QP  min 1/2 v^T A v - b^T v, v_SZ = l_SZ,
 * whose normal equations A_FF v_F = b_F - A_F,SZ l_SZ we solve with the
 * Cholesky factor of the reduced matrix (ActiveSetSystem).
 *
 * In our signs (lambda = -Sigma): start with every constraint at its bound
 * (SZ = S, SP empty, u_E optimal for that); then repeatedly
 *   Step 3: stop if SZ is empty or lambda_SZ >= 0;
 *   Step 4: move t = argmin_{SZ} lambda_t into SP;
 *   Step 5: solve the QP for u_bar with u_SZ = l_SZ;
 *   Step 6: if u_bar_SP > l_SP accept it and go to Step 3;
 *   Step 7: else step to the first bound hit, alpha = min over i in SP with
 *           u_bar_i <= l_i of (u_i - l_i) / (u_i - u_bar_i), move the indices
 *           that reached their bound back to SZ, and repeat Step 5.
 * As in Lawson & Hanson, a t that cannot enter (u_bar_t <= l_t at once, a
 * round-off effect) is set aside until the next accepted step; Step 3 uses
 * a round-off tolerance on lambda.
 */
#include <unilateral/lcp/active_set_system.h>
#include <unilateral/lcp/solver.h>

#include <cmath>
#include <limits>
#include <ostream>

namespace unilateral::lcp
{
  namespace
  {
    class Lssnn : public Solver
    {
    public:
      using Parameters = NoParameters;

      Lssnn(const SolverParameters &parameters, const Parameters &)
        : Solver(parameters)
      {}

      static SolverInfo
      properties()
      {
        SolverInfo info;
        info.name               = "lssnn";
        info.label              = "LSSNN";
        info.description        = "least squares with selected nonnegativity "
                                  "constraints (Lawson & Hanson; Ainsworth & Mihai)";
        info.default_iterations = "3|S| + 100";
        info.needs_definite_matrix = true;
        info.single_pivot          = true;
        return info;
      }

      void
      solve(const Problem &problem,
            Solution      &solution,
            Report        &report,
            std::ostream  *progress) override
      {
        const Index  n     = problem.size();
        const Index  n_c   = problem.n_constrained();
        const Vector bound = problem.full_lower_bound();

        // Step 1: SZ = S, u_SZ = l_SZ and u_E the matching optimum.
        std::vector<char> at_bound = problem.constrained_mask(); // SZ
        std::vector<char> set_aside(n, 0);
        Vector           &u = solution.u;
        u                   = Vector::Zero(n);
        for (Index k = 0; k < n_c; ++k)
          u[problem.constrained[k]] = problem.lower_bound[k];
        ActiveSetSystem system(problem.A, report.counters);
        if (!solve_qp(system, at_bound, problem, u, report, 0))
          return;

        const double       epsilon = std::numeric_limits<double>::epsilon();
        const SparseMatrix abs_A   = problem.A.cwiseAbs();
        const unsigned int limit   = iteration_limit(3 * n_c + 100);
        Vector             u_bar;
        for (unsigned int iteration = 0;;)
          {
            // Steps 2-3.
            const Vector lambda = problem.A * u - problem.b;
            ++report.counters.matrix_vector_products;
            const double force_scale =
              problem.b.lpNorm<Eigen::Infinity>() +
              (abs_A * u.cwiseAbs()).lpNorm<Eigen::Infinity>();
            const double dual_tolerance = 10 * n * epsilon * force_scale;
            Index        t              = -1;
            for (const Index i : problem.constrained)
              if (at_bound[i] && !set_aside[i] && lambda[i] < -dual_tolerance &&
                  (t < 0 || lambda[i] < lambda[t]))
                t = i;
            if (t < 0)
              {
                report.status = Status::converged;
                return;
              }
            if (iteration >= limit)
              {
                report.status = Status::iteration_limit;
                report.message =
                  "LSSNN reached " + std::to_string(limit) + " iterations";
                return;
              }

            // Step 4.
            ++iteration;
            report.iterations = iteration;
            at_bound[t]       = 0;

            // Steps 5-7, until the QP solution is strictly feasible on SP.
            for (;;)
              {
                u_bar = u;
                if (!solve_qp(
                      system, at_bound, problem, u_bar, report, iteration))
                  return;
                double alpha    = 1;
                bool   feasible = true;
                for (const Index i : problem.constrained)
                  if (!at_bound[i] && u_bar[i] <= bound[i])
                    {
                      feasible          = false;
                      const double drop = u[i] - u_bar[i];
                      const double step =
                        drop > 0 ? (u[i] - bound[i]) / drop : 0.0;
                      alpha = std::min(alpha, step);
                    }
                if (feasible)
                  {
                    u = u_bar;
                    std::fill(set_aside.begin(), set_aside.end(), 0);
                    break;
                  }
                // Step 7: to the first bound hit; those indices leave SP.
                u += alpha * (u_bar - u);
                bool t_left = false;
                for (const Index i : problem.constrained)
                  if (!at_bound[i] &&
                      u[i] <= bound[i] + 10 * epsilon * std::abs(bound[i]))
                    {
                      at_bound[i] = 1;
                      u[i]        = bound[i];
                      t_left |= (i == t);
                    }
                if (t_left && alpha == 0)
                  {
                    // t could not enter at all: round-off; set it aside.
                    set_aside[t] = 1;
                    break;
                  }
              }
            if (progress != nullptr && (iteration & (iteration - 1)) == 0)
              *progress << "    lssnn iteration " << iteration << std::endl;
          }
      }

    private:
      bool
      solve_qp(ActiveSetSystem         &system,
               const std::vector<char> &at_bound,
               const Problem           &problem,
               Vector                  &u,
               Report                  &report,
               const unsigned int       iteration) const
      {
        if (system.solve(at_bound, problem.b, u))
          return true;
        report.status  = Status::singular;
        report.message = "LSSNN: the reduced system is singular at iteration " +
                         std::to_string(iteration);
        return false;
      }
    };
  } // namespace

  UNILATERAL_REGISTER_SOLVER(Lssnn)
} // namespace unilateral::lcp
