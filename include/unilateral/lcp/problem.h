#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <memory>
#include <string>
#include <vector>

/**
 * The solver layer: one mixed linear complementarity problem (LCP) form that
 * both studies reduce to, and every algorithm they describe.
 *
 * Problem form. Given A (n x n, sparse, symmetric positive semidefinite), b,
 * a set S of constrained indices and lower bounds l_S, find u such that with
 *   lambda = A u - b:
 *     lambda_i = 0                      for i not in S,
 *     u_S >= l_S,  lambda_S >= 0,  (u_S - l_S)^T lambda_S = 0.
 * Equivalently: u minimises 1/2 u^T A u - b^T u subject to u_S >= l_S.
 *
 * How the papers map onto it:
 *  - Ainsworth & Mihai (masonry), LCP (3.7)-(3.8): A u + Sigma = b with
 *    Sigma_S <= 0, u_S >= 0. So Sigma = -lambda and l = 0 (after their change
 *    of variables; we keep Signorini bounds as l = -g instead of shifting).
 *  - Fernandes, Figueiredo & Judice (plate), MLCP (32)-(35):
 *    w_J = C_JJ z_J - F_J, z_J1 >= psi, w_J1 >= 0. So A = C_JJ, b = F_J,
 *    u = z, lambda = w, S = J1 and l = psi.
 */
namespace unilateral::lcp
{
  struct Tearing;
  struct Hierarchy;

  using Index        = int;
  using Vector       = Eigen::VectorXd;
  using DenseMatrix  = Eigen::MatrixXd;
  using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, Index>;

  struct Problem
  {
    Problem()                = default;
    Problem(const Problem &) = default;
    Problem &
    operator=(const Problem &) = default;

    /**
     * Moves hand A over by swapping it. Eigen 3.4's SparseMatrix has no
     * move operations, so the defaults would copy A, the largest object of
     * a run, and hold it twice (a masonry wall of m = 1000 was killed by
     * the kernel storing its assembled problem). A member added below must
     * be added to the move assignment too (problem.cc).
     */
    Problem(Problem &&other) noexcept;

    Problem &
    operator=(Problem &&other) noexcept;

    /// Symmetric positive semidefinite, both triangles stored, compressed,
    /// every diagonal entry present in the pattern (possibly zero).
    SparseMatrix A;
    Vector       b;
    /// S: the constrained indices, strictly increasing.
    std::vector<Index> constrained;
    /// l_S: one lower bound per entry of `constrained`, in the same order.
    Vector lower_bound;

    /**
     * @name What the builder knows of the problem
     * Not data of the LCP: they only choose the solvers' automatic settings
     * and what the answer checks may blame.
     */
    /// @{
    /// A is singular unless the constraints hold the bodies (blocks free to
    /// move): 'Solver/Regularisation = auto' regularises from the start.
    bool floating_bodies = false;
    /// Most constraints are active at the solution (structures in contact
    /// almost everywhere): 'Solver/PDAS/Start = auto' starts all active.
    bool mostly_active = false;
    /// A is known to be positive semidefinite: by construction (a stiffness
    /// matrix assembled from semidefinite element matrices, or a congruence
    /// of one) or verified (verify_semidefinite): solve_lcp does not
    /// factorise it to verify that again.
    bool known_semidefinite = false;
    /// A is positive definite by construction (every body held: the
    /// clamped plate). No rigid motion can hide in |A| |u| then, and its
    /// size against the loads measures the conditioning (h^-4 for the
    /// plate) rather than a drift: the answer checks (answer_checks.h) do
    /// not refuse an answer for it.
    bool definite = false;
    /// A and b were computed by an elimination (the Schur complement on the
    /// constrained unknowns): they carry the rounding of the original
    /// problem's forces, which their own |A| |u| does not show (where A_EE
    /// holds all of A's rank they are nothing but that rounding), so the
    /// check of each contact against its own row does not apply to them;
    /// the full problem's judgement of the recovered answer does.
    bool eliminated = false;
    /// The problem torn into floating subdomains (tearing.h), for the dual
    /// methods; null if the builder made none.
    std::shared_ptr<const Tearing> tearing;
    /// The problem on a sequence of coarser meshes (hierarchy.h), for the
    /// multigrid methods; null if the builder made none.
    std::shared_ptr<const Hierarchy> hierarchy;
    /// The builder's unit of energy: where it divided A and b by a unit of
    /// force (so that the solvers see the same numbers in any units),
    /// energy() reports the objective times it, multiplied before the sum
    /// is rounded to double. Multiplied afterwards, the scaled energy of a
    /// plate of E = 1e300 (about 1e-590) had already underflowed to 0.
    double energy_unit = 1;
    /// @}

    Index
    size() const
    {
      return static_cast<Index>(b.size());
    }

    Index
    n_constrained() const
    {
      return static_cast<Index>(constrained.size());
    }

    /// mask[i] != 0 iff i is in S.
    std::vector<char>
    constrained_mask() const;

    /// The bound of every index: l_i on S, -infinity elsewhere.
    Vector
    full_lower_bound() const;
  };

  /**
   * Check that @p problem is a well-posed instance of the form above and put
   * it into the canonical storage (compressed, sorted S, diagonal present).
   * Throws InputError with one line naming the problem: dimension mismatch,
   * non-symmetric A, NaN or infinite entries, negative diagonal, repeated or
   * out-of-range indices in S.
   */
  void
  check_and_normalise(Problem &problem);

  /**
   * Set to zero the diagonal entries of @p schur, a Schur complement
   * A_UU - A_UF A_FF^-1 A_FU formed by the solver layer itself (U =
   * @p indices, in the order of its rows), that are negative by no more
   * than 1e-10 times the diagonal of @p A they came from: A is
   * semidefinite (verified to
   * that tolerance), so the complement is, and its diagonal vanishes
   * exactly where releasing an index leaves a body free, where
   * cancellation leaves it a few ulps either side of zero. Not for the
   * user's data: check_and_normalise refuses a negative diagonal there,
   * and here, after this, it would refuse only a complement that is not
   * semidefinite beyond round-off.
   */
  void
  clamp_rounded_diagonal(DenseMatrix              &schur,
                         const SparseMatrix       &A,
                         const std::vector<Index> &indices);

  /// Where each diagonal entry of @p A sits in its value array (A
  /// compressed, every diagonal entry stored: what check_and_normalise()
  /// makes of a Problem's A); std::logic_error otherwise.
  std::vector<Index>
  diagonal_positions(const SparseMatrix &A);

  /// The mean of @p A's diagonal, or 1 where that is not positive (an
  /// empty or indefinite A): the unit of every relative eps and shift.
  double
  diagonal_scale(const SparseMatrix &A);

  /// The objective 1/2 u^T A u - b^T u, in the builder's units
  /// (Problem::energy_unit).
  double
  energy(const Problem &problem, const Vector &u);

  /// What a failure message blames where a system of A's rows came out
  /// singular or an answer ran away: a body held by no constraint, or,
  /// where A is definite (Problem::definite: every body held), round-off,
  /// which only a badly scaled problem makes that large.
  std::string
  singular_cause(const Problem &problem);

  /// |A| |u|: the size of the terms that cancel in A u (its rounding error
  /// is epsilon times that).
  Vector
  absolute_product(const SparseMatrix &A, const Vector &u);

  /**
   * Relative KKT residuals of u (lambda = A u - b is computed here, so no
   * solver can report a residual it did not earn), in the unknowns scaled
   * to A's unit diagonal: with D = diag(A) (its mean where an entry is not
   * positive), forces are measured as D^-1/2 lambda and displacements as
   * D^1/2 u, so that unknowns of different units (a plate's deflections,
   * slopes and twists) each count in their own. With the force scale
   * f = ||D^-1/2 b||_inf + ||D^-1/2 |A| |u| ||_inf (1 if zero) and the
   * displacement scale d = ||D^1/2 u||_inf (||D^1/2 l_S||_inf where u = 0;
   * 1 if zero):
   *  stationarity       = ||D^-1/2 lambda_{not S}||_inf / f
   *  primal feasibility = ||D^1/2 max(l_S - u_S, 0)||_inf / d
   *  dual feasibility   = ||D^-1/2 max(-lambda_S, 0)||_inf / f
   *  complementarity    = max over S of
   *                       min(|u_i - l_i| A_ii^1/2, |lambda_i| A_ii^-1/2) / f,
   * the natural (min-map) residual in force units. Unlike the product
   * (u_i - l_i) lambda_i it bounds the error of u: an interior-point iterate
   * with slack 1e-6 at a contact has a product near 1e-12 but a min-map
   * residual near 1e-6, which is its real accuracy.
   */
  struct KktResiduals
  {
    double stationarity       = 0;
    double primal_feasibility = 0;
    double dual_feasibility   = 0;
    double complementarity    = 0;

    double
    max() const;
  };

  KktResiduals
  kkt_residuals(const Problem &problem, const Vector &u);

  /// The multiplier lambda = A u - b on S, zero elsewhere.
  Vector
  multiplier(const Problem &problem, const Vector &u);
} // namespace unilateral::lcp
