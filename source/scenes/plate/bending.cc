#include <unilateral/scenes/plate/bending.h>

#include <deal.II/base/quadrature_lib.h>

#include <cmath>

namespace unilateral::plate
{
  double
  flexural_rigidity(const double youngs_modulus,
                    const double poisson_ratio,
                    const double thickness)
  {
    return youngs_modulus * thickness * thickness * thickness /
           (12 * (1 - poisson_ratio * poisson_ratio));
  }

  CellIntegrals::CellIntegrals(const double h1,
                               const double h2,
                               const double rigidity,
                               const double poisson_ratio)
    : h1(h1)
    , h2(h2)
    , stiffness(n_dofs, n_dofs)
  {
    const dealii::QGauss<2>   quadrature(n_gauss_points_1d);
    const fe::BognerFoxSchmit element(dealii::Point<2>(), h1, h2);
    std::array<dealii::Tensor<2, 2>, n_dofs> hessians;

    offsets.resize(quadrature.size());
    JxW.resize(quadrature.size());
    shape_values.resize(quadrature.size());
    for (unsigned int q = 0; q < quadrature.size(); ++q)
      {
        const dealii::Point<2> &unit = quadrature.point(q);
        offsets[q][0]                = unit[0] * h1;
        offsets[q][1]                = unit[1] * h2;
        JxW[q]                       = quadrature.weight(q) * h1 * h2;
        const dealii::Point<2> x(offsets[q]);
        element.evaluate(x, &shape_values[q], nullptr, &hessians);
        for (unsigned int i = 0; i < n_dofs; ++i)
          for (unsigned int j = 0; j <= i; ++j)
            stiffness(i, j) += bending_integrand(hessians[i],
                                                 hessians[j],
                                                 rigidity,
                                                 poisson_ratio) *
                               JxW[q];
      }
    // Symmetric by construction, not by rounding.
    for (unsigned int i = 0; i < n_dofs; ++i)
      for (unsigned int j = i + 1; j < n_dofs; ++j)
        stiffness(i, j) = stiffness(j, i);
  }

  CellIntegralsCache::CellIntegralsCache(const double rigidity,
                                         const double poisson_ratio)
    : rigidity(rigidity)
    , poisson_ratio(poisson_ratio)
  {}

  const CellIntegrals &
  CellIntegralsCache::get(const double h1, const double h2)
  {
    for (const CellIntegrals &entry : entries)
      if (std::abs(entry.h1 - h1) <= 1e-12 * h1 &&
          std::abs(entry.h2 - h2) <= 1e-12 * h2)
        return entry;
    entries.emplace_back(h1, h2, rigidity, poisson_ratio);
    return entries.back();
  }
} // namespace unilateral::plate
