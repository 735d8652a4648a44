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

#include <ostream>

namespace unilateral::lcp
{
  namespace
  {
    class BlockPivoting : public Solver
    {
    public:
      using Solver::Solver;

      void
      solve(const Problem &problem,
            Solution      &solution,
            Report        &report,
            std::ostream  *progress) override
      {
        const Index        n   = problem.size();
        const Index        n_c = problem.n_constrained();
        const unsigned int p   = parameters.block_pivoting.p;
        const double       eps = parameters.block_pivoting.tolerance;

        // at_bound[i]: i in S (the bound set). Step 1: R = Jf.
        std::vector<char> at_bound = problem.constrained_mask();
        std::vector<char> saved_at_bound;
        std::vector<Index> H, saved_H;
        Index              ninf = n + 1;
        unsigned int       nit  = 0;

        ActiveSetSystem system(problem.A, report.counters);
        Vector         &z     = solution.u;
        z                     = Vector::Zero(n);
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
              *progress << "    block pivoting iteration " << iteration
                        << ": " << H.size() << " infeasibilities"
                        << std::endl;
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
    };
  } // namespace

  UNILATERAL_REGISTER_SOLVER(BlockPivoting,
                             "block_pivoting",
                             "block principal pivoting of Judice & Pires "
                             "(Fernandes et al.), parameters p, tolerance",
                             true,
                             false,
                             true,
                             0,
                             false)
} // namespace unilateral::lcp
