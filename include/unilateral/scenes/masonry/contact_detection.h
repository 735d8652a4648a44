#pragma once

#include <unilateral/scenes/masonry/change_of_variables.h>
#include <unilateral/scenes/masonry/layout.h>

#include <array>
#include <string>
#include <vector>

namespace dealii
{
  template <int dim, int spacedim>
  class DoFHandler;
}

namespace unilateral::masonry
{
  /**
   * Everything the boundary and the joints impose, found geometrically on the
   * triangulation of separately meshed blocks (material_id = block index):
   *  - u_x = 0 on the sides x = x_min, x = x_max of the bounding box;
   *  - on the base y = y_min: Signorini u_y >= -g at nodes with
   *    x < x_split, u_y = 0 at nodes with x > x_split; a node at x_split is
   *    Signorini only if its block ends there;
   *  - one non-penetration constraint per pair of coincident nodes on every
   *    edge shared by two blocks (boundary faces of different blocks that
   *    overlap on a segment of positive length; blocks that touch only at a
   *    corner share none).
   */
  struct ContactSet
  {
    /// dirichlet[i] != 0: DOF i is fixed to zero (and not an LCP unknown).
    std::vector<char> dirichlet;
    /// Signorini rows first, then joint rows (sorted by DOF).
    std::vector<UnilateralConstraint> constraints;
    /// Where each constraint acts.
    std::vector<std::array<double, 2>> position;
    /// The blocks of each constraint: {lower or left, upper or right};
    /// Signorini: {block, block}.
    std::vector<std::array<unsigned int, 2>> blocks;
    /**
     * For the contact pressure: per DOF (a node and a normal direction), the
     * Simpson weight of the node on its contact faces with that normal (h/6
     * at a face end, 2h/3 at a face midpoint, summed over the faces that
     * contain the node). Zero off contact faces.
     */
    std::vector<double> contact_weight;

    unsigned int n_dirichlet        = 0;
    unsigned int n_signorini        = 0;
    unsigned int n_horizontal_joint = 0;
    unsigned int n_vertical_joint   = 0;
  };

  /**
   * Build the ContactSet of @p dof_handler (FESystem of two scalar quadratic
   * Lagrange elements, FE_Q or FE_SimplexP, on straight-sided cells).
   * @p tolerance decides coincidence of coordinates (a small multiple of the
   * machine precision times the cell size). Throws InputError for boundary
   * faces that are not axis-parallel and for non-matching nodes on a shared
   * edge.
   */
  ContactSet
  detect_contacts(const dealii::DoFHandler<2, 2> &dof_handler,
                  double                          signorini_fraction,
                  double                          gap,
                  double                          tolerance);

  /// "(x, y) in block b" for messages.
  std::string
  describe_point(double x, double y, unsigned int block);
} // namespace unilateral::masonry
