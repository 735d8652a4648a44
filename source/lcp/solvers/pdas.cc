/**
 * Primal-dual active set method (Hintermueller, Ito & Kunisch), as given by
 * Ainsworth & Mihai, Section 4 "PDAS". In our sign convention (lambda =
 * -Sigma, slack u - l):
 *   Step 2: lambda = A u - b;
 *           active SZ = {i in S : (u_i - l_i) - tau lambda_i < 0}
 *   Step 3: stop if iter >= 1 and SZ did not change (then u_SZ = l_SZ,
 *           lambda_SP = 0, and the new sets certify feasibility)
 *   Step 4: solve A_FF u_F = b_F - A_F,SZ l_SZ with u_SZ = l_SZ.
 * solve() is that loop. The safeguards the paper does not have are named
 * pieces below, each saying when it fires and why (all but the first are
 * switched off by 'Safeguard = 0'):
 *  - RoundingTest: Step 2 with a rounding tolerance, so that degenerate
 *    indices (at the bound with zero multiplier) do not flip sides forever;
 *  - ViolationHistory: the number of violated indices and which indices
 *    changed side; from it
 *  - CyclingStop: at the default iteration limit, PDAS stops as cycling
 *    where no safeguard can end the cycle, and the driver hands over to the
 *    interior point (the registration declares it);
 *  - the cycle resolution: after 'Safeguard' iterations without a new low
 *    of that number, the indices that changed side meanwhile are resolved
 *    exactly at once (resolve_subset), or, if that fails, Judice & Pires'
 *    single pivot changes only the least index (finite for definite A);
 *  - the creep resolution: a few violated indices that do not halve in
 *    number (the boundary of a separated zone drifting by a node per
 *    iteration) are resolved with their neighbours;
 *  - the free-motion resolution: a Step 4 whose system is singular (a body
 *    left unsupported) resolves the open constraints the free motion moves.
 * The same routine is the projection step when run on A from u_eps.
 */
#include <unilateral/base/input_error.h>
#include <unilateral/base/text.h>
#include <unilateral/lcp/active_set_system.h>
#include <unilateral/lcp/answer_checks.h>
#include <unilateral/lcp/solver.h>
#include <unilateral/lcp/subset_resolution.h>
#include <unilateral/lcp/unbounded_direction.h>

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <ostream>

namespace unilateral::lcp
{
  namespace
  {
    /// Subsection "Solver/PDAS".
    class PdasParameters : public MethodParametersBase<PdasParameters>
    {
    public:
      double tau = 1e-3;
      /// "auto", "zero" or "all active".
      std::string start = "auto";
      /// Relative rounding tolerance of the active-set test (RoundingTest).
      double round_off = 1e-12;
      /// Iterations without a new low before the cycle is resolved; 0: the
      /// paper's PDAS without safeguards.
      unsigned int safeguard = 10;

      void
      add_parameters(dealii::ParameterHandler &prm) override
      {
        using namespace dealii::Patterns;
        prm.add_parameter("Tau",
                          tau,
                          "tau > 0 of the active-set test u_i - l_i - tau "
                          "lambda_i < 0 (Ainsworth & Mihai: tau ~ 1e-3). Also "
                          "used by the projection step.",
                          Double(0));
        prm.add_parameter(
          "Start",
          start,
          "The initial iterate u0 (Ainsworth & Mihai allow any u0 with u0_S "
          ">= l_S). 'zero': u0 = 0, as in the paper. 'all active': u0 "
          "minimises the energy with every constraint at its bound (the start "
          "of LSSNN and block pivoting); the first active set is then the set "
          "of compressed contacts, which for walls in contact almost "
          "everywhere is nearly the answer (stack bond m = 50 and 100: 1 "
          "iteration instead of 5; at m = 225 both starts take 5) but for an "
          "obstacle touched on a third "
          "of its nodes is worse (34 instead of 24). 'auto': 'all active' "
          "where the scene expects contact almost everywhere (masonry), "
          "'zero' otherwise.",
          Selection("auto|zero|all active"));
        prm.add_parameter(
          "Round-off tolerance",
          round_off,
          "An index changes side only if it violates it by more than this "
          "times the magnitude of the terms of its multiplier, sum_j |A_ij "
          "u_j| + |b_i| (the slack in the same units). Without it, a closed "
          "contact carrying exactly zero force (the top of a wall's vertical "
          "joints, an obstacle node touched with no pressure) flips sides on "
          "round-off and PDAS never stops. 0 compares exactly, as the paper.",
          Double(0, 1e-3));
        prm.add_parameter(
          "Safeguard",
          safeguard,
          "After this many iterations without a new low in the number of "
          "violated indices (above 1000 violated, a new low must be a tenth "
          "lower), the indices that changed side meanwhile are resolved "
          "exactly at once (Schur complement on them, Graves' method); a "
          "singular step resolves the open constraints its free motion "
          "moves; at most 1000 violated indices that do not halve in number "
          "within 4 iterations (a creeping boundary of a separated zone) "
          "resolve those that changed side in them, with their neighbours. A "
          "cycle of more than 1000 indices, or more than 1000 violated "
          "indices whose fewest do not halve within 8 iterations, ends PDAS "
          "as cycling at the default 'Maximum iterations', and the solve "
          "continues from the interior point's answer (noted in the report); "
          "with a limit set, Judice & Pires' single pivots take over instead. "
          "0: the paper's PDAS without any of these.",
          Integer(0));
      }

      void
      check(const std::string &section) const override
      {
        check_parameter(tau > 0, section, "Tau", tau, "must be > 0");
      }
    };

    /**
     * Step 2 with a rounding tolerance: index i changes side only if
     * u_i - l_i - tau lambda_i is beyond +-tolerance_i, the rounding error
     * of lambda_i (and of the slack, lambda_i / A_ii) at the size of its
     * terms. A closed contact carrying exactly zero force otherwise flips
     * sides on round-off, and PDAS never stops. A free index below its bound
     * by more than the slack's own rounding error becomes active: the
     * tolerance of the multiplier's term must not let an infeasible u pass.
     * Nor a pulling contact (balance_limit): an active index whose multiplier
     * is negative beyond what the driver's balance check allows is freed
     * whatever the rounding tolerance says, when nothing else changes. Where
     * |A| |u| is far larger than the forces (a plate of elements 2000 times
     * longer than wide: A_ii 1e14 against loads of 1), the tolerance,
     * 'Round-off tolerance' times |A| |u|, exceeds the contact forces
     * themselves; PDAS then stopped with a contact pulling at 3e-4 of the
     * largest force, which the driver refused as 'inaccurate'.
     */
    class RoundingTest
    {
    public:
      RoundingTest(const Problem        &problem,
                   const PdasParameters &options,
                   const double          kkt_tolerance)
        : problem(problem)
        , tau(options.tau)
        , round_off(options.round_off)
        , kkt_tolerance(kkt_tolerance)
      {}

      /// The constrained indices on the wrong side of the test.
      std::vector<Index>
      violated(const Vector &u, const std::vector<char> &active) const
      {
        const Vector       lambda = problem.A * u - problem.b;
        std::vector<Index> result;
        std::vector<Index> pulling;
        // Below this no multiplier can fail the balance check (its
        // allowance is at least the tolerance times the loads).
        const double least_allowance =
          kkt_tolerance * problem.b.lpNorm<Eigen::Infinity>();
        for (Index k = 0; k < problem.n_constrained(); ++k)
          {
            const Index i         = problem.constrained[k];
            double      magnitude = std::abs(problem.b[i]);
            double      diagonal  = 0;
            for (SparseMatrix::InnerIterator entry(problem.A, i); entry;
                 ++entry)
              {
                magnitude += std::abs(entry.value() * u[entry.row()]);
                if (entry.row() == i)
                  diagonal = entry.value();
              }
            const double slack_rounding =
              round_off * magnitude * (diagonal > 0 ? 1.0 / diagonal : 0.0);
            const double tolerance =
              slack_rounding + round_off * magnitude * tau;
            const double slack = u[i] - problem.lower_bound[k];
            const double test  = slack - tau * lambda[i];
            // An exact tie stays on its side (resolve_subset sends ties to
            // the active side; flipping them back would undo it). A free
            // index whose value alone lies below its bound beyond rounding
            // joins the active set whatever its multiplier: tau lambda's
            // share of the tolerance can exceed the slack's own where A_ii
            // tau >> 1 (the fine plate), and the test would then accept an
            // infeasible u.
            const bool now_active =
              active[i] ? test <= tolerance :
                          test < -tolerance || slack < -slack_rounding;
            if (now_active != static_cast<bool>(active[i]))
              result.push_back(i);
            else if (active[i] && lambda[i] < -least_allowance)
              pulling.push_back(i);
          }
        return balance_limit(u, lambda, pulling, result);
      }

    private:
      /// @p result with the @p pulling active indices added whose
      /// multiplier the driver's balance check would refuse.
      std::vector<Index>
      balance_limit(const Vector             &u,
                    const Vector             &lambda,
                    const std::vector<Index> &pulling,
                    std::vector<Index>        result) const
      {
        // Only where PDAS would otherwise stop: earlier, the multipliers of
        // an active set still changing are not the answer's.
        if (pulling.empty() || !result.empty())
          return result;
        const double allowance =
          balance_allowance(problem, u, lambda, kkt_tolerance);
        for (const Index i : pulling) // ascending, as the test's result
          if (lambda[i] < -allowance)
            result.push_back(i);
        return result;
      }

      const Problem &problem;
      const double   tau;
      const double   round_off;
      const double   kkt_tolerance;
    };

    /**
     * How the number of violated indices developed, and which indices
     * changed side: since that number last reached a new low (the cycle),
     * and in each of the last creep_window iterations. What the safeguards
     * decide from.
     */
    class ViolationHistory
    {
    public:
      /// Up to max_resolved_subset violated indices, a count that has not
      /// halved within this many iterations is creeping: a few dozen
      /// contacts flip back and forth while the boundary of a separated
      /// zone drifts by a node per iteration or two.
      static constexpr unsigned int creep_window = 4;

      explicit ViolationHistory(const Index n)
        : in_cycle(n, 0)
      {}

      /// Iterations since the count last reached a new low.
      unsigned int without_progress = 0;
      /// The same, restarted by each exact resolution of the cycle.
      unsigned int stalled = 0;
      /// The lowest count reached (a new low above max_resolved_subset must
      /// be a tenth lower).
      Index fewest_violations;
      /// The fewest violated indices up to each iteration.
      std::vector<Index> fewest_so_far;
      /// The indices that changed side since the last new low.
      std::vector<Index> cycle;
      /// The indices that changed side in each of the last creep_window
      /// iterations (since the last exact resolution).
      std::deque<std::vector<Index>> recent_changes;

      /// The count of this iteration (every iteration, before the stops).
      void
      count(const Index n_violated)
      {
        fewest_so_far.push_back(fewest_so_far.empty() ?
                                  n_violated :
                                  std::min(fewest_so_far.back(), n_violated));
      }

      /// The fewest violated up to @p iterations_ago iterations before this
      /// one (0 if there were none).
      Index
      fewest_before(const unsigned int iterations_ago) const
      {
        return fewest_so_far.size() > iterations_ago ?
                 fewest_so_far[fewest_so_far.size() - 1 - iterations_ago] :
                 0;
      }

      /**
       * A new low, or not, of @p violated (from the second iteration, with
       * safeguards on). Above max_resolved_subset only a drop by a tenth
       * counts: a count that creeps down by a few percent while thousands
       * change side (running bond walls) is wandering.
       */
      void
      record(const std::vector<Index> &violated)
      {
        const Index n_violated = static_cast<Index>(violated.size());
        const bool  new_low =
          n_violated < fewest_violations &&
          (n_violated <= max_resolved_subset ||
           n_violated < 0.9 * static_cast<double>(fewest_violations));
        if (new_low)
          {
            fewest_violations = n_violated;
            without_progress = stalled = 0;
            for (const Index i : cycle)
              in_cycle[i] = 0;
            cycle.clear();
          }
        else
          ++without_progress;
        add_to_cycle(violated);
      }

      void
      add_to_cycle(const std::vector<Index> &indices)
      {
        for (const Index i : indices)
          if (!in_cycle[i])
            {
              in_cycle[i] = 1;
              cycle.push_back(i);
            }
      }

      /// Remember what changed side in this iteration, or forget the recent
      /// changes after an exact resolution.
      void
      remember_changes(const std::vector<Index> &violated, const bool resolved)
      {
        if (resolved)
          recent_changes.clear();
        else
          {
            recent_changes.push_back(violated);
            if (recent_changes.size() > creep_window)
              recent_changes.pop_front();
          }
      }

      /// At most max_resolved_subset violated indices that have not halved
      /// in number within creep_window iterations.
      bool
      creeping(const Index n_violated) const
      {
        return n_violated <= max_resolved_subset &&
               recent_changes.size() == creep_window &&
               fewest_so_far.back() >
                 0.5 * static_cast<double>(fewest_before(creep_window));
      }

    private:
      std::vector<char> in_cycle;
    };

    /**
     * PDAS stops as cycling, at the default iteration limit only, where no
     * exact resolution can end the cycle: each iteration costs a
     * factorisation while thousands of indices change side. The driver then
     * continues from the interior point (the registration's hand-over).
     */
    class CyclingStop
    {
    public:
      /// Iterations without a new low after which PDAS stops.
      static constexpr unsigned int wandering_limit = 50;

      /// Above max_resolved_subset violated indices, PDAS stops unless the
      /// fewest violated so far halve within this many iterations: long
      /// enough for a wall that converges slowly (the laminae), short
      /// enough not to spend many factorisations on one that cycles (the
      /// running bond; measured in README.md, "PDAS safeguards").
      static constexpr unsigned int halving_window = 8;

      /// Wandering: no new low for long, exact resolutions included (a
      /// cycle too large to resolve). Checked before the count.
      static std::string
      wandering(const ViolationHistory &history)
      {
        if (history.without_progress <= wandering_limit)
          return "";
        return "PDAS did not settle: the number of violated constraints has "
               "not reached a new low below " +
               std::to_string(history.fewest_violations) + " in " +
               std::to_string(wandering_limit) + " iterations (cycling)";
      }

      /// Slow progress above what can be resolved at once: thousands of
      /// indices change side each iteration while their number falls by a
      /// few percent (balanced bricks).
      static std::string
      not_halving(const ViolationHistory &history)
      {
        const Index fewest = history.fewest_so_far.back();
        const Index before = history.fewest_before(halving_window);
        if (history.fewest_so_far.size() <= halving_window ||
            fewest <= max_resolved_subset ||
            fewest <= 0.5 * static_cast<double>(before))
          return "";
        return "PDAS did not settle: the fewest violated constraints fell "
               "only from " +
               std::to_string(before) + " to " + std::to_string(fewest) +
               " in " + std::to_string(halving_window) +
               " iterations, too many to resolve at once (cycling)";
      }

      /// A cycle too large to resolve, where single pivots would take
      /// thousands of factorisations.
      static std::string
      unresolvable_cycle(const ViolationHistory &history)
      {
        if (static_cast<Index>(history.cycle.size()) <= max_resolved_subset)
          return "";
        return "PDAS did not settle: " + std::to_string(history.cycle.size()) +
               " constraints changed side in the " +
               std::to_string(history.without_progress) +
               " iterations since the number of violated ones last reached a "
               "new low (" +
               std::to_string(history.fewest_violations) +
               "), too many to resolve at once (cycling)";
      }
    };

    class Pdas : public Solver
    {
    public:
      using Parameters = PdasParameters;

      Pdas(const SolverParameters &parameters, const Parameters &options)
        : Solver(parameters)
        , options(options)
      {}

      static SolverInfo
      properties()
      {
        SolverInfo info;
        info.name        = "pdas";
        info.label       = "PDAS";
        info.description = "primal-dual active set (Hintermueller et al.; "
                           "Ainsworth & Mihai), parameter tau";
        info.subsection  = "PDAS";
        info.default_iterations           = "500";
        info.is_default                   = true;
        info.needs_definite_matrix        = true;
        info.warm_start                   = true;
        info.finishes_approximate_answers = true;
        // Where PDAS stops as cycling (CyclingStop), the interior point
        // converges whatever the start; the projection from its answer is
        // PDAS again, near the solution. Mehrotra's variant: far fewer
        // iterations on the degenerate walls where PDAS cycles.
        FollowUp hand_over;
        hand_over.kind                  = FollowUp::Kind::hand_over;
        hand_over.when                  = Status::iteration_limit;
        hand_over.only_at_default_limit = true;
        hand_over.method                = "interior_point";
        hand_over.settings              = {
                       {"Interior point/Variant", "predictor-corrector"}};
        info.follow_ups.push_back(hand_over);
        // A system that stays singular means that no active set PDAS
        // tried holds every body: the LCP may have no solution at all,
        // which Graves' Case 2 proves (where it can take the problem).
        FollowUp proof;
        proof.kind   = FollowUp::Kind::verification;
        proof.when   = Status::singular;
        proof.method = "graves";
        info.follow_ups.push_back(proof);
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
     * The state of one PDAS solve: the iterate, the active set, the linear
     * systems of Step 4 and the history the safeguards read. Each step and
     * each safeguard is one member function.
     */
    class PdasIteration
    {
    public:
      PdasIteration(const Problem          &problem,
                    const SolverParameters &parameters,
                    const PdasParameters   &options,
                    Solution               &solution,
                    Report                 &report)
        : problem(problem)
        , options(options)
        , safeguards_on(options.safeguard > 0)
        , stop_as_cycling(safeguards_on && parameters.max_iterations == 0)
        , kkt_tolerance(parameters.kkt_tolerance)
        , report(report)
        , u(solution.u)
        // The system owns the given factor while it runs (solution.factor
        // is set again at the end), so that the factor is freed as soon as
        // the system factorises its own: two factors at once would set the
        // peak memory of the largest problems.
        , system(problem.A, report.counters, std::move(solution.factor))
        // Ties go to the active side: before the first test every index
        // counts as active, so an index at its bound with a zero multiplier
        // (up to round-off) stays there. An active degenerate contact costs
        // nothing; an inactive one can leave a body unsupported.
        , active(problem.constrained_mask())
        , history(problem.size())
      {
        history.fewest_violations = problem.n_constrained() + 1;
      }

      /**
       * Step 1, u0: a given iterate (the projection step's u_eps, a warm
       * start), or else the 'Start' parameter's, moved onto the feasible
       * set. A given first active set (with the start) replaces the first
       * test. False if the all-active start is singular.
       */
      bool
      start(Solution &solution)
      {
        const Index n           = problem.size();
        const bool  start_given = u.size() == n;
        if (start_given && !solution.active_set.empty())
          {
            given_active.assign(n, 0);
            for (const Index i : solution.active_set)
              given_active[i] = 1;
          }
        solution.active_set.clear();
        if (start_given)
          return true;
        u = Vector::Zero(n);
        for (Index k = 0; k < problem.n_constrained(); ++k)
          u[problem.constrained[k]] = std::max(0.0, problem.lower_bound[k]);
        const bool all_active =
          options.start == "all active" ||
          (options.start == "auto" && problem.mostly_active);
        if (!all_active)
          return true;
        // u0: the minimiser with every constraint at its bound.
        for (Index k = 0; k < problem.n_constrained(); ++k)
          u[problem.constrained[k]] = problem.lower_bound[k];
        return system.solve(active, problem.b, u);
      }

      /// Step 2: the indices whose side changes; at the first iteration
      /// with a given active set, those where it differs.
      std::vector<Index>
      violated(const unsigned int iteration)
      {
        if (iteration > 0 || given_active.empty())
          {
            ++report.counters.matrix_vector_products; // lambda = A u - b
            return RoundingTest(problem, options, kkt_tolerance)
              .violated(u, active);
          }
        std::vector<Index> result;
        for (const Index i : problem.constrained)
          if (active[i] != given_active[i])
            result.push_back(i);
        return result;
      }

      /**
       * The reason to stop before Step 3 (empty if none): cycling
       * (CyclingStop) or the iteration limit. Records the iteration's count.
       */
      std::string
      stop_reason(const unsigned int        iteration,
                  const unsigned int        limit,
                  const std::vector<Index> &violated)
      {
        if (stop_as_cycling)
          if (std::string reason = CyclingStop::wandering(history);
              !reason.empty())
            return reason;
        history.count(static_cast<Index>(violated.size()));
        if (stop_as_cycling)
          if (std::string reason = CyclingStop::not_halving(history);
              !reason.empty())
            return reason;
        if (iteration >= limit)
          return "PDAS did not settle on an active set in " +
                 quantity(limit, "iteration") +
                 " (last change: " + std::to_string(violated.size()) +
                 " indices)";
        return "";
      }

      /// How Step 3 changed the active set.
      enum class Change
      {
        every_violated, ///< the paper's step
        least_index,    ///< Judice & Pires' single pivot
        resolved        ///< an exact resolution (resolve_subset)
      };

      /**
       * Step 3, safeguarded: every violated index changes side while their
       * number reaches new lows often enough. After 'Safeguard' iterations
       * without, the cycle is resolved exactly; if it is too large (or that
       * fails), only the least violated index changes (Murty's rule, finite
       * for definite A) or, at the default limit, PDAS stops as cycling
       * (@p stop gets the reason). A creeping count is resolved with its
       * neighbours.
       */
      Change
      change_active_set(const unsigned int iteration,
                        std::vector<Index> violated,
                        std::string       &stop)
      {
        Change change = Change::every_violated;
        if (iteration >= 1 && safeguards_on)
          {
            history.record(violated);
            if (history.without_progress > 0 &&
                ++history.stalled > options.safeguard)
              {
                change          = resolve(history.cycle) ? Change::resolved :
                                                           Change::least_index;
                history.stalled = 0;
                if (change == Change::least_index && stop_as_cycling)
                  {
                    stop = CyclingStop::unresolvable_cycle(history);
                    if (!stop.empty())
                      return change;
                  }
              }
            if (change == Change::every_violated &&
                history.creeping(static_cast<Index>(violated.size())))
              change = resolve(creeping_subset(violated)) ?
                         Change::resolved :
                         Change::every_violated;
          }
        history.remember_changes(violated, change == Change::resolved);
        if (change != Change::resolved)
          {
            if (change == Change::least_index)
              violated.resize(1); // the constrained indices are sorted
            for (const Index i : violated)
              active[i] = !active[i];
          }
        return change;
      }

      /**
       * Step 4 with u_SZ = l_SZ. A singular system means that the active
       * set leaves some body free to move: a freed index took its support,
       * or (from an interior point or a regularised answer, where the
       * solution is not unique) a contact closed without force that alone
       * kept a brick from rotating lies slightly open. The open constrained
       * indices that the free motion moves are then resolved exactly, with
       * the rest kept (a few times, if that frees another body). False if
       * the system stays singular, or if the free motion is one along which
       * the loads drive the unknowns without bound (then no_solution says
       * so: the LCP has none).
       */
      bool
      solve_step(const unsigned int iteration,
                 Change            &change,
                 std::ostream      *progress)
      {
        bool solved = solve_with_active_at_bounds();
        for (unsigned int attempt = 0; !solved && safeguards_on && attempt < 3;
             ++attempt)
          {
            Vector       driven;
            const Vector free_motion =
              system.near_null_direction(active, &problem.b, &driven);
            no_solution = unbounded_direction(problem, driven);
            if (!no_solution.empty())
              break;
            const std::vector<Index> subset = moved_by_free_motion(free_motion);
            history.add_to_cycle(subset);
            if (progress != nullptr)
              *progress << "    pdas iteration " << iteration + 1
                        << ": singular system; " << subset.size()
                        << " open constraints move with the free motion"
                        << (static_cast<Index>(subset.size()) >
                                max_resolved_subset ?
                              ", too many to resolve" :
                              ", resolving them exactly")
                        << std::endl;
            if (subset.empty() || !resolve(subset))
              break;
            change = Change::resolved;
            solved = solve_with_active_at_bounds();
          }
        return solved;
      }

      Index
      n_active() const
      {
        Index result = 0;
        for (const Index i : problem.constrained)
          result += active[i];
        return result;
      }

      std::shared_ptr<const ActiveSetFactor>
      factor() const
      {
        return system.factor();
      }

      /// The size of the last subset resolved exactly.
      std::size_t resolved_size = 0;
      /// Set where a singular system's free motion proves that the LCP has
      /// no solution (unbounded_direction.h): what it proves.
      std::string no_solution;

    private:
      // Resolve U exactly (see resolve_subset); false if that failed.
      bool
      resolve(std::vector<Index> subset)
      {
        resolved_size = subset.size();
        std::sort(subset.begin(), subset.end());
        if (static_cast<Index>(subset.size()) > max_resolved_subset ||
            resolve_subset(problem, system, subset, active, report.counters) !=
              SubsetResolution::resolved)
          return false;
        ++report.counters.resolved_subsets;
        report.counters.resolved_indices +=
          static_cast<unsigned int>(subset.size());
        return true;
      }

      /// What changed side in the creep window and now, and the constrained
      /// indices A couples to these: the drifting boundary moves on to the
      /// neighbours.
      std::vector<Index>
      creeping_subset(const std::vector<Index> &violated) const
      {
        std::vector<char>  in_subset(problem.size(), 0);
        std::vector<Index> subset;
        const auto         add = [&](const Index i) {
          if (!in_subset[i])
            {
              in_subset[i] = 1;
              subset.push_back(i);
            }
        };
        for (const auto &changes : history.recent_changes)
          for (const Index i : changes)
            add(i);
        for (const Index i : violated)
          add(i);
        const std::vector<char> is_constrained = problem.constrained_mask();
        const std::size_t       changed        = subset.size();
        for (std::size_t q = 0; q < changed; ++q)
          for (SparseMatrix::InnerIterator it(problem.A, subset[q]); it; ++it)
            if (is_constrained[it.row()])
              add(it.row());
        return subset;
      }

      bool
      solve_with_active_at_bounds()
      {
        for (Index k = 0; k < problem.n_constrained(); ++k)
          if (active[problem.constrained[k]])
            u[problem.constrained[k]] = problem.lower_bound[k];
        return system.solve(active, problem.b, u);
      }

      /// The open constraints @p free_motion of the singular system moves.
      std::vector<Index>
      moved_by_free_motion(const Vector &free_motion) const
      {
        std::vector<Index> subset;
        if (free_motion.size() == problem.size())
          for (const Index i : problem.constrained)
            if (!active[i] && std::abs(free_motion[i]) > 1e-6)
              subset.push_back(i);
        return subset;
      }

      const Problem        &problem;
      const PdasParameters &options;
      const bool            safeguards_on;
      /// At the default iteration limit PDAS stops as cycling (CyclingStop).
      const bool stop_as_cycling;
      /// 'Solver/KKT tolerance', which the active-set test's balance_limit
      /// applies.
      const double      kkt_tolerance;
      Report           &report;
      Vector           &u;
      ActiveSetSystem   system;
      std::vector<char> active;
      std::vector<char> given_active;
      ViolationHistory  history;
    };

    void
    Pdas::solve(const Problem &problem,
                Solution      &solution,
                Report        &report,
                std::ostream  *progress)
    {
      PdasIteration pdas(problem, parameters, options, solution, report);
      // The first system's ordering and factorisation come before the
      // first iteration's line, seconds on large problems (a review: 8 s
      // without a line at m = 100).
      if (progress != nullptr)
        *progress << "    pdas: factorising its first system ("
                  << problem.size() << " unknowns)" << std::endl;
      if (!pdas.start(solution))
        {
          report.status  = Status::singular;
          report.message = "PDAS: the system with every constraint active "
                           "is singular";
          return;
        }
      const unsigned int limit = iteration_limit(500);
      for (unsigned int iteration = 0;; ++iteration)
        {
          // Step 2.
          const std::vector<Index> violated = pdas.violated(iteration);
          if (iteration >= 1 && violated.empty())
            {
              report.status = Status::converged;
              break;
            }
          std::string stop = pdas.stop_reason(iteration, limit, violated);
          // Step 3.
          auto change = PdasIteration::Change::every_violated;
          if (stop.empty())
            change = pdas.change_active_set(iteration, violated, stop);
          if (!stop.empty())
            {
              report.status  = Status::iteration_limit;
              report.message = stop;
              break;
            }
          // Step 4.
          if (!pdas.solve_step(iteration, change, progress))
            {
              if (!pdas.no_solution.empty())
                {
                  report.status     = Status::infeasible;
                  report.message    = "PDAS: " + pdas.no_solution;
                  report.iterations = iteration + 1;
                  break;
                }
              report.status = Status::singular;
              report.message =
                "PDAS: the reduced system A_FF is singular for the active "
                "set of iteration " +
                std::to_string(iteration + 1) + " (" + singular_cause(problem) +
                ")";
              break;
            }
          report.iterations = iteration + 1;
          if (progress != nullptr)
            {
              *progress << "    pdas iteration " << iteration + 1
                        << ": active set " << pdas.n_active() << ", ";
              if (change == PdasIteration::Change::resolved)
                *progress << "resolved " << pdas.resolved_size
                          << " indices exactly";
              else
                *progress << "changed " << violated.size()
                          << (change == PdasIteration::Change::least_index ?
                                " (safeguard: least index)" :
                                "");
              *progress << std::endl;
            }
        }
      solution.factor = pdas.factor();
    }
  } // namespace

  UNILATERAL_REGISTER_SOLVER(Pdas)
} // namespace unilateral::lcp
