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
  struct Discretisation
  {
    explicit Discretisation(ElementType element);

    /// Vertical and horizontal displacement: two quadratic Lagrange fields.
    ElementType                               element;
    dealii::Triangulation<2>                  triangulation;
    std::unique_ptr<dealii::FiniteElement<2>> fe;
    /// The scalar quadratic element with the same nodes, for nodal output.
    std::unique_ptr<dealii::FiniteElement<2>> scalar_fe;
    std::unique_ptr<dealii::Mapping<2>>       mapping;
    std::unique_ptr<dealii::Quadrature<2>>    quadrature;
    std::unique_ptr<dealii::Quadrature<1>>    face_quadrature;
    dealii::DoFHandler<2>                     dof_handler;
  };
} // namespace unilateral::masonry
