#pragma once

#include <unilateral/scenes/masonry/change_of_variables.h>
#include <unilateral/scenes/masonry/contact_detection.h>
#include <unilateral/scenes/masonry/discretisation.h>
#include <unilateral/scenes/masonry/layout.h>
#include <unilateral/scenes/masonry/masonry_scene.h>

#include <memory>
#include <vector>

namespace unilateral::masonry
{
  /// The heavy part of MasonryScene (its deal.II objects), shared by the
  /// scene's translation units only: a private header, beside them.
  struct MasonryScene::State
  {
    explicit State(const ElementType element)
      : discretisation(element)
    {}

    Layout                             layout;
    std::vector<unsigned int>          class_of_block;
    Discretisation                     discretisation;
    ContactSet                         contacts;
    std::unique_ptr<ChangeOfVariables> change;
    /// u = C~^-1 u~: the physical displacement, one entry per DOF.
    std::vector<double> displacement;
  };
} // namespace unilateral::masonry
