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
 * fix. What needs the mesh to be checked (boundary names, expressions with
 * the mesh's constants) is checked by the scene when the mesh is there.
 */
namespace unilateral::masonry
{
  enum class ElementType
  {
    q2, ///< FESystem(FE_Q<dim>(2), dim) on quadrilaterals or hexahedra
    p2  ///< FESystem(FE_SimplexP<dim>(2), dim): triangles or tetrahedra
  };

  std::string
  to_string(ElementType element);

  /// Which structure and how it is meshed.
  struct GeometryParameters
  {
    /// 2 (plane strain) or 3.
    unsigned int dimension = 2;
    /// Blocks from 'Mesh file' instead of a built-in wall.
    bool        from_mesh_file = false;
    Bond        bond           = Bond::stack;
    std::string mesh_file;
    /// Blocks per side of a built-in wall: H = 1/m.
    unsigned int m          = 20;
    unsigned int refinement = 0; ///< r: cells of size h = H / 2^r
    ElementType  element    = ElementType::q2;
    /// 3D built-in walls: blocks through the thickness, and the thickness
    /// in units of H.
    unsigned int blocks_through_thickness = 1;
    double       thickness                = 1;
    /// Points closer than this times the smallest cell size coincide.
    double coincidence_tolerance = 1e-8;

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  /**
   * Where a support or a load acts: a boundary (a name of the mesh, or its
   * number), optionally only where a region expression of x, y (and z) is
   * true ("base where x < s").
   */
  struct BoundarySelection
  {
    std::string boundary;
    std::string region;
  };

  /// Supports and loads (Ainsworth & Mihai, Section 5 and Fig. 3, for the
  /// built-in walls; any boundary of a mesh file).
  struct BoundaryParameters
  {
    /// g / H: the constant g of the expressions (the built-in walls' gap).
    double relative_gap = 0.5;
    /// s = x_min + fraction * width: the constant s of the expressions
    /// (where the built-in walls' settled stretch of the base ends).
    double                         signorini_fraction = 0.5;
    std::vector<BoundarySelection> fixed;
    std::vector<BoundarySelection> normal_displacement_zero;
    std::vector<BoundarySelection> signorini;
    std::vector<BoundarySelection> prescribed;
    std::vector<BoundarySelection> traction;
    /// The Signorini gap, a function of position.
    std::string gap = "g";
    /// Components separated by ';', dim of them (all-zero ones may have
    /// fewer).
    std::string prescribed_displacement = "0; 0";
    std::string traction_value          = "0; 0";
    /// The body force is density * gravity * the direction made unit.
    double                gravity = 1.0;
    std::array<double, 3> gravity_direction{{0.0, -1.0, 0.0}};

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  /// One linear elastic material (plane strain in 2D).
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
    cyclic,              ///< class = block index mod number of classes
    physical_tag         ///< a mesh file's cells: class of their tag
  };

  struct MaterialParameters
  {
    std::vector<MaterialClass> classes{MaterialClass()};
    MaterialAssignment         assignment = MaterialAssignment::single;
    /// With 'physical tag': the tag (name or number) of each class.
    std::vector<std::string> tags;

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);

    /// The class of every block of @p layout under the assignment rule
    /// (not 'physical tag').
    std::vector<unsigned int>
    classes_of_blocks(const Layout &layout) const;
  };

  /// How the methods that work on subdomains (TFETI) tear the structure.
  struct TearingParameters
  {
    /// A block longer than this many times its shortest side is cut into
    /// pieces; 0: blocks stay whole.
    double largest_aspect_ratio = 2;

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  struct Parameters
  {
    GeometryParameters geometry;
    BoundaryParameters boundary;
    MaterialParameters materials;
    TearingParameters  tearing;
    /// Start from the same wall solved on a coarser mesh.
    bool coarse_mesh_start = true;

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  /// "left, right, base where x > s" as selections; InputError naming
  /// @p parameter if an entry has no boundary.
  std::vector<BoundarySelection>
  parse_selections(const std::string &text, const std::string &parameter);
} // namespace unilateral::masonry
