#include <unilateral/scenes/masonry/discretisation.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/fe/mapping_q.h>

namespace unilateral::masonry
{
  Discretisation::Discretisation(const ElementType element)
    : element(element)
  {
    if (element == ElementType::q2)
      {
        fe = std::make_unique<dealii::FESystem<2>>(dealii::FE_Q<2>(2), 2);
        scalar_fe = std::make_unique<dealii::FE_Q<2>>(2);
        // Straight-sided squares: the bilinear mapping is exact.
        mapping    = std::make_unique<dealii::MappingQ<2>>(1);
        quadrature = std::make_unique<dealii::QGauss<2>>(3);
      }
    else
      {
        fe =
          std::make_unique<dealii::FESystem<2>>(dealii::FE_SimplexP<2>(2), 2);
        scalar_fe = std::make_unique<dealii::FE_SimplexP<2>>(2);
        mapping =
          std::make_unique<dealii::MappingFE<2>>(dealii::FE_SimplexP<2>(1));
        // Exact for the degree-2 integrands of the stiffness matrix and the
        // body force.
        quadrature = std::make_unique<dealii::QGaussSimplex<2>>(3);
      }
    face_quadrature = std::make_unique<dealii::QGauss<1>>(3);
  }
} // namespace unilateral::masonry
