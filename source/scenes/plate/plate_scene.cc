#include <unilateral/base/input_error.h>
#include <unilateral/base/memory.h>
#include <unilateral/scenes/plate/bending.h>
#include <unilateral/scenes/plate/plate_scene.h>

#include <deal.II/base/geometry_info.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/component_mask.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/grid/grid_generator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <limits>
#include <ostream>
#include <sstream>

namespace unilateral::plate
{
  void
  PlateScene::declare_parameters(dealii::ParameterHandler &prm)
  {
    Parameters::declare_parameters(prm);
  }

  namespace
  {
    Parameters
    parsed(dealii::ParameterHandler &prm)
    {
      Parameters parameters;
      parameters.parse_parameters(prm);
      return parameters;
    }

    /// D of the paper's steel plate (E = 21e3 kg/mm^2, t = 2 mm, nu = 0.28)
    /// in @p units: the solvers' reference stiffness.
    double
    paper_steel_rigidity(const Units &units)
    {
      return 15190.972222222221 * units.kg * units.mm;
    }
  } // namespace

  PlateScene::PlateScene(dealii::ParameterHandler &prm)
    : PlateScene(parsed(prm))
  {}

  PlateScene::PlateScene(const Parameters &parameters)
    : Scene(registered_name)
    , parameters(parameters)
    , fe(dealii::FE_Q<2>(1), fe::BognerFoxSchmit::dofs_per_vertex)
  {
    rigidity = flexural_rigidity(parameters.material.youngs_modulus,
                                 parameters.material.poisson_ratio,
                                 parameters.geometry.thickness);
    // Each of E, t and nu is in range, but t^3 E can leave double precision
    // (a thickness of 1e-110): then A = 0 or infinite, which the solvers
    // would blame on the lengths or the load. A subnormal D is refused too:
    // dividing b by the force unit D / D_steel (assemble_system) made b
    // infinite, an error that named no parameter (a review).
    const double relative_rigidity =
      rigidity / paper_steel_rigidity(parameters.units);
    if (!(std::isnormal(rigidity) && rigidity > 0 &&
          std::isnormal(relative_rigidity)))
      {
        std::ostringstream message;
        message << "the bending rigidity D = E t^3 / (12 (1 - nu^2)) of "
                   "'Plate/Geometry/Thickness' = "
                << parameters.geometry.thickness
                << " and 'Plate/Material/Young's modulus' = "
                << parameters.material.youngs_modulus << " is " << rigidity
                << ", beyond double precision: give them in "
                   "units nearer to each other (choose 'Plate/Units' = "
                << (parameters.units.labelled() ?
                      "m and N, mm and N or mm and kg; in mm and kg steel "
                      "is t = 2, E = 21000" :
                      "mm and kg, with t = 2 and E = 21000 for steel, or "
                      "units of your own nearer to each other")
                << ")";
        throw InputError(message.str());
      }
    // The expressions were checked while parsing; these cannot fail.
    if (parameters.obstacle.present())
      obstacle = parse_function("Plate/Obstacle/Function",
                                parameters.obstacle.expression,
                                "");
    force = parse_function("Plate/Load/Force", parameters.load.expression, "");
  }

  void
  PlateScene::make_grid(RunContext &context)
  {
    const Geometry &geometry = parameters.geometry;
    // Refused before anything is built where the mesh and its DOFs alone
    // would not fit (a lower bound per cell, below every method's peak per
    // cell in benchmarks/plate_multigrid/README.md): 100000 x 100000
    // elements, which the parameters allow, would otherwise allocate until
    // the kernel kills the run.
    const double n_cells = static_cast<double>(geometry.n_x) * geometry.n_y;
    memory::require(n_cells * 1e3,
                    "the mesh of " + dealii::Utilities::to_string(n_cells) +
                      " elements and its set-up");
    dealii::GridGenerator::subdivided_hyper_rectangle(
      triangulation,
      {geometry.n_x, geometry.n_y},
      dealii::Point<2>(0, 0),
      dealii::Point<2>(geometry.length_x, geometry.length_y));
    // Progress through the set-up, as the masonry scene's (a review: a
    // large plate assembled for seconds without a line).
    context.stage(registered_name,
                  std::to_string(geometry.n_x) + " x " +
                    std::to_string(geometry.n_y) +
                    " Bogner-Fox-Schmit elements");
  }

  void
  PlateScene::setup_system(RunContext &)
  {
    dof_handler.reinit(triangulation);
    dof_handler.distribute_dofs(fe);
    // Less than the plate's peak per DOF with every method (tnnmg's is the
    // least), so that the peak does not grow; from about 650 x 650
    // elements, where the touch reaches its 1 GB minimum (the rate:
    // benchmarks/plate_multigrid/README.md, "Pages faulted in on the idle
    // core").
    constexpr double pretouched_bytes_per_dof = 600;
    pretouch(pretouched_bytes_per_dof * dof_handler.n_dofs());

    const dealii::ComponentMask clamped(
      {true, true, true, parameters.geometry.clamp_twist});
    const dealii::IndexSet fixed =
      dealii::DoFTools::extract_boundary_dofs(dof_handler, clamped);
    free_dofs = number_free_dofs(dof_handler.n_dofs(), fixed);

    // The unknowns' scale (see unknown_scale), the same for every node.
    const double h_x = parameters.geometry.length_x / parameters.geometry.n_x;
    const double h_y = parameters.geometry.length_y / parameters.geometry.n_y;
    const auto   far_from_unit = [](const double h) {
      return h < 1e-2 || h > 1e2;
    };
    const bool scaled = far_from_unit(h_x) || far_from_unit(h_y);
    component_scale.fill(1);
    if (scaled)
      {
        component_scale[fe::BognerFoxSchmit::slope_x] = 1 / h_x;
        component_scale[fe::BognerFoxSchmit::slope_y] = 1 / h_y;
        component_scale[fe::BognerFoxSchmit::twist]   = 1 / (h_x * h_y);
      }
    unknown_scale.resize(scaled ? free_dofs.size() : 0);

    // The w DOF of every node that is not clamped, with its vertex.
    const std::vector<unsigned int> bfs_index =
      fe::bfs_local_indices(dof_handler.get_fe());
    std::vector<dealii::types::global_dof_index> local_dofs(
      fe.n_dofs_per_cell());
    std::vector<std::pair<lcp::Index, unsigned int>> interior_nodes;
    std::vector<bool> seen(triangulation.n_vertices(), false);
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(local_dofs);
        for (unsigned int i = 0; i < local_dofs.size(); ++i)
          {
            const unsigned int vertex    = bfs_index[i] / 4;
            const unsigned int component = bfs_index[i] % 4;
            const lcp::Index   free      = free_dofs.index[local_dofs[i]];
            if (scaled && free >= 0)
              unknown_scale[free] = component_scale[component];
            if (component != fe::BognerFoxSchmit::deflection || free < 0 ||
                seen[cell->vertex_index(vertex)])
              continue;
            seen[cell->vertex_index(vertex)] = true;
            interior_nodes.emplace_back(free, cell->vertex_index(vertex));
          }
      }
    std::sort(interior_nodes.begin(), interior_nodes.end());

    lcp_problem.constrained.clear();
    bound_vertex.clear();
    if (obstacle == nullptr)
      {
        lcp_problem.lower_bound.resize(0);
        return;
      }
    const std::vector<dealii::Point<2>> &vertices =
      triangulation.get_vertices();
    lcp_problem.lower_bound.resize(interior_nodes.size());
    for (const auto &[free, vertex] : interior_nodes)
      {
        const double psi = obstacle->value(vertices[vertex]);
        // A coarser mesh's node that the user's mesh does not have (odd
        // sides are halved rounded up): an obstacle infinite there (a
        // pole between the plate's nodes, a review) leaves the node free
        // on that mesh, which only gives a start; the plate's own mesh
        // decides.
        if (coarse_level && !std::isfinite(psi))
          continue;
        if (!std::isfinite(psi))
          {
            std::ostringstream message;
            message << "parameter 'Plate/Obstacle/Function' = "
                    << parameters.obstacle.name << ": evaluates to "
                    << (std::isnan(psi) ? "nan" :
                        psi > 0         ? "inf" :
                                          "-inf")
                    << " at the node (" << vertices[vertex][0] << ", "
                    << vertices[vertex][1]
                    << "); give an obstacle that is finite at every node";
            throw InputError(message.str());
          }
        lcp_problem.lower_bound[lcp_problem.constrained.size()] = psi;
        lcp_problem.constrained.push_back(free);
        bound_vertex.push_back(vertex);
      }
    lcp_problem.lower_bound.conservativeResize(lcp_problem.constrained.size());

    // Where the clamped edge holds w = 0 and dw/dn = 0, the plate can climb
    // away from it no faster than the square of the distance d: an obstacle
    // that is positive just inside the edge and grows there slower than
    // d^2 (a constant, a slope from zero) cannot be met in the continuum.
    // Sampled along each edge face (between its vertices, a review; not at
    // its ends, which lie on the neighbouring edge) at d = delta and
    // 2 delta inside: psi(delta) > 0 and psi(delta) > psi(2 delta) / 3 (a
    // constant or a slope; d^2 gives exactly a quarter). The edge line
    // itself does not count: the obstacle acts inside.
    obstacle_on_edge = 0;
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          {
            const auto                 face = cell->face(f);
            const dealii::Point<2>     a = face->vertex(0), b = face->vertex(1);
            const dealii::Tensor<1, 2> inward =
              -dealii::GeometryInfo<2>::unit_normal_vector[f];
            const double delta = 1e-3 * a.distance(b);
            for (const double s : {0.1, 0.3, 0.5, 0.7, 0.9})
              {
                const dealii::Point<2> on_edge = a + s * (b - a);
                const double near = obstacle->value(on_edge + delta * inward);
                const double further =
                  obstacle->value(on_edge + 2 * delta * inward);
                if (near > 0 && near > further / 3 && near > obstacle_on_edge)
                  {
                    obstacle_on_edge    = near;
                    obstacle_on_edge_at = on_edge + delta * inward;
                  }
              }
          }
  }

  // The clamped DOFs are zero, so F needs no lifting.
  void
  PlateScene::assemble_system(RunContext &context)
  {
    context.stage(registered_name,
                  "assembling the bending stiffness (" +
                    std::to_string(free_dofs.size()) + " free DOFs)");
    assemble_plate_system(dof_handler,
                          free_dofs,
                          nullptr,
                          rigidity,
                          parameters.material.poisson_ratio,
                          *force,
                          "parameter 'Plate/Load/Force' = " +
                            parameters.load.name,
                          lcp_problem.A,
                          lcp_problem.b);
    // The solvers' force unit. PDAS's tau weighs a deflection against a
    // force, and other methods' tolerances are absolute: a plate far
    // stiffer or softer than the paper's (a 1e-4 mm sheet with its load
    // scaled alike, the same deflections) handed them numbers 1e13 apart
    // and three methods failed where one converged. Within a factor 1e3 of
    // the paper's steel plate nothing is scaled (its tables stay as they
    // were); beyond, A and b are divided by D / D_steel, so that the
    // solvers see the steel plate's numbers. Energies and contact forces
    // are reported in the parameter file's units.
    const double ratio = rigidity / paper_steel_rigidity(parameters.units);
    unit               = ratio > 1e3 || ratio < 1e-3 ? ratio : 1.0;
    if (unit != 1)
      {
        lcp_problem.A /= unit;
        lcp_problem.b /= unit;
        lcp_problem.energy_unit = unit;
        // A load far larger than so thin a plate can carry in double
        // precision (f ~ 1, D ~ 1e-300).
        if (!lcp_problem.b.allFinite())
          {
            std::ostringstream message;
            message << "parameter 'Plate/Load/Force' = " << parameters.load.name
                    << ": divided by the plate's bending rigidity relative "
                       "to the paper's steel plate ("
                    << unit
                    << "), the load leaves double precision: give the force, "
                       "'Plate/Material/Young's modulus' and "
                       "'Plate/Geometry/Thickness' in units nearer to each "
                       "other";
            throw InputError(message.str());
          }
      }
    if (unknown_scale.size() > 0) // S A S in place: A may be gigabytes
      {
        for (lcp::Index j = 0; j < lcp_problem.A.outerSize(); ++j)
          for (lcp::SparseMatrix::InnerIterator entry(lcp_problem.A, j); entry;
               ++entry)
            entry.valueRef() *=
              unknown_scale[entry.row()] * unknown_scale[entry.col()];
        lcp_problem.b.array() *= unknown_scale.array();
      }
    // The bending stiffness with the clamped DOFs eliminated.
    lcp_problem.known_semidefinite = true;
    // Clamped on every side (or all but the twist): no rigid motion.
    lcp_problem.definite = true;
    if (lcp::SolverRegistry::get(context.solver.method).needs_hierarchy)
      lcp_problem.hierarchy = make_hierarchy();
  }

  lcp::Vector
  PlateScene::dofs_of(const lcp::Vector &u) const
  {
    return unknown_scale.size() > 0 ?
             lcp::Vector(unknown_scale.cwiseProduct(u)) :
             u;
  }

  lcp::Vector
  PlateScene::unknowns_of(const lcp::Vector &dofs) const
  {
    return unknown_scale.size() > 0 ?
             lcp::Vector(dofs.cwiseQuotient(unknown_scale)) :
             dofs;
  }

  void
  PlateScene::initial_solution(RunContext &context)
  {
    if (uses_coarse_mesh_start(context))
      lcp_solution = coarse_mesh_start(context);
  }

  // w at the centre is evaluated on the cell that contains it.
  void
  PlateScene::postprocess(const RunContext &, lcp::Report &report)
  {
    report.regularisation *= unit;
    dof_values.reinit(dof_handler.n_dofs());
    const lcp::Vector dofs = dofs_of(lcp_solution.u);
    for (lcp::Index k = 0; k < free_dofs.size(); ++k)
      dof_values[free_dofs.dof[k]] = dofs[k];

    plate_results.n_elements = triangulation.n_active_cells();
    plate_results.n_free     = static_cast<unsigned int>(lcp_problem.size());
    plate_results.n_bounds =
      static_cast<unsigned int>(lcp_problem.n_constrained());
    plate_results.n_contact = report.n_active;
    plate_results.rigidity  = rigidity;

    const std::vector<unsigned int> bfs_index =
      fe::bfs_local_indices(dof_handler.get_fe());
    const dealii::Point<2> centre(parameters.geometry.length_x / 2,
                                  parameters.geometry.length_y / 2);
    plate_results.min_deflection = std::numeric_limits<double>::infinity();
    bool centre_found            = false;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        const auto coefficients =
          cell_coefficients(cell, bfs_index, dof_values);
        // NaN wins: std::min would drop it and show a broken answer's
        // minimum as a number.
        for (unsigned int v = 0; v < 4; ++v)
          {
            const double w =
              coefficients[fe::BognerFoxSchmit::local_index(v, 0)];
            if (std::isnan(w) || w < plate_results.min_deflection)
              plate_results.min_deflection = w;
          }
        const fe::BognerFoxSchmit element = cell_element(cell);
        const dealii::Point<2>    upper   = element.vertex(3);
        if (!centre_found && element.vertex(0)[0] <= centre[0] &&
            centre[0] <= upper[0] && element.vertex(0)[1] <= centre[1] &&
            centre[1] <= upper[1])
          {
            plate_results.centre_deflection =
              element.value(coefficients, centre);
            centre_found = true;
          }
      }
  }

  void
  PlateScene::print_summary(std::ostream &out, const lcp::Report &report) const
  {
    const Geometry &geometry = parameters.geometry;
    const Material &material = parameters.material;
    const Units    &units    = parameters.units;
    // " mm" after a number; nothing in units of the user's own.
    const auto in = [](const std::string &unit) {
      return unit.empty() ? std::string() : " " + unit;
    };
    const auto flags     = out.flags();
    const auto precision = out.precision();
    // The solver's progress lines share this stream and its format state.
    out << std::defaultfloat << std::setprecision(6);
    out << "  plate " << geometry.length_x << " x " << geometry.length_y
        << in(units.length) << ", t = " << geometry.thickness
        << in(units.length) << ", " << geometry.n_x << " x " << geometry.n_y
        << " Bogner-Fox-Schmit elements, "
        << (geometry.clamp_twist ? "fully clamped" : "clamped (w_xy free)")
        << "\n"
        << "  material " << material.name << ": E = " << material.youngs_modulus
        << in(units.stress()) << ", nu = " << material.poisson_ratio
        << ", D = " << rigidity << in(units.moment()) << "\n"
        << "  obstacle " << parameters.obstacle.name << ", force "
        << parameters.load.name << "\n"
        << "  |J| = " << plate_results.n_free
        << " free DOFs, |J1| = " << plate_results.n_bounds
        << " bounded nodes\n";
    // A mesh of one element in a direction has every node on the clamped
    // edge (a review: a 1 x 1 plate went 23 mm through the obstacle
    // without a word).
    if (obstacle != nullptr && plate_results.n_bounds == 0)
      out
        << "  note: no node of the mesh is off the clamped edge, and the "
           "obstacle acts at nodes only, so it acts nowhere"
        << (plate_results.n_free == 0 ? " (and every DOF is clamped)" : "")
        << ": refine the mesh ('Plate/Geometry/Elements x' and 'Elements y')\n";
    // w = 0 on the clamped edge: an obstacle above it there has no
    // solution in the continuum, and the plate climbs onto it within one
    // element, ever more steeply as the mesh is refined (a review: the
    // centre deflection 1.1, 15 and 37 mm on 20, 64 and 128 elements).
    if (obstacle != nullptr && obstacle_on_edge > 0)
      out << "  note: the obstacle rises above the clamped edge (psi = "
          << obstacle_on_edge << in(units.length) << " at ("
          << std::setprecision(8) << obstacle_on_edge_at[0] << ", "
          << obstacle_on_edge_at[1] << std::setprecision(6)
          << "), just inside the edge, where w = 0 and its slope is 0): the "
             "plate must climb onto "
             "it within one element of the edge, so the answer depends on "
             "the mesh and grows as it is refined; an obstacle under a "
             "clamped plate is negative at the edge, or rises from 0 there "
             "no faster than the square of the distance\n";
    print_solver_summary(out, lcp_problem, report);
    if (!coarse_levels.empty())
      {
        out << "  started from the solution on";
        for (const CoarseLevel &level : coarse_levels)
          out << (&level == &coarse_levels.front() ? " " : ", ") << level.n_x
              << " x " << level.n_y << " (" << level.iterations << " iterations"
              << (level.status == lcp::Status::converged ?
                    "" :
                    ", " + lcp::to_string(level.status))
              << ")";
        out << "\n";
      }
    out << "  contact nodes cn = " << plate_results.n_contact << "\n"
        << std::scientific << std::setprecision(6) << "  min nodal deflection "
        << plate_results.min_deflection << in(units.length)
        << ", centre deflection " << plate_results.centre_deflection
        << in(units.length) << std::endl;
    out.flags(flags);
    out.precision(precision);
  }

  void
  PlateScene::add_summary(JsonObject &summary) const
  {
    summary.set("n_elements", plate_results.n_elements)
      .set("n_free", plate_results.n_free)
      .set("n_bounds", plate_results.n_bounds)
      .set("n_contact", plate_results.n_contact)
      .set("min_deflection", plate_results.min_deflection)
      .set("centre_deflection", plate_results.centre_deflection)
      .set("units", parameters.units.name)
      .set("n1", parameters.geometry.n_x)
      .set("n2", parameters.geometry.n_y)
      .set("length_x", parameters.geometry.length_x)
      .set("length_y", parameters.geometry.length_y)
      .set("thickness", parameters.geometry.thickness)
      .set("lcp_force_unit", unit)
      .set("lcp_unknown_scale",
           std::vector<double>(component_scale.begin(), component_scale.end()))
      .set("boundary_condition",
           parameters.geometry.clamp_twist ? "fully clamped" : "clamped")
      .set("material", parameters.material.name)
      .set("youngs_modulus", parameters.material.youngs_modulus)
      .set("poisson_ratio", parameters.material.poisson_ratio)
      .set("flexural_rigidity", rigidity)
      .set("obstacle", parameters.obstacle.name)
      .set("obstacle_expression", parameters.obstacle.expression)
      .set("force", parameters.load.name)
      .set("force_expression", parameters.load.expression);
    // The coarse-mesh start, finest first: [] when the run had none.
    std::vector<JsonObject> levels;
    for (const CoarseLevel &level : coarse_levels)
      levels.emplace_back()
        .set("n1", level.n_x)
        .set("n2", level.n_y)
        .set("iterations", level.iterations)
        .set("status", lcp::to_string(level.status));
    summary.set("coarse_mesh_start", levels);
  }

  std::string
  PlateScene::failure_description(const lcp::Report &report) const
  {
    // Elements far from square scale the unknowns apart by their own
    // ratio, whatever the units.
    const Geometry    &g      = parameters.geometry;
    const double       h_x    = g.length_x / g.n_x;
    const double       h_y    = g.length_y / g.n_y;
    const double       aspect = std::max(h_x / h_y, h_y / h_x);
    std::ostringstream elongated;
    elongated << std::setprecision(3) << "the elements are " << aspect
              << " times longer than wide (" << h_x << " x " << h_y
              << "): choose 'Plate/Geometry/Elements x' and 'Elements y' so "
                 "that they are nearer square ("
              << report.message << ")";
    // A multigrid iterate gone NaN on such elements: their shape first.
    if (report.status == lcp::Status::singular && aspect > 100 &&
        report.message.find("NaN or infinite") != std::string::npos)
      return elongated.str();
    // Only a factorisation's verdict (PDAS's "... is singular for the
    // active set"), not a method's numerical breakdown, which the status
    // names alike.
    if (report.status != lcp::Status::singular ||
        report.message.find("is singular") == std::string::npos)
      return Scene::failure_description(report);
    const std::string judged =
      "a factorisation judged the plate's stiffness singular, but a clamped "
      "plate's is positive definite: its condition estimate (smallest to "
      "largest pivot) fell below 1e-14, most likely because ";
    if (aspect > 100)
      return judged + elongated.str();
    return judged +
           "the deflection, slope and twist unknowns differ in size by "
           "powers of the element size (the scene evens them out only where "
           "the elements are shorter than 0.01 or longer than 100 in the "
           "plate's units); give the lengths in units in which the elements "
           "are about 1 long, with the modulus and the load converted alike (" +
           report.message + ")";
  }

  UNILATERAL_REGISTER_SCENE(
    PlateScene,
    "a clamped Kirchhoff plate on an obstacle, Bogner-Fox-Schmit elements "
    "(Fernandes, Figueiredo & Judice 2002)")
} // namespace unilateral::plate
