#pragma once

#include <unilateral/scenes/masonry/parameters.h>

#include <deal.II/base/function.h>
#include <deal.II/base/point.h>
#include <deal.II/base/types.h>

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace unilateral::masonry
{
  /// The boundaries of a mesh: names (a mesh file's physical names, the
  /// built-in walls' left, right, base, top, front, back) and the ids that
  /// are on the boundary.
  struct BoundaryNames
  {
    std::map<std::string, dealii::types::boundary_id> id_of_name;
    std::set<dealii::types::boundary_id>              ids_on_boundary;
    /// What the boundaries belong to, for messages ("arch.msh").
    std::string source;
    /// What a support on a boundary of none of these names should do
    /// instead, for messages.
    std::string fix;
    /// Names that may be absent from the mesh without an error (the
    /// built-in walls' collar, which a wall one block thick has not).
    std::set<std::string> optional;

    /// The name of @p id (its number if it has none).
    std::string
    name(dealii::types::boundary_id id) const;
  };

  /**
   * One support or load on one boundary: what the parameters'
   * BoundarySelections become once the mesh is known (names resolved to
   * boundary ids, region expressions parsed).
   */
  template <int dim>
  struct Support
  {
    /// In the order of strength: where several meet at a node, the
    /// stronger wins, direction by direction.
    enum class Kind
    {
      held,        ///< u = 0 (Fixed) or the prescribed displacement
      normal_zero, ///< u . n = 0
      signorini,   ///< u . n <= gap (n outward)
      traction     ///< loaded by the traction
    };

    Kind                       kind       = Kind::held;
    bool                       prescribed = false; ///< held: prescribed or 0
    dealii::types::boundary_id boundary   = 0;
    /// The boundary as the parameter file names it.
    std::string name;
    /// The parameter and its item, for messages ("'Signorini' = 'base
    /// where x < s'").
    std::string description;
    /// Where on the boundary; null: everywhere.
    std::shared_ptr<const dealii::Function<dim>> region;
  };

  /// The supports and loads of a run, and the functions they use.
  template <int dim>
  struct Supports
  {
    std::vector<Support<dim>> list;
    /// The Signorini gap (scalar), the prescribed displacement and the
    /// traction (dim components).
    std::shared_ptr<const dealii::Function<dim>> gap, displacement, traction;
    /// The traction is '0' in every component: nothing to integrate.
    bool zero_traction = true;
    /// The body force per unit density: gravity times its unit direction.
    dealii::Tensor<1, dim> gravity;

    /**
     * Whether @p support acts at @p node of a face with vertices
     * @p face_vertices: the node lies in the closure of the face's part
     * inside the region (probed at the node and just inside the face
     * towards each vertex and the face's centre).
     */
    bool
    acts_at(const Support<dim>                    &support,
            const dealii::Point<dim>              &node,
            const std::vector<dealii::Point<dim>> &face_vertices) const;

    /// The supports of @p boundary (in the order of the list).
    std::vector<const Support<dim> *>
    on_boundary(dealii::types::boundary_id boundary) const;
  };

  /// The constants of the expressions.
  struct ExpressionConstants
  {
    double g = 0; ///< Relative gap * H
    double H = 1; ///< the built-in walls' block height; 1 for a mesh file
    double s = 0; ///< where the built-in walls' settled base ends
  };

  /**
   * The supports and loads of @p parameters on a mesh with boundaries
   * @p names. Throws InputError (one line naming the parameter) for a
   * boundary that is not on the mesh, a region or function that does not
   * parse, or a vector function with the wrong number of components.
   */
  template <int dim>
  Supports<dim>
  make_supports(const BoundaryParameters  &parameters,
                const BoundaryNames       &names,
                const ExpressionConstants &constants);
} // namespace unilateral::masonry
