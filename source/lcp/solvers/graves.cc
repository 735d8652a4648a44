/**
 * Graves' principal pivoting simplex method (Ainsworth & Mihai, Section 4),
 * dense, for LCPs in which every unknown is constrained: in practice the
 * reduced Schur-complement LCP ('Solver/Schur complement = true'). The
 * algorithm is principal_pivoting(), which PDAS's exact resolutions use too.
 */
#include <unilateral/base/input_error.h>
#include <unilateral/lcp/principal_pivoting.h>
#include <unilateral/lcp/solver.h>

namespace unilateral::lcp
{
  namespace
  {
    class Graves : public Solver
    {
    public:
      using Parameters = NoParameters;

      Graves(const SolverParameters &parameters, const Parameters &)
        : Solver(parameters)
      {}

      static SolverInfo
      properties()
      {
        SolverInfo info;
        info.name  = "graves";
        info.label = "Graves";
        info.description =
          "Graves' principal pivoting simplex method, dense, lexicographic "
          "(use with 'Schur complement')";
        info.default_iterations        = "10|S| + 100";
        info.dense                     = true;
        info.every_unknown_constrained = true;
        info.single_pivot              = true;
        // Case 2 can claim that no solution exists through round-off
        // (Ainsworth & Mihai: running bond, m = 5, without load): PDAS,
        // which never makes that claim, checks it.
        FollowUp check;
        check.kind   = FollowUp::Kind::verification;
        check.when   = Status::infeasible;
        check.method = "pdas";
        info.follow_ups.push_back(check);
        return info;
      }

      void
      solve(const Problem &problem,
            Solution      &solution,
            Report        &report,
            std::ostream  *progress) override
      {
        const Index n = problem.size();
        if (problem.n_constrained() != n)
          throw InputError(
            "graves solves LCPs in which every unknown is constrained; this "
            "one has " +
            std::to_string(n - problem.n_constrained()) +
            " unconstrained unknowns: set 'Solver/Schur complement = true'");
        principal_pivoting(
          problem, iteration_limit(10 * n + 100), solution, report, progress);
      }
    };
  } // namespace

  UNILATERAL_REGISTER_SOLVER(Graves)
} // namespace unilateral::lcp
