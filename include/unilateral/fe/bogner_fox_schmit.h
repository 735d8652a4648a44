#pragma once

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <vector>

namespace dealii
{
  template <int dim, int spacedim>
  class FiniteElement;
  template <int dim, typename RangeNumberType>
  class Function;
} // namespace dealii

/**
 * The Bogner-Fox-Schmit (BFS) rectangle: the C1 element of the plate study
 * (Fernandes, Figueiredo & Judice 2002, eqs. 18-21; Ciarlet 1991).
 *
 * deal.II 9.4 has no Hermite element, so this is the element on its own: the
 * 16 shape functions of one axis-aligned rectangle and their first and second
 * derivatives at arbitrary points. deal.II still numbers the degrees of
 * freedom: a DoFHandler with FESystem<2>(FE_Q<2>(1), 4) has exactly four DOFs
 * per vertex, shared by the cells around it (component c = w, w_x, w_y, w_xy),
 * and bfs_local_indices() maps its local DOF order onto the one used here.
 */
namespace unilateral::fe
{
  class BognerFoxSchmit
  {
  public:
    static constexpr unsigned int dofs_per_vertex = 4;
    static constexpr unsigned int dofs_per_cell   = 16;

    /// What a vertex DOF is: the value and three derivatives of the field.
    enum Component : unsigned int
    {
      deflection = 0, ///< w
      slope_x    = 1, ///< w_x
      slope_y    = 2, ///< w_y
      twist      = 3  ///< w_xy
    };

    using Coefficients = std::array<double, dofs_per_cell>;

    /**
     * Local DOF order: vertex-major in deal.II's vertex numbering (0 lower
     * left, 1 lower right, 2 upper left, 3 upper right), and per vertex
     * w, w_x, w_y, w_xy.
     */
    static constexpr unsigned int
    local_index(const unsigned int vertex, const unsigned int component)
    {
      return dofs_per_vertex * vertex + component;
    }

    /// The rectangle [x0, x0 + h1] x [y0, y0 + h2]; h1, h2 > 0.
    BognerFoxSchmit(const dealii::Point<2> &lower_left,
                    const double            h1,
                    const double            h2);

    /**
     * The rectangle with these four vertices in deal.II order. Throws
     * std::invalid_argument if they do not form an axis-aligned rectangle
     * (relative tolerance 1e-10): the element is only defined there.
     */
    static BognerFoxSchmit
    from_vertices(const std::array<dealii::Point<2>, 4> &vertices);

    dealii::Point<2>
    vertex(const unsigned int v) const;

    /// Cell size in direction @p direction (0: h1, 1: h2).
    double
    size(const unsigned int direction) const
    {
      return h[direction];
    }

    /// Shape function i at the point p (p need not lie in the cell: the
    /// polynomial is evaluated there).
    double
    shape_value(const unsigned int i, const dealii::Point<2> &p) const;

    dealii::Tensor<1, 2>
    shape_gradient(const unsigned int i, const dealii::Point<2> &p) const;

    dealii::Tensor<2, 2>
    shape_hessian(const unsigned int i, const dealii::Point<2> &p) const;

    /// All 16 values, gradients and Hessians at p; null pointers are skipped.
    void
    evaluate(const dealii::Point<2>                          &p,
             std::array<double, dofs_per_cell>               *values,
             std::array<dealii::Tensor<1, 2>, dofs_per_cell> *gradients,
             std::array<dealii::Tensor<2, 2>, dofs_per_cell> *hessians) const;

    /// The field sum_i c_i phi_i at p, its gradient and Hessian.
    double
    value(const Coefficients &coefficients, const dealii::Point<2> &p) const;

    dealii::Tensor<1, 2>
    gradient(const Coefficients &coefficients, const dealii::Point<2> &p) const;

    dealii::Tensor<2, 2>
    hessian(const Coefficients &coefficients, const dealii::Point<2> &p) const;

    /**
     * The nodal interpolant's coefficients: f, f_x, f_y and f_xy at the
     * vertices (f_xy from f.hessian()). Reproduces every bicubic exactly.
     */
    Coefficients
    interpolate(const dealii::Function<2, double> &f) const;

  private:
    dealii::Point<2>      lower_left;
    std::array<double, 2> h;
  };

  /**
   * For a DoFHandler built on FESystem<2>(FE_Q<2>(1), 4): entry i is the BFS
   * local index (BognerFoxSchmit::local_index) of the element's local DOF i.
   * Throws std::invalid_argument for any other element.
   */
  std::vector<unsigned int>
  bfs_local_indices(const dealii::FiniteElement<2, 2> &fe);
} // namespace unilateral::fe
