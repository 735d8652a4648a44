#pragma once

#include <unilateral/scenes/masonry/change_of_variables.h>
#include <unilateral/scenes/masonry/supports.h>

#include <array>
#include <string>
#include <vector>

namespace dealii
{
  template <int dim, int spacedim>
  class DoFHandler;
  template <int dim, int spacedim>
  class Mapping;
} // namespace dealii

namespace unilateral::masonry
{
  /**
   * Everything the supports and the joints impose, found geometrically on a
   * triangulation of separately meshed blocks (material_id = block index),
   * in 2D and 3D and for faces of any orientation:
   *  - the nodes: every support point of a block, with the DOF of each of
   *    its displacement components;
   *  - the supports (supports.h), node by node: a support acts at the nodes
   *    of its boundary's faces (inside its region); where several meet at a
   *    node the stronger wins, direction by direction: a held node (Fixed,
   *    Prescribed displacement) takes no other condition, a roller
   *    (Normal displacement zero) removes Signorini in its direction.
   *    Normals of faces at a node that differ by less than 25 degrees are
   *    averaged (a curved boundary made of flat faces);
   *  - the joints: boundary faces of two different blocks that are
   *    parallel, opposite and in one plane (to the tolerance) and overlap
   *    with positive length (2D) or area (3D) are in contact; every pair of
   *    coincident nodes on them gives one constraint along the faces'
   *    normal (faces that touch only along an edge or at a corner give
   *    none). Nodes inside the other face without a coincident partner are
   *    an error (node-to-node contact needs matching nodes), and so are
   *    parallel opposite overlapping faces at a distance between the
   *    tolerance and 1e-2 times the cell size (a gap or an overlap).
   */
  template <int dim>
  struct ContactSet
  {
    /// @name The nodes
    /// @{
    std::vector<std::array<DofIndex, dim>> node_dofs;
    std::vector<std::array<double, dim>>   node_position;
    std::vector<unsigned int>              node_block;
    /// The node of every DOF.
    std::vector<unsigned int> node_of_dof;
    /// @}

    /// Held nodes (a support's index in `support_names` for each).
    std::vector<HeldNode<dim>> held;
    std::vector<unsigned int>  held_support;
    /// Rollers, and their supports.
    std::vector<Roller<dim>>  rollers;
    std::vector<unsigned int> roller_support;
    /// For the contact pressure at a roller: the node's weight on the
    /// roller's faces, int phi_node over them (as `weight`).
    std::vector<double> roller_weight;

    /// Signorini rows first (in DOF order), then joint rows (sorted by
    /// DOF).
    std::vector<UnilateralConstraint<dim>> constraints;
    /// Where each constraint acts.
    std::vector<std::array<double, dim>> position;
    /// The blocks of each constraint: {lower, upper}; Signorini: {block,
    /// block}.
    std::vector<std::array<unsigned int, 2>> blocks;
    /// Signorini rows: their support's index in `support_names`.
    std::vector<unsigned int> signorini_support;
    /**
     * For the contact pressure: per constraint and end (lower, upper), the
     * node's weight on its contact (or support) faces in the constraint's
     * direction, int phi_node over those faces (h/6 and 2h/3 on a quadratic
     * edge: exact for a uniform pressure).
     */
    std::vector<std::array<double, 2>> weight;

    /// The supports' names ("base"), for the reactions.
    std::vector<std::string> support_names;
    /// Supports and tractions restricted to a region that holds no node
    /// of their boundary (a mistyped region, or one the wall's size leaves
    /// empty), by their descriptions: the scene notes them.
    std::vector<std::string> supports_acting_nowhere;
    /// Faces of two blocks parallel, opposite and overlapping, at a
    /// distance beyond the refusal band (1e-2 of the smallest cell) but
    /// within 4e-2 of it: no joint, which a drawing meant as touching did
    /// not intend. One line per pair of blocks, for notes.
    std::vector<std::string> nearly_touching;

    unsigned int n_held_dofs        = 0;
    unsigned int n_rollers          = 0;
    unsigned int n_signorini        = 0;
    unsigned int n_horizontal_joint = 0; ///< normal along y
    unsigned int n_vertical_joint   = 0; ///< normal along x or z
    unsigned int n_inclined_joint   = 0; ///< any other normal

    /// DOFs that are not LCP unknowns: held ones and rollers.
    unsigned int
    n_eliminated() const
    {
      return n_held_dofs + n_rollers;
    }

    /// "(x, y) in block b" for messages.
    std::string
    describe_node(unsigned int node) const;
  };

  /**
   * Build the ContactSet of @p dof_handler (FESystem of dim scalar
   * quadratic Lagrange elements, FE_Q or FE_SimplexP, on cells with flat
   * faces) with the supports @p supports. @p tolerance decides coincidence
   * (of nodes, and of the planes of faces); @p cell_size is the smallest
   * cell size (near faces, closer than 1e-2 of it, must coincide). Throws
   * InputError for degenerate faces, non-matching nodes on a shared face,
   * gaps and overlaps between faces that nearly coincide, conflicting
   * prescribed displacements at a node, and Signorini gaps below zero.
   */
  template <int dim>
  ContactSet<dim>
  detect_contacts(const dealii::DoFHandler<dim, dim> &dof_handler,
                  const dealii::Mapping<dim, dim>    &mapping,
                  const Supports<dim>                &supports,
                  double                              tolerance,
                  double                              cell_size);

  /// "(x, y[, z]) in block b" for messages.
  template <int dim>
  std::string
  describe_point(const std::array<double, dim> &point, unsigned int block);
} // namespace unilateral::masonry
