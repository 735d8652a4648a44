#pragma once

#include <unilateral/scenes/masonry/layout.h>
#include <unilateral/scenes/masonry/parameters.h>

namespace dealii
{
  template <int dim, int spacedim>
  class Triangulation;
}

namespace unilateral::masonry
{
  /**
   * Mesh every block of @p layout on its own: a block of size w x h_b gets
   * round(w / cell_size) x round(h_b / cell_size) cells (at least one), with
   * its own vertices, so no vertex is shared between blocks and each block is
   * a connected component of the triangulation. Every cell's material_id is
   * its block index (children inherit it under refinement). With P2 each
   * square is split into two triangles along its rising diagonal.
   *
   * Blocks whose sides are not multiples of the cell size get stretched
   * cells; the contact detection then reports non-matching nodes on shared
   * edges.
   */
  void
  build_triangulation(const Layout                &layout,
                      double                       cell_size,
                      ElementType                  element,
                      dealii::Triangulation<2, 2> &triangulation);
} // namespace unilateral::masonry
