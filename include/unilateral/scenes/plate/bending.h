#pragma once

#include <unilateral/fe/bogner_fox_schmit.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/full_matrix.h>

#include <array>
#include <deque>
#include <vector>

/**
 * Kirchhoff plate bending on one Bogner-Fox-Schmit rectangle: the element
 * matrix and load integrals of the plate study (Fernandes, Figueiredo &
 * Judice 2002, eqs. 15-17 and 27-29).
 */
namespace unilateral::plate
{
  /// D = E t^3 / (12 (1 - nu^2)), eq. (17).
  double
  flexural_rigidity(double youngs_modulus,
                    double poisson_ratio,
                    double thickness);

  /**
   * The integrand of the bending form (15) for Hessians hz, hw:
   * D [nu tr(hz) tr(hw) + (1 - nu) hz : hw]. Equal to the paper's
   * (t^2/12) S^T D S of (27)-(28) with curvatures (w_xx, w_yy, 2 w_xy).
   */
  inline double
  bending_integrand(const dealii::Tensor<2, 2> &hz,
                    const dealii::Tensor<2, 2> &hw,
                    const double                rigidity,
                    const double                poisson_ratio)
  {
    return rigidity * (poisson_ratio * dealii::trace(hz) * dealii::trace(hw) +
                       (1 - poisson_ratio) * dealii::scalar_product(hz, hw));
  }

  /**
   * Bending moments from the Hessian of the deflection w, sign convention
   * M = -D (kappa + nu tr(kappa) I) restricted to Kirchhoff kinematics:
   *   M_xx = -D (w_xx + nu w_yy), M_yy = -D (w_yy + nu w_xx),
   *   M_xy = -D (1 - nu) w_xy.
   * (moment per unit length, kg mm / mm), w positive upwards. Under a
   * downward load the plate leaves a clamped edge curving downwards
   * (w_xx < 0), so M_xx > 0 there, and sags in the middle (w_xx > 0,
   * M_xx < 0).
   */
  inline std::array<double, 3>
  bending_moments(const dealii::Tensor<2, 2> &hessian,
                  const double                rigidity,
                  const double                poisson_ratio)
  {
    return {{-rigidity * (hessian[0][0] + poisson_ratio * hessian[1][1]),
             -rigidity * (hessian[1][1] + poisson_ratio * hessian[0][0]),
             -rigidity * (1 - poisson_ratio) * hessian[0][1]}};
  }

  /**
   * Everything one cell size needs: the 16 x 16 element stiffness C^e and
   * the shape values at the quadrature points, for all cells of size
   * h1 x h2 (they differ only by a translation).
   *
   * Quadrature: 4 x 4 Gauss points, exact for polynomials of degree 7 in
   * each variable. The stiffness integrands are products of second
   * derivatives of bicubics, of degree at most 6 in each variable (w_xx w_xx
   * is degree 2 in x and 6 in y), so C^e is exact; the load is exact for
   * forces of degree <= 4 in each variable (f times a bicubic).
   */
  class CellIntegrals
  {
  public:
    static constexpr unsigned int n_gauss_points_1d = 4;
    static constexpr unsigned int n_dofs = fe::BognerFoxSchmit::dofs_per_cell;

    CellIntegrals(double h1, double h2, double rigidity, double poisson_ratio);

    double h1, h2;

    /// C^e in BFS local order.
    dealii::FullMatrix<double> stiffness;

    /// Quadrature points relative to the cell's lower-left corner, weights
    /// times the cell area, and shape_values[q][i] = phi_i(x_q).
    std::vector<dealii::Tensor<1, 2>>       offsets;
    std::vector<double>                     JxW;
    std::vector<std::array<double, n_dofs>> shape_values;

    /**
     * F^e_i = int f phi_i over the cell with lower-left corner
     * @p lower_left, with @p force evaluated at the quadrature points.
     */
    template <typename ForceAtPoint>
    std::array<double, n_dofs>
    load(const dealii::Point<2> &lower_left, const ForceAtPoint &force) const
    {
      std::array<double, n_dofs> result{};
      for (unsigned int q = 0; q < offsets.size(); ++q)
        {
          const double f = force(lower_left + offsets[q]) * JxW[q];
          for (unsigned int i = 0; i < n_dofs; ++i)
            result[i] += f * shape_values[q][i];
        }
      return result;
    }
  };

  /**
   * CellIntegrals for each distinct cell size, computed once: a uniform
   * mesh has one size (up to rounding of the vertex coordinates, which a
   * relative tolerance of 1e-12 absorbs), so assembly costs a lookup per
   * cell.
   */
  class CellIntegralsCache
  {
  public:
    CellIntegralsCache(double rigidity, double poisson_ratio);

    const CellIntegrals &
    get(double h1, double h2);

  private:
    double                    rigidity;
    double                    poisson_ratio;
    std::deque<CellIntegrals> entries; // references stay valid on growth
  };
} // namespace unilateral::plate
