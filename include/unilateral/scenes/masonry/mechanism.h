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
   * Where @p floating_noted (free_rigid_motions noted groups), sets of
   * blocks joined to nothing held are set aside as those groups, and a
   * motion that moves the blocks of every closed joint as one body is
   * taken for their noted motion.
   *
   * Found as the null space of the rows of those conditions on the blocks'
   * rigid motions (3 per block in 2D, 6 in 3D): the blocks held from the
   * supports up, then inverse iteration on the Gram matrix of the rest,
   * scaled block by block: a motion that changes the closed gaps by less
   * than 1e-7 of its size (mechanism.cc). A contact closed without force
   * counts as closed: a family that opens it shows as degenerate contacts
   * instead. The blocks a found motion moves, in words ("blocks 15 and 17
   * (the first centred at ...)"); empty where there is none.
   */
  template <int dim>
  std::string
  answer_mechanism(const ContactSet<dim>   &contacts,
                   const std::vector<char> &closed,
                   bool                     floating_noted);
} // namespace unilateral::masonry
