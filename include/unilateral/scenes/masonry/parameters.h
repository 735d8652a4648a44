#pragma once

#include <unilateral/scenes/masonry/layout.h>

#include <array>
#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

/**
 * The parameters of the masonry scene, subsection "Masonry" of the parameter
 * file: one struct per subsection with static declare_parameters and
 * parse_parameters (step-44's AllParameters). parse_parameters validates and
 * throws InputError with one line naming the parameter, its value and the
 * fix.
 */
namespace unilateral::masonry
{
  enum class ElementType
  {
    q2, ///< FESystem(FE_Q<2>(2), 2) on squares
    p2  ///< FESystem(FE_SimplexP<2>(2), 2), each square split in two
  };

  std::string
  to_string(ElementType element);

  /// Which wall and how it is meshed.
  struct GeometryParameters
  {
    Bond         bond       = Bond::stack;
    unsigned int m          = 20; ///< blocks per side: H = 1/m
    unsigned int refinement = 0;  ///< r: cells of size h = H / 2^r
    ElementType  element    = ElementType::q2;

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  /// Supports and loads (Ainsworth & Mihai, Section 5 and Fig. 3).
  struct BoundaryParameters
  {
    /// g / H: the gap between the base and the settled ground on Gamma_S.
    double relative_gap = 0.5;
    /// Gamma_S = [x_min, x_min + fraction * width] x {y_min}.
    double signorini_fraction = 0.5;
    /// Prescribed traction on the top (force per length); 0 = traction free.
    std::array<double, 2> top_traction{{0.0, 0.0}};
    /// Gravitational acceleration; the body force is (0, -density * gravity).
    double gravity = 1.0;

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  /// One linear elastic material (plane strain).
  struct MaterialClass
  {
    double youngs_modulus = 4e3;
    double poissons_ratio = 0.3;
    double density        = 1.0;

    /// Lame's first parameter lambda = E nu / ((1 + nu)(1 - 2 nu)).
    double
    lambda() const
    {
      return youngs_modulus * poissons_ratio /
             ((1 + poissons_ratio) * (1 - 2 * poissons_ratio));
    }

    /// Shear modulus mu = E / (2 (1 + nu)).
    double
    mu() const
    {
      return youngs_modulus / (2 * (1 + poissons_ratio));
    }
  };

  enum class MaterialAssignment
  {
    single,              ///< every block is class 0
    alternating_courses, ///< class = course index mod number of classes
    cyclic               ///< class = block index mod number of classes
  };

  struct MaterialParameters
  {
    std::vector<MaterialClass> classes{MaterialClass()};
    MaterialAssignment         assignment = MaterialAssignment::single;

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);

    /// The class of every block of @p layout under the assignment rule.
    std::vector<unsigned int>
    classes_of_blocks(const Layout &layout) const;
  };

  struct Parameters
  {
    GeometryParameters geometry;
    BoundaryParameters boundary;
    MaterialParameters materials;

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);
  };
} // namespace unilateral::masonry
