#pragma once

#include <deal.II/base/array_view.h>

#include <array>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

/**
 * The change of variables of Ainsworth & Mihai, Section 3: from physical
 * displacement DOFs u to new variables u~ = C~ u (+ a constant where
 * displacements are prescribed), in which every unilateral constraint is a
 * simple bound, so the LCP has the form of lcp/problem.h.
 *
 * The paper writes it for joints along the axes, where a constraint row of C
 * involves one displacement component of two nodes. For joints and supports
 * of any orientation we write each node's displacement in a frame of its
 * own, and then do exactly what the paper does in each direction:
 *  - the normals of all constraints and rollers are grouped into direction
 *    classes d_k (equal up to sign, to 1e-9); constraint i has normal
 *    n_i = s_i d_k;
 *  - a node a that is not held gets a frame T_a: first the classes of the
 *    constraints and rollers at a (at most dim, linearly independent), then
 *    an orthonormal completion; its frame variables are v_a = T_a u_a, so
 *    u_a = T_a^-1 v_a, and v_{a,k} = d_k . u_a is the node's displacement
 *    along class k;
 *  - per class, nodes are vertices of a graph and constraints edges, with
 *    one extra "ground" vertex for held nodes, rollers (v_{a,k} = 0) and
 *    Signorini constraints. C~ is invertible iff each class's graph is a
 *    forest in which ground is one vertex (a cycle, or a chain on two
 *    supports, is a dependent row); union-find checks it;
 *  - each tree is oriented from its root (ground if it touches it, else its
 *    smallest node); the child of each edge owns it, and the gap of the edge
 *    replaces the child's frame variable of that class:
 *    v_child = +-s w + v_parent (a joint's gap w = n . (u_upper - u_lower)),
 *    v_child = s w (Signorini: w = n . u >= bound);
 *  - C~^-1 is explicit and sparse: u at a DOF is a short list of (variable,
 *    coefficient) terms plus a constant (a prescribed displacement at the
 *    root of a chain).
 * For axis-parallel normals every frame is the identity up to the order of
 * its rows and this is the paper's change of variables, term for term. One
 * variable per DOF that is neither held nor on a roller, numbered in DOF
 * order (each frame row is assigned to one of the node's components).
 *
 * The assembly expands every local physical DOF into these terms, which gives
 * A~ = C~^-T A C~^-1 and b~ = C~^-T (b - A c) cell by cell, with no global
 * product.
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

  template <int dim>
  using Direction = std::array<double, dim>;

  enum class ConstraintKind : unsigned char
  {
    signorini, ///< n . u >= bound at a node (a rigid support)
    joint      ///< n . (u_upper - u_lower) >= 0 at a pair of coincident nodes
  };

  std::string
  to_string(ConstraintKind kind);

  /**
   * One row of C. Joints: the normal gap n . (u[upper] - u[lower]) >= 0,
   * where n is the outward unit normal of the lower node's block (it points
   * into the upper node's block), so C u >= 0 means no penetration.
   * Signorini: n . u[lower] >= bound (= -gap), n the unit normal pointing
   * from the support into the block; upper unused. lower and upper are
   * node indices.
   */
  template <int dim>
  struct UnilateralConstraint
  {
    ConstraintKind kind  = ConstraintKind::signorini;
    unsigned int   lower = 0;
    unsigned int   upper = 0;
    Direction<dim> normal{};
    double         bound = 0;
  };

  /**
   * Direction classes: normals equal up to sign (to @p tolerance in each
   * component, 1e-9 unless the caller says otherwise) share one canonical
   * direction d, the first of the class met (made to have its first
   * component above 1e-8 in magnitude positive), so that n = s d with
   * s = +-1.
   */
  template <int dim>
  class DirectionClasses
  {
  public:
    explicit DirectionClasses(double tolerance = 1e-9);

    /// The class of the unit vector @p normal, the nearest within the
    /// tolerance of d or -d (a new one if none is), and the sign s with
    /// normal = s d. A class made later may be nearer to a direction
    /// classified before: where equal normals must get one class, classify
    /// them all once and then again (the second pass makes none).
    std::pair<unsigned int, double>
    classify(const Direction<dim> &normal);

    /// The classes within @p radius (at most 10 times the tolerance) of
    /// the class direction @p d, each with +1, or -1 where its direction is
    /// near -d.
    std::vector<std::pair<unsigned int, double>>
    within(const Direction<dim> &d, double radius) const;

    /// d of each class.
    std::vector<Direction<dim>> directions;

  private:
    double tolerance;
    /// The classes by their d on a grid of spacing 10 tolerance (a cell
    /// may hold several: directions further apart than the tolerance).
    std::map<std::array<long, dim>, std::vector<unsigned int>> index;

    /// The normals classified since a class was last made, with their
    /// classes, the latest last (at most max_recent): a wall classifies a
    /// few normals (its faces' four or six) many times over, alternating,
    /// and each classification probes the grid 18 times. A class is a
    /// function of the normal and the classes, so these hold until a
    /// class is made.
    std::vector<std::pair<Direction<dim>, std::pair<unsigned int, double>>>
                                 recent;
    static constexpr std::size_t max_recent = 8;

    /// classify() without the memory of the recent calls.
    std::pair<unsigned int, double>
    classify_anew(const Direction<dim> &normal);

    /// The nearest class within the tolerance of @p d (-1 if none) and
    /// its distance.
    std::pair<int, double>
    find(const Direction<dim> &d) const;

    /// @p action(k, difference) for each class k within @p radius of @p d.
    template <typename Action>
    void
    for_each_near(const Direction<dim> &d,
                  double                radius,
                  const Action         &action) const;
  };

  /// n . u = 0 at a node (normal displacement zero).
  template <int dim>
  struct Roller
  {
    unsigned int   node = 0;
    Direction<dim> normal{};
  };

  /// u = value at a node (fixed, or a prescribed displacement).
  template <int dim>
  struct HeldNode
  {
    unsigned int            node = 0;
    std::array<double, dim> value{};
  };

  template <int dim>
  class ChangeOfVariables
  {
  public:
    /// u_dof = constant + sum over the terms of coefficient * u~[variable].
    struct Term
    {
      int    variable;
      double coefficient;
    };

    /**
     * Build the change of variables for @p n_dofs physical DOFs grouped into
     * @p nodes (the DOF of each component), of which the @p held ones are
     * prescribed (and drop out of the LCP, like DOFs whose frame row is a
     * roller), subject to @p constraints. @p describe names a node for error
     * messages (its position and block). Throws InputError if the
     * constraints make C~ singular (a cycle, a chain on two supports, more
     * than dim or dependent directions at a node).
     */
    ChangeOfVariables(DofIndex                                      n_dofs,
                      const std::vector<std::array<DofIndex, dim>> &nodes,
                      const std::vector<HeldNode<dim>>             &held,
                      const std::vector<Roller<dim>>               &rollers,
                      const std::vector<UnilateralConstraint<dim>> &constraints,
                      const std::function<std::string(unsigned int)> &describe);

    /// n: the LCP unknowns (DOFs neither held nor on a roller).
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

    /// The new variable of physical DOF @p dof, or -1 if it has none (held,
    /// or its frame row is on a roller).
    int
    variable_of_dof(const DofIndex dof) const
    {
      return variable[dof];
    }

    /// The terms of u_dof in the new variables.
    std::pair<const Term *, const Term *>
    expansion(const DofIndex dof) const
    {
      return {terms.data() + term_start[dof],
              terms.data() + term_start[dof + 1]};
    }

    /// The constant part of u_dof (prescribed displacements).
    double
    offset(const DofIndex dof) const
    {
      return offsets[dof];
    }

    /// Whether any DOF has a constant part.
    bool
    has_offsets() const
    {
      return any_offset;
    }

    /// The longest expansion (1 + depth of the deepest constraint tree, for
    /// axis-parallel normals).
    unsigned int
    max_expansion_length() const;

    /// u = C~^-1 u~ (+ the constants) for all physical DOFs.
    std::vector<double>
    to_physical(const double *new_variables) const;

    /// Row @p variable of C~ itself: u~_variable = sum of coefficient *
    /// u_dof over these (DOF, coefficient) pairs, the constants aside (a
    /// gap is n . (u_upper - u_lower) or n . u, any other variable its
    /// node's frame row times u). For the dual methods, which work in the
    /// physical DOFs.
    dealii::ArrayView<const std::pair<DofIndex, double>>
    row(const unsigned int variable) const
    {
      return {row_entries.data() + row_start[variable],
              row_start[variable + 1] - row_start[variable]};
    }

  private:
    unsigned int             n_variables = 0;
    std::vector<int>         variable;
    std::vector<int>         constraint_variable;
    std::vector<std::size_t> term_start;
    std::vector<Term>        terms;
    std::vector<double>      offsets;
    bool                     any_offset = false;
    /// Row t of C~: row_entries[row_start[t], row_start[t + 1]).
    std::vector<std::size_t>                 row_start;
    std::vector<std::pair<DofIndex, double>> row_entries;
  };
} // namespace unilateral::masonry
