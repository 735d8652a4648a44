/**
 * Primal-dual active set method (Hintermueller, Ito & Kunisch), as given by
 * Ainsworth & Mihai, Section 4 "PDAS". In our sign convention (lambda = -Sigma,
 * slack u - l):
 *   Step 2: lambda = A u - b; active SZ = {i in S : (u_i - l_i) - tau lambda_i < 0}
 *   Step 3: stop if iter >= 1 and SZ did not change (then u_SZ = l_SZ,
 *           lambda_SP = 0, and the new sets certify feasibility)
 *   Step 4: solve A_FF u_F = b_F - A_F,SZ l_SZ with u_SZ = l_SZ.
 * The same routine is the projection step when run on A from u_eps.
 */
#include <unilateral/lcp/active_set_system.h>
#include <unilateral/lcp/solver.h>

#include <algorithm>
#include <ostream>

namespace unilateral::lcp
{
  namespace
  {
    class Pdas : public Solver
    {
    public:
      using Solver::Solver;

      void
      solve(const Problem &problem,
            Solution      &solution,
            Report        &report,
            std::ostream  *progress) override
      {
        const Index  n   = problem.size();
        const double tau = parameters.pdas.tau;
        Vector      &u   = solution.u;
        if (u.size() != n)
          {
            // u0 = 0, moved onto the feasible set.
            u = Vector::Zero(n);
            for (Index k = 0; k < problem.n_constrained(); ++k)
              u[problem.constrained[k]] =
                std::max(0.0, problem.lower_bound[k]);
          }

        // A factor from a previous stage (the regularised solve before the
        // projection) preconditions the first systems.
        ActiveSetSystem   system(problem.A, report.counters, solution.factor);
        std::vector<char> active(n, 0);
        if (parameters.pdas.start == SolverParameters::PdasStart::all_active &&
            solution.factor == nullptr)
          {
            // u0: the minimiser with every constraint at its bound.
            active = problem.constrained_mask();
            for (Index k = 0; k < problem.n_constrained(); ++k)
              u[problem.constrained[k]] = problem.lower_bound[k];
            if (!system.solve(active, problem.b, u))
              {
                report.status  = Status::singular;
                report.message = "PDAS: the system with every constraint "
                                 "active is singular";
                return;
              }
          }
        const unsigned int limit = iteration_limit(500);
        for (unsigned int iteration = 0;; ++iteration)
          {
            const Vector lambda = problem.A * u - problem.b;
            ++report.counters.matrix_vector_products;
            std::vector<char> new_active(n, 0);
            unsigned int      n_active = 0, n_changes = 0;
            for (Index k = 0; k < problem.n_constrained(); ++k)
              {
                const Index i = problem.constrained[k];
                new_active[i] =
                  (u[i] - problem.lower_bound[k]) - tau * lambda[i] < 0;
                n_active += new_active[i];
                n_changes += (new_active[i] != active[i]);
              }
            if (iteration >= 1 && n_changes == 0)
              {
                report.status = Status::converged;
                break;
              }
            if (iteration >= limit)
              {
                report.status  = Status::iteration_limit;
                report.message = "PDAS did not settle on an active set in " +
                                 std::to_string(limit) +
                                 " iterations (last change: " +
                                 std::to_string(n_changes) + " indices)";
                break;
              }
            active.swap(new_active);

            for (Index k = 0; k < problem.n_constrained(); ++k)
              if (active[problem.constrained[k]])
                u[problem.constrained[k]] = problem.lower_bound[k];
            if (!system.solve(active, problem.b, u))
              {
                report.status = Status::singular;
                report.message =
                  "PDAS: the reduced system A_FF is singular for the active "
                  "set of iteration " +
                  std::to_string(iteration + 1) +
                  " (some body is held by no active constraint)";
                break;
              }
            report.iterations = iteration + 1;
            solution.factor = system.factor();
            if (progress != nullptr)
              *progress << "    pdas iteration " << iteration + 1
                        << ": active set " << n_active << ", changed "
                        << n_changes << std::endl;
          }
      }
    };
  } // namespace

  UNILATERAL_REGISTER_SOLVER(Pdas,
                             "pdas",
                             "primal-dual active set (Hintermueller et al.; "
                             "Ainsworth & Mihai), parameter tau",
                             true,
                             false,
                             true,
                             0)
} // namespace unilateral::lcp
