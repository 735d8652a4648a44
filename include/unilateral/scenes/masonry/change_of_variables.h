#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

/**
 * The change of variables of Ainsworth & Mihai, Section 3: from physical
 * displacement DOFs u to new variables u~ = C~ u, in which every unilateral
 * constraint is a simple bound, so the LCP has the form of lcp/problem.h.
 *
 * The matrix C~ is the identity with the rows of "owner" DOFs replaced by the
 * constraint rows of C. We never form C~ or its inverse as matrices. Instead:
 *  - DOFs are vertices of a graph, constraints are edges; Dirichlet DOFs and
 *    Signorini constraints are edges to one extra "ground" vertex.
 *  - C~ is invertible iff every connected component is a tree with at most
 *    one ground connection (union-find detects the cycles; for rectangular
 *    blocks there are none).
 *  - Each tree is oriented from its root (the ground if it touches it, else
 *    its smallest DOF); the owner of an edge is its child endpoint, so owners
 *    are distinct and each DOF carries exactly one new variable: the gap of
 *    its parent edge, its Signorini displacement, zero (Dirichlet, then
 *    eliminated), or itself (roots and unconstrained DOFs).
 *  - C~^-1 is then explicit and sparse: u_v is u_root plus the signed gaps on
 *    the path from the root, a list of a few (variable, +-1) terms per DOF.
 * The assembly expands every local physical DOF into these terms, which gives
 * A~ = C~^-T A C~^-1 and b~ = C~^-T b cell by cell, with no global product.
 *
 * Why not deal.II's AffineConstraints, which expands DOFs cell by cell in
 * the same way: a constraint there removes a DOF, writing it in terms of
 * the others; here a DOF is replaced by a new unknown of its own, the gap,
 * which stays in the problem and carries the bound. AffineConstraints has
 * no place for such a substitution, so the expansion lists are ours.
 */
namespace unilateral::masonry
{
  /// Same as dealii::types::global_dof_index (checked where both are seen).
  using DofIndex = unsigned int;

  enum class ConstraintKind : unsigned char
  {
    signorini,        ///< u_y >= -g at a base node (rigid obstacle)
    horizontal_joint, ///< u_y(upper) - u_y(lower) >= 0 at a node pair
    vertical_joint    ///< u_x(right) - u_x(left) >= 0 at a node pair
  };

  std::string
  to_string(ConstraintKind kind);

  /**
   * One row of C. Joints: the normal gap u[upper] - u[lower] >= 0, where
   * "upper" is the DOF of the block above (horizontal joint) or to the right
   * (vertical joint), so C u >= 0 means no penetration. Signorini: u[lower]
   * >= bound = -g (upper unused).
   */
  struct UnilateralConstraint
  {
    ConstraintKind kind  = ConstraintKind::signorini;
    DofIndex       lower = 0;
    DofIndex       upper = 0;
    double         bound = 0;
  };

  class ChangeOfVariables
  {
  public:
    /// u_dof = sum over the terms of coefficient * u~[variable].
    struct Term
    {
      int    variable;
      double coefficient;
    };

    /**
     * Build the change of variables for @p n_dofs physical DOFs, of which
     * those with @p dirichlet[i] != 0 are fixed to zero and eliminated (they
     * are not LCP unknowns), subject to @p constraints (no duplicates).
     * @p describe names a DOF for error messages (e.g. its position). Throws
     * InputError if the constraints make C~ singular (a cycle).
     */
    ChangeOfVariables(DofIndex                                    n_dofs,
                      const std::vector<char>                    &dirichlet,
                      const std::vector<UnilateralConstraint>    &constraints,
                      const std::function<std::string(DofIndex)> &describe);

    /// n: the LCP unknowns (physical DOFs minus Dirichlet DOFs).
    unsigned int
    n_unknowns() const
    {
      return n_variables;
    }

    /// n_c: the constrained variables.
    unsigned int
    n_constraints() const
    {
      return static_cast<unsigned int>(constraint_variable.size());
    }

    /// The LCP variable that carries constraint @p k (the owner's variable).
    int
    variable_of_constraint(const std::size_t k) const
    {
      return constraint_variable[k];
    }

    /// The new variable of physical DOF @p dof, or -1 for Dirichlet DOFs.
    int
    variable_of_dof(const DofIndex dof) const
    {
      return variable[dof];
    }

    /// The terms of u_dof in the new variables (empty for Dirichlet DOFs).
    std::pair<const Term *, const Term *>
    expansion(const DofIndex dof) const
    {
      return {terms.data() + term_start[dof],
              terms.data() + term_start[dof + 1]};
    }

    /// The longest expansion (1 + depth of the deepest constraint tree).
    unsigned int
    max_expansion_length() const;

    /// u = C~^-1 u~ for all physical DOFs (zero on Dirichlet DOFs).
    std::vector<double>
    to_physical(const double *new_variables) const;

  private:
    unsigned int             n_variables = 0;
    std::vector<int>         variable;
    std::vector<int>         constraint_variable;
    std::vector<std::size_t> term_start;
    std::vector<Term>        terms;
  };
} // namespace unilateral::masonry
