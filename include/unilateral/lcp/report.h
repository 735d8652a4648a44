#pragma once

#include <unilateral/lcp/problem.h>

#include <chrono>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace unilateral::lcp
{
  enum class Status
  {
    converged,
    iteration_limit,
    infeasible, ///< the LCP has no solution (Graves' method proves it)
    singular,   ///< a reduced system could not be factorised
    inaccurate  ///< the method's own test passed, the KKT check did not
  };

  std::string
  to_string(Status status);

  /// Work counters: what ran, not how long it took (deterministic, testable).
  struct Counters
  {
    /// Fill-reducing orderings computed on their own (AMD).
    unsigned int orderings              = 0;
    unsigned int symbolic_analyses      = 0;
    unsigned int numeric_factorisations = 0;
    /// Systems solved with the factor of a nearby matrix as preconditioner
    /// instead of a new factorisation.
    unsigned int reused_factorisations = 0;
    /// Systems solved with a factor updated row by row from the previous
    /// active set's (CHOLMOD's rowadd/rowdel) instead of a new one.
    unsigned int modified_factorisations = 0;
    /// Rows and columns added to or deleted from a factor in those updates.
    unsigned int factor_row_modifications = 0;
    /// Sets of indices an active-set method could not settle, resolved
    /// exactly through their Schur complement (resolve_subset), and their
    /// total size.
    unsigned int resolved_subsets  = 0;
    unsigned int resolved_indices  = 0;
    unsigned int cg_iterations     = 0;
    unsigned int triangular_solves = 0; ///< one per right-hand side
    /// Right-hand sides solved forward only, along their elimination-tree
    /// paths (SparseCholesky::inverse_gram, for resolved subsets).
    unsigned int partial_forward_solves = 0;
    /// Gondzio's centrality correctors the interior point kept (one solve
    /// each with the iteration's factor).
    unsigned int centrality_correctors  = 0;
    unsigned int matrix_vector_products = 0;

    /// The work of another stage of the same solve, added.
    Counters &
    operator+=(const Counters &other);
  };

  /**
   * One report per solve: status, iterations, time per phase, relative KKT
   * residuals of the final iterate against the original (unregularised) A.
   */
  struct Report
  {
    std::string  solver;
    Status       status     = Status::converged;
    unsigned int iterations = 0;
    /// Iterations of the projection step (PDAS on A from u_eps), if it ran.
    unsigned int projection_iterations = 0;
    /// eps-continuation stages the projection needed (0 normally).
    unsigned int continuation_stages = 0;
    bool         projected           = false;
    /// False where no method ran: the scene proved before solving that the
    /// LCP has no solution, and u is the zero start.
    bool solved = true;
    /// Regularisation actually added to the diagonal (absolute), 0 if none.
    double       regularisation = 0;
    unsigned int n_active       = 0;
    double       energy         = 0;
    KktResiduals kkt;
    Counters     counters;
    /// Empty when converged; otherwise one line saying what went wrong.
    std::string message;
    /// Wall time per phase in seconds, in the order the phases first ran.
    std::vector<std::pair<std::string, double>> phase_times;
    /// A method's own figures, by name, in the order first set (TFETI:
    /// outer and inner iterations, products with F, the coarse problem's
    /// size and time); summary.json has them as "method".
    std::vector<std::pair<std::string, double>> figures;

    bool
    converged() const
    {
      return status == Status::converged;
    }

    void
    add_time(const std::string &phase, double seconds);

    /// Set the figure @p name (replacing its earlier value).
    void
    set_figure(const std::string &name, double value);

    /// Take @p other's iterations, projection iterations, continuation
    /// stages, projection flag and regularisation: where its answer is
    /// the one given (a verifier's, the Schur complement's solve).
    void
    take_counts_of(const Report &other);

    /// The phase times of @p other, each named with @p prefix in front.
    void
    add_times(const Report &other, const std::string &prefix = "");

    double
    total_time() const;
  };

  /// Adds the wall time of its lifetime to a phase of a Report.
  class PhaseTimer
  {
  public:
    PhaseTimer(Report &report, std::string phase)
      : report(report)
      , phase(std::move(phase))
      , start(std::chrono::steady_clock::now())
    {}

    ~PhaseTimer()
    {
      const std::chrono::duration<double> elapsed =
        std::chrono::steady_clock::now() - start;
      report.add_time(phase, elapsed.count());
    }

  private:
    Report                               &report;
    std::string                           phase;
    std::chrono::steady_clock::time_point start;
  };

  /**
   * The primal-dual solution: u, lambda = A u - b on S (zero elsewhere), and
   * the active set: indices of S where u sits at its bound, or (for
   * interior-point iterates) where the slack times A_ii is below lambda_i.
   * On entry, u of the right size is the start of the methods that take one
   * (PDAS, PSOR), and a non-empty active_set with it is PDAS's first active
   * set, in place of the test on u (a start from a coarser mesh, whose
   * multipliers would be noise on this one).
   */
  struct ActiveSetFactor;

  struct Solution
  {
    Vector             u;
    Vector             lambda;
    std::vector<Index> active_set;
    /// The last factorisation of an active-set method, or the analysis of
    /// an interior-point method's Newton matrix (with its factor's storage),
    /// handed to a follow-up solve on a nearby matrix (the projection
    /// step).
    std::shared_ptr<const ActiveSetFactor> factor;
  };
} // namespace unilateral::lcp
