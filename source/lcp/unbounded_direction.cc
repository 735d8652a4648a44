#include <unilateral/lcp/unbounded_direction.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace unilateral::lcp
{
  namespace
  {
    /// A's stiffness along a proof, relative to its diagonal along it, at
    /// most.
    constexpr double null_stiffness = 1e-15;
    /// Entries of the other sign on constrained indices, relative.
    constexpr double sign_round_off = 1e-8;
    /// The loads' work along a proof, relative to |b| |d|, at least.
    constexpr double least_drive = 1e-6;
    /// A force (A d)_i beyond this of (|A| |d|)_i resists the motion there.
    constexpr double resisting_force = 1e-8;
  } // namespace

  std::string
  unbounded_direction(const Problem &problem, Vector direction)
  {
    if (direction.size() != problem.size() || problem.definite)
      return "";
    const double largest = direction.lpNorm<Eigen::Infinity>();
    const double loads   = problem.b.norm();
    if (!(largest > 0) || !(loads > 0) || !std::isfinite(largest))
      return "";
    direction /= largest;
    // Entries at round-off of the largest are none (an inverse iteration
    // leaves them on rows that A holds; on a row whose diagonal is zero they
    // would set the scale of the stiffness below).
    for (double &entry : direction)
      if (std::abs(entry) <= 1e-12)
        entry = 0;
    // The loads' side of the motion.
    if (problem.b.dot(direction) < 0)
      direction = -direction;
    // Away from the bounds on every constrained index it moves.
    for (const Index i : problem.constrained)
      {
        if (direction[i] < -sign_round_off)
          return "";
        direction[i] = std::max(direction[i], 0.0);
      }
    const double length    = direction.norm();
    const Vector force     = problem.A * direction;
    const double stiffness = direction.dot(force);
    const double drive     = problem.b.dot(direction);
    // Against A's own diagonal along the motion, not its mean: a stiff
    // unknown beside a soft one is not round-off (a review: A = diag(1,
    // 1e-16), definite, was said to have no solution for b = (1, 1)); not
    // floored by the mean either (a review: scaled, a soft spring then
    // passed for none).
    const double own_diagonal =
      direction.cwiseAbs2().dot(problem.A.diagonal().cwiseAbs());
    if (!(stiffness <= null_stiffness * own_diagonal) ||
        !(drive >= least_drive * loads * length))
      return "";
    // The loads' work must come from where A does not resist the motion:
    // a motion mostly free can carry a small part that A resists, and the
    // work done there proves nothing (a review: a body held 1e6 away by a
    // bound, its loads on a soft spring, solved exactly, was said to have
    // no solution; benchmarks/stress/README.md).
    const Vector rounding      = absolute_product(problem.A, direction);
    double       resisted_work = 0;
    for (Index i = 0; i < problem.size(); ++i)
      if (std::abs(force[i]) > resisting_force * rounding[i])
        resisted_work += std::abs(problem.b[i] * direction[i]);
    if (resisted_work > 1e-3 * drive)
      return "";
    // Moved: beyond round-off of the largest entry (one), as the free
    // motion's subset in PDAS (a review: counting every nonzero named 151
    // unknowns where one body of 4 was driven off).
    Index moved = 0;
    for (Index i = 0; i < direction.size(); ++i)
      moved += std::abs(direction[i]) > 1e-6;
    std::ostringstream message;
    message << std::setprecision(3)
            << "the LCP has no solution: the loads drive "
            << (moved == problem.size() ?
                  std::string("every unknown") :
                  std::to_string(moved) + " of the " +
                    std::to_string(problem.size()) + " unknowns")
            << " away along a motion that neither A nor any bound "
               "resists (its stiffness "
            << (own_diagonal > 0 ? std::max(stiffness, 0.0) / own_diagonal :
                                   0.0)
            << " of A's diagonal along it, the loads' work along it "
            << drive / (loads * length)
            << " of |b| |d|): the energy falls without bound";
    return message.str();
  }
} // namespace unilateral::lcp
