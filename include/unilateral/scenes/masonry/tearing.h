#pragma once

#include <unilateral/lcp/tearing.h>
#include <unilateral/scenes/masonry/assembly.h>
#include <unilateral/scenes/masonry/change_of_variables.h>
#include <unilateral/scenes/masonry/contact_detection.h>
#include <unilateral/scenes/masonry/discretisation.h>

#include <memory>

namespace unilateral::masonry
{
  /**
   * The structure torn into its blocks (lcp/tearing.h), for the dual
   * methods: every block a floating subdomain with its own stiffness (the
   * same cell matrices as the LCP's, summed per block, divided by
   * @p force_unit like the LCP) and its rigid motions (3 in 2D, 6 in 3D);
   * the joints and the Signorini supports as inequality multipliers, the
   * held nodes (fixed, prescribed) and the rollers as equalities; the map
   * to the LCP's variables is C~ itself (ChangeOfVariables::row).
   *
   * Blocks with the same stiffness (the same shape, orientation and
   * material: most of a bond's) share it: a block's DOFs are numbered by
   * component and then by their position relative to the block's lowest
   * corner, so that translated copies number alike.
   */
  template <int dim>
  std::shared_ptr<const lcp::Tearing>
  tear_into_blocks(const Discretisation<dim>    &discretisation,
                   const ContactSet<dim>        &contacts,
                   const ChangeOfVariables<dim> &change,
                   const LoadData<dim>          &loads,
                   unsigned int                  n_blocks,
                   double                        force_unit,
                   double                        tolerance);
} // namespace unilateral::masonry
