#include <unilateral/base/input_error.h>
#include <unilateral/scenes/plate/parameters.h>

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <tuple>

namespace unilateral::plate
{
  namespace
  {
    // The paper's obstacles (eq. 64) and forces (eq. 65), for x, y in mm on
    // [0, 100]^2 and forces in kg/mm^2.
    const std::map<std::string, std::string> named_obstacles = {
      {"psi1", "-2"},
      {"psi2", "-0.1 - (x/50 - 1)^2 * (y/100 - 0.5)^2"},
      {"psi3",
       "-0.5*(x/50 - 1)^2 - 0.02*(x/50 - 1) - 0.5/(1 + 30*(x/50 - 1)^2)"}};

    const std::map<std::string, std::string> named_forces = {{"f1", "-1"},
                                                             {"f2", "-5"},
                                                             {"f3", "-10"}};

    struct NamedMaterial
    {
      double youngs_modulus;
      double poisson_ratio;
    };

    // The paper's materials (Section 4), E in kg/mm^2.
    const std::map<std::string, NamedMaterial> named_materials = {
      {"steel", {21e3, 0.28}},
      {"bronze", {11e3, 0.31}},
      {"lead", {1.8e3, 0.44}}};

    const std::string obstacle_hint =
      "use psi1, psi2, psi3, none or an expression in x and y such as "
      "-0.5 - 0.001*x";
    const std::string force_hint =
      "use f1, f2, f3 or an expression in x and y such as -1 - 0.01*x";

    // muparser reports a parse error on std::cerr before deal.II throws;
    // the user should get our one line instead, so capture it while parsing.
    class SilenceStandardError
    {
    public:
      SilenceStandardError()
        : saved(std::cerr.rdbuf(captured.rdbuf()))
      {}

      ~SilenceStandardError()
      {
        std::cerr.rdbuf(saved);
      }

    private:
      std::ostringstream captured;
      std::streambuf    *saved;
    };

    // Whether @p entry of subsection Plate/Material was set in the input.
    // deal.II tracks this for entries declared with has_to_be_set = true,
    // and lists those not set by their path, each character outside
    // [A-Za-z0-9] written as '_' and two hex digits ("Young_27s_20modulus").
    bool
    material_entry_set(const dealii::ParameterHandler &prm,
                       const std::string              &entry)
    {
      std::string path = "Plate.Material.";
      for (const unsigned char c : entry)
        if (std::isalnum(c))
          path += static_cast<char>(c);
        else
          {
            char hex[4];
            std::snprintf(hex, sizeof hex, "_%02x", c);
            path += hex;
          }
      return prm.get_entries_wrongly_not_set().count(path) == 0;
    }

    // A number as the shortest text that reads back as itself.
    std::string
    exact_text(const double value)
    {
      for (int digits = 6;; ++digits)
        {
          std::ostringstream text;
          text << std::setprecision(digits) << value;
          if (digits >= 17 || std::stod(text.str()) == value)
            return text.str();
        }
    }

    // The paper's expression @p paper (x, y and its value in mm, or its
    // value in kg/mm^2 if @p is_length is false) in @p units: a length
    // psi(x, y) becomes mm psi(x / mm, y / mm), a force per area is
    // multiplied by kg / mm^2. Unchanged in the paper's units.
    std::string
    in_units(const std::string &paper, const Units &units, const bool is_length)
    {
      const double factor =
        is_length ? units.mm : units.kg / (units.mm * units.mm);
      if (units.mm == 1 && factor == 1)
        return paper;
      std::string converted;
      for (std::size_t i = 0; i < paper.size(); ++i)
        {
          const char c          = paper[i];
          const auto identifier = [&](const std::size_t j) {
            return j < paper.size() &&
                   (std::isalnum(static_cast<unsigned char>(paper[j])) ||
                    paper[j] == '_');
          };
          // The paper's expressions name no function or constant with an
          // x or a y: every standalone x and y is a coordinate.
          if ((c == 'x' || c == 'y') && !(i > 0 && identifier(i - 1)) &&
              !identifier(i + 1))
            converted +=
              std::string("(") + c + " / " + exact_text(units.mm) + ")";
          else
            converted += c;
        }
      return exact_text(factor) + " * (" + converted + ")";
    }

    // A named quantity of the paper in units that name none.
    void
    require_labelled_units(const Units       &units,
                           const std::string &parameter,
                           const std::string &name,
                           const std::string &instead)
    {
      check_parameter(units.labelled(),
                      "Plate",
                      parameter,
                      name,
                      "is the plate study's, in mm and kg, and 'Plate/Units' "
                      "= " +
                        units.name +
                        " names no unit to convert it to: " + instead +
                        ", or choose 'Plate/Units' = mm and kg, mm and N or "
                        "m and N");
    }

    // What @p name in 'Plate/<parameter>' stands for: one of the paper's
    // @p named expressions converted to @p units (refused in units that
    // name none, with @p instead as the fix), or else @p name itself.
    std::string
    expression_of(const std::map<std::string, std::string> &named,
                  const std::string                        &name,
                  const Units                              &units,
                  const bool                                is_length,
                  const std::string                        &parameter,
                  const std::string                        &instead)
    {
      const auto found = named.find(name);
      if (found == named.end())
        return name;
      require_labelled_units(units, parameter, name, instead);
      return in_units(found->second, units, is_length);
    }
  } // namespace

  std::string
  Units::stress() const
  {
    if (!labelled())
      return "";
    return length == "m" && force == "N" ? "Pa" : force + "/" + length + "^2";
  }

  std::string
  Units::moment() const
  {
    return labelled() ? force + " " + length : "";
  }

  void
  Units::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.declare_entry(
      "Units",
      "mm and kg",
      dealii::Patterns::Selection("mm and kg|mm and N|m and N|any consistent"),
      "The units of every number in subsection Plate. mm and kg: the plate "
      "study's (lengths in mm, forces in kilogram-force, so E and f in "
      "kg/mm^2); mm and N (E and f in N/mm^2 = MPa); m and N (E and f in "
      "Pa); any consistent: units of your own, consistent with each other "
      "(the summary then names none). The named materials (steel, bronze, "
      "lead), obstacles (psi1-psi3) and forces (f1-f3) are the study's, "
      "converted to the chosen units (1 kg = 9.80665 N); with any consistent "
      "they are refused. The defaults of the lengths (100 x 100, t = 2) are "
      "numbers, in whichever unit is chosen.");
  }

  void
  Units::parse_parameters(dealii::ParameterHandler &prm)
  {
    name = prm.get("Units");
    // Selection: one of the four.
    length = name == "any consistent" ? "" : name.substr(0, name.find(' '));
    force  = name == "any consistent" ? "" : name.substr(name.rfind(' ') + 1);
    mm     = length == "m" ? 1e-3 : 1.0;
    kg     = force == "N" ? 9.80665 : 1.0;
  }

  std::unique_ptr<dealii::Function<2, double>>
  parse_function(const std::string &parameter,
                 const std::string &expression,
                 const std::string &hint)
  {
    if (expression.find_first_not_of(" \t") == std::string::npos)
      throw InputError("parameter '" + parameter + "' is empty; " + hint);
    auto function = std::make_unique<dealii::FunctionParser<2>>(1);
    try
      {
        SilenceStandardError silence;
        function->initialize("x,y", expression, {{"pi", M_PI}});
        // deal.II parses lazily, at the first evaluation: force it here.
        function->value(dealii::Point<2>());
      }
    catch (const std::exception &error)
      {
        throw InputError("parameter '" + parameter + "' = " + expression +
                         ": not a valid expression in x and y (" +
                         one_line_message(error) + "); " + hint);
      }
    return function;
  }

  void
  Geometry::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    prm.declare_entry(
      "Length x",
      "100",
      dealii::Patterns::Double(),
      "L1: the plate is [0, L1] x [0, L2], in the length unit of "
      "'Plate/Units'; > 0.");
    prm.declare_entry("Length y",
                      "100",
                      dealii::Patterns::Double(),
                      "L2; > 0.");
    prm.declare_entry("Thickness",
                      "2",
                      dealii::Patterns::Double(),
                      "t; > 0. Enters through D = E t^3 / (12 (1 - nu^2)).");
    prm.declare_entry(
      "Elements x",
      "20",
      dealii::Patterns::Integer(),
      "n1: number of Bogner-Fox-Schmit rectangles in x; 1 to 100000.");
    prm.declare_entry("Elements y",
                      "20",
                      dealii::Patterns::Integer(),
                      "n2: number of rectangles in y; 1 to 100000.");
    prm.declare_entry(
      "Boundary condition",
      "clamped",
      dealii::Patterns::Selection("clamped|fully clamped"),
      "clamped: w = w_x = w_y = 0 at boundary nodes and w_xy free, as in the "
      "plate study (|J| = 4 (n1 - 1)(n2 - 1) + 2 (n1 + n2)); fully clamped: "
      "w_xy = 0 there too, so the discrete plate is clamped along the whole "
      "edge, not only at the nodes.");
    prm.leave_subsection();
  }

  void
  Geometry::parse_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Geometry");
    length_x      = prm.get_double("Length x");
    length_y      = prm.get_double("Length y");
    thickness     = prm.get_double("Thickness");
    const long n1 = prm.get_integer("Elements x");
    const long n2 = prm.get_integer("Elements y");
    clamp_twist   = prm.get("Boundary condition") == "fully clamped";
    prm.leave_subsection();

    const std::string section = "Plate/Geometry";
    check_parameter(length_x > 0, section, "Length x", length_x, "must be > 0");
    check_parameter(length_y > 0, section, "Length y", length_y, "must be > 0");
    check_parameter(
      thickness > 0, section, "Thickness", thickness, "must be > 0");
    check_parameter(n1 >= 1 && n1 <= 100000,
                    section,
                    "Elements x",
                    n1,
                    "must be an integer between 1 and 100000");
    check_parameter(n2 >= 1 && n2 <= 100000,
                    section,
                    "Elements y",
                    n2,
                    "must be an integer between 1 and 100000");
    n_x = static_cast<unsigned int>(n1);
    n_y = static_cast<unsigned int>(n2);
  }

  void
  Material::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    prm.declare_entry("Name",
                      "steel",
                      dealii::Patterns::Anything(),
                      "steel (E = 21e3 kg/mm^2, nu = 0.28), bronze (11e3, "
                      "0.31), lead (1.8e3, 0.44), E converted to "
                      "'Plate/Units', or custom to take "
                      "'Young's modulus' and 'Poisson's ratio' below (set "
                      "beside a named material with other values, they are "
                      "refused).");
    // has_to_be_set = true only lets material_entry_set() see whether the
    // input set them; the defaults stand for custom.
    prm.declare_entry("Young's modulus",
                      "21000",
                      dealii::Patterns::Double(),
                      "E (force per area, e.g. kg/mm^2 with the default Units) "
                      "for Name = custom; > 0. Its default, 21000, is a "
                      "number in whichever units are chosen (steel in the "
                      "paper's).",
                      true);
    prm.declare_entry("Poisson's ratio",
                      "0.28",
                      dealii::Patterns::Double(),
                      "nu for Name = custom; in (-1, 0.5).",
                      true);
    prm.leave_subsection();
  }

  void
  Material::parse_parameters(dealii::ParameterHandler &prm, const Units &units)
  {
    prm.enter_subsection("Material");
    name                  = prm.get("Name");
    const double E_given  = prm.get_double("Young's modulus");
    const double nu_given = prm.get_double("Poisson's ratio");
    prm.leave_subsection();

    const std::string section = "Plate/Material";
    const auto        named   = named_materials.find(name);
    if (named != named_materials.end())
      {
        require_labelled_units(units,
                               "Material/Name",
                               name,
                               "set Name = custom with its 'Young's modulus'");
        youngs_modulus =
          named->second.youngs_modulus * units.kg / (units.mm * units.mm);
        poisson_ratio = named->second.poisson_ratio;
        // A different value set beside a named material would be ignored.
        for (const auto &[entry, given, own] :
             {std::tuple{"Young's modulus", E_given, youngs_modulus},
              std::tuple{"Poisson's ratio", nu_given, poisson_ratio}})
          {
            // Twelve digits: a value that differs from the material's in
            // the seventh would read as the same number.
            std::ostringstream requirement, value;
            requirement << std::setprecision(12)
                        << "is used only with 'Plate/Material/Name' = "
                        << "custom; 'Plate/Material/Name' = " << name
                        << " has its own (" << own
                        << "): set Name = custom or remove the line";
            value << std::setprecision(12) << given;
            // Within rounding of the material's own (E converted to
            // other units: lead's 1800 kg/mm^2 in N/mm^2 is
            // 17651.969999999998, a review).
            const bool same = std::abs(given - own) <= 1e-13 * std::abs(own);
            check_parameter(same || !material_entry_set(prm, entry),
                            section,
                            entry,
                            value.str(),
                            requirement.str());
          }
        return;
      }
    check_parameter(name == "custom",
                    section,
                    "Name",
                    name,
                    "unknown material; choose steel, bronze, lead, or custom "
                    "with 'Young's modulus' and 'Poisson's ratio'");
    check_parameter(
      E_given > 0, section, "Young's modulus", E_given, "must be > 0");
    check_parameter(nu_given > -1 && nu_given < 0.5,
                    section,
                    "Poisson's ratio",
                    nu_given,
                    "must lie in (-1, 0.5) for an isotropic elastic plate");
    youngs_modulus = E_given;
    poisson_ratio  = nu_given;
  }

  void
  Obstacle::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Obstacle");
    prm.declare_entry(
      "Function",
      "psi3",
      dealii::Patterns::Anything(),
      "psi (a length), the lower bound w >= psi at every interior node: "
      "psi1 = -2, "
      "psi2 = -0.1 - (x/50 - 1)^2 (y/100 - 0.5)^2, psi3 = -0.5 (x/50 - 1)^2 - "
      "0.02 (x/50 - 1) - 0.5 / (1 + 30 (x/50 - 1)^2) (the paper's eq. 64, "
      "for x, y in mm, converted to 'Plate/Units'), none (no obstacle: a "
      "linear system), or any "
      "expression in x and y (muparser syntax, constant pi).");
    prm.leave_subsection();
  }

  void
  Obstacle::parse_parameters(dealii::ParameterHandler &prm, const Units &units)
  {
    prm.enter_subsection("Obstacle");
    name = prm.get("Function");
    prm.leave_subsection();
    if (name == "none")
      expression.clear();
    else
      {
        expression = expression_of(named_obstacles,
                                   name,
                                   units,
                                   true,
                                   "Obstacle/Function",
                                   "give psi as an expression in x and y");
        parse_function("Plate/Obstacle/Function", expression, obstacle_hint);
      }
  }

  void
  Load::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Load");
    prm.declare_entry(
      "Force",
      "f1",
      dealii::Patterns::Anything(),
      "f, the transverse force per area, positive upwards: f1 = -1, "
      "f2 = -5, f3 = -10 (the paper's eq. 65, in kg/mm^2, converted to "
      "'Plate/Units'), or any expression in x and y "
      "(muparser syntax, constant pi). Integrated with 4 x 4 Gauss points "
      "per cell, exactly for polynomials of degree <= 4 in each variable.");
    prm.leave_subsection();
  }

  void
  Load::parse_parameters(dealii::ParameterHandler &prm, const Units &units)
  {
    prm.enter_subsection("Load");
    name = prm.get("Force");
    prm.leave_subsection();
    expression =
      expression_of(named_forces,
                    name,
                    units,
                    false,
                    "Load/Force",
                    "give f as a number or an expression in x and y");
    parse_function("Plate/Load/Force", expression, force_hint);
  }

  void
  Output::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    prm.declare_entry("Subdivisions",
                      "6",
                      dealii::Patterns::Integer(),
                      "Each cell is written as Subdivisions^2 patches of the "
                      "exact bicubic field (plate.vtu); >= 1 and <= 32.");
    prm.leave_subsection();
  }

  void
  Output::parse_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    const long n = prm.get_integer("Subdivisions");
    prm.leave_subsection();
    check_parameter(n >= 1 && n <= 32,
                    "Plate/Output",
                    "Subdivisions",
                    n,
                    "must be an integer between 1 and 32");
    subdivisions = static_cast<unsigned int>(n);
  }

  void
  Parameters::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Plate");
    Units::declare_parameters(prm);
    Geometry::declare_parameters(prm);
    Material::declare_parameters(prm);
    Obstacle::declare_parameters(prm);
    Load::declare_parameters(prm);
    Output::declare_parameters(prm);
    prm.declare_entry(
      "Coarse-mesh start",
      "true",
      dealii::Patterns::Bool(),
      "Nested iteration: first solve the plate on a mesh with half as many "
      "cells per side (rounded up), itself started the same way down to 8 "
      "cells per side, and start the solver from that solution evaluated at "
      "the nodes of this mesh (the bicubic field and its derivatives, "
      "exactly). The active set is then nearly right from the start: at 90 x "
      "90 PDAS needs 6 iterations instead of 37. Used with an obstacle, "
      "meshes of at least 16 cells per side and the methods that take a "
      "start (pdas, psor); the others keep the paper's start. false: the "
      "method's own start always.");
    prm.leave_subsection();
  }

  void
  Parameters::parse_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Plate");
    units.parse_parameters(prm);
    geometry.parse_parameters(prm);
    material.parse_parameters(prm, units);
    obstacle.parse_parameters(prm, units);
    load.parse_parameters(prm, units);
    output.parse_parameters(prm);
    coarse_mesh_start = prm.get_bool("Coarse-mesh start");
    prm.leave_subsection();
  }
} // namespace unilateral::plate
