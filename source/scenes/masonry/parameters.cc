#include <unilateral/base/input_error.h>
#include <unilateral/base/text.h>
#include <unilateral/lcp/solver.h>
#include <unilateral/scenes/masonry/parameters.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <tuple>

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
    const std::string tearing_section   = "Masonry/Tearing";

    // Defaults that the checks of settings the run would not read compare
    // with (a value other than the default was set on purpose).
    const std::string default_blocks_per_side = "20";
    const std::string default_blocks_through  = "1";
    const std::string default_thickness       = "1";
    const std::string default_gap             = "g";

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
          double value = 0;
          check_parameter(parse_number(item, value) && std::isfinite(value),
                          section,
                          name,
                          text,
                          "must be a comma-separated list of numbers");
          values.push_back(value);
        }
      return values;
    }
  } // namespace

  std::vector<BoundarySelection>
  parse_selections(const std::string &text, const std::string &parameter)
  {
    std::vector<BoundarySelection> result;
    for (const std::string &item :
         dealii::Utilities::split_string_list(text, ','))
      {
        BoundarySelection selection;
        const std::size_t where = item.find(" where ");
        selection.boundary = dealii::Utilities::trim(item.substr(0, where));
        if (where != std::string::npos)
          selection.region = dealii::Utilities::trim(item.substr(where + 7));
        const std::size_t slash = parameter.rfind('/');
        check_parameter(!selection.boundary.empty() &&
                          (where == std::string::npos ||
                           !selection.region.empty()),
                        parameter.substr(0, slash),
                        parameter.substr(slash + 1),
                        text,
                        "each comma-separated entry is a boundary (a name of "
                        "the mesh or its number), optionally followed by "
                        "'where' and a region ('base where x < s')");
        // A comma inside a region (max(x, 1), if(c, a, b)) splits it into
        // two entries: muparser would only say 'Missing parenthesis'.
        check_parameter(std::count(item.begin(), item.end(), '(') ==
                          std::count(item.begin(), item.end(), ')'),
                        parameter.substr(0, slash),
                        parameter.substr(slash + 1),
                        text,
                        "has an entry with unbalanced parentheses, '" +
                          dealii::Utilities::trim(item) +
                          "': every '(' needs its ')', and a region cannot "
                          "contain a comma, which separates the entries (no "
                          "max(a, b), min(a, b) or if(c, a, b)); combine "
                          "conditions with && and || instead ('base where x "
                          "> 1 && x < 2')");
        result.push_back(selection);
      }
    return result;
  }

  // Numbers are declared with unrestricted patterns and checked in
  // parse_parameters, so a bad value gets our one-line message with the fix
  // instead of a pattern description.
  void
  GeometryParameters::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.declare_entry("Dimension",
                      "2",
                      Integer(),
                      "2 (plane strain) or 3. The built-in walls in 3D are "
                      "the 2D walls extruded through 'Thickness' in z, "
                      "with 'Blocks through the thickness' blocks "
                      "behind each other.");
    prm.declare_entry("Geometry",
                      "stack bond",
                      Selection(bond_names() + "|mesh file"),
                      "The built-in walls on the unit square (Ainsworth & "
                      "Mihai, Fig. 2): 'stack bond' (H x H blocks), 'running "
                      "bond' (2H x H bricks, the base row starting with a full "
                      "brick at x = 0, each next row shifted by H, half bricks "
                      "at the ends) or 'laminae' (1 x H strips); their "
                      "boundaries are named left, right, base, top (and front "
                      "z = 0, back z = thickness, collar between the blocks "
                      "through the thickness in 3D). Or 'mesh file': the "
                      "blocks of 'Mesh file'.");
    prm.declare_entry("Mesh file",
                      "",
                      dealii::Patterns::Anything(),
                      "With 'Geometry = mesh file': a Gmsh mesh (.msh, "
                      "formats 2.2 and 4.1 ASCII) of quadrilaterals or "
                      "triangles (2D), hexahedra or tetrahedra (3D); a "
                      "relative path is taken from the parameter file's "
                      "folder. Each block is a connected set of cells of one "
                      "geometric entity and physical tag: blocks may touch "
                      "with coincident separate nodes or share nodes (then "
                      "they are split). A cell's physical tag is its material "
                      "('Materials/Assignment = physical tag'); the physical "
                      "tags (or names) of boundary lines (2D) or surfaces "
                      "(3D) name the boundaries the supports and loads refer "
                      "to.");
    prm.declare_entry("Blocks per side",
                      default_blocks_per_side,
                      Integer(),
                      "1 <= m <= 100000: the block height of the built-in "
                      "walls is "
                      "H = 1/m (Table 1 of the paper uses m = 5, 10, ..., "
                      "225).");
    prm.declare_entry("Refinement",
                      "0",
                      Integer(),
                      "0 <= r <= 12: cells of size h = H / 2^r for the "
                      "built-in "
                      "walls (the paper uses r = 0, h = H; r >= 1 for "
                      "convergence studies); a mesh file's cells are refined "
                      "r times.");
    prm.declare_entry("Element",
                      "Q2",
                      Selection("Q2|P2"),
                      "Q2: FESystem(FE_Q(2), dim) on quadrilaterals or "
                      "hexahedra. P2: FESystem(FE_SimplexP(2), dim) on "
                      "triangles or tetrahedra (the built-in walls split each "
                      "square into two triangles, each cube into six "
                      "tetrahedra: the same nodes, hence the same n and n_c; "
                      "the paper's element). A mesh file's cells decide: P2 "
                      "for a simplex mesh.");
    prm.declare_entry("Blocks through the thickness",
                      default_blocks_through,
                      Integer(),
                      "3D built-in walls: each block of the 2D wall becomes "
                      "this many blocks behind each other in z (collar "
                      "joints between them); 1 to 1000.");
    prm.declare_entry("Thickness",
                      default_thickness,
                      Double(),
                      "3D built-in walls: the thickness in z, in units of H "
                      "(> 0); each block gets round(depth / h) cells in z, and "
                      "must be at least 1e-6 h deep.");
    prm.declare_entry("Coincidence tolerance",
                      "1e-8",
                      Double(),
                      "Points (nodes, faces) closer than this times the "
                      "smallest cell size coincide, and faces whose normals "
                      "differ by less than 4 times this are parallel (a "
                      "joint needs both, and takes the direction of its "
                      "class, off by up to 4 times this); in (0, 1e-3]. "
                      "Faces of two blocks "
                      "that are opposite and overlapping but further apart "
                      "than this, or not parallel, and closer than 1e-2 "
                      "times the cell size (a gap, an overlap or a tilt; "
                      "coordinates written with too few digits) are an "
                      "error.");
  }

  void
  GeometryParameters::parse_parameters(dealii::ParameterHandler &prm)
  {
    const long dim = prm.get_integer("Dimension");
    check_parameter(dim == 2 || dim == 3,
                    geometry_section,
                    "Dimension",
                    dim,
                    "must be 2 (plane strain) or 3");
    dimension = static_cast<unsigned int>(dim);

    const std::string geometry = prm.get("Geometry");
    from_mesh_file             = geometry == "mesh file";
    if (!from_mesh_file)
      bond = parse_bond(geometry);
    mesh_file = prm.get("Mesh file");
    check_parameter(!from_mesh_file || !mesh_file.empty(),
                    geometry_section,
                    "Mesh file",
                    "''",
                    "'Geometry = mesh file' needs a mesh file (.msh)");
    // A setting the run would not read is refused rather than ignored (as
    // the plate refuses material values beside a named material).
    check_parameter(from_mesh_file || mesh_file.empty(),
                    geometry_section,
                    "Mesh file",
                    mesh_file,
                    "is read only with 'Geometry = mesh file' (now '" +
                      geometry + "'): set that, or remove the line");

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

    const long through = prm.get_integer("Blocks through the thickness");
    check_parameter(through >= 1 && through <= 1000,
                    geometry_section,
                    "Blocks through the thickness",
                    through,
                    "must be an integer in [1, 1000]");
    blocks_through_thickness = static_cast<unsigned int>(through);
    thickness                = prm.get_double("Thickness");
    check_parameter(thickness > 0 && std::isfinite(thickness),
                    geometry_section,
                    "Thickness",
                    thickness,
                    "must be > 0 (in units of the block height H)");
    // A 3D built-in wall's boundaries are told apart by the faces' position
    // to 1e-8 h: leaves far thinner than their cells are wide would have
    // their front and back taken for one boundary, and such cells leave
    // nothing double precision can solve (refused here, by name). A mesh
    // file's cells are its own and do not read these two parameters.
    const double leaf_depth_over_h =
      thickness / blocks_through_thickness * std::pow(2.0, refinement);
    check_parameter(dimension != 3 || from_mesh_file ||
                      leaf_depth_over_h >= 1e-6,
                    geometry_section,
                    "Thickness",
                    thickness,
                    "over 'Blocks through the thickness' = " +
                      std::to_string(blocks_through_thickness) +
                      " gives leaves less than 1e-6 of a cell's width "
                      "(h = H / 2^r) deep; make it larger or the blocks "
                      "through the thickness fewer");
    // Settings the run would not read are refused rather than ignored, as
    // 'Mesh file' above (a review: 'Blocks per side' beside a mesh file,
    // 'Thickness' in 2D, both exit 0 without a word).
    for (const auto &[name, default_value, built_in_only] :
         {std::tuple{"Blocks per side", default_blocks_per_side, true},
          std::tuple{"Blocks through the thickness",
                     default_blocks_through,
                     false},
          std::tuple{"Thickness", default_thickness, false}})
      {
        // As numbers: '1.0' is the default '1' (a review).
        const std::string value = prm.get(name);
        check_parameter(prm.get_double(name) == std::stod(default_value) ||
                          (!from_mesh_file &&
                           (built_in_only || dimension == 3)),
                        geometry_section,
                        name,
                        value,
                        from_mesh_file ?
                          "is read only for the built-in walls (now "
                          "'Geometry = mesh file'): remove the line" :
                          "is read only for 3D walls (now 'Dimension = 2'): "
                          "set 'Dimension = 3', or remove the line");
      }
    coincidence_tolerance = prm.get_double("Coincidence tolerance");
    check_parameter(coincidence_tolerance > 0 && coincidence_tolerance <= 1e-3,
                    geometry_section,
                    "Coincidence tolerance",
                    coincidence_tolerance,
                    "must be in (0, 1e-3] (relative to the smallest cell "
                    "size)");
  }

  void
  BoundaryParameters::declare_parameters(dealii::ParameterHandler &prm)
  {
    const std::string where =
      " A comma-separated list of boundaries (names of the mesh, or their "
      "numbers), each optionally restricted to a region: 'base where x < "
      "s' (an expression of x, y, z and the constants g, H, s, without "
      "commas: combine conditions with && and ||). A condition holds at a "
      "node of its faces if the node lies in the face's part inside the "
      "region or on its edge. Where faces "
      "with different conditions meet, a node takes the stronger one, "
      "direction by direction: Fixed and Prescribed displacement over "
      "Normal displacement zero over Signorini over traction.";
    prm.enter_subsection("Boundary conditions");
    prm.declare_entry(
      "Relative gap",
      "0.5",
      Double(),
      "g / H >= 0: the constant g of the expressions, the settlement gap "
      "between the built-in walls' base and the rigid ground on their "
      "Signorini part, in units of the block height H (H = 1 for a mesh "
      "file). The paper takes 0 < g < H without stating g; the default "
      "g = H/2 is the middle of that range at every m, a settlement far "
      "larger than the elastic deformation (about 1e-4), so the settling "
      "blocks move as bodies and open joints. g = 0 closes every joint (the "
      "patch test).");
    prm.declare_entry(
      "Signorini part of the base",
      "0.5",
      Double(),
      "f in [0, 1]: the constant s = x_min + f (x_max - x_min) of the "
      "expressions, where the built-in walls' settled stretch of the base "
      "ends (the paper: the left half settles, f = 0.5). A base node "
      "exactly at x = s is held unless its block ends there.");
    prm.declare_entry("Fixed",
                      "",
                      dealii::Patterns::Anything(),
                      "Boundaries where u = 0." + where);
    prm.declare_entry(
      "Normal displacement zero",
      "left, right, base where x > s",
      dealii::Patterns::Anything(),
      "Boundaries where u.n = 0 (a roller, frictionless and bilateral; "
      "on inclined faces too). The default: the built-in walls' sides and "
      "the part of the base right of s (the paper's Gamma_D)." +
        where);
    prm.declare_entry("Signorini",
                      "base where x < s",
                      dealii::Patterns::Anything(),
                      "Boundaries resting on a rigid frictionless support "
                      "along the face normal, 'Signorini gap' away: u.n <= "
                      "gap (n outward). The default: the built-in walls' "
                      "settled stretch of the base (Gamma_S)." +
                        where);
    prm.declare_entry("Signorini gap",
                      default_gap,
                      dealii::Patterns::Anything(),
                      "The gap between a Signorini boundary and its support, "
                      "along the normal: a function of x, y, z (a settlement "
                      "profile) with the constants g, H, s and pi; the "
                      "support may not lie inside the block (gap >= 0).");
    prm.declare_entry("Prescribed displacement boundaries",
                      "",
                      dealii::Patterns::Anything(),
                      "Boundaries where u = 'Prescribed displacement' (a "
                      "support that moved: a spreading springing)." +
                        where);
    prm.declare_entry("Prescribed displacement",
                      "0; 0",
                      dealii::Patterns::Anything(),
                      "u on the 'Prescribed displacement boundaries': dim "
                      "components separated by ';', functions of x, y, z with "
                      "the constants g, H, s, pi ('0.01; 0'; a single 0 is "
                      "zero in every direction).");
    prm.declare_entry("Traction boundaries",
                      "top",
                      dealii::Patterns::Anything(),
                      "Boundaries loaded by 'Traction'. Boundaries not named "
                      "anywhere are traction free. A traction restricted to "
                      "a region loads the part of each face inside it: "
                      "exactly where the region's edges cross a face "
                      "straight, to about 1e-4 of the face's load where a "
                      "corner of the region or a curved edge lies inside "
                      "it; parts narrower than 1/16 of a face are missed." +
                        where);
    prm.declare_entry("Traction",
                      "0; 0",
                      dealii::Patterns::Anything(),
                      "Force per length (2D) or area (3D) on the 'Traction "
                      "boundaries': dim components separated by ';', "
                      "functions of x, y, z with the constants g, H, s, pi. "
                      "'0; 0' is the paper's traction-free top (a single 0 "
                      "is zero in every direction); '0; -1' a downward "
                      "load.");
    prm.declare_entry("Gravity",
                      "1",
                      Double(),
                      "Gravitational acceleration: the body force is density "
                      "* gravity * the unit 'Gravity direction'. With density "
                      "1 this gives the paper's f = (0, -1).");
    prm.declare_entry("Gravity direction",
                      "0, -1, 0",
                      List(Double(), 2, 3, ","),
                      "The direction of gravity, x, y[, z] (made unit; z must "
                      "be 0 in 2D): '0, -1, 0' is down; tilt it for a "
                      "structure on an inclined plane, or add a horizontal "
                      "part for an equivalent seismic load.");
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
    fixed = parse_selections(prm.get("Fixed"), boundary_section + "/Fixed");
    normal_displacement_zero =
      parse_selections(prm.get("Normal displacement zero"),
                       boundary_section + "/Normal displacement zero");
    signorini =
      parse_selections(prm.get("Signorini"), boundary_section + "/Signorini");
    gap = prm.get("Signorini gap");
    check_parameter(!dealii::Utilities::trim(gap).empty(),
                    boundary_section,
                    "Signorini gap",
                    "''",
                    "give the gap as an expression ('g', '0.01 * x')");
    prescribed = parse_selections(prm.get("Prescribed displacement boundaries"),
                                  boundary_section +
                                    "/Prescribed displacement boundaries");
    prescribed_displacement = prm.get("Prescribed displacement");
    traction                = parse_selections(prm.get("Traction boundaries"),
                                boundary_section + "/Traction boundaries");
    traction_value          = prm.get("Traction");
    // A gap that no boundary would take is refused rather than dropped
    // (a review); so are a traction and a prescribed displacement
    // (make_supports, which knows their components).
    check_parameter(!signorini.empty() ||
                      dealii::Utilities::trim(gap) == default_gap,
                    boundary_section,
                    "Signorini gap",
                    gap,
                    "is read only where 'Signorini' names a boundary (now "
                    "empty): name the boundaries it applies to, or remove "
                    "the line");
    gravity = prm.get_double("Gravity");
    check_parameter(std::isfinite(gravity),
                    boundary_section,
                    "Gravity",
                    gravity,
                    "must be a finite number");
    const std::vector<double> direction =
      get_doubles(prm, boundary_section, "Gravity direction");
    gravity_direction   = {{direction.at(0),
                            direction.at(1),
                          direction.size() > 2 ? direction[2] : 0.0}};
    const double length = std::hypot(gravity_direction[0],
                                     gravity_direction[1],
                                     gravity_direction[2]);
    check_parameter(length > 0 && std::isfinite(length),
                    boundary_section,
                    "Gravity direction",
                    prm.get("Gravity direction"),
                    "must be a nonzero vector x, y[, z]");
    for (double &component : gravity_direction)
      component /= length;
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
                      "is density * 'Gravity' along 'Gravity direction'.");
    prm.declare_entry("Tags",
                      "",
                      dealii::Patterns::Anything(),
                      "With 'Assignment = physical tag': the physical tag "
                      "(name or number) of the mesh file's cells of each "
                      "class, comma separated, one per class in the order of "
                      "'Young's modulus'. Empty: tags 1, 2, ... A cell whose "
                      "tag is not listed is an error.");
    prm.declare_entry("Assignment",
                      "single",
                      Selection(
                        "single|alternating courses|cyclic|physical tag"),
                      "Which class each block gets: 'single' (one class for "
                      "all), 'alternating courses' (course k gets class k mod "
                      "the number of classes, e.g. bricks and bond beams), "
                      "'cyclic' (block b gets class b mod the number of "
                      "classes), both for the built-in walls, whose blocks are "
                      "numbered row by row from the bottom left; 'physical "
                      "tag' (a mesh file: each cell's physical tag, see "
                      "'Tags').");
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
    tags.clear();
    const std::string tag_text = prm.get("Tags");
    for (const std::string &tag :
         dealii::Utilities::split_string_list(tag_text, ','))
      tags.push_back(tag);
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
    else if (rule == "cyclic")
      assignment = MaterialAssignment::cyclic;
    else
      assignment = MaterialAssignment::physical_tag;
    if (tags.empty())
      for (std::size_t k = 0; k < classes.size(); ++k)
        tags.push_back(std::to_string(k + 1));
    check_parameter(assignment == MaterialAssignment::physical_tag ||
                      tag_text.empty(),
                    materials_section,
                    "Tags",
                    tag_text,
                    "is read only with 'Assignment = physical tag' (now '" +
                      rule + "'): set that, or remove the line");
    check_parameter(assignment != MaterialAssignment::physical_tag ||
                      tags.size() == classes.size(),
                    materials_section,
                    "Tags",
                    tag_text,
                    "has " + std::to_string(tags.size()) + " entries for " +
                      std::to_string(classes.size()) +
                      " material classes; give one tag per class");
    for (std::size_t k = 1; k < tags.size(); ++k)
      check_parameter(std::find(tags.begin(), tags.begin() + k, tags[k]) ==
                        tags.begin() + k,
                      materials_section,
                      "Tags",
                      tag_text,
                      "names '" + tags[k] +
                        "' twice: a physical group belongs to one class; "
                        "give each class its own tags");
    check_parameter(assignment != MaterialAssignment::single ||
                      classes.size() == 1,
                    materials_section,
                    "Assignment",
                    rule,
                    std::to_string(classes.size()) +
                      " material classes are given but 'single' uses one; "
                      "give one class, or choose 'physical tag' (a mesh "
                      "file's groups) or, for the built-in walls, "
                      "'alternating courses' or 'cyclic'");
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
  TearingParameters::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Tearing");
    prm.declare_entry(
      "Largest aspect ratio",
      "2",
      dealii::Patterns::Double(0),
      "Methods that tear the structure into subdomains (" +
        lcp::methods_where(
          [](const lcp::SolverInfo &info) { return info.needs_tearing; }) +
        "): a block whose bounding box is longer than this many times its "
        "shortest side is cut into pieces about as long as that side, "
        "glued by equality multipliers (each piece floats like a block). A "
        "long block alone (a lamina: one block of m cells) makes the dual "
        "problem's condition grow with m. 0 keeps every block whole.");
    prm.leave_subsection();
  }

  void
  TearingParameters::parse_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Tearing");
    largest_aspect_ratio = prm.get_double("Largest aspect ratio");
    prm.leave_subsection();
    check_parameter(largest_aspect_ratio == 0 || largest_aspect_ratio >= 1,
                    tearing_section,
                    "Largest aspect ratio",
                    largest_aspect_ratio,
                    "is below 1, which no block can meet; give 0 (blocks "
                    "whole) or a number >= 1");
  }

  void
  Parameters::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Masonry");
    GeometryParameters::declare_parameters(prm);
    BoundaryParameters::declare_parameters(prm);
    MaterialParameters::declare_parameters(prm);
    TearingParameters::declare_parameters(prm);
    prm.declare_entry(
      "Coarse-mesh start",
      "true",
      dealii::Patterns::Bool(),
      "Nested iteration for walls of slender blocks with many cells along "
      "them (the laminae: m cells along each lamina): first solve the same "
      "wall on a mesh whose cells are k times as long along the blocks (the "
      "largest k that keeps every block corner a node and at least 20 cells "
      "along each block), and start the solver from that displacement "
      "evaluated at the nodes of this mesh; the joints it leaves closed, or "
      "open by less than its interpolation error, start closed. Laminae m = 225: 7 PDAS iterations instead of 29. Used by the "
      "built-in walls (not mesh files) whose blocks are all at least twice as "
      "long as wide, with the methods that take a start (pdas, psor); other "
      "walls (the paper's stack and running bond: one or two cells per "
      "block side) keep the method's own start. false: the method's own "
      "start always.");
    prm.leave_subsection();
  }

  void
  Parameters::parse_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Masonry");
    geometry.parse_parameters(prm);
    boundary.parse_parameters(prm);
    materials.parse_parameters(prm);
    tearing.parse_parameters(prm);
    coarse_mesh_start = prm.get_bool("Coarse-mesh start");
    prm.leave_subsection();
    const bool by_layout =
      materials.assignment == MaterialAssignment::alternating_courses ||
      materials.assignment == MaterialAssignment::cyclic;
    check_parameter(!(geometry.from_mesh_file && by_layout),
                    materials_section,
                    "Assignment",
                    by_layout ? "alternating courses or cyclic" : "",
                    "numbers the built-in walls' blocks; a mesh file's "
                    "blocks take their class from their physical tag "
                    "('physical tag')");
    check_parameter(geometry.from_mesh_file ||
                      materials.assignment != MaterialAssignment::physical_tag,
                    materials_section,
                    "Assignment",
                    "physical tag",
                    "needs 'Geometry = mesh file' (the built-in walls have "
                    "no physical tags): choose 'single', 'alternating "
                    "courses' or 'cyclic'");
    check_parameter(geometry.dimension == 3 ||
                      boundary.gravity_direction[2] == 0,
                    boundary_section,
                    "Gravity direction",
                    prm.get({"Masonry", "Boundary conditions"},
                            "Gravity direction"),
                    "has a z component in 2D; give x, y");
  }
} // namespace unilateral::masonry
