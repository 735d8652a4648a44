#pragma once

#include <unilateral/scenes/masonry/contact_detection.h>

#include <string>
#include <vector>

namespace unilateral::masonry
{
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
   * Each group's free motions are the null space of the Gram matrix of its
   * support rows in a basis of rigid motions about its centroid (dim
   * translations and dim (dim - 1) / 2 rotations scaled by the group's
   * size), eigenvalues below 1e-10 of the largest counting as zero.
   * Returns one line per group with free motions, saying which blocks and
   * how they can move (the first ten groups, then one line counting the
   * rest); empty if every group is held.
   */
  template <int dim>
  std::vector<std::string>
  free_rigid_motions(const ContactSet<dim> &contacts);

  /**
   * The proof that the structure has no equilibrium, if the loads do work
   * along one of those free motions: a rigid motion of a group changes
   * neither the elastic energy (the elements reproduce it exactly) nor any
   * gap, so the energy falls without bound along it. Empty if they do no
   * work along any, to the rounding of their sum (1e-10 of sum |f| |u|),
   * or if the motion changes a gap by more than the rounding of the nodes'
   * positions (1e-10 of its size, more far from the origin): then the
   * solver decides. The solvers' own proof cannot see this where the
   * factorisation meets a pivot above round-off along the motion and
   * moves the structure by 1e9 (a block on a frictionless slope).
   * @p load: the nodal loads f at every DOF.
   */
  template <int dim>
  std::string
  loads_driving_a_free_motion(const ContactSet<dim>     &contacts,
                              const std::vector<double> &load);
} // namespace unilateral::masonry
