#pragma once

#include <unilateral/scenes/masonry/contact_detection.h>

#include <algorithm>
#include <array>
#include <string>
#include <vector>

namespace unilateral::masonry
{
  /// A block's rigid motions: dim translations and dim (dim - 1) / 2
  /// rotations.
  constexpr unsigned int
  n_rigid_motions(const int dim)
  {
    return dim == 2 ? 3 : 6;
  }

  /**
   * A rigid motion v of a body written about its @p centre, its rotation
   * scaled by the body's @p size (every column of one scale): dim
   * translations t, then the rotation w (w e_z in 2D). Its displacement at
   * @p p: t + (w / size) x (p - centre).
   */
  template <int dim>
  std::array<double, dim>
  rigid_displacement(const double                  *v,
                     const std::array<double, dim> &p,
                     const std::array<double, dim> &centre,
                     const double                   size)
  {
    std::array<double, dim> u{}, d{};
    for (unsigned int c = 0; c < dim; ++c)
      {
        u[c] = v[c];
        d[c] = (p[c] - centre[c]) / std::max(size, 1e-300);
      }
    if constexpr (dim == 2)
      {
        u[0] -= v[2] * d[1];
        u[1] += v[2] * d[0];
      }
    else
      {
        u[0] += v[4] * d[2] - v[5] * d[1];
        u[1] += v[5] * d[0] - v[3] * d[2];
        u[2] += v[3] * d[1] - v[4] * d[0];
      }
    return u;
  }

  /// The row of @p normal . u at @p p over that motion's components:
  /// n . t + w . ((p - centre) x n) / size.
  template <int dim>
  std::array<double, n_rigid_motions(dim)>
  rigid_row(const std::array<double, dim> &normal,
            const std::array<double, dim> &p,
            const std::array<double, dim> &centre,
            const double                   size)
  {
    std::array<double, n_rigid_motions(dim)> row{};
    std::array<double, dim>                  d{};
    for (unsigned int c = 0; c < dim; ++c)
      {
        row[c] = normal[c];
        d[c]   = (p[c] - centre[c]) / std::max(size, 1e-300);
      }
    if constexpr (dim == 2)
      row[2] = d[0] * normal[1] - d[1] * normal[0];
    else
      {
        row[3] = d[1] * normal[2] - d[2] * normal[1];
        row[4] = d[2] * normal[0] - d[0] * normal[2];
        row[5] = d[0] * normal[1] - d[1] * normal[0];
      }
    return row;
  }

  /// The number of blocks (their indices run from 0); 0 without nodes.
  template <int dim>
  unsigned int
  n_blocks_of(const ContactSet<dim> &contacts);

  /**
   * The rigid motions that no support resists, for each group of blocks
   * linked by joints. A rigid motion of a whole group keeps the gaps of
   * the joints inside it, and no joint links it to another group, so where
   * it also leaves every support's row at zero it changes neither the
   * elastic energy nor any constraint: the displacements are then
   * determined only up to that motion if the load does no work along it,
   * and there is no equilibrium if it does. A forgotten roller (a wall on
   * its base alone slides sideways) or a block that touches nothing is
   * such a group. Supports count in both directions here (that a
   * Signorini support only pushes is the solver's business).
   *
   * Each group's free motions are the null space of its support rows in a
   * basis of rigid motions about its centroid (dim translations and
   * dim (dim - 1) / 2 rotations scaled by the group's size): their singular
   * values below a hundred times the rounding of the rows count as zero
   * (epsilon times the largest coordinate over the supports' face length,
   * estimated from the size and the number of rows), so that a motion a
   * support resists only slightly (a block in a V-groove of 5e-6 near the
   * origin) is not free.
   * Returns one line per group with free motions, saying which blocks and
   * how they can move (the first ten groups, then one line counting the
   * rest); empty if every group is held. Sets @p held_by_signorini if the
   * Signorini supports of some group hold it in a motion that its other
   * supports leave free: they only push, so whether they hold it depends
   * on where the loads push (loads_driving_a_free_motion).
   */
  template <int dim>
  std::vector<std::string>
  free_rigid_motions(const ContactSet<dim> &contacts, bool &held_by_signorini);

  /**
   * Sets of blocks that can slide along their joints, in one direction: a
   * translation t of the set keeps every gap between its blocks, and
   * changes none of its joints with the other blocks if their normals are
   * perpendicular to t (|n . t| within a thousand times the rounding of a
   * unit vector), nor of its supports. A course of a wall without side
   * rollers slides so on the course below; the groups of
   * free_rigid_motions() do not show it, for the wall as a whole is held.
   * The directions tried are those perpendicular to the joints' normals (in
   * 3D two in the plane of each normal, and the cross product of each
   * pair), for the 16 most frequent normals.
   */
  template <int dim>
  struct FreeSlides
  {
    std::array<double, dim> direction{};
    /// For each block, the index of its set; none where a support holds
    /// the set.
    std::vector<unsigned int> set_of_block;
    unsigned int              n_sets = 0;

    static constexpr unsigned int none = static_cast<unsigned int>(-1);
  };

  /// The directions along which some set of blocks can slide, with those
  /// sets.
  template <int dim>
  std::vector<FreeSlides<dim>>
  free_slides(const ContactSet<dim> &contacts);

  /**
   * The proof that the structure has no equilibrium, if the loads do work
   * along one of those free motions or slides: a rigid motion of a group
   * (or a translation of a set) changes neither the elastic energy (the
   * elements reproduce it exactly) nor any gap, so the energy falls
   * without bound along it. Only where the motion changes no gap by more
   * than a hundred times the rounding of the support rows (above; more
   * far from the origin), and the loads' work along it (of
   * sum |f| |u|) exceeds a thousand times the gap change measured or that
   * rounding, and 1e-10; else empty, and the solver decides. The solvers' own
   * proof cannot see this where the factorisation meets a pivot above round-off
   * along the motion and moves the structure by 1e9 (a block on a frictionless
   * slope).
   *
   * Also for a group that its Signorini supports hold in a motion its other
   * supports leave free (free_rigid_motions' @p held_by_signorini): the
   * proof that they cannot
   * balance its loads by pushing (rigid-body statics: a block on a slope
   * whose other support lies uphill, a review found it 'converged' at a
   * loose 'KKT tolerance' with a motion of 1e9), a rigid motion that opens
   * them and along which the loads do work, judged as above with only the
   * gaps that it closes counted.
   * @p load: the nodal loads f at every DOF.
   */
  template <int dim>
  std::string
  loads_driving_a_free_motion(const ContactSet<dim>              &contacts,
                              const std::vector<FreeSlides<dim>> &slides,
                              const std::vector<double>          &load);
} // namespace unilateral::masonry
