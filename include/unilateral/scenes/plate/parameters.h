#pragma once

#include <memory>
#include <string>

namespace dealii
{
  class ParameterHandler;
  template <int dim, typename RangeNumberType>
  class Function;
} // namespace dealii

/**
 * Parameters of the plate scene, subsection "Plate", in the units of
 * Plate/Units (by default the plate study's: mm, kg; forces per area in
 * kg/mm^2). One struct per subsection,
 * each with its declare_parameters/parse_parameters; parse_parameters checks
 * every value and throws InputError naming parameter, value and fix.
 */
namespace unilateral::plate
{
  /**
   * Plate/Units: the unit system of the subsection's numbers. The plate
   * study's named materials, obstacles and forces are given in its mm and
   * kg (kilogram-force) and converted to the chosen system; the summary
   * labels its numbers with it. "any consistent" names no unit and refuses
   * the named quantities.
   */
  struct Units
  {
    std::string name = "mm and kg";
    /// Labels of a length and a force ("mm", "kg"); empty: any consistent.
    std::string length = "mm";
    std::string force  = "kg";
    /// One mm and one kg (force) in the chosen units.
    double mm = 1;
    double kg = 1;

    bool
    labelled() const
    {
      return !length.empty();
    }

    /// Labels of a force per area (E, f) and of a force times a length (D).
    std::string
    stress() const;

    std::string
    moment() const;

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  /// Subsection Plate/Geometry: the rectangle, the mesh and the clamping.
  struct Geometry
  {
    double       length_x  = 100; ///< L1 (length unit)
    double       length_y  = 100; ///< L2
    double       thickness = 2;   ///< t
    unsigned int n_x       = 20;  ///< n1 cells in x
    unsigned int n_y       = 20;  ///< n2 cells in y
    /// Also fix w_xy at boundary nodes. The paper leaves it free, which gives
    /// |J| = 4 (n1 - 1)(n2 - 1) + 2 (n1 + n2).
    bool clamp_twist = false;

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  /// Subsection Plate/Material: a named material of the paper or E and nu.
  struct Material
  {
    std::string name           = "steel";
    double      youngs_modulus = 21e3; ///< E (force per area)
    double      poisson_ratio  = 0.28; ///< nu

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm, const Units &units);
  };

  /// Subsection Plate/Obstacle: psi, the lower bound on w at interior nodes.
  struct Obstacle
  {
    /// As given: psi1, psi2, psi3, none or an expression.
    std::string name = "psi3";
    /// The expression in x and y (empty for none).
    std::string expression;

    bool
    present() const
    {
      return !expression.empty();
    }

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm, const Units &units);
  };

  /// Subsection Plate/Load: the transverse force per area f.
  struct Load
  {
    std::string name = "f1";
    std::string expression;

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm, const Units &units);
  };

  /// Subsection Plate/Output.
  struct Output
  {
    /// Each cell is written as subdivisions x subdivisions patches.
    unsigned int subdivisions = 6;

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  struct Parameters
  {
    Units    units;
    Geometry geometry;
    Material material;
    Obstacle obstacle;
    Load     load;
    Output   output;
    /// Plate/Coarse-mesh start: for methods that take a start, solve on
    /// coarser meshes first.
    bool coarse_mesh_start = true;

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  /**
   * A function of x and y from @p expression (muparser syntax, constant pi).
   * A parse error, an unknown variable or an empty expression throws
   * InputError: "parameter '<parameter>' = <expression>: <what is wrong>;
   * <hint>". Each evaluation later is as cheap as FunctionParser's.
   */
  std::unique_ptr<dealii::Function<2, double>>
  parse_function(const std::string &parameter,
                 const std::string &expression,
                 const std::string &hint);
} // namespace unilateral::plate
