/**
 * Primal-dual active set method (Hintermueller, Ito & Kunisch), as given by
 * Ainsworth & Mihai, Section 4 "PDAS". In our sign convention (lambda = -Sigma,
 * slack u - l):
 *   Step 2: lambda = A u - b; active SZ = {i in S : (u_i - l_i) - tau lambda_i < 0}
 *   Step 3: stop if iter >= 1 and SZ did not change (then u_SZ = l_SZ,
 *           lambda_SP = 0, and the new sets certify feasibility)
 *   Step 4: solve A_FF u_F = b_F - A_F,SZ l_SZ with u_SZ = l_SZ.
 * Safeguards the paper does not have (each can be switched off): the test
 * of Step 2 has a rounding tolerance, so degenerate indices (at the bound
 * with zero multiplier) do not flip sides forever. When the number of
 * violated indices stops falling, the indices that changed side meanwhile
 * (the cycle) are resolved exactly at once, with the rest kept
 * (resolve_subset); a step whose system is singular (a freed index left a
 * body unsupported) is resolved the same way, and so are the indices that
 * changed side in the last few iterations, with their neighbours, when a
 * few hundred violated indices do not halve in number (creep). Above
 * max_resolved_subset violated indices only a drop by a tenth counts as a
 * new low, and the
 * fewest violated must halve within halving_window iterations. A cycle
 * beyond max_resolved_subset indices ends PDAS as cycling at the default
 * iteration limit (the driver continues from an interior point); with a
 * limit set, Judice & Pires' single-pivot rule takes over until the count
 * falls again, which makes the method terminate on definite matrices.
 * The same routine is the projection step when run on A from u_eps.
 */
#include <unilateral/lcp/active_set_system.h>
#include <unilateral/lcp/solver.h>
#include <unilateral/lcp/subset_resolution.h>

#include <algorithm>
#include <cmath>
#include <deque>
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

      /// Above max_resolved_subset violated indices, PDAS (at its default
      /// iteration limit) stops as cycling unless the fewest violated so far
      /// halve within this many iterations. Running bond m = 225: 15757,
      /// 11667, ..., 7573 at the 10th iteration, then 26 more to 6181
      /// (86 s) before the stall test saw it; laminae m = 225 halve within
      /// 7 (2405 at the 3rd, 1179 at the 10th) and go on to converge.
      static constexpr unsigned int halving_window = 8;

      /// Up to max_resolved_subset violated indices, a count that has not
      /// halved within this many iterations is creeping: a few dozen
      /// contacts flip back and forth while the boundary of a separated
      /// zone drifts by a node per iteration or two (laminae m = 225: 60
      /// violated at the 15th iteration, 1 at the 56th). The indices that
      /// changed side in these iterations are then resolved exactly.
      static constexpr unsigned int creep_window = 4;

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
        // Iterations since the last new low of the violation count; the
        // stall counter restarts after each exact resolution.
        unsigned int       without_progress = 0, stalled = 0;
        // The fewest violated indices up to each iteration.
        std::vector<Index> fewest_so_far;
        // The indices that changed side since the last new low: the cycle.
        std::vector<char>  in_cycle(n, 0);
        std::vector<Index> cycle;
        // The indices that changed side in each of the last creep_window
        // iterations (since the last exact resolution).
        std::deque<std::vector<Index>> recent_changes;
        const std::vector<char> is_constrained = problem.constrained_mask();
        const auto add_to_cycle = [&](const std::vector<Index> &indices) {
          for (const Index i : indices)
            if (!in_cycle[i])
              {
                in_cycle[i] = 1;
                cycle.push_back(i);
              }
        };
        // Resolve U exactly (see resolve_subset); false if that failed.
        std::size_t resolved_size = 0;
        const auto  resolve       = [&](std::vector<Index> subset) {
          resolved_size = subset.size();
          std::sort(subset.begin(), subset.end());
          if (static_cast<Index>(subset.size()) > max_resolved_subset ||
              resolve_subset(problem, system, subset, active,
                             report.counters) != SubsetResolution::resolved)
            return false;
          ++report.counters.resolved_subsets;
          report.counters.resolved_indices +=
            static_cast<unsigned int>(subset.size());
          return true;
        };
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
                // An exact tie stays on its side (resolve_subset sends ties
                // to the active side; flipping them back would undo it).
                const bool now_active =
                  active[i] ? test <= tolerance : test < -tolerance;
                if (now_active != static_cast<bool>(active[i]))
                  violated.push_back(i);
              }
            if (iteration >= 1 && violated.empty())
              {
                report.status = Status::converged;
                break;
              }
            // Wandering: the count of violated indices has not reached a
            // new low for long, exact resolutions included (a cycle too
            // large to resolve). With the default limit PDAS stops instead
            // and the driver continues from an interior point (solve_lcp).
            if (parameters.max_iterations == 0 && safeguard > 0 &&
                without_progress > wandering_limit)
              {
                report.status  = Status::iteration_limit;
                report.message = "PDAS did not settle: the number of "
                                 "violated constraints has not reached a "
                                 "new low below " +
                                 std::to_string(fewest_violations) + " in " +
                                 std::to_string(wandering_limit) +
                                 " iterations (cycling)";
                break;
              }
            // Slow progress above what can be resolved at once: thousands
            // of indices change side each iteration while their number
            // falls by a few percent (balanced bricks), each iteration a
            // factorisation.
            const Index n_violated = static_cast<Index>(violated.size());
            fewest_so_far.push_back(
              fewest_so_far.empty() ? n_violated :
                                      std::min(fewest_so_far.back(), n_violated));
            const Index fewest_before =
              fewest_so_far.size() > halving_window ?
                fewest_so_far[fewest_so_far.size() - 1 - halving_window] :
                0;
            if (parameters.max_iterations == 0 && safeguard > 0 &&
                fewest_so_far.size() > halving_window &&
                fewest_so_far.back() > max_resolved_subset &&
                fewest_so_far.back() > 0.5 * static_cast<double>(fewest_before))
              {
                report.status  = Status::iteration_limit;
                report.message =
                  "PDAS did not settle: the fewest violated constraints "
                  "fell only from " +
                  std::to_string(fewest_before) + " to " +
                  std::to_string(fewest_so_far.back()) + " in " +
                  std::to_string(halving_window) +
                  " iterations, too many to resolve at once (cycling)";
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

            // Step 3, safeguarded: every violated index changes side while
            // their number reaches new lows often enough. After `safeguard`
            // iterations without, the cycle is resolved exactly; if it is
            // too large (or that fails), only the least violated index
            // changes (Murty's rule, finite for definite A).
            bool single = false, resolved = false;
            if (iteration >= 1 && safeguard > 0)
              {
                // Above what can be resolved at once, a new low must be a
                // tenth lower to count: a count that creeps down by a few
                // percent while thousands change side (running bond walls:
                // 3491, 3285, 3189, ... over 30 iterations) is wandering.
                const bool new_low =
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
                if (without_progress > 0 && ++stalled > safeguard)
                  {
                    resolved = resolve(cycle);
                    single   = !resolved;
                    stalled  = 0;
                    // Single pivots cannot end a cycle of thousands of
                    // indices in reasonable time (running bond walls from
                    // m = 30 on); with the default limit PDAS stops now
                    // and the driver continues from an interior point.
                    if (single && parameters.max_iterations == 0 &&
                        static_cast<Index>(cycle.size()) > max_resolved_subset)
                      {
                        report.status  = Status::iteration_limit;
                        report.message =
                          "PDAS did not settle: " +
                          std::to_string(cycle.size()) +
                          " constraints changed side in the " +
                          std::to_string(without_progress) +
                          " iterations since the number of violated ones "
                          "last reached a new low (" +
                          std::to_string(fewest_violations) +
                          "), too many to resolve at once (cycling)";
                        break;
                      }
                  }
              }
            // Creeping (see creep_window): resolve what changed side lately.
            if (iteration >= 1 && safeguard > 0 && !resolved && !single &&
                n_violated <= max_resolved_subset &&
                recent_changes.size() == creep_window &&
                fewest_so_far.back() >
                  0.5 * static_cast<double>(
                          fewest_so_far[fewest_so_far.size() - 1 -
                                        creep_window]))
              {
                std::vector<char>  in_subset(n, 0);
                std::vector<Index> subset;
                const auto         add = [&](const Index i) {
                  if (!in_subset[i])
                    {
                      in_subset[i] = 1;
                      subset.push_back(i);
                    }
                };
                for (const auto &changes : recent_changes)
                  for (const Index i : changes)
                    add(i);
                for (const Index i : violated)
                  add(i);
                // The drifting boundary moves on to the neighbours: the
                // constrained indices A couples to these (laminae m = 100:
                // 28 iterations instead of 49 with them, 42 without).
                const std::size_t changed = subset.size();
                for (std::size_t q = 0; q < changed; ++q)
                  for (SparseMatrix::InnerIterator it(problem.A, subset[q]);
                       it;
                       ++it)
                    if (is_constrained[it.row()])
                      add(it.row());
                resolved = resolve(subset);
              }
            if (resolved)
              recent_changes.clear();
            else
              {
                recent_changes.push_back(violated);
                if (recent_changes.size() > creep_window)
                  recent_changes.pop_front();
              }
            if (!resolved)
              {
                if (single)
                  violated.resize(1); // the constrained indices are sorted
                for (const Index i : violated)
                  active[i] = !active[i];
              }

            // Step 4. A singular system means that the active set leaves
            // some body free to move: a freed index took its support, or
            // (from an interior point or a regularised answer, where the
            // solution is not unique) a contact closed without force that
            // alone kept a brick from rotating lies slightly open. The open
            // constrained indices that the free motions move are resolved
            // exactly, with the rest kept (a few times, if that frees
            // another body).
            const auto solve_step = [&]() {
              for (Index k = 0; k < problem.n_constrained(); ++k)
                if (active[problem.constrained[k]])
                  u[problem.constrained[k]] = problem.lower_bound[k];
              return system.solve(active, problem.b, u);
            };
            bool solved = solve_step();
            for (unsigned int attempt = 0;
                 !solved && safeguard > 0 && attempt < 3;
                 ++attempt)
              {
                const Vector free_motion = system.near_null_direction(active);
                std::vector<Index> subset;
                if (free_motion.size() == n)
                  for (const Index i : problem.constrained)
                    if (!active[i] && std::abs(free_motion[i]) > 1e-6)
                      subset.push_back(i);
                add_to_cycle(subset);
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
                resolved = true;
                solved   = solve_step();
              }
            if (!solved)
              {
                report.status = Status::singular;
                report.message =
                  "PDAS: the reduced system A_FF is singular for the active "
                  "set of iteration " +
                  std::to_string(iteration + 1) +
                  " (some body is held by no active constraint)";
                break;
              }
            Index n_active = 0;
            for (Index k = 0; k < problem.n_constrained(); ++k)
              n_active += active[problem.constrained[k]];
            report.iterations = iteration + 1;
            solution.factor   = system.factor();
            if (progress != nullptr)
              {
                *progress << "    pdas iteration " << iteration + 1
                          << ": active set " << n_active << ", ";
                if (resolved)
                  *progress << "resolved " << resolved_size
                            << " indices exactly";
                else
                  *progress << "changed " << violated.size()
                            << (single ? " (safeguard: least index)" : "");
                *progress << std::endl;
              }
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
