/**
 * Primal-dual active set method (Hintermueller, Ito & Kunisch), as given by
 * Ainsworth & Mihai, Section 4 "PDAS". In our sign convention (lambda = -Sigma,
 * slack u - l):
 *   Step 2: lambda = A u - b; active SZ = {i in S : (u_i - l_i) - tau lambda_i < 0}
 *   Step 3: stop if iter >= 1 and SZ did not change (then u_SZ = l_SZ,
 *           lambda_SP = 0, and the new sets certify feasibility)
 *   Step 4: solve A_FF u_F = b_F - A_F,SZ l_SZ with u_SZ = l_SZ.
 * Two safeguards the paper does not have (both can be switched off): the
 * test of Step 2 has a rounding tolerance, so degenerate indices (at the
 * bound with zero multiplier) do not flip sides forever, and when the number
 * of violated indices stops falling, Judice & Pires' single-pivot rule takes
 * over until it falls again, which makes the method terminate.
 * The same routine is the projection step when run on A from u_eps.
 */
#include <unilateral/lcp/active_set_system.h>
#include <unilateral/lcp/solver.h>

#include <algorithm>
#include <cmath>
#include <ostream>

namespace unilateral::lcp
{
  namespace
  {
    class Pdas : public Solver
    {
    public:
      using Solver::Solver;

      /// Iterations without a new low in the count of violated indices
      /// after which PDAS (at its default iteration limit) stops as cycling.
      static constexpr unsigned int wandering_limit = 50;

      void
      solve(const Problem &problem,
            Solution      &solution,
            Report        &report,
            std::ostream  *progress) override
      {
        const Index  n   = problem.size();
        const double tau = parameters.pdas.tau;
        Vector      &u   = solution.u;
        // A given iterate (the projection step's u_eps, a warm start) is the
        // start; the 'Start' parameter only chooses when none is given.
        const bool start_given = u.size() == n;
        // A given first active set (with the start) replaces the first test.
        std::vector<char> given_active;
        if (start_given && !solution.active_set.empty())
          {
            given_active.assign(n, 0);
            for (const Index i : solution.active_set)
              given_active[i] = 1;
          }
        solution.active_set.clear();
        if (!start_given)
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
        // Ties go to the active side: before the first test every index
        // counts as active, so an index at its bound with a zero multiplier
        // (up to round-off) stays there. An active degenerate contact costs
        // nothing; an inactive one can leave a body unsupported.
        std::vector<char> active = problem.constrained_mask();
        if (parameters.pdas.start == SolverParameters::PdasStart::all_active &&
            !start_given)
          {
            // u0: the minimiser with every constraint at its bound.
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
        const unsigned int limit     = iteration_limit(500);
        const unsigned int safeguard = parameters.pdas.safeguard;
        Index              fewest_violations = problem.n_constrained() + 1;
        unsigned int       without_progress  = 0;
        for (unsigned int iteration = 0;; ++iteration)
          {
            const Vector lambda = problem.A * u - problem.b;
            ++report.counters.matrix_vector_products;

            // Step 2 with a rounding tolerance: index i changes side only if
            // u_i - l_i - tau lambda_i is beyond +-tolerance_i, the rounding
            // error of lambda_i (and of the slack, lambda_i / A_ii) at the
            // size of its terms.
            std::vector<Index> violated;
            for (Index k = 0; k < problem.n_constrained(); ++k)
              {
                const Index i = problem.constrained[k];
                if (iteration == 0 && !given_active.empty())
                  {
                    if (active[i] != given_active[i])
                      violated.push_back(i);
                    continue;
                  }
                double magnitude = std::abs(problem.b[i]);
                double diagonal  = 0;
                for (SparseMatrix::InnerIterator entry(problem.A, i); entry;
                     ++entry)
                  {
                    magnitude += std::abs(entry.value() * u[entry.row()]);
                    if (entry.row() == i)
                      diagonal = entry.value();
                  }
                const double tolerance =
                  parameters.pdas.round_off * magnitude *
                  ((diagonal > 0 ? 1.0 / diagonal : 0.0) + tau);
                const double test =
                  (u[i] - problem.lower_bound[k]) - tau * lambda[i];
                const bool now_active =
                  active[i] ? test < tolerance : test < -tolerance;
                if (now_active != static_cast<bool>(active[i]))
                  violated.push_back(i);
              }
            if (iteration >= 1 && violated.empty())
              {
                report.status = Status::converged;
                break;
              }
            // Cycling: the count of violated indices has not reached a new
            // low for long (running bond walls with a large settlement, from
            // m = 30 on; nearly degenerate contacts, we guess). Murty's
            // rule would end it, one index per factorisation; with the
            // default limit PDAS stops instead and the driver continues
            // from an interior point (solve_lcp).
            if (parameters.max_iterations == 0 && safeguard > 0 &&
                without_progress > wandering_limit)
              {
                report.status  = Status::iteration_limit;
                report.message = "PDAS did not settle: the number of "
                                 "violated constraints has not fallen below " +
                                 std::to_string(fewest_violations) + " in " +
                                 std::to_string(wandering_limit) +
                                 " iterations (cycling)";
                break;
              }
            if (iteration >= limit)
              {
                report.status  = Status::iteration_limit;
                report.message = "PDAS did not settle on an active set in " +
                                 std::to_string(limit) +
                                 " iterations (last change: " +
                                 std::to_string(violated.size()) + " indices)";
                break;
              }

            // Step 3, safeguarded (Judice & Pires): every violated index
            // changes side while their number falls often enough; otherwise
            // only the least one (Murty's rule, finite for definite A).
            const Index n_violated = static_cast<Index>(violated.size());
            bool        single     = false;
            if (iteration >= 1 && safeguard > 0)
              {
                if (n_violated < fewest_violations)
                  {
                    fewest_violations = n_violated;
                    without_progress  = 0;
                  }
                else
                  single = ++without_progress > safeguard;
              }
            if (single)
              violated.resize(1); // the constrained indices are sorted
            for (const Index i : violated)
              active[i] = !active[i];

            Index n_active = 0;
            for (Index k = 0; k < problem.n_constrained(); ++k)
              if (active[problem.constrained[k]])
                {
                  u[problem.constrained[k]] = problem.lower_bound[k];
                  ++n_active;
                }
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
            solution.factor   = system.factor();
            if (progress != nullptr)
              *progress << "    pdas iteration " << iteration + 1
                        << ": active set " << n_active << ", changed "
                        << violated.size()
                        << (single ? " (safeguard: least index)" : "")
                        << std::endl;
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
                             0,
                             true)
} // namespace unilateral::lcp
