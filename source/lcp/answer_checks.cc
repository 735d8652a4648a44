#include <unilateral/lcp/answer_checks.h>

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

namespace unilateral::lcp
{
  namespace
  {
    /**
     * The forces of an answer and how finely double precision resolves
     * them: F = max(|b|_inf, |lambda_S|_inf) (0 without loads), and the
     * rounding error of A u, epsilon |A| |u|_inf, relative to F.
     */
    struct ForceScale
    {
      double forces     = 0;
      double resolution = 0;
      /// |A| |u|_inf / F: how far the displacements exceed the elastic ones
      /// the forces cause.
      double rigid_ratio = 0;
    };

    ForceScale
    force_scale(const Problem &problem, const Vector &u, const Vector &lambda)
    {
      ForceScale   scale;
      const double abs_size =
        absolute_product(problem.A, u).lpNorm<Eigen::Infinity>();
      // The contact forces count even without loads, where bounds alone (a
      // support moved into a body) drive them; not where they are nothing
      // but the round-off of A u (no loads, nothing pressed: u = 0 or a
      // free motion).
      double contact_forces = 0;
      for (const Index i : problem.constrained)
        contact_forces = std::max(contact_forces, std::abs(lambda[i]));
      scale.forces = problem.b.lpNorm<Eigen::Infinity>();
      if (scale.forces > 0 ||
          contact_forces >
            100 * std::numeric_limits<double>::epsilon() * abs_size)
        scale.forces = std::max(scale.forces, contact_forces);
      if (!(scale.forces > 0))
        return scale;
      scale.rigid_ratio = abs_size / scale.forces;
      scale.resolution =
        std::numeric_limits<double>::epsilon() * scale.rigid_ratio;
      return scale;
    }

    /// The largest residual of an answer whose forces are @p scale: the
    /// tolerance in force units, plus ten times the rounding error of A u
    /// (an answer exact to double precision shows that much).
    double
    allowance(const ForceScale &scale, const double kkt_tolerance)
    {
      return kkt_tolerance * scale.forces +
             10 * scale.resolution * scale.forces;
    }

    /// Where A is definite (every body held) an answer that fails a check
    /// has not converged, whatever its method's own test said.
    constexpr const char *stopped_short =
      "the method stopped short of the answer: tighten its own tolerance";

    // The report becomes 'inaccurate' with @p message in front.
    void
    downgrade(Report &report, const std::string &message)
    {
      report.status = Status::inaccurate;
      report.message =
        report.message.empty() ? message : message + "; " + report.message;
    }
  } // namespace

  void
  assess_answer(const Problem &problem,
                const double   kkt_tolerance,
                Solution      &solution,
                Report        &report)
  {
    {
      PhaseTimer timer(report, "kkt check");
      if (solution.u.size() != problem.size())
        solution.u = Vector::Zero(problem.size());
      solution.lambda = multiplier(problem, solution.u);
      // An index is active if u sits exactly at its bound (active-set and
      // pivoting methods put it there) or, for interior-point iterates that
      // never reach a bound, if its slack is smaller than its multiplier in
      // the same units (slack times the diagonal of A).
      solution.active_set.clear();
      for (Index k = 0; k < problem.n_constrained(); ++k)
        {
          const Index  i     = problem.constrained[k];
          const double slack = solution.u[i] - problem.lower_bound[k];
          const double scale =
            problem.A.coeff(i, i) > 0 ? problem.A.coeff(i, i) : 1.0;
          if (slack == 0 || slack * scale < solution.lambda[i])
            solution.active_set.push_back(i);
        }
      report.n_active = static_cast<unsigned int>(solution.active_set.size());
      report.kkt      = kkt_residuals(problem, solution.u);
      report.energy   = energy(problem, solution.u);
      ++report.counters.matrix_vector_products;
    }
    check_finite(problem, solution, report);
    check_kkt(kkt_tolerance, report);
    check_work(problem, solution, report);
    check_balance(problem, solution, kkt_tolerance, report);
    check_contact_forces(problem, solution, kkt_tolerance, report);
  }

  bool
  passes_checks(const Problem &problem,
                const double   kkt_tolerance,
                const Vector  &u)
  {
    Solution candidate;
    candidate.u = u;
    Report report;
    report.status = Status::converged;
    assess_answer(problem, kkt_tolerance, candidate, report);
    return report.converged();
  }

  void
  check_finite(const Problem &problem, const Solution &solution, Report &report)
  {
    if (!report.converged())
      return;
    const char *what = !solution.u.allFinite()          ? "u" :
                       !solution.lambda.allFinite()     ? "the multipliers" :
                       !std::isfinite(report.energy)    ? "the energy" :
                       !std::isfinite(report.kkt.max()) ? "the residuals" :
                                                          nullptr;
    if (what == nullptr)
      return;
    // The sizes that met, for the user to see which is out of range.
    double largest_u = 0;
    bool   finite_u  = false;
    for (const double value : solution.u)
      if (std::isfinite(value))
        {
          largest_u = std::max(largest_u, std::abs(value));
          finite_u  = true;
        }
    // The bounds too: an obstacle or a gap of 1e300 overflows as well.
    double largest_bound = 0;
    for (const double bound : problem.lower_bound)
      if (std::isfinite(bound))
        largest_bound = std::max(largest_bound, std::abs(bound));
    std::ostringstream message;
    message << std::setprecision(3)
            << "the answer is not a finite number (NaN or infinity in " << what
            << "): ";
    if (finite_u)
      message << "displacements up to " << largest_u;
    else
      message << "displacements with no finite entry";
    message << " under loads up to " << problem.b.lpNorm<Eigen::Infinity>()
            << " with a stiffness (mean diagonal of A) of "
            << (problem.size() > 0 ? problem.A.diagonal().mean() : 0.0)
            << " and bounds (obstacle, gaps) up to " << largest_bound
            << " are beyond double precision; give the loads, the bounds and "
               "the stiffness in units closer to each other";
    downgrade(report, message.str());
  }

  void
  check_kkt(const double kkt_tolerance, Report &report)
  {
    if (!report.converged() || report.kkt.max() <= kkt_tolerance)
      return;
    std::ostringstream message;
    message << std::setprecision(3)
            << "the method's stopping test passed but the relative KKT "
               "residual is "
            << report.kkt.max()
            << " > 'Solver/KKT tolerance' = " << kkt_tolerance;
    downgrade(report, message.str());
  }

  void
  check_work(const Problem &problem, const Solution &solution, Report &report)
  {
    if (!report.converged() || solution.u.size() != problem.size())
      return;
    const Vector lambda = problem.A * solution.u - problem.b;
    // Summed in long double: b and u are each within double's range where
    // b_i u_i is not (a plate of E = 1e-250, whose scaled loads are 1e254
    // and its deflections 1e255, failed this check with W = NaN).
    long double work = 0, scale = 0;
    for (Index i = 0; i < problem.size(); ++i)
      {
        const long double product =
          static_cast<long double>(problem.b[i]) * solution.u[i];
        work += product;
        scale += std::abs(product);
      }
    // Each lambda_i carries the rounding error of A u, epsilon (|A| |u|)_i,
    // into lambda_i l_i: W cannot be known more finely than their sum
    // (without loads lambda is nothing but that error).
    long double rounding = 0;
    for (Index k = 0; k < problem.n_constrained(); ++k)
      {
        const Index       i = problem.constrained[k];
        const long double product =
          static_cast<long double>(lambda[i]) * problem.lower_bound[k];
        work += product;
        scale += std::abs(product);
        double abs_product = 0;
        for (SparseMatrix::InnerIterator it(problem.A, i); it; ++it)
          abs_product += std::abs(it.value() * solution.u[it.row()]);
        rounding += static_cast<long double>(abs_product) *
                    std::abs(problem.lower_bound[k]);
      }
    rounding *= 10 * std::numeric_limits<double>::epsilon();
    if (work >= -1e-6 * scale - rounding)
      return;
    std::ostringstream message;
    message << std::setprecision(3) << "the answer fails the work check: "
            << "b^T u + lambda_S^T l_S = " << work
            << " < 0, but it equals u^T A u >= 0 at every solution ("
            << (problem.definite ? stopped_short :
                                   "a body drifted away as a rigid motion?")
            << ")";
    downgrade(report, message.str());
  }

  void
  check_balance(const Problem  &problem,
                const Solution &solution,
                const double    kkt_tolerance,
                Report         &report)
  {
    if (!report.converged() || solution.u.size() != problem.size())
      return;
    const Vector     lambda = problem.A * solution.u - problem.b;
    const ForceScale scale  = force_scale(problem, solution.u, lambda);
    if (!(scale.forces > 0))
      return; // no loads and no contact force: nothing to balance
    // The residuals of stationarity and of dual feasibility, and, in force
    // units (times the diagonal of A, as the relative complementarity), a
    // force on an open contact: the relative KKT residual measures it
    // against |A| |u|, which a large rigid motion elsewhere makes blind to
    // it.
    const std::vector<char> in_S     = problem.constrained_mask();
    double                  residual = 0;
    for (Index i = 0; i < problem.size(); ++i)
      if (!in_S[i])
        residual = std::max(residual, std::abs(lambda[i]));
    const double mean_diagonal = diagonal_scale(problem.A);
    for (Index k = 0; k < problem.n_constrained(); ++k)
      {
        const Index  i     = problem.constrained[k];
        const double slack = solution.u[i] - problem.lower_bound[k];
        const double stiffness =
          problem.A.coeff(i, i) > 0 ? problem.A.coeff(i, i) : mean_diagonal;
        residual = std::max(
          {residual, -lambda[i], std::min(slack * stiffness, lambda[i])});
      }
    const double       forces     = scale.forces;
    const double       resolution = scale.resolution;
    std::ostringstream message;
    message << std::setprecision(3);
    // Where A is definite no rigid motion hides in |A| |u|: its size
    // against the forces is the conditioning (the plate's grows like
    // h^-4), and the answer is as good as double precision makes it.
    if (resolution > kkt_tolerance && !problem.definite)
      message << "the answer cannot be checked to 'Solver/KKT tolerance' = "
              << kkt_tolerance
              << " in double precision: its displacements are mostly rigid "
                 "motions, "
              << scale.rigid_ratio
              << " times the elastic ones the forces cause, so its forces "
                 "and energy are resolved only to "
              << resolution
              << " of their size; give the loads, the stiffness and the "
                 "gaps in units closer to each other, or accept that "
                 "accuracy with a larger 'KKT tolerance'";
    else if (residual > allowance(scale, kkt_tolerance))
      message << "the forces of the answer do not balance the loads: the "
                 "residual is "
              << residual / forces
              << " of the largest load or contact force (> 'Solver/KKT "
                 "tolerance' and ten times its rounding error, "
              << 10 * resolution
              << "), counting a force on an open contact, although "
                 "the relative KKT residuals pass ("
              << (problem.definite ?
                    stopped_short :
                    "a body held by round-off, or a contact force far "
                    "smaller than the problem's largest motion?")
              << ")";
    else
      return;
    downgrade(report, message.str());
  }

  void
  check_contact_forces(const Problem  &problem,
                       const Solution &solution,
                       const double    kkt_tolerance,
                       Report         &report)
  {
    // The multipliers assess_answer computed from u.
    const Vector &lambda = solution.lambda;
    if (!report.converged() || lambda.size() != problem.size() ||
        problem.eliminated)
      return;
    const Vector terms    = absolute_product(problem.A, solution.u);
    const double rounding = 10 * std::numeric_limits<double>::epsilon() *
                            terms.lpNorm<Eigen::Infinity>();
    double worst   = 0; // the largest pull over its allowance
    Index  worst_k = 0;
    for (Index k = 0; k < problem.n_constrained(); ++k)
      {
        const Index i = problem.constrained[k];
        if (solution.u[i] != problem.lower_bound[k])
          continue;
        const double wrong = -lambda[i];
        const double allowed =
          kkt_tolerance * (std::abs(problem.b[i]) + terms[i]) + rounding;
        if (wrong > allowed && wrong / allowed > worst)
          {
            worst   = wrong / allowed;
            worst_k = k;
          }
      }
    if (worst == 0)
      return;
    const Index        i = problem.constrained[worst_k];
    std::ostringstream message;
    message << std::setprecision(3) << "constraint " << worst_k + 1
            << " (unknown " << i + 1 << ")"
            << " is held at its bound and pulls with a force of " << -lambda[i]
            << ", "
            << -lambda[i] / (std::abs(problem.b[i]) + terms[i] +
                             std::numeric_limits<double>::min())
            << " of the terms of its own row (> 'Solver/KKT tolerance' = "
            << kkt_tolerance
            << " and the rounding of A u), although the residuals relative "
               "to the whole problem pass: it should open (in a part of the "
               "problem loaded far less than the rest)";
    downgrade(report, message.str());
  }

  double
  balance_allowance(const Problem &problem,
                    const Vector  &u,
                    const Vector  &lambda,
                    const double   kkt_tolerance)
  {
    const ForceScale scale = force_scale(problem, u, lambda);
    // Nothing to balance, or forces double precision cannot resolve to the
    // tolerance (check_balance then says so instead): no limit.
    if (!(scale.forces > 0) ||
        (scale.resolution > kkt_tolerance && !problem.definite))
      return std::numeric_limits<double>::infinity();
    return allowance(scale, kkt_tolerance);
  }
} // namespace unilateral::lcp
