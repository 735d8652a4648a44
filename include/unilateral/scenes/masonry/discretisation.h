#pragma once

#include <unilateral/scenes/masonry/parameters.h>

#include <deal.II/base/quadrature.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/tria.h>

#include <memory>

namespace unilateral::masonry
{
  /**
   * The finite element side of the masonry scene: mesh, element, mapping,
   * quadratures and DOFs. Only the masonry sources include this header (it
   * pulls in heavy deal.II headers).
   */
  template <int dim>
  struct Discretisation
  {
    explicit Discretisation(ElementType element);

    /// The displacement: dim quadratic Lagrange fields.
    ElementType                                 element;
    dealii::Triangulation<dim>                  triangulation;
    std::unique_ptr<dealii::FiniteElement<dim>> fe;
    /// The scalar quadratic element with the same nodes, for nodal output.
    std::unique_ptr<dealii::FiniteElement<dim>>  scalar_fe;
    std::unique_ptr<dealii::Mapping<dim>>        mapping;
    std::unique_ptr<dealii::Quadrature<dim>>     quadrature;
    std::unique_ptr<dealii::Quadrature<dim - 1>> face_quadrature;
    dealii::DoFHandler<dim>                      dof_handler;
  };
} // namespace unilateral::masonry
