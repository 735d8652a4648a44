/**
 * Truncated nonsmooth Newton multigrid, TNNMG (Graeser & Kornhuber,
 * "Multigrid methods for obstacle problems", J. Comput. Math. 27 (2009)
 * 1-44; its truncation from Kornhuber's monotone multigrid, Numer. Math. 69
 * (1994)), on the problem's hierarchy of meshes (lcp/hierarchy.h). The
 * energy E(u) = 1/2 u^T A u - b^T u never rises. One iteration from a
 * feasible u:
 *   1. nonlinear smoothing: a symmetric projected block Gauss-Seidel sweep
 *      (forward, then backward), each node's block minimised exactly under
 *      its bound (one projection: at most one unknown of a node is
 *      constrained);
 *   2. truncation: the unknowns at their bound are held (mask M);
 *   3. linear correction: d ~ (M A M)^-1 M (b - A u), conjugate gradients
 *      preconditioned by V- or W-cycles ('Cycle') of the truncated multigrid
 *      (lcp/truncated_multigrid.h) until the residual has fallen by
 *      'Correction reduction' (an inexact Newton step on the free set);
 *   4. where u + d crosses bounds, those are held too and the correction
 *      is made again ('Expansions per correction' times); where it still
 *      crosses, the step is projected onto the defect obstacle,
 *      d_i >= l_i - u_i;
 *   5. line search: u += alpha d with alpha minimising E on [0, alpha_max],
 *      alpha_max the largest feasible step (a quadratic: one product A d).
 * Nested iteration: from the coarsest level's problem (A_0 = P^T ... A P,
 * b_0 = P^T ... b, the scene's bounds there) up, each level starts from
 * the one below, interpolated and projected onto its bounds, and is left
 * once its held set stays and its last step is below 'Coarse tolerance';
 * the finest level stops there at 'Tolerance' (relative to |u|_inf). Once
 * the held set is the solution's, step 3 is Newton's step on it, so the
 * last iterate is the exact solution to the accuracy of that step.
 */
#include <unilateral/base/input_error.h>
#include <unilateral/base/text.h>
#include <unilateral/lcp/hierarchy.h>
#include <unilateral/lcp/solver.h>
#include <unilateral/lcp/truncated_multigrid.h>

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <limits>
#include <ostream>
#include <sstream>

namespace unilateral::lcp
{
  namespace
  {
    using LevelVector = TruncatedMultigrid::LevelVector;
    using Block       = BlockMatrix::Block;
    using NodeVector  = BlockMatrix::NodeVector;
    constexpr int B   = BlockMatrix::size;

    /// Subsection "Solver/TNNMG".
    class TnnmgParameters : public MethodParametersBase<TnnmgParameters>
    {
    public:
      double       tolerance        = 1e-12;
      double       coarse_tolerance = 1e-6;
      double       reduction        = 1e-1;
      unsigned int cycles           = 20;
      unsigned int expansions       = 1;
      unsigned int smoothing_steps  = 1;
      /// "V" or "W".
      std::string cycle = "W";

      void
      add_parameters(dealii::ParameterHandler &prm) override
      {
        using namespace dealii::Patterns;
        prm.add_parameter(
          "Tolerance",
          tolerance,
          "Stop on the finest level when the held set did not change and "
          "the last correction moved u by at most this times |u|_inf.",
          Double(0));
        prm.add_parameter(
          "Coarse tolerance",
          coarse_tolerance,
          "The same test for leaving a coarser level of the nested "
          "iteration: its answer is only the start of the next level.",
          Double(0));
        prm.add_parameter(
          "Correction reduction",
          reduction,
          "The factor in [1e-14, 1) by which conjugate gradients reduce the "
          "residual of the free unknowns in each correction.",
          Double(0, 1));
        prm.add_parameter("Cycles per correction",
                          cycles,
                          "At most this many multigrid cycles (conjugate "
                          "gradient steps) per correction.",
                          Integer(1));
        prm.add_parameter(
          "Expansions per correction",
          expansions,
          "Where the Newton step crosses bounds, those unknowns are held and "
          "the correction is made again, at most this many times per "
          "iteration (0: the step is only projected and searched). Each "
          "expansion holds every unknown the step crosses, more than the "
          "solution holds near the edge of contact, and only the next "
          "iterations' smoothing releases them again; one expansion "
          "overshoots least.",
          Integer(0));
        prm.add_parameter("Smoothing steps",
                          smoothing_steps,
                          "Block Gauss-Seidel sweeps before and after each "
                          "coarse correction of a cycle.",
                          Integer(1));
        prm.add_parameter(
          "Cycle",
          cycle,
          "The multigrid cycle that preconditions the conjugate gradients: "
          "'V' visits each coarser level once per cycle, 'W' twice (the "
          "second visit corrects what the first left). The block "
          "Gauss-Seidel smoother alone does not give the biharmonic plate a "
          "rate independent of the mesh; the W-cycle's extra coarse work "
          "keeps the number of cycles from growing as fast, and on large "
          "plates costs less than the cycles it saves.",
          Selection("V|W"));
      }

      void
      check(const std::string &section) const override
      {
        // Below 1e-14 the residual CG aims at is round-off (at 1e-300 it
        // underflowed, and the corrections came back NaN).
        check_parameter(reduction >= 1e-14 && reduction < 1,
                        section,
                        "Correction reduction",
                        reduction,
                        "must be in [1e-14, 1)");
      }
    };

    /// One level's LCP in node layout (held entries: l = u).
    struct LevelProblem
    {
      LevelVector b;
      /// l, -infinity where unconstrained (and on padding).
      LevelVector lower;
      /// 1 where the node layout has an unknown.
      LevelVector present;
      /// Per node: its constrained entry (0..3) or -1.
      std::vector<int> bounded;
      /// The inverses of A_l's diagonal blocks.
      DiagonalInverses inverses;
    };

    /**
     * A step on a settled held set that is above this fraction of the last
     * one has stopped falling: the rounding floor of A u, where the
     * iteration ends. A linear iteration whose steps fall by this factor
     * is still 1 / (1 - factor) = 10 times its last step from its limit,
     * so the answer is known to ten times that step (judge()).
     */
    constexpr double rounding_floor_fall = 0.9;

    /// How one level's iteration ended.
    struct LevelOutcome
    {
      unsigned int iterations = 0, cycles = 0, products = 0;
      /// Projected Newton steps rejected for the line search.
      unsigned int rejected  = 0;
      Index        held      = 0;
      bool         converged = false;
      /// The last Newton step relative to |u|_inf where it converged by no
      /// longer falling rather than by the tolerance (0 otherwise).
      double stalled_at = 0;
    };

    /// What went wrong where the iterate is no longer finite on @p level.
    std::string
    broke_down(const unsigned int level)
    {
      return "TNNMG's iterate became NaN or infinite on level " +
             std::to_string(level) +
             " of the hierarchy (as with 'Solver/TNNMG/Cycles per "
             "correction' in the hundreds, or on elements thousands of times "
             "longer than wide): use 'Solver/Method = pdas', or TNNMG's "
             "default parameters";
    }

    class Tnnmg : public Solver
    {
    public:
      using Parameters = TnnmgParameters;

      Tnnmg(const SolverParameters &parameters, const Parameters &options)
        : Solver(parameters)
        , options(options)
      {}

      static SolverInfo
      properties()
      {
        SolverInfo info;
        info.name        = "tnnmg";
        info.label       = "TNNMG";
        info.description = "truncated nonsmooth Newton multigrid (Graeser & "
                           "Kornhuber) on the problem's hierarchy of meshes, "
                           "with nested iteration";
        info.subsection  = "TNNMG";
        info.default_iterations = "100 per level";
        info.needs_hierarchy    = true;
        // Where the block smoother fails (elements tens of times longer
        // than wide: the iteration limit) or round-off stops the
        // corrections short of the KKT tolerance (thousands of times: A's
        // conditioning), PDAS's direct solves still give the answer.
        for (const Status when : {Status::iteration_limit, Status::inaccurate})
          {
            FollowUp hand_over;
            hand_over.kind                  = FollowUp::Kind::hand_over;
            hand_over.when                  = when;
            hand_over.only_at_default_limit = when == Status::iteration_limit;
            hand_over.method                = "pdas";
            hand_over.from_iterate          = true;
            info.follow_ups.push_back(hand_over);
          }
        return info;
      }

      void
      solve(const Problem &problem,
            Solution      &solution,
            Report        &report,
            std::ostream  *progress) override;

    private:
      LevelProblem
      level_problem(const TruncatedMultigrid &mg,
                    const Hierarchy          &hierarchy,
                    const Problem            &problem,
                    unsigned int              level,
                    const LevelVector        &b,
                    double                    answer_scale) const;

      /// The status from the finest level's outcome and the answer.
      void
      judge(const LevelOutcome &outcome,
            unsigned int        finest,
            const Solution     &solution,
            Report             &report) const;

      LevelOutcome
      iterate(TruncatedMultigrid &mg,
              unsigned int        level,
              const LevelProblem &lcp,
              LevelVector        &u,
              double              tolerance,
              bool                carried) const;

      const Parameters options;
    };

    /// One projected block Gauss-Seidel sweep: node by node, the block's
    /// minimiser with the other nodes fixed, under its bound.
    void
    projected_gauss_seidel(const BlockMatrix  &A,
                           const LevelProblem &lcp,
                           LevelVector        &u,
                           const bool          backward)
    {
      double     *x = u.begin();
      const Index n = A.n_rows();
      for (Index k = 0; k < n; ++k)
        {
          const Index      i         = backward ? n - 1 - k : k;
          const NodeVector r         = A.row_residual(i, lcp.b.begin(), x);
          const Block     &D_inverse = lcp.inverses[i];
          NodeVector       y         = Eigen::Map<const NodeVector>(x + B * i);
          y.noalias() += D_inverse * r;
          const int c = lcp.bounded[i];
          if (c >= 0 && y[c] < lcp.lower[B * i + c])
            {
              const double bound = lcp.lower[B * i + c];
              y += ((bound - y[c]) / D_inverse(c, c)) * D_inverse.col(c);
              y[c] = bound;
            }
          Eigen::Map<NodeVector>(x + B * i) = y;
        }
    }

    /// The largest alpha with u + alpha d >= l (infinity if none binds).
    double
    feasible_step(const LevelProblem &lcp,
                  const LevelVector  &u,
                  const LevelVector  &d)
    {
      double alpha = std::numeric_limits<double>::infinity();
      for (std::size_t i = 0; i < u.size(); ++i)
        if (d[i] < 0 && lcp.lower[i] > -std::numeric_limits<double>::infinity())
          alpha = std::min(alpha, (lcp.lower[i] - u[i]) / d[i]);
      return alpha;
    }

    LevelProblem
    Tnnmg::level_problem(const TruncatedMultigrid &mg,
                         const Hierarchy          &hierarchy,
                         const Problem            &problem,
                         const unsigned int        level,
                         const LevelVector        &b,
                         const double              answer_scale) const
    {
      const bool                finest = level + 1 == mg.n_levels();
      const Hierarchy::Level   &data   = hierarchy.levels[level];
      const std::vector<Index> &constrained =
        finest ? problem.constrained : data.constrained;
      const Vector &bounds = finest ? problem.lower_bound : data.lower_bound;

      LevelProblem lcp;
      lcp.b        = b;
      Vector lower = Vector::Constant(data.n_unknowns,
                                      -std::numeric_limits<double>::infinity());
      for (std::size_t k = 0; k < constrained.size(); ++k)
        lower[constrained[k]] = bounds[k] / answer_scale;
      Vector marks = Vector::Zero(data.n_unknowns);
      for (const Index i : constrained)
        marks[i] = 1;
      LevelVector bounded_entries;
      mg.to_nodes(level, lower, lcp.lower);
      mg.to_nodes(level, Vector::Ones(data.n_unknowns), lcp.present);
      mg.to_nodes(level, marks, bounded_entries);
      const Index n_nodes = mg.size(level) / B;
      lcp.bounded.assign(n_nodes, -1);
      for (Index i = 0; i < n_nodes; ++i)
        {
          for (int c = 0; c < B; ++c)
            {
              if (lcp.present[B * i + c] == 0)
                lcp.lower[B * i + c] = -std::numeric_limits<double>::infinity();
              if (bounded_entries[B * i + c] != 0)
                lcp.bounded[i] = c;
            }
        }
      lcp.inverses.set_all(mg.matrix(level), lcp.present.begin());
      return lcp;
    }

    /**
     * The line search of Graeser & Kornhuber: @p d projected onto the
     * defect obstacle (d_i >= l_i - u_i), then u += alpha d with alpha
     * minimising the energy on [0, alpha_max]; @p r is the residual b - A u
     * where d may be nonzero. The energy never rises. Returns the products
     * with A (one).
     */
    unsigned int
    line_search(const BlockMatrix  &A,
                const LevelProblem &lcp,
                const LevelVector  &r,
                LevelVector        &d,
                LevelVector        &u)
    {
      for (std::size_t i = 0; i < u.size(); ++i)
        d[i] = std::max(d[i], lcp.lower[i] - u[i]);
      LevelVector Ad(u.size());
      A.vmult(Ad.begin(), d.begin());
      const double curvature = d * Ad;
      const double slope     = d * r;
      if (curvature > 0 && slope > 0)
        u.add(std::min(slope / curvature, feasible_step(lcp, u, d)), d);
      for (std::size_t i = 0; i < u.size(); ++i)
        u[i] = std::max(u[i], lcp.lower[i]);
      return 1;
    }

    /// The residual b - A u and the energy -1/2 u^T (b + r) of u.
    double
    residual_and_energy(const BlockMatrix  &A,
                        const LevelProblem &lcp,
                        const LevelVector  &u,
                        LevelVector        &r)
    {
      A.vmult(r.begin(), u.begin());
      r.sadd(-1, 1, lcp.b);
      return -0.5 * (u * lcp.b + u * r);
    }

    /// The free entries of @p v below their bound: held from now on, and
    /// put on it. Returns how many.
    unsigned int
    hold_penetrating(const LevelProblem &lcp, LevelVector &v, LevelVector &mask)
    {
      unsigned int count = 0;
      for (std::size_t i = 0; i < v.size(); ++i)
        if (mask[i] != 0 && v[i] < lcp.lower[i])
          {
            mask[i] = 0;
            v[i]    = lcp.lower[i];
            ++count;
          }
      return count;
    }

    LevelOutcome
    Tnnmg::iterate(TruncatedMultigrid &mg,
                   const unsigned int  level,
                   const LevelProblem &lcp,
                   LevelVector        &u,
                   const double        tolerance,
                   const bool          carried) const
    {
      const BlockMatrix &A = mg.matrix(level);
      const std::size_t  n = u.size();
      LevelVector mask(n), held_before, truncated, r(n), d(n), v(n), rv(n),
        dv(n), step(n);
      LevelOutcome       outcome;
      const unsigned int limit     = iteration_limit(100);
      double             last_step = std::numeric_limits<double>::infinity();
      while (outcome.iterations < limit)
        {
          ++outcome.iterations;
          // A start carried up from the coarser level is first corrected
          // as it is: its slopes, interpolated, do not fit the values put
          // on the bounds, and a sweep would release much of what it
          // should hold. The sweep is symmetric, as the linear smoother:
          // one direction releases the nodes held too far mainly on the
          // side it comes from.
          if (outcome.iterations > 1 || !carried)
            {
              projected_gauss_seidel(A, lcp, u, false);
              projected_gauss_seidel(A, lcp, u, true);
            }
          const double energy = residual_and_energy(A, lcp, u, r);
          // Held: at the bound, or no unknown at all.
          outcome.held = 0;
          for (std::size_t i = 0; i < n; ++i)
            {
              mask[i] = lcp.present[i] != 0 && u[i] > lcp.lower[i] ? 1 : 0;
              outcome.held += lcp.present[i] != 0 && mask[i] == 0;
            }
          const bool same_set = held_before.size() == n && mask == held_before;
          if (!same_set)
            last_step = std::numeric_limits<double>::infinity();
          held_before = mask;
          if (truncated.size() != n || !(truncated == mask))
            {
              mg.truncate(level, mask);
              truncated = mask;
            }
          r.scale(mask);
          outcome.cycles += mg.solve(d, r, options.reduction, options.cycles);
          outcome.products += 2;

          // The Newton step; where it crosses bounds, those are held (and
          // put on them) and the step is taken again, until it crosses
          // none or the expansions allowed are spent.
          v = u;
          v += d;
          const bool   crossed    = hold_penetrating(lcp, v, truncated) > 0;
          unsigned int expansions = 0;
          bool         crossing   = crossed;
          while (crossing && expansions < options.expansions)
            {
              ++expansions;
              mg.truncate(level, truncated);
              residual_and_energy(A, lcp, v, rv);
              rv.scale(truncated);
              outcome.cycles +=
                mg.solve(dv, rv, options.reduction, options.cycles);
              v += dv;
              ++outcome.products;
              crossing = hold_penetrating(lcp, v, truncated) > 0;
            }
          // Taken if the energy did not rise; else the line search.
          step = v;
          step -= u;
          if (crossed && residual_and_energy(A, lcp, v, rv) > energy)
            {
              step = u;
              line_search(A, lcp, r, d, step);
              step -= u;
              ++outcome.rejected;
              ++outcome.products;
            }
          u += step;
          ++outcome.products;
          const double size     = u.linfty_norm();
          const double relative = step.linfty_norm() / (size > 0 ? size : 1);
          // Done when the held set stays, the Newton step crosses no
          // bound, and it is below the tolerance or has stopped falling
          // (the rounding floor of A u): that step lowered the energy. A
          // step that falls, if slowly, is no floor: on elements 2000
          // times longer than wide the steps fell by 0.6 per iteration at
          // 1e-8 of |u| and stopping there (as "no longer halving") left
          // the answer 6e-8 off PDAS's (a review).
          if (same_set && !crossed &&
              (relative <= tolerance ||
               relative > rounding_floor_fall * last_step))
            {
              outcome.converged  = true;
              outcome.stalled_at = relative <= tolerance ? 0 : relative;
              break;
            }
          last_step = same_set ? relative : last_step;
        }
      return outcome;
    }

    /**
     * The start on @p level from the answer @p u one level down: the
     * coarse field interpolated, and held at its bound wherever every
     * coarse node it is interpolated from is held (the coarse contact set
     * carried up; the first smoothing sweep releases what it should not
     * hold).
     */
    void
    start_from_coarser(const TruncatedMultigrid &mg,
                       const unsigned int        level,
                       const LevelProblem       &coarse,
                       const LevelProblem       &fine,
                       LevelVector              &u)
    {
      std::vector<char> held(coarse.bounded.size(), 0);
      for (std::size_t k = 0; k < held.size(); ++k)
        {
          const int c = coarse.bounded[k];
          held[k]     = c >= 0 && u[B * k + c] <= coarse.lower[B * k + c];
        }
      const LevelVector coarse_u = u;
      mg.prolongate(level - 1, coarse_u, u);
      const std::vector<char> carried = mg.all_parents(level - 1, held);
      for (std::size_t k = 0; k < carried.size(); ++k)
        if (carried[k] && fine.bounded[k] >= 0)
          u[B * k + fine.bounded[k]] = fine.lower[B * k + fine.bounded[k]];
    }

    void
    Tnnmg::solve(const Problem &problem,
                 Solution      &solution,
                 Report        &report,
                 std::ostream  *progress)
    {
      const Hierarchy &hierarchy = *problem.hierarchy;
      check_hierarchy(hierarchy, problem);
      TruncatedMultigrid mg(hierarchy,
                            problem.A,
                            options.smoothing_steps,
                            options.cycle == "W" ?
                              TruncatedMultigrid::Cycle::w :
                              TruncatedMultigrid::Cycle::v);
      const unsigned int finest = mg.n_levels() - 1;

      // The LCP solved for u / s, s the size the answer will have: the
      // products of the conjugate gradients and the line search are of the
      // order of u^2 |A|, which a load of 1e-150 takes below the smallest
      // double (and 1e200 beyond the largest), where they become NaN. The
      // answer is about as large as the loads' deflection |b| / d (d the
      // mean diagonal) or the highest bound above zero, which lifts it at
      // least that far.
      double highest_bound = 0;
      for (Index k = 0; k < problem.n_constrained(); ++k)
        if (std::isfinite(problem.lower_bound[k]))
          highest_bound = std::max(highest_bound, problem.lower_bound[k]);
      const double answer_size  = std::max(problem.b.lpNorm<Eigen::Infinity>() /
                                            diagonal_scale(problem.A),
                                          highest_bound);
      const double answer_scale = answer_size > 0 ? answer_size : 1.0;

      // The loads of every level, restricted from the finest.
      std::vector<LevelVector> b(mg.n_levels());
      mg.to_nodes(finest, problem.b / answer_scale, b[finest]);
      for (unsigned int level = finest; level-- > 0;)
        mg.restrict_to(level, b[level + 1], b[level]);

      // Always from the coarsest level: started on a fine level far from
      // the solution (from zero on the plate), the line search creeps
      // towards the obstacle and the held set stays empty.
      const unsigned int first = 0;
      LevelVector        u(mg.size(first));

      LevelOutcome outcome;
      LevelProblem coarse_lcp;
      for (unsigned int level = first; level <= finest; ++level)
        {
          LevelProblem lcp = level_problem(
            mg, hierarchy, problem, level, b[level], answer_scale);
          if (level > first)
            start_from_coarser(mg, level, coarse_lcp, lcp, u);
          for (std::size_t i = 0; i < u.size(); ++i)
            u[i] = std::max(u[i], lcp.lower[i]);
          outcome    = iterate(mg,
                            level,
                            lcp,
                            u,
                            level == finest ? options.tolerance :
                                                 options.coarse_tolerance,
                            level > first);
          coarse_lcp = std::move(lcp);
          if (!std::all_of(u.begin(), u.end(), [](const double x) {
                return std::isfinite(x);
              }))
            {
              // The finer levels would only carry the NaN along.
              solution.u =
                Vector::Constant(problem.size(),
                                 std::numeric_limits<double>::quiet_NaN());
              report.status  = Status::singular;
              report.message = broke_down(level);
              return;
            }
          report.counters.cg_iterations += outcome.cycles;
          report.counters.matrix_vector_products += outcome.products;
          if (progress != nullptr)
            *progress << "    tnnmg level " << level << " ("
                      << hierarchy.levels[level].n_unknowns
                      << " unknowns): " << outcome.iterations << " iterations, "
                      << outcome.cycles << " " << options.cycle << "-cycles, "
                      << outcome.held << " held, " << outcome.rejected
                      << " line searches" << std::endl;
        }
      if (progress != nullptr)
        {
          // The yardstick of the cost: one product with the finest A (the
          // fastest of five).
          LevelVector Au(u.size());
          double      fastest = std::numeric_limits<double>::infinity();
          for (unsigned int k = 0; k < 5; ++k)
            {
              const auto start = std::chrono::steady_clock::now();
              mg.matrix(finest).vmult(Au.begin(), u.begin());
              fastest = std::min(fastest,
                                 std::chrono::duration<double>(
                                   std::chrono::steady_clock::now() - start)
                                   .count());
            }
          *progress << "    tnnmg: one product with A on the finest level "
                    << fastest << " s" << std::endl;
        }
      solution.u        = answer_scale * mg.from_nodes(finest, u);
      report.iterations = outcome.iterations;
      judge(outcome, finest, solution, report);
    }

    void
    Tnnmg::judge(const LevelOutcome &outcome,
                 const unsigned int  finest,
                 const Solution     &solution,
                 Report             &report) const
    {
      if (!solution.u.allFinite())
        {
          report.status  = Status::singular;
          report.message = broke_down(finest);
        }
      // Stopped by round-off, not by the tolerance: the answer is known
      // only to ten times the last step, which the KKT residuals (relative to
      // |A| |u|) do not see where A is ill-conditioned (a review: 4000 x 2
      // elements 2000 times longer than wide stalled at 9e-8 of |u|, its
      // energy 3.6e-4 above PDAS's, a contact force 18 % off, with KKT
      // residuals of 2e-16).
      else if (outcome.converged &&
               outcome.stalled_at / (1 - rounding_floor_fall) >
                 parameters.kkt_tolerance)
        {
          std::ostringstream message;
          message << std::setprecision(3)
                  << "TNNMG's corrections stopped falling at "
                  << outcome.stalled_at
                  << " of |u| on the finest level, so its answer is known "
                     "to about ten times that, more than 'Solver/KKT "
                     "tolerance' = "
                  << parameters.kkt_tolerance
                  << " allows (the rounding floor of an ill-conditioned A, "
                     "as on elements far longer than wide, or an iteration "
                     "that no longer converges)";
          report.status  = Status::inaccurate;
          report.message = message.str();
        }
      else if (outcome.converged)
        {
          report.status = Status::converged;
          // Accepted, but short of 'Tolerance': say how well the answer is
          // known (a review: 1000 x 3 elements ended 3.7e-9 off PDAS at a
          // floor of 6e-10, with nothing said).
          if (outcome.stalled_at > 0)
            {
              std::ostringstream message;
              message << std::setprecision(2)
                      << "TNNMG ended at its rounding floor, above "
                         "'Solver/TNNMG/Tolerance': its answer is known to "
                         "about "
                      << outcome.stalled_at / (1 - rounding_floor_fall)
                      << " of |u| (ten times its last step); 'Solver/Method "
                         "= pdas' solves directly";
              report.message = message.str();
            }
        }
      else
        {
          // At the default limit PDAS finishes (the hand-over), and a
          // higher limit would only switch that off: there the advice is
          // the direct method (a review: 1000 iterations on elements 100
          // times longer than wide took 36 s and ended 1 % off).
          report.status = Status::iteration_limit;
          report.message =
            "TNNMG did not reach 'Tolerance' within " +
            quantity(iteration_limit(100), "iteration") +
            " on the finest level: " +
            (parameters.max_iterations > 0 ?
               "raise 'Solver/Maximum iterations', or use " :
               "use ") +
            "'Solver/Method = pdas', a direct method (where elements are "
            "several times longer than wide, TNNMG's smoother is slow and "
            "PDAS the faster)";
        }
    }
  } // namespace

  UNILATERAL_REGISTER_SOLVER(Tnnmg)
} // namespace unilateral::lcp
