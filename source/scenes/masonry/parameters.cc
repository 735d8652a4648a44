#include <unilateral/base/input_error.h>
#include <unilateral/scenes/masonry/parameters.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <cmath>

namespace unilateral::masonry
{
  using dealii::Patterns::Double;
  using dealii::Patterns::Integer;
  using dealii::Patterns::List;
  using dealii::Patterns::Selection;

  std::string
  to_string(const ElementType element)
  {
    return element == ElementType::q2 ? "Q2" : "P2";
  }

  namespace
  {
    const std::string geometry_section  = "Masonry";
    const std::string boundary_section  = "Masonry/Boundary conditions";
    const std::string materials_section = "Masonry/Materials";

    std::vector<double>
    get_doubles(dealii::ParameterHandler &prm,
                const std::string        &section,
                const std::string        &name)
    {
      const std::string   text = prm.get(name);
      std::vector<double> values;
      for (const std::string &item :
           dealii::Utilities::split_string_list(text, ','))
        {
          char        *end   = nullptr;
          const double value = std::strtod(item.c_str(), &end);
          check_parameter(end != item.c_str() && *end == '\0' &&
                            std::isfinite(value),
                          section,
                          name,
                          text,
                          "must be a comma-separated list of numbers");
          values.push_back(value);
        }
      return values;
    }
  } // namespace

  // Numbers are declared with unrestricted patterns and checked in
  // parse_parameters, so a bad value gets our one-line message with the fix
  // instead of a pattern description.
  void
  GeometryParameters::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.declare_entry("Geometry",
                      "stack bond",
                      Selection(bond_names()),
                      "The wall on the unit square (Ainsworth & Mihai, "
                      "Fig. 2): 'stack bond' (H x H blocks), 'running bond' "
                      "(2H x H bricks, the base row starting with a full "
                      "brick at x = 0, each next row shifted by H, half "
                      "bricks at the ends) or 'laminae' (1 x H strips).");
    prm.declare_entry("Blocks per side",
                      "20",
                      Integer(),
                      "m >= 1: the block height is H = 1/m (Table 1 of the "
                      "paper uses m = 5, 10, ..., 225).");
    prm.declare_entry("Refinement",
                      "0",
                      Integer(),
                      "r >= 0: cells of size h = H / 2^r. The paper uses r = 0 "
                      "(h = H); r >= 1 for convergence studies.");
    prm.declare_entry("Element",
                      "Q2",
                      Selection("Q2|P2"),
                      "Q2: biquadratic quadrilaterals, FESystem(FE_Q(2), 2). "
                      "P2: each square split into two triangles with "
                      "quadratic elements (the paper's element). Both have "
                      "the same nodes, hence the same n and n_c.");
  }

  void
  GeometryParameters::parse_parameters(dealii::ParameterHandler &prm)
  {
    bond = parse_bond(prm.get("Geometry"));

    const long blocks = prm.get_integer("Blocks per side");
    check_parameter(blocks >= 1 && blocks <= 100000,
                    geometry_section,
                    "Blocks per side",
                    blocks,
                    "must be an integer in [1, 100000] (the block height is "
                    "H = 1/m)");
    m = static_cast<unsigned int>(blocks);

    const long levels = prm.get_integer("Refinement");
    check_parameter(levels >= 0 && levels <= 12,
                    geometry_section,
                    "Refinement",
                    levels,
                    "must be an integer in [0, 12] (cells of size H / 2^r)");
    refinement = static_cast<unsigned int>(levels);

    element = prm.get("Element") == "P2" ? ElementType::p2 : ElementType::q2;
  }

  void
  BoundaryParameters::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Boundary conditions");
    prm.declare_entry(
      "Relative gap",
      "0.5",
      Double(),
      "g / H >= 0: the settlement gap g between the base and the rigid ground "
      "on the Signorini part Gamma_S, in units of the block height H. The "
      "paper takes 0 < g < H without stating g; the default g = H/2 is the "
      "middle of that range at every m, a settlement far larger than the "
      "elastic deformation (about 1e-4), so the settling blocks move as "
      "bodies and open joints. g = 0 closes every joint (the patch test).");
    prm.declare_entry(
      "Signorini part of the base",
      "0.5",
      Double(),
      "s in [0, 1]: Gamma_S is the left part [0, s] of the base (u_y >= -g), "
      "the rest of the base has u_y = 0 (Gamma_D). A base node exactly at "
      "x = s is Signorini only if its block ends there. The paper: s = 0.5.");
    prm.declare_entry("Top traction",
                      "0, 0",
                      List(Double(), 2, 2, ","),
                      "Traction (force per length, x and y) on the top "
                      "y = 1; '0, 0' is the paper's traction-free top. "
                      "A downward load is e.g. '0, -1'.");
    prm.declare_entry("Gravity",
                      "1",
                      Double(),
                      "Gravitational acceleration: the body force is (0, "
                      "-density * gravity). With density 1 this gives the "
                      "paper's f = (0, -1).");
    prm.leave_subsection();
  }

  void
  BoundaryParameters::parse_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Boundary conditions");
    relative_gap = prm.get_double("Relative gap");
    check_parameter(relative_gap >= 0 && std::isfinite(relative_gap),
                    boundary_section,
                    "Relative gap",
                    relative_gap,
                    "the gap g / H must be >= 0 (0 closes the base, the "
                    "paper takes 0 < g < H)");
    signorini_fraction = prm.get_double("Signorini part of the base");
    check_parameter(signorini_fraction >= 0 && signorini_fraction <= 1,
                    boundary_section,
                    "Signorini part of the base",
                    signorini_fraction,
                    "must be in [0, 1] (a fraction of the base width; the "
                    "paper uses 0.5)");
    const std::vector<double> traction =
      get_doubles(prm, boundary_section, "Top traction");
    top_traction = {{traction.at(0), traction.at(1)}};
    gravity      = prm.get_double("Gravity");
    check_parameter(std::isfinite(gravity),
                    boundary_section,
                    "Gravity",
                    gravity,
                    "must be a finite number");
    prm.leave_subsection();
  }

  void
  MaterialParameters::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Materials");
    prm.declare_entry("Young's modulus",
                      "4e3",
                      List(Double(), 1, 64, ","),
                      "E > 0 of each material class, comma separated (one "
                      "entry per class). The paper: E = 4e3.");
    prm.declare_entry("Poisson's ratio",
                      "0.3",
                      List(Double(), 1, 64, ","),
                      "nu in (-1, 0.5) of each material class (plane "
                      "strain). The paper: nu = 0.3.");
    prm.declare_entry("Density",
                      "1",
                      List(Double(), 1, 64, ","),
                      "Density >= 0 of each material class; the body force "
                      "is (0, -density * gravity).");
    prm.declare_entry("Assignment",
                      "single",
                      Selection("single|alternating courses|cyclic"),
                      "Which class each block gets: 'single' (one class for "
                      "all), 'alternating courses' (course k gets class k mod "
                      "the number of classes, e.g. bricks and bond beams), "
                      "'cyclic' (block b gets class b mod the number of "
                      "classes). Blocks are numbered row by row from the "
                      "bottom left.");
    prm.leave_subsection();
  }

  void
  MaterialParameters::parse_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Materials");
    const std::vector<double> E =
      get_doubles(prm, materials_section, "Young's modulus");
    const std::vector<double> nu =
      get_doubles(prm, materials_section, "Poisson's ratio");
    const std::vector<double> rho =
      get_doubles(prm, materials_section, "Density");
    const std::string rule = prm.get("Assignment");
    prm.leave_subsection();

    for (const auto &[name, values] :
         {std::pair<std::string, std::size_t>{"Poisson's ratio", nu.size()},
          std::pair<std::string, std::size_t>{"Density", rho.size()}})
      {
        prm.enter_subsection("Materials");
        const std::string text = prm.get(name);
        prm.leave_subsection();
        check_parameter(values == E.size(),
                        materials_section,
                        name,
                        text,
                        "has " + std::to_string(values) +
                          " entries but 'Young's modulus' has " +
                          std::to_string(E.size()) +
                          "; give one entry per material class");
      }
    classes.clear();
    for (std::size_t k = 0; k < E.size(); ++k)
      {
        check_parameter(E[k] > 0,
                        materials_section,
                        "Young's modulus",
                        E[k],
                        "must be > 0 (class " + std::to_string(k) + ")");
        check_parameter(nu[k] > -1 && nu[k] < 0.5,
                        materials_section,
                        "Poisson's ratio",
                        nu[k],
                        "must be in (-1, 0.5) (class " + std::to_string(k) +
                          "; 0.5 is incompressible, which plane strain "
                          "displacement elements cannot represent)");
        check_parameter(rho[k] >= 0,
                        materials_section,
                        "Density",
                        rho[k],
                        "must be >= 0 (class " + std::to_string(k) + ")");
        classes.push_back({E[k], nu[k], rho[k]});
      }

    if (rule == "single")
      assignment = MaterialAssignment::single;
    else if (rule == "alternating courses")
      assignment = MaterialAssignment::alternating_courses;
    else
      assignment = MaterialAssignment::cyclic;
    check_parameter(assignment != MaterialAssignment::single ||
                      classes.size() == 1,
                    materials_section,
                    "Assignment",
                    rule,
                    std::to_string(classes.size()) +
                      " material classes are given but 'single' uses one; "
                      "give one class or choose 'alternating courses' or "
                      "'cyclic'");
  }

  std::vector<unsigned int>
  MaterialParameters::classes_of_blocks(const Layout &layout) const
  {
    const auto n_classes = static_cast<unsigned int>(classes.size());
    std::vector<unsigned int> result(layout.blocks.size(), 0);
    if (assignment == MaterialAssignment::alternating_courses)
      {
        result = layout.courses();
        for (unsigned int &c : result)
          c %= n_classes;
      }
    else if (assignment == MaterialAssignment::cyclic)
      for (std::size_t b = 0; b < result.size(); ++b)
        result[b] = static_cast<unsigned int>(b % n_classes);
    return result;
  }

  void
  Parameters::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Masonry");
    GeometryParameters::declare_parameters(prm);
    BoundaryParameters::declare_parameters(prm);
    MaterialParameters::declare_parameters(prm);
    prm.leave_subsection();
  }

  void
  Parameters::parse_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Masonry");
    geometry.parse_parameters(prm);
    boundary.parse_parameters(prm);
    materials.parse_parameters(prm);
    prm.leave_subsection();
  }
} // namespace unilateral::masonry
