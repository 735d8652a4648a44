#include <unilateral/lcp/unbounded_direction.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace unilateral::lcp
{
  namespace
  {
    /// A's stiffness along a proof, relative to its mean diagonal, at most.
    constexpr double null_stiffness = 1e-15;
    /// Entries of the other sign on constrained indices, relative.
    constexpr double sign_round_off = 1e-8;
    /// The loads' work along a proof, relative to |b| |d|, at least.
    constexpr double least_drive = 1e-6;
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
    const double stiffness = direction.dot(problem.A * direction);
    const double drive     = problem.b.dot(direction);
    if (!(stiffness <=
          null_stiffness * diagonal_scale(problem.A) * length * length) ||
        !(drive >= least_drive * loads * length))
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
            << std::max(stiffness, 0.0) /
                 (diagonal_scale(problem.A) * length * length)
            << " of A's mean diagonal, the loads' work along it "
            << drive / (loads * length)
            << " of |b| |d|): the energy falls without bound";
    return message.str();
  }
} // namespace unilateral::lcp
