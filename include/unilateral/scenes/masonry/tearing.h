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
   * The structure torn into subdomains (lcp/tearing.h), for the dual
   * methods: every block, or every piece of a long block, a floating
   * subdomain with its own stiffness (the same cell matrices as the LCP's,
   * summed per subdomain, divided by @p force_unit like the LCP) and its
   * rigid motions (3 in 2D, 6 in 3D); the joints and the Signorini supports
   * as inequality multipliers, the held nodes (fixed, prescribed), the
   * rollers and the gluing of pieces as equalities; the map to the LCP's
   * variables is C~ itself (ChangeOfVariables::row).
   *
   * A block whose bounding box is longer than @p largest_aspect_ratio
   * times its shortest side (0: never) is cut into pieces about as long as
   * that side (cut_into_pieces in the source); each DOF on a cut is
   * duplicated, one copy per piece, and the copies glued by x_a - x_b = 0.
   * A long subdomain alone makes the dual's condition grow with its length
   * (benchmarks/tfeti/README.md). @p n_cut_blocks: how many were cut.
   *
   * Subdomains with the same stiffness (the same shape, orientation and
   * material: most of a bond's) share it: a subdomain's DOFs are numbered
   * by component and then by their position relative to its lowest corner,
   * so that translated copies number alike.
   */
  template <int dim>
  std::shared_ptr<const lcp::Tearing>
  tear_into_blocks(const Discretisation<dim>    &discretisation,
                   const ContactSet<dim>        &contacts,
                   const ChangeOfVariables<dim> &change,
                   const LoadData<dim>          &loads,
                   unsigned int                  n_blocks,
                   double                        largest_aspect_ratio,
                   double                        force_unit,
                   double                        tolerance,
                   unsigned int                 &n_cut_blocks);
} // namespace unilateral::masonry
