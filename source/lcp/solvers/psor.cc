/**
 * Successive over-relaxation with projection, as given by Ainsworth & Mihai
 * (Section 4, "PSOR"; Glowinski, Lions & Tremolieres):
 *   Step 3: for i in S in order, the Gauss-Seidel value
 *           (b_i - sum_{j != i} A_ij u_j) / A_ii (new values for j < i),
 *           then u_i = max((1 - omega) u_i^old + omega u_i, l_i);
 *   Step 4: u_E = A_EE^-1 (b_E - A_ES u_S) (a factorisation of A_EE);
 *   Step 5: stop when ||u_old - u||_2 / ||u||_2 < tol.
 * Defaults omega = 2 / (1 + sin(pi / n)) and tol = n * machine epsilon.
 */
#include <unilateral/base/input_error.h>
#include <unilateral/lcp/active_set_system.h>
#include <unilateral/lcp/solver.h>

#include <deal.II/base/parameter_handler.h>

#include <cmath>
#include <iomanip>
#include <limits>
#include <ostream>
#include <sstream>

namespace unilateral::lcp
{
  namespace
  {
    /// Subsection "Solver/PSOR".
    class PsorParameters : public MethodParametersBase<PsorParameters>
    {
    public:
      /// omega; 0: 2 / (1 + sin(pi / n)).
      double omega = 0;
      /// tol; 0: n * machine epsilon.
      double tolerance = 0;

      void
      add_parameters(dealii::ParameterHandler &prm) override
      {
        prm.add_parameter("Relaxation",
                          omega,
                          "omega in (0, 2); 0 takes 2 / (1 + sin(pi / n)) as "
                          "Ainsworth & Mihai.",
                          dealii::Patterns::Double(0, 2));
        prm.add_parameter("Tolerance",
                          tolerance,
                          "Stop when ||u_old - u|| / ||u|| < tolerance; 0 "
                          "takes n * machine epsilon as Ainsworth & Mihai.",
                          dealii::Patterns::Double(0));
      }

      void
      check(const std::string &section) const override
      {
        check_parameter(omega < 2,
                        section,
                        "Relaxation",
                        omega,
                        "must be in (0, 2) for convergence, or 0 for "
                        "automatic");
      }
    };

    class Psor : public Solver
    {
    public:
      using Parameters = PsorParameters;

      Psor(const SolverParameters &parameters, const Parameters &options)
        : Solver(parameters)
        , options(options)
      {}

      static SolverInfo
      properties()
      {
        SolverInfo info;
        info.name        = "psor";
        info.label       = "PSOR";
        info.description = "projected successive over-relaxation (Ainsworth "
                           "& Mihai), parameters omega, tol";
        info.subsection  = "PSOR";
        info.default_iterations    = "100000 sweeps";
        info.needs_definite_matrix = true;
        info.exact                 = false;
        // Its rate of convergence is set by eps; the projection makes the
        // answer exact anyway.
        info.preferred_regularisation = 1e-2;
        info.warm_start               = true;
        info.stationary               = true;
        return info;
      }

      void
      solve(const Problem &problem,
            Solution      &solution,
            Report        &report,
            std::ostream  *progress) override
      {
        const Index  n         = problem.size();
        const double pi        = std::acos(-1.0);
        const double omega     = options.omega > 0 ?
                                   options.omega :
                                   (n > 1 ? 2.0 / (1.0 + std::sin(pi / n)) : 1.0);
        const double tolerance = options.tolerance > 0 ?
                                   options.tolerance :
                                   n * std::numeric_limits<double>::epsilon();

        Vector &u = solution.u;
        if (u.size() != n)
          {
            u = Vector::Zero(n);
            for (Index k = 0; k < problem.n_constrained(); ++k)
              u[problem.constrained[k]] = std::max(0.0, problem.lower_bound[k]);
          }

        const Vector diagonal = problem.A.diagonal();
        for (const Index i : problem.constrained)
          if (!(diagonal[i] > 0))
            {
              report.status = Status::singular;
              report.message =
                "PSOR needs A_ii > 0 on S, but A(" + std::to_string(i + 1) +
                "," + std::to_string(i + 1) + ") <= 0 (counted from 1)";
              return;
            }

        const std::vector<char> in_S          = problem.constrained_mask();
        const bool              has_free_part = problem.n_constrained() < n;
        ActiveSetSystem         free_part(problem.A, report.counters);

        const unsigned int limit = iteration_limit(100000);
        for (unsigned int sweep = 1;; ++sweep)
          {
            const Vector u_old = u;
            // Step 3: projected Gauss-Seidel over S. A is symmetric, so
            // column i holds row i.
            for (Index k = 0; k < problem.n_constrained(); ++k)
              {
                const Index i     = problem.constrained[k];
                double      sigma = 0;
                for (SparseMatrix::InnerIterator it(problem.A, i); it; ++it)
                  if (it.row() != i)
                    sigma += it.value() * u[it.row()];
                const double gauss_seidel =
                  (problem.b[i] - sigma) / diagonal[i];
                u[i] = std::max((1 - omega) * u_old[i] + omega * gauss_seidel,
                                problem.lower_bound[k]);
              }
            // Step 4: the unconstrained block exactly.
            if (has_free_part && !free_part.solve(in_S, problem.b, u))
              {
                report.status  = Status::singular;
                report.message = "PSOR: A_EE (the unconstrained block) is "
                                 "singular";
                return;
              }
            report.iterations = sweep;

            // Step 5.
            const double change = (u_old - u).norm();
            const double size   = u.norm();
            const double error  = size > 0 ? change / size : change;
            if (progress != nullptr && (sweep & (sweep - 1)) == 0)
              *progress << "    psor sweep " << sweep << ": relative change "
                        << error << std::endl;
            // A sweep that changed nothing is at its fixed point, which
            // the relative test misses where u = 0 (an LCP without
            // constraints: tolerance n * epsilon = 0).
            if (error < tolerance || change == 0)
              {
                report.status = Status::converged;
                return;
              }
            if (!std::isfinite(error))
              {
                report.status  = Status::singular;
                report.message = "PSOR diverged (non-finite iterate)";
                return;
              }
            if (sweep >= limit)
              {
                // std::to_string's fixed six decimals showed 3e-9 as
                // "0.000000 > tolerance" (a review).
                std::ostringstream message;
                message << std::setprecision(3) << "PSOR reached " << limit
                        << " sweeps with relative change " << error
                        << " > the tolerance " << tolerance
                        << " ('Solver/PSOR/Tolerance'; 0 means n eps)";
                report.status  = Status::iteration_limit;
                report.message = message.str();
                return;
              }
          }
      }

    private:
      const Parameters options;
    };
  } // namespace

  UNILATERAL_REGISTER_SOLVER(Psor)
} // namespace unilateral::lcp
