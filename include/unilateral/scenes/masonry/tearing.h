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
   * The wall torn into its blocks (lcp/tearing.h), for the dual methods:
   * every block a floating subdomain with its own stiffness (the same cell
   * matrices as the LCP's, summed per block, divided by @p force_unit like
   * the LCP) and its three rigid motions; the joints and the Signorini
   * supports as inequality multipliers, the fixed DOFs (sides, the settled
   * base's fixed half) as equalities; the map to the LCP's gap variables
   * is C~ itself (a joint's variable is its gap, any other DOF's variable
   * is the DOF).
   *
   * Blocks with the same stiffness (the same shape and material: most of a
   * bond's) share it: a block's DOFs are numbered by component and then by
   * their position relative to the block's lower left corner, so that
   * translated copies number alike.
   */
  std::shared_ptr<const lcp::Tearing>
  tear_into_blocks(const Discretisation    &discretisation,
                   const ContactSet        &contacts,
                   const ChangeOfVariables &change,
                   const LoadData          &loads,
                   unsigned int             n_blocks,
                   double                   force_unit,
                   double                   tolerance);
} // namespace unilateral::masonry
