#pragma once

#include <unilateral/scenes/masonry/assembly.h>
#include <unilateral/scenes/masonry/change_of_variables.h>
#include <unilateral/scenes/masonry/contact_detection.h>
#include <unilateral/scenes/masonry/discretisation.h>
#include <unilateral/scenes/masonry/layout.h>
#include <unilateral/scenes/masonry/masonry_scene.h>
#include <unilateral/scenes/masonry/supports.h>

#include <memory>
#include <vector>

namespace unilateral::masonry
{
  /// The heavy part of MasonryScene (its deal.II objects), shared by the
  /// scene's translation units only: a private header, beside them.
  template <int dim>
  struct MasonryScene<dim>::State
  {
    explicit State(const ElementType element)
      : discretisation(element)
    {}

    /// The built-in wall's layout (empty for a mesh file).
    Layout layout;
    /// A mesh file's name, for the summary (empty for a built-in wall).
    std::string                             mesh_file;
    std::vector<unsigned int>               class_of_block;
    Discretisation<dim>                     discretisation;
    BoundaryNames                           boundaries;
    Supports<dim>                           supports;
    LoadData<dim>                           loads;
    ContactSet<dim>                         contacts;
    std::unique_ptr<ChangeOfVariables<dim>> change;
    /// u = C~^-1 u~: the physical displacement, one entry per DOF.
    std::vector<double> displacement;
  };
} // namespace unilateral::masonry
