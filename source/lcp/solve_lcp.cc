#include <unilateral/base/input_error.h>
#include <unilateral/base/ranks.h>
#include <unilateral/base/text.h>
#include <unilateral/lcp/active_set_system.h>
#include <unilateral/lcp/answer_checks.h>
#include <unilateral/lcp/distributed_cholesky.h>
#include <unilateral/lcp/projection.h>
#include <unilateral/lcp/schur_complement.h>
#include <unilateral/lcp/solve_lcp.h>
#include <unilateral/lcp/sparse_cholesky.h>

#include <algorithm>
#include <iomanip>
#include <limits>
#include <memory>
#include <optional>
#include <ostream>
#include <sstream>

namespace unilateral::lcp
{
  namespace
  {
    /// 'Regularisation = auto' on a problem whose bodies can float, and the
    /// retry of a method that met a singular matrix where none was expected.
    constexpr double floating_bodies_regularisation = 1e-9;

    /// A relative regularisation at most this size holds no body: the
    /// Schur complement's n_c eps of Ainsworth & Mihai, which keeps its
    /// factorisation from failing on round-off only.
    constexpr double round_off_regularisation = 1e-12;

    /// d |l|_inf / |b|_inf where bodies can float: how far the bounds let
    /// the bodies move as rigid bodies, against the elastic displacements
    /// the loads cause (0 where that means nothing).
    double
    rigid_to_elastic(const Problem &problem)
    {
      const double loads  = problem.b.lpNorm<Eigen::Infinity>();
      const double bounds = problem.n_constrained() > 0 ?
                              problem.lower_bound.lpNorm<Eigen::Infinity>() :
                              0.0;
      const double stiffness =
        problem.size() > 0 ? std::abs(problem.A.diagonal().mean()) : 0.0;
      return problem.floating_bodies && loads > 0 ? stiffness * bounds / loads :
                                                    0.0;
    }

    /**
     * 'Regularisation = auto' where bodies can float: 1e-9, unless that
     * would hold them. A + eps d I ties every body to its place by a spring
     * of stiffness eps d; where the bounds let it move by l (a block
     * settling by its gap), that spring pulls with eps d l against the
     * loads b, and the regularised answer keeps the bodies where the
     * springs hold them instead of where the loads take them: a start the
     * projection may never recover from. So eps d |l| stays below a
     * hundredth of |b|: eps = min(1e-9, 1e-2 |b| / (d |l|)), down to 1e-14
     * (below that a factorisation cannot tell A + eps d I from A). The
     * paper's walls (d |l| / |b| up to a few million) keep 1e-9.
     */
    double
    floating_bodies_eps(const Problem &problem)
    {
      const double ratio = rigid_to_elastic(problem);
      if (!(ratio > 0))
        return floating_bodies_regularisation;
      return std::clamp(1e-2 / ratio, 1e-14, floating_bodies_regularisation);
    }

    /**
     * Where a run did not converge and the bodies' rigid motions dwarf their
     * elastic deformation beyond what double precision resolves to the KKT
     * tolerance (see check_balance), that is the likely cause: say so.
     */
    void
    explain_unresolvable(const Problem          &problem,
                         const SolverParameters &parameters,
                         Report                 &report)
    {
      const double ratio = rigid_to_elastic(problem);
      if (report.converged() ||
          !(std::numeric_limits<double>::epsilon() * ratio >
            parameters.kkt_tolerance))
        return;
      std::ostringstream hint;
      hint << std::setprecision(3) << "; the bounds let bodies move " << ratio
           << " times as far as the loads deform them, more than double "
              "precision resolves to 'KKT tolerance': give the loads, the "
              "stiffness and the gaps in units closer to each other";
      report.message += hint.str();
    }

    /**
     * A method with its options, run as a user would run it: regularised if
     * it needs a definite matrix, projected if its answer is approximate.
     */
    struct Attempt
    {
      const SolverInfo *method;
      SolverParameters  parameters;
      /// The relative eps 'Regularisation = auto' means for this attempt.
      double auto_regularisation;
      /// A hand-over that starts from the last attempt's iterate.
      bool from_iterate = false;
      /// A follow-up after the projection step was taken (once per run).
      bool after_projection_taken = false;
      /// The settings of the follow-up that made this attempt, as text.
      std::string settings = {};
    };

    // The method alone on @p problem as given.
    void
    run_method(const Attempt &attempt,
               const Problem &problem,
               Solution      &solution,
               Report        &report,
               std::ostream  *progress)
    {
      const SolverInfo &info = *attempt.method;
      if (info.dense && static_cast<unsigned int>(problem.size()) >
                          attempt.parameters.max_dense_size)
        throw InputError("method '" + info.name +
                         "' is dense and the LCP has " +
                         std::to_string(problem.size()) +
                         " unknowns, more than 'Solver/Maximum dense size' = " +
                         std::to_string(attempt.parameters.max_dense_size) +
                         ": use 'Schur complement = true' (" + info.name +
                         " works on S only) or a sparse method");
      if (info.needs_tearing && problem.tearing == nullptr)
        throw InputError("method '" + info.name +
                         "' works on a problem torn into subdomains, which "
                         "this scene does not build (the masonry scene "
                         "does): choose another method");
      if (info.needs_hierarchy && problem.hierarchy == nullptr)
        throw InputError("method '" + info.name +
                         "' works on a hierarchy of meshes, which this "
                         "problem does not have (the plate scene builds one; "
                         "a Schur complement has none): choose another "
                         "method");
      PhaseTimer timer(report, "solve");
      // Every sparse factorisation the method makes, however deep, runs
      // over the ranks while this scope is open. Said where one ran: a
      // method may factorise nothing (TNNMG on the plate), which was
      // reported as factorising over the ranks (a review).
      std::optional<DistributedFactorisations> over_ranks;
      if (attempt.parameters.factorises_over_ranks(info))
        over_ranks.emplace(MPI_COMM_WORLD);
      const unsigned int before = report.counters.numeric_factorisations;
      info.create(attempt.parameters, attempt.parameters.of(info.name))
        ->solve(problem, solution, report, progress);
      if (over_ranks && report.counters.numeric_factorisations > before)
        {
          const unsigned int n_ranks = ranks::n_ranks();
          report.set_figure("factorisation_ranks", n_ranks);
          if (progress != nullptr)
            *progress << "  factorisations over " << n_ranks
                      << (n_ranks == 1 ? " rank" : " ranks") << " (MUMPS)\n";
        }
    }

    // The regularisation the attempt's method gets (relative eps, 0: none):
    // 'auto' is the problem's need, raised to the method's own preference
    // (PSOR converges at a rate set by eps; the projection makes the answer
    // exact anyway). Where bodies can float, the interior-point methods get
    // it too: a semidefinite LCP's solutions can form an unbounded set (a
    // block free to move away from a joint, which no load drives: the back
    // leaf of a 3D wall), whose centre an interior iterate follows off to
    // infinity; A + eps d I has one solution, which the projection step
    // then makes exact.
    double
    relative_regularisation(const Attempt &attempt)
    {
      const SolverInfo &info         = *attempt.method;
      const bool        bodies_float = attempt.auto_regularisation > 0;
      if (!info.needs_definite_matrix &&
          !(bodies_float && info.follows_central_path()))
        return 0;
      if (attempt.parameters.regularisation >= 0)
        return attempt.parameters.regularisation;
      return attempt.auto_regularisation > 0 ?
               std::max(attempt.auto_regularisation,
                        info.preferred_regularisation) :
               0.0;
    }

    /**
     * A + eps I in A's own storage, for the run of one method: each diagonal
     * entry is shifted in place and put back, value for value, when this
     * goes out of scope (also on an exception). A regularised copy of the
     * Problem would double the largest matrix in memory (benchmarks/tfeti/
     * README.md, "The largest walls").
     *
     * The values of a Problem's matrix are a heap array the Problem points
     * to, not part of the (const) Problem object, so writing them through
     * a const_cast is defined; nothing reads A while it is shifted but the
     * method the shifted problem is given to.
     */
    class DiagonalShift
    {
    public:
      DiagonalShift(const Problem &problem, const double shift)
        : values(const_cast<SparseMatrix &>(problem.A).valuePtr())
        , position(diagonal_positions(problem.A))
        , saved(position.size())
      {
        for (std::size_t j = 0; j < position.size(); ++j)
          {
            saved[j] = values[position[j]];
            values[position[j]] += shift;
          }
      }

      ~DiagonalShift()
      {
        for (std::size_t j = 0; j < position.size(); ++j)
          values[position[j]] = saved[j];
      }

      DiagonalShift(const DiagonalShift &) = delete;
      DiagonalShift &
      operator=(const DiagonalShift &) = delete;

    private:
      double *const            values;
      const std::vector<Index> position;
      std::vector<double>      saved;
    };

    /// What an attempt ended with.
    struct Outcome
    {
      Report report;
      /// The status of the method's own run, before any projection: what
      /// follow-ups are chosen by.
      Status method_status;
    };

    /**
     * One attempt: the method on A (or on A + eps d I if it needs a definite
     * matrix), then the projection step where its answer is approximate or
     * regularised, or fails the KKT check.
     */
    Outcome
    run_attempt(const Problem &problem,
                const Attempt &attempt,
                Solution      &solution,
                std::ostream  *progress)
    {
      const SolverInfo       &info       = *attempt.method;
      const SolverParameters &parameters = attempt.parameters;
      Outcome                 outcome;
      Report                 &report = outcome.report;
      report.solver                  = info.name;

      const double relative_eps  = relative_regularisation(attempt);
      const bool   regularise    = relative_eps > 0;
      const double mean_diagonal = diagonal_scale(problem.A);
      if (!regularise)
        run_method(attempt, problem, solution, report, progress);
      else
        {
          std::optional<DiagonalShift> shifted;
          {
            PhaseTimer timer(report, "regularise");
            report.regularisation = relative_eps * mean_diagonal;
            shifted.emplace(problem, report.regularisation);
          }
          run_method(attempt, problem, solution, report, progress);
        } // A's diagonal restored
      outcome.method_status = report.status;

      if (regularise && !parameters.projection && report.converged())
        {
          // A small KKT residual of the answer to A + eps I against A
          // bounds the backward error only; nearly floating bodies turn it
          // into a far larger forward error (benchmarks/stress/README.md,
          // Results). Not the user's problem solved.
          std::ostringstream message;
          message << std::setprecision(3)
                  << "the answer solves the regularised LCP (A + eps I, eps = "
                  << relative_eps
                  << " times the mean diagonal), not the given one, and its "
                     "error is not bounded by the KKT residual; set "
                     "'Solver/Projection = true' for the exact solution";
          report.status  = Status::inaccurate;
          report.message = message.str();
        }
      // An approximate method kept without the projection step: its answer
      // is only as accurate as its own tolerance. Said here, so that final
      // checks that find it short name this cause beside theirs (a review:
      // TFETI's 'inaccurate' pointed at the wall, and its Tolerance 1e-10
      // was the cure).
      if (!info.exact && !regularise && !parameters.projection &&
          report.converged() && report.message.empty())
        report.message = "without the projection step ('Solver/Projection "
                         "= false') the answer of " +
                         info.label +
                         " is only as accurate as its own tolerance";
      // An exact method on A itself needs no projection, unless its answer
      // fails the final checks: pivoting methods with an absolute tolerance
      // (block pivoting's 1e-6) can stop a few indices short on large
      // plates, or a contact short where a far bound hides it from the
      // relative residuals.
      const bool exact_answer =
        info.exact && !regularise && report.converged() &&
        solution.u.size() == problem.size() &&
        passes_checks(problem, parameters.kkt_tolerance, solution.u);
      if (!report.converged() || !parameters.projection || exact_answer)
        {
          // An analysis handed over for a projection that does not run
          // holds the storage of the method's whole factor: freed now,
          // before a verification or a hand-over needs the memory.
          if (solution.factor != nullptr && solution.factor->analysis_only)
            solution.factor.reset();
          return outcome;
        }

      // An approximate method that ran on A itself, and an interior-point
      // method (on A + eps d I only where bodies float), continue from the
      // problem's regularisation, from an active set by the interior
      // indicators.
      const bool interior_point =
        (!regularise && !info.exact) || info.follows_central_path();
      const double first_eps =
        regularise && !info.follows_central_path() ?
          report.regularisation :
          1e3 * std::max(attempt.auto_regularisation, 1e-12) * mean_diagonal;
      const FirstActiveSet first_active_set =
        info.gives_active_set ? FirstActiveSet::given :
        interior_point        ? FirstActiveSet::interior_point :
                                FirstActiveSet::test_on_u;
      project(problem,
              parameters,
              first_eps,
              first_active_set,
              solution,
              report,
              progress);
      return outcome;
    }

    // The follow-up of @p kind that @p info declares for @p status (of the
    // method, or of the projection after it: FollowUp::after_projection).
    const FollowUp *
    declared_follow_up(const SolverInfo       &info,
                       const SolverParameters &parameters,
                       const Status            status,
                       const FollowUp::Kind    kind,
                       const bool              after_projection = false)
    {
      for (const FollowUp &follow_up : info.follow_ups)
        if (follow_up.kind == kind && follow_up.when == status &&
            follow_up.after_projection == after_projection &&
            !(follow_up.only_at_default_limit && parameters.max_iterations > 0))
          return &follow_up;
      return nullptr;
    }

    // "'Solver/<entry>' = <value>, ..." of a follow-up's settings.
    std::string
    settings_text(
      const std::vector<std::pair<std::string, std::string>> &settings)
    {
      std::string text;
      for (const auto &[entry, value] : settings)
        text +=
          (text.empty() ? "'Solver/" : ", 'Solver/") + entry + "' = " + value;
      return text;
    }

    // Whether each of @p follow_up's settings lies below @p parameters'
    // value (FollowUp::after_projection).
    bool
    tightens(const FollowUp &follow_up, const SolverParameters &parameters)
    {
      for (const auto &[entry, value] : follow_up.settings)
        if (!(std::stod(value) < std::stod(parameters.get(entry))))
          return false;
      return true;
    }

    // The attempt a follow-up asks for.
    Attempt
    follow_up_attempt(const FollowUp &follow_up, const Attempt &from)
    {
      Attempt next{&SolverRegistry::get(follow_up.method),
                   from.parameters,
                   from.auto_regularisation};
      next.parameters.method     = follow_up.method;
      next.parameters.projection = true;
      next.after_projection_taken =
        from.after_projection_taken || follow_up.after_projection;
      next.settings     = settings_text(follow_up.settings);
      next.from_iterate = follow_up.from_iterate &&
                          SolverRegistry::get(follow_up.method).warm_start;
      for (const auto &[entry, value] : follow_up.settings)
        next.parameters.set(entry, value);
      return next;
    }

    /**
     * The attempt that continues @p attempt after its @p outcome, if any,
     * with the progress line that says why:
     *  - a method that needs a definite matrix and meets a singular one on
     *    a problem expected definite ('auto' without floating bodies: an LCP
     *    read from files, or the Schur complement with its round-off
     *    regularisation) is tried again regularised, as on floating bodies,
     *    and then projected onto A; this follows from the property, so no
     *    method declares it (a review: block pivoting on the Schur
     *    complement ended `singular` on A = [1 1; 1 1], b = (1, 1), whose
     *    solutions form a segment);
     *  - a hand-over the method declares;
     *  - once per run, the follow-up a method declares for a projection
     *    step that did not settle after it (the interior point again with
     *    a tighter complementarity tolerance).
     */
    std::optional<Attempt>
    next_attempt(const Attempt &attempt,
                 const Outcome &outcome,
                 std::ostream  *progress)
    {
      if (outcome.method_status == Status::singular &&
          relative_regularisation(attempt) <= round_off_regularisation &&
          attempt.method->needs_definite_matrix &&
          attempt.parameters.regularisation < 0 &&
          attempt.auto_regularisation <= round_off_regularisation)
        {
          if (progress != nullptr)
            *progress << "    " << outcome.report.message
                      << "; regularising with eps = "
                      << floating_bodies_regularisation << " (auto)"
                      << std::endl;
          Attempt retry             = attempt;
          retry.auto_regularisation = floating_bodies_regularisation;
          return retry;
        }
      if (const FollowUp *hand_over =
            declared_follow_up(*attempt.method,
                               attempt.parameters,
                               outcome.method_status,
                               FollowUp::Kind::hand_over))
        {
          Attempt next = follow_up_attempt(*hand_over, attempt);
          if (progress != nullptr)
            *progress << "    " << outcome.report.message
                      << "; continuing from the " << next.method->label
                      << std::endl;
          return next;
        }
      // The method converged, and the projection from its answer did not.
      const FollowUp *again = outcome.method_status == Status::converged &&
                                  !attempt.after_projection_taken ?
                                declared_follow_up(*attempt.method,
                                                   attempt.parameters,
                                                   outcome.report.status,
                                                   FollowUp::Kind::hand_over,
                                                   true) :
                                nullptr;
      if (again != nullptr && tightens(*again, attempt.parameters))
        {
          Attempt next = follow_up_attempt(*again, attempt);
          if (progress != nullptr)
            *progress << "    " << outcome.report.message << "; the "
                      << attempt.method->label << " again, with "
                      << next.settings << std::endl;
          return next;
        }
      return std::nullopt;
    }

    /**
     * Run @p attempt and the attempts that continue it (next_attempt), one
     * after the other: a short loop, not a recursion. A retry starts from
     * the same start and its report replaces the failed one's (whose work
     * and time are kept); a hand-over starts afresh (or from the last
     * iterate, FollowUp::from_iterate), and its report carries the earlier
     * iterations, work and times, and a note.
     */
    Report
    run_attempts(const Problem &problem,
                 Attempt        attempt,
                 Solution      &solution,
                 std::ostream  *progress)
    {
      Solution start   = solution;
      Outcome  outcome = run_attempt(problem, attempt, solution, progress);
      for (std::optional<Attempt> next;
           (next = next_attempt(attempt, outcome, progress));
           attempt = std::move(*next))
        {
          // The same method after its projection failed is a run of its
          // own, reported as a hand-over is.
          const bool again =
            next->after_projection_taken && !attempt.after_projection_taken;
          const bool retry = next->method == attempt.method && !again;
          if (!retry)
            start = next->from_iterate ? solution : Solution();
          solution            = start;
          Outcome       later = run_attempt(problem, *next, solution, progress);
          const Report &earlier = outcome.report;
          later.report.counters += earlier.counters;
          if (retry)
            later.report.add_times(earlier);
          else
            {
              later.report.solver = earlier.solver;
              later.report.iterations += earlier.iterations;
              // The first run's projection ran (a hand-over follows a
              // method that failed, whose answer is not projected).
              later.report.projection_iterations +=
                earlier.projection_iterations;
              later.report.add_times(earlier,
                                     attempt.method->name +
                                       (again ? " (first run): " :
                                                " (handed over): "));
              const std::string note =
                earlier.message + " after " +
                quantity(earlier.iterations, "iteration") +
                (again ? " and " +
                           quantity(earlier.projection_iterations,
                                    "projection iteration") +
                           "; the " + next->method->label + " again, with " +
                           next->settings :
                         "; handed over to " + next->method->label) +
                ", whose answer is given";
              later.report.message = later.report.message.empty() ?
                                       note :
                                       note + "; " + later.report.message;
            }
          outcome = std::move(later);
        }
      // The last attempt met a singular matrix it was not regularised for.
      if (outcome.method_status == Status::singular &&
          attempt.method->needs_definite_matrix &&
          relative_regularisation(attempt) == 0)
        outcome.report.message += "; regularise ('Solver/Regularisation' > 0)";
      return outcome.report;
    }

    /**
     * The verification a method declares for an outcome, by another
     * method: Graves' claim that the LCP has no solution, which round-off
     * can produce (Ainsworth & Mihai: running bond, m = 5, without load,
     * where u = 0 solves it), is checked by PDAS, which never makes one;
     * PDAS that ends on a singular system asks Graves whether the LCP has a
     * solution at all, which Graves' Case 2 proves or disproves. If the
     * checking method solves the LCP its answer is given; if it proves
     * that there is none, the status says so; the note says what happened.
     * A checking method that cannot take the problem (dense and too large,
     * or needing every unknown constrained) is not run.
     */
    void
    verify(const Problem  &problem,
           const Attempt  &attempt,
           const FollowUp &verification,
           Solution       &solution,
           Report         &report,
           std::ostream   *progress)
    {
      const Attempt check_attempt = follow_up_attempt(verification, attempt);
      const SolverInfo &checker   = *check_attempt.method;
      if ((checker.dense && static_cast<unsigned int>(problem.size()) >
                              attempt.parameters.max_dense_size) ||
          (checker.every_unknown_constrained &&
           problem.n_constrained() < problem.size()))
        return;
      const std::string &label = checker.label;
      Solution           check;
      const Report       check_report =
        run_attempts(problem, check_attempt, check, progress);
      report.counters += check_report.counters;
      report.add_times(check_report, "verification: ");
      if (check_report.converged() &&
          passes_checks(problem, attempt.parameters.kkt_tolerance, check.u))
        {
          report.message += "; but " + label + " solved it in " +
                            quantity(check_report.iterations +
                                       check_report.projection_iterations,
                                     "iteration") +
                            (report.status == Status::infeasible ?
                               ", so the claim came from round-off" :
                               "") +
                            ": the answer given is " + label + "'s";
          report.status = Status::converged;
          solution      = check;
          // The answer is the checker's: so are its method and counts.
          report.solver = check_report.solver;
          report.take_counts_of(check_report);
        }
      else if (check_report.status == Status::infeasible)
        {
          report.message = check_report.message + "; " + attempt.method->label +
                           " had ended " + to_string(report.status) +
                           " after " + quantity(report.iterations, "iteration");
          report.status = Status::infeasible;
          // The proof is the checker's: so are the iterate it ends on, its
          // method and its counts (the first method's are in the note).
          solution      = check;
          report.solver = check_report.solver;
          report.take_counts_of(check_report);
        }
      else if (check_report.converged())
        report.message += "; " + label + "'s answer fails the checks too";
      else
        report.message += "; " + label + " found none either (" +
                          to_string(check_report.status) + ")";
    }

    // The full LCP: the selected method's attempts, and the verification
    // of a claim it declares to be checked.
    Report
    solve_full(const Problem          &problem,
               const SolverParameters &parameters,
               Solution               &solution,
               std::ostream           *progress,
               const double            auto_regularisation)
    {
      const Attempt first{&SolverRegistry::get(parameters.method),
                          parameters,
                          auto_regularisation};
      Report        report = run_attempts(problem, first, solution, progress);
      if (const FollowUp *verification =
            declared_follow_up(*first.method,
                               parameters,
                               report.status,
                               FollowUp::Kind::verification))
        verify(problem, first, *verification, solution, report, progress);
      return report;
    }

    // Ainsworth & Mihai's reduced LCP on S (3.13-3.18), solved by
    // solve_full, and u_E recovered.
    Report
    solve_schur_complement(const Problem          &problem,
                           const SolverParameters &parameters,
                           Solution               &solution,
                           std::ostream           *progress)
    {
      const SolverInfo &method = SolverRegistry::get(parameters.method);
      if (method.needs_tearing || method.needs_hierarchy)
        throw InputError("method '" + method.name +
                         "' works on the whole problem (its subdomains or "
                         "its meshes), not on the Schur complement on the "
                         "constrained unknowns: set 'Solver/Schur "
                         "complement = false'");
      Report report;
      report.solver = method.name + "_sc";
      std::unique_ptr<SchurComplement> schur;
      {
        PhaseTimer timer(report, "schur complement");
        schur = std::make_unique<SchurComplement>(problem,
                                                  parameters.max_dense_size,
                                                  report.counters);
      }
      if (schur->singular())
        {
          report.status  = Status::singular;
          report.message = "A_EE (the unconstrained block) is not positive "
                           "definite, so the Schur complement does not "
                           "exist; solve the full LCP instead";
          solution.u     = Vector::Zero(problem.size());
          return report;
        }
      // Ainsworth & Mihai regularise the (scaled) Schur complement with
      // eps ~ n_c * machine epsilon.
      const double sc_eps =
        problem.n_constrained() * std::numeric_limits<double>::epsilon();
      Solution reduced_solution;
      if (solution.u.size() == problem.size())
        {
          reduced_solution.u.resize(problem.n_constrained());
          for (Index k = 0; k < problem.n_constrained(); ++k)
            reduced_solution.u[k] = solution.u[problem.constrained[k]];
        }
      SolverParameters reduced_parameters = parameters;
      reduced_parameters.schur_complement = false;
      const Report reduced_report         = solve_full(schur->reduced_problem(),
                                               reduced_parameters,
                                               reduced_solution,
                                               progress,
                                               sc_eps);
      report.status                       = reduced_report.status;
      report.message                      = reduced_report.message;
      report.take_counts_of(reduced_report);
      report.counters += reduced_report.counters;
      // Its figures too: 'factorisation_ranks' where the reduced problem's
      // factorisations ran over the ranks (a review: absent from
      // summary.json, which then did not say so).
      for (const auto &[name, value] : reduced_report.figures)
        report.set_figure(name, value);
      report.add_times(reduced_report);
      PhaseTimer timer(report, "recover u_E");
      solution.u = schur->recover(reduced_solution.u);
      // Where A_EE holds all of A's rank, M and q are round-off, and a
      // failure of the reduced problem (PDAS's proof that it has no
      // solution) is a failure on round-off: a review's LCPs with solutions
      // ended 'infeasible', their recovered u the answer. There, and only
      // where every entry of q is the rounding of its own terms (a real
      // imbalance of a free motion is not, however heavily loaded the rest
      // of the problem: a review), the recovered u is judged on the full
      // LCP; the final judgement checks it like any answer.
      if (!report.converged() && schur->loads_round_off() &&
          passes_checks(problem, parameters.kkt_tolerance, solution.u))
        {
          if (progress != nullptr)
            *progress << "    the reduced problem's " << report.message
                      << "; but u recovered from its last iterate solves the "
                         "full LCP"
                      << std::endl;
          report.status = Status::converged;
          report.message.clear();
        }
      return report;
    }

  } // namespace

  void
  verify_semidefinite(const Problem &problem)
  {
    if (problem.known_semidefinite || problem.size() == 0)
      return;
    // Each row shifted by its own diagonal (floored far below the mean):
    // a shift by the mean diagonal would hide an indefinite block of small
    // entries beside a stiff one.
    const double floor   = 1e-12 * diagonal_scale(problem.A);
    SparseMatrix shifted = problem.A;
    for (Index j = 0; j < problem.size(); ++j)
      shifted.coeffRef(j, j) +=
        semidefinite_shift * std::max(problem.A.coeff(j, j), floor);
    SparseCholesky cholesky;
    Counters       counters;
    if (!cholesky.factorise(shifted, counters))
      {
        std::ostringstream message;
        message << std::setprecision(3)
                << "A is not positive semidefinite: the Cholesky "
                   "factorisation of A + "
                << semidefinite_shift
                << " D (D the diagonal of A) meets a non-positive pivot, so "
                   "D^-1/2 A D^-1/2 has an eigenvalue below -"
                << semidefinite_shift
                << "; the LCP methods need a symmetric positive semidefinite "
                   "A (an energy bounded from below)";
        throw InputError(message.str());
      }
  }

  Report
  solve_lcp(const Problem          &problem,
            const SolverParameters &parameters,
            Solution               &solution,
            std::ostream           *progress)
  {
    verify_semidefinite(problem);
    Report report =
      parameters.schur_complement ?
        solve_schur_complement(problem, parameters, solution, progress) :
        solve_full(problem,
                   parameters,
                   solution,
                   progress,
                   problem.floating_bodies ? floating_bodies_eps(problem) :
                                             0.0);
    // Release the last factorisation (it can be large) before returning.
    solution.factor.reset();
    assess_answer(problem, parameters.kkt_tolerance, solution, report);
    explain_unresolvable(problem, parameters, report);
    return report;
  }
} // namespace unilateral::lcp
