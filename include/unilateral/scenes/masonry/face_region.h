#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>

#include <functional>
#include <vector>

namespace unilateral::masonry
{
  /**
   * The part of a cell's face inside a region, as a quadrature: what a
   * traction restricted to a region ('top where x > 0.95') integrates
   * over. Weighing the face's own Gauss points by whether they lie in the
   * region loads whatever part of the face those few points stand for
   * (nothing at all for a strip between them).
   *
   * The face is a line (2D) or a quadrilateral or triangle (3D),
   * parametrised affinely from the reference cell, x(s) or x(s, t); the
   * real point is interpolated from the face's vertices, which is what the
   * masonry scene's mappings (MappingQ(1), MappingFE of P1) do. A face is
   * whole or outside if 17 (17 x 17) samples say so. Otherwise, on a line
   * the region's edge is found by 65 samples and bisection of each change
   * to 2^-52 of the face, and each part inside gets a Gauss rule: exact
   * for polynomial loads. In 3D the same is done along t at Gauss points
   * in s; [0, 1] in s is cut (65 samples, bisection) where the parts along
   * t change in kind (their number, or whether an end is inside: the
   * region's edge meets a face edge), and a piece is halved while its area
   * inside differs from its halves' by more than 1e-12 of its width. Exact
   * where the region's edges cross the face straight; where a corner of
   * the region or a curved edge lies inside the face, the parts of lines
   * narrower than their sampling (1/64 of the face) escape it: errors up to
   * about 1e-4 of the face's load. Parts of a region narrower than
   * the samples' spacing (1/16 of a face that no sample of the region
   * reaches, 1/64 on a face it cuts) are missed.
   */
  template <int dim>
  struct FaceRegionRule
  {
    enum class Coverage
    {
      none,
      whole,
      partial
    };
    Coverage coverage = Coverage::none;
    /// For a partial face: points in the cell's reference coordinates and
    /// weights in the face's parameters (ds, or ds dt).
    std::vector<dealii::Point<dim>> points;
    std::vector<double>             weights;
    /// The reference-cell tangents dx/ds (and dx/dt): with the mapping's
    /// Jacobian J, the face's measure is |J e_s| ds or |J e_s x J e_t| ds dt.
    std::vector<dealii::Tensor<1, dim>> tangents;
  };

  /**
   * Whether any sample of face_region_rule on the face with these
   * @p corners (deal.II's vertex order of the face) lies inside: whether a
   * traction restricted to that region loads the face at all.
   */
  template <int dim>
  bool
  face_touches_region(
    const std::vector<dealii::Point<dim>>                 &corners,
    const std::function<bool(const dealii::Point<dim> &)> &inside);

  template <int dim>
  FaceRegionRule<dim>
  face_region_rule(
    const typename dealii::DoFHandler<dim>::active_cell_iterator &cell,
    unsigned int                                                  face,
    const std::function<bool(const dealii::Point<dim> &)>        &inside);
} // namespace unilateral::masonry
