#pragma once

#include <unilateral/scenes/masonry/layout.h>
#include <unilateral/scenes/masonry/parameters.h>
#include <unilateral/scenes/masonry/supports.h>

#include <array>

namespace dealii
{
  template <int dim, int spacedim>
  class Triangulation;
}

namespace unilateral::masonry
{
  /// The boundary ids of the built-in walls' triangulations.
  namespace wall_boundary
  {
    constexpr unsigned int left  = 1; ///< x = x_min
    constexpr unsigned int right = 2; ///< x = x_max
    constexpr unsigned int base  = 3; ///< y = y_min
    constexpr unsigned int top   = 4; ///< y = y_max
    constexpr unsigned int front = 5; ///< z = 0 (3D)
    constexpr unsigned int back  = 6; ///< z = thickness (3D)
    /// Between blocks behind each other (3D): their collar joints.
    constexpr unsigned int collar = 7;
  } // namespace wall_boundary

  /// The names of the built-in walls' boundaries (left, right, base, top;
  /// front, back and collar in 3D) and the ids on @p triangulation's
  /// boundary.
  template <int dim>
  BoundaryNames
  wall_boundary_names(const dealii::Triangulation<dim, dim> &triangulation);

  /**
   * Mesh every block of @p layout on its own: a block of size w x h_b gets
   * round(w / cell_size) x round(h_b / cell_size) cells (at least one), with
   * its own vertices, so no vertex is shared between blocks and each block is
   * a connected component of the triangulation. In 3D each block is extruded
   * into @p blocks_through_thickness blocks behind each other through
   * z in [0, thickness], with round(depth / cell_size) cells each. Every
   * cell's material_id is its block index (in 3D block b of the layout
   * becomes blocks b k, ..., b k + k - 1); the faces on the bounding box get
   * the ids of wall_boundary, and so do the faces between blocks behind
   * each other (collar). With P2 each square is split into two
   * triangles along its rising diagonal, each cube into six tetrahedra
   * around its main diagonal (the same nodes as Q2).
   *
   * Blocks whose sides are not multiples of the cell size get stretched
   * cells; the contact detection then reports non-matching nodes on shared
   * faces. @p coarsening: cells @p coarsening[0] times as long in x and
   * @p coarsening[1] times in y (the coarse meshes of the coarse-mesh
   * start).
   */
  template <int dim>
  void
  build_triangulation(const Layout                    &layout,
                      double                           cell_size,
                      ElementType                      element,
                      unsigned int                     blocks_through_thickness,
                      double                           thickness,
                      dealii::Triangulation<dim, dim> &triangulation,
                      const std::array<unsigned int, 2> &coarsening = {{1, 1}});
} // namespace unilateral::masonry
