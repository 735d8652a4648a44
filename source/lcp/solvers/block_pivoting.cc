/**
 * The block principal pivoting method of Judice & Pires, as given by
 * Fernandes, Figueiredo & Judice (2002), Section 3.2. A complementary basis
 * is a partition of J into R (free; Jf is always in R) and S (at the bound,
 * z_S = psi_S); its solution (57) is
 *   C_RR z_R = F_R - C_RS psi_S,   w_S = C_S z - F_S.
 * Infeasibilities (59)/(67): H = {i in R n J1 : z_i < psi_i - eps}
 *                              u {i in S : w_i < -eps}.
 * Steps:
 *  1. R = Jf, ninf = |J| + 1, nit = 0.
 *  2. Solve (57), form H. If H is empty: done. If |H| < ninf: ninf = |H|,
 *     nit = 0, go to 3. If nit <= p: go to 3 (when nit = 1 remember R_bar =
 *     R, H_bar = H). Otherwise go to 4 (when nit = p + 1 restore R = R_bar,
 *     H = H_bar).
 *  3. Block pivot: every index of H changes side; nit = nit + 1; go to 2.
 *  4. Single pivot (Murty's least-index rule, which terminates finitely):
 *     t = min H changes side; nit = nit + 1; go to 2.
 * p = 10 and eps = 1e-6 as in the paper. Each step 2 is one iteration (the
 * paper's "it"); its linear system reuses the symbolic analysis of C.
 */
#include <unilateral/lcp/active_set_system.h>
#include <unilateral/lcp/solver.h>

#include <deal.II/base/parameter_handler.h>

#include <ostream>

namespace unilateral::lcp
{
  namespace
  {
    /// Subsection "Solver/Block pivoting".
    class BlockPivotingParameters
      : public MethodParametersBase<BlockPivotingParameters>
    {
    public:
      unsigned int p         = 10;
      double       tolerance = 1e-6; ///< epsilon in (67)

      void
      add_parameters(dealii::ParameterHandler &prm) override
      {
        prm.add_parameter("p",
                          p,
                          "Block iterations allowed without a decrease of "
                          "the infeasibility count before single pivots take "
                          "over (Judice & Pires; the paper takes 10).",
                          dealii::Patterns::Integer(1));
        prm.add_parameter("Tolerance",
                          tolerance,
                          "epsilon of the infeasibility set H (eq. 67).",
                          dealii::Patterns::Double(0));
      }
    };

    class BlockPivoting : public Solver
    {
    public:
      using Parameters = BlockPivotingParameters;

      BlockPivoting(const SolverParameters &parameters,
                    const Parameters       &options)
        : Solver(parameters)
        , options(options)
      {}

      static SolverInfo
      properties()
      {
        SolverInfo info;
        info.name               = "block_pivoting";
        info.label              = "block principal pivoting";
        info.description        = "block principal pivoting of Judice & Pires "
                                  "(Fernandes et al.), parameters p, tolerance";
        info.subsection         = "Block pivoting";
        info.default_iterations = "10|S| + 100";
        info.needs_definite_matrix = true;
        return info;
      }

      void
      solve(const Problem &problem,
            Solution      &solution,
            Report        &report,
            std::ostream  *progress) override
      {
        const Index        n   = problem.size();
        const Index        n_c = problem.n_constrained();
        const unsigned int p   = options.p;
        const double       eps = options.tolerance;

        // at_bound[i]: i in S (the bound set). Step 1: R = Jf.
        std::vector<char>  at_bound = problem.constrained_mask();
        std::vector<char>  saved_at_bound;
        std::vector<Index> H, saved_H;
        Index              ninf = n + 1;
        unsigned int       nit  = 0;

        ActiveSetSystem system(problem.A, report.counters);
        Vector         &z        = solution.u;
        z                        = Vector::Zero(n);
        const unsigned int limit = iteration_limit(10 * n_c + 100);
        for (unsigned int iteration = 1;; ++iteration)
          {
            // Step 2: the complementary basic solution (57).
            for (Index k = 0; k < n_c; ++k)
              if (at_bound[problem.constrained[k]])
                z[problem.constrained[k]] = problem.lower_bound[k];
            if (!system.solve(at_bound, problem.b, z))
              {
                report.status  = Status::singular;
                report.message = "block pivoting: C_RR is singular at "
                                 "iteration " +
                                 std::to_string(iteration);
                return;
              }
            report.iterations = iteration;
            const Vector w    = problem.A * z - problem.b;
            ++report.counters.matrix_vector_products;
            H.clear();
            for (Index k = 0; k < n_c; ++k)
              {
                const Index i = problem.constrained[k];
                if (at_bound[i] ? (w[i] < -eps) :
                                  (z[i] < problem.lower_bound[k] - eps))
                  H.push_back(i); // increasing, since S is sorted
              }
            if (progress != nullptr)
              *progress << "    block pivoting iteration " << iteration << ": "
                        << H.size() << " infeasibilities" << std::endl;
            if (H.empty())
              {
                report.status = Status::converged;
                return;
              }
            if (iteration >= limit)
              {
                report.status  = Status::iteration_limit;
                report.message = "block pivoting reached " +
                                 std::to_string(limit) + " iterations with " +
                                 std::to_string(H.size()) +
                                 " infeasibilities left";
                return;
              }

            const Index count = static_cast<Index>(H.size());
            bool        block = true;
            if (ninf > count)
              {
                ninf = count;
                nit  = 0;
              }
            else if (nit <= p)
              {
                if (nit == 1)
                  {
                    saved_at_bound = at_bound;
                    saved_H        = H;
                  }
              }
            else
              {
                if (nit == p + 1 && !saved_H.empty())
                  {
                    at_bound = saved_at_bound;
                    H        = saved_H;
                  }
                block = false;
              }

            if (block) // Step 3
              for (const Index i : H)
                at_bound[i] = !at_bound[i];
            else // Step 4
              at_bound[H.front()] = !at_bound[H.front()];
            ++nit;
          }
      }

    private:
      const Parameters options;
    };
  } // namespace

  UNILATERAL_REGISTER_SOLVER(BlockPivoting)
} // namespace unilateral::lcp
