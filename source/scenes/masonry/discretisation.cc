#include <unilateral/scenes/masonry/discretisation.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/fe/mapping_q.h>

namespace unilateral::masonry
{
  template <int dim>
  Discretisation<dim>::Discretisation(const ElementType element)
    : element(element)
  {
    if (element == ElementType::q2)
      {
        fe = std::make_unique<dealii::FESystem<dim>>(dealii::FE_Q<dim>(2), dim);
        scalar_fe = std::make_unique<dealii::FE_Q<dim>>(2);
        // Straight-sided cells: the (bi/tri)linear mapping is exact.
        mapping         = std::make_unique<dealii::MappingQ<dim>>(1);
        quadrature      = std::make_unique<dealii::QGauss<dim>>(3);
        face_quadrature = std::make_unique<dealii::QGauss<dim - 1>>(3);
      }
    else
      {
        fe =
          std::make_unique<dealii::FESystem<dim>>(dealii::FE_SimplexP<dim>(2),
                                                  dim);
        scalar_fe = std::make_unique<dealii::FE_SimplexP<dim>>(2);
        mapping =
          std::make_unique<dealii::MappingFE<dim>>(dealii::FE_SimplexP<dim>(1));
        // Exact for the degree-2 integrands of the stiffness matrix and the
        // body force.
        quadrature = std::make_unique<dealii::QGaussSimplex<dim>>(3);
        if constexpr (dim == 2)
          face_quadrature = std::make_unique<dealii::QGauss<1>>(3);
        else
          face_quadrature = std::make_unique<dealii::QGaussSimplex<2>>(3);
      }
  }

  template struct Discretisation<2>;
  template struct Discretisation<3>;
} // namespace unilateral::masonry
