#pragma once

#include <unilateral/scenes/masonry/contact_detection.h>

#include <string>
#include <vector>

namespace unilateral::masonry
{
  /**
   * A mechanism of an answer: rigid motions of its blocks that keep every
   * held node and roller where it is and every closed contact (@p closed,
   * per constraint of @p contacts) closed. Along one the elastic energy and
   * every closed gap stay as they are, and at a solution the loads do no
   * work along it (else the solution would not be one): the solutions form
   * a family, and the displacements given are one member of it (two mirror
   * image blocks of an arch sliding past each other on frictionless radial
   * joints; a review moved the structure and got another member, 14 %
   * apart). free_rigid_motions() finds the rigid motions of groups that no
   * support holds before solving; this finds motions of blocks against
   * each other, which only the closed contacts of the answer decide.
   *
   * Found as the null space of the rows of those conditions on the blocks'
   * rigid motions (3 per block in 2D, 6 in 3D), by inverse iteration on
   * their Gram matrix scaled to a unit diagonal: a mechanism to 1e-9 of
   * that diagonal, a motion that changes the closed gaps by less than 3e-5
   * of its size (a joint tilted by less than that against the motion
   * leaves it for the elastic deformation of the blocks alone to decide,
   * which double precision does not). The blocks a found motion moves, in
   * words ("blocks 15 and 17 (a node at ...)"); empty where there is none.
   */
  template <int dim>
  std::string
  answer_mechanism(const ContactSet<dim>   &contacts,
                   const std::vector<char> &closed);
} // namespace unilateral::masonry
