#include <unilateral/base/input_error.h>
#include <unilateral/base/text.h>
#include <unilateral/scenes/masonry/assembly.h>
#include <unilateral/scenes/masonry/mesh.h>
#include <unilateral/scenes/masonry/tearing.h>

#include "scene_state.h"

#include <deal.II/base/parameter_handler.h>
#include <deal.II/fe/mapping.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <optional>
#include <ostream>

namespace unilateral::masonry
{
  void
  MasonryScene::declare_parameters(dealii::ParameterHandler &prm)
  {
    Parameters::declare_parameters(prm);
  }

  MasonryScene::MasonryScene(dealii::ParameterHandler &prm)
    : Scene(registered_name)
  {
    parameters.parse_parameters(prm);
  }

  MasonryScene::MasonryScene(const Parameters &parameters)
    : Scene(registered_name)
    , parameters(parameters)
  {}

  MasonryScene::MasonryScene(const Parameters &parameters, const Layout &layout)
    : Scene(registered_name)
    , parameters(parameters)
    , custom_layout(std::make_unique<Layout>(layout))
  {}

  MasonryScene::~MasonryScene() = default;

  const ContactSet &
  MasonryScene::contact_set() const
  {
    return state->contacts;
  }

  const ChangeOfVariables &
  MasonryScene::change_of_variables() const
  {
    return *state->change;
  }

  double
  MasonryScene::force_unit() const
  {
    return unit;
  }

  void
  MasonryScene::make_grid(RunContext &context)
  {
    state         = std::make_unique<State>(parameters.geometry.element);
    state->layout = custom_layout ? *custom_layout :
                                    make_layout(parameters.geometry.bond,
                                                parameters.geometry.m);
    validate(state->layout);
    state->class_of_block =
      parameters.materials.classes_of_blocks(state->layout);

    const double H = state->layout.course_height;
    const double h = H / std::pow(2.0, parameters.geometry.refinement);
    build_triangulation(state->layout,
                        h,
                        parameters.geometry.element,
                        state->discretisation.triangulation);

    problem_sizes = Sizes();
    problem_sizes.n_blocks =
      static_cast<unsigned int>(state->layout.blocks.size());
    problem_sizes.n_cells =
      state->discretisation.triangulation.n_active_cells();
    problem_sizes.block_height = H;
    problem_sizes.cell_size    = h;
    problem_sizes.gap          = parameters.boundary.relative_gap * H;
    context.stage(registered_name,
                  quantity(problem_sizes.n_blocks, "block") + ", " +
                    quantity(problem_sizes.n_cells, "cell"));
  }

  // Points closer than this are the same point: far above the round-off
  // in the coordinates, far below the node spacing h/2.
  double
  MasonryScene::coincidence_tolerance() const
  {
    return 1e-8 * problem_sizes.cell_size;
  }

  void
  MasonryScene::setup_system(RunContext &context)
  {
    {
      Discretisation &discretisation = state->discretisation;
      discretisation.dof_handler.reinit(discretisation.triangulation);
      discretisation.dof_handler.distribute_dofs(*discretisation.fe);
      problem_sizes.n_dofs = discretisation.dof_handler.n_dofs();
    }
    context.stage(registered_name,
                  std::to_string(problem_sizes.n_dofs) +
                    " DOFs; detecting contacts");
    {
      state->contacts = detect_contacts(state->discretisation.dof_handler,
                                        parameters.boundary.signorini_fraction,
                                        problem_sizes.gap,
                                        coincidence_tolerance());
    }
    {
      const ContactSet &contacts = state->contacts;
      // Only cycles among constrained DOFs can fail, so the constraint list
      // names every DOF an error message needs.
      auto describe = [&contacts](const DofIndex dof) {
        for (std::size_t k = 0; k < contacts.constraints.size(); ++k)
          if (contacts.constraints[k].lower == dof ||
              (contacts.constraints[k].kind != ConstraintKind::signorini &&
               contacts.constraints[k].upper == dof))
            return "the node at " +
                   describe_point(contacts.position[k][0],
                                  contacts.position[k][1],
                                  contacts.constraints[k].lower == dof ?
                                    contacts.blocks[k][0] :
                                    contacts.blocks[k][1]);
        return "DOF " + std::to_string(dof);
      };
      state->change = std::make_unique<ChangeOfVariables>(problem_sizes.n_dofs,
                                                          contacts.dirichlet,
                                                          contacts.constraints,
                                                          describe);
    }
    const ContactSet &contacts         = state->contacts;
    problem_sizes.n_dirichlet          = contacts.n_dirichlet;
    problem_sizes.n_unknowns           = state->change->n_unknowns();
    problem_sizes.n_constraints        = state->change->n_constraints();
    problem_sizes.n_signorini          = contacts.n_signorini;
    problem_sizes.n_horizontal_joint   = contacts.n_horizontal_joint;
    problem_sizes.n_vertical_joint     = contacts.n_vertical_joint;
    problem_sizes.max_expansion_length = state->change->max_expansion_length();
    context.stage(registered_name,
                  "n = " + std::to_string(problem_sizes.n_unknowns) +
                    " unknowns, n_c = " +
                    std::to_string(problem_sizes.n_constraints) +
                    " constraints");
  }

  void
  MasonryScene::assemble_system(RunContext &context)
  {
    context.stage(registered_name, "assembling A~ and b~ in the gap variables");
    LoadData loads;
    loads.classes        = parameters.materials.classes;
    loads.class_of_block = state->class_of_block;
    loads.gravity        = parameters.boundary.gravity;
    loads.top_traction   = parameters.boundary.top_traction;
    loads.y_top          = state->layout.bounding_box().y1;
    loads.tolerance      = coincidence_tolerance();
    lcp_problem          = assemble_lcp(state->discretisation,
                               *state->change,
                               state->contacts,
                               loads);
    // Blocks are free to move unless contacts hold them, and a wall is in
    // contact almost everywhere: the solvers' automatic settings for both.
    // A~ = C~^-T A C~^-1 is a congruence of the semidefinite stiffness.
    lcp_problem.floating_bodies    = true;
    lcp_problem.mostly_active      = true;
    lcp_problem.known_semidefinite = true;

    // The solvers' force unit (see force_unit()): their tolerances and
    // parameters (PDAS's tau weighs a displacement against a force, the
    // interior-point methods' tolerances and starting points are absolute)
    // then see the same numbers whatever unit the parameter file uses. A
    // change of units must not change the answer.
    double largest_modulus = 0;
    for (const MaterialClass &material : parameters.materials.classes)
      largest_modulus = std::max(largest_modulus, material.youngs_modulus);
    unit = largest_modulus / 4e3;
    if (unit != 1 && unit > 0)
      {
        lcp_problem.A /= unit;
        lcp_problem.b /= unit;
      }
    else
      unit = 1;

    // The wall torn into its blocks, for a method that works on them.
    if (lcp::SolverRegistry::get(context.solver.method).needs_tearing)
      lcp_problem.tearing = tear_into_blocks(state->discretisation,
                                             state->contacts,
                                             *state->change,
                                             loads,
                                             problem_sizes.n_blocks,
                                             unit,
                                             coincidence_tolerance());
  }

  // u = C~^-1 u~, and for every constraint its normal gap (the gap variable,
  // or u_y + g on Gamma_S), its force lambda and whether it is active.
  void
  MasonryScene::postprocess(const RunContext &, lcp::Report &report)
  {
    report.energy *= unit;
    report.regularisation *= unit;
    const lcp::Solution &solution = lcp_solution;
    state->displacement = state->change->to_physical(solution.u.data());

    std::vector<char> active(lcp_problem.size(), 0);
    for (const lcp::Index i : solution.active_set)
      active[i] = 1;
    const ContactSet &contacts = state->contacts;
    constraints.resize(contacts.constraints.size());
    n_closed_contacts = 0;
    for (std::size_t k = 0; k < contacts.constraints.size(); ++k)
      {
        const int v    = state->change->variable_of_constraint(k);
        constraints[k] = {contacts.constraints[k].kind,
                          contacts.position[k],
                          contacts.blocks[k],
                          solution.u[v] - contacts.constraints[k].bound,
                          solution.lambda[v] * unit,
                          active[v] != 0};
        n_closed_contacts += active[v];
      }

    // Largest nodal displacement: pair the two components of each node.
    const dealii::DoFHandler<2> &dof_handler =
      state->discretisation.dof_handler;
    const dealii::FiniteElement<2> &fe  = dof_handler.get_fe();
    const unsigned int n_nodes_per_cell = fe.base_element(0).n_dofs_per_cell();
    std::vector<dealii::types::global_dof_index> dofs(fe.n_dofs_per_cell());
    double                                       largest = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        for (unsigned int k = 0; k < n_nodes_per_cell; ++k)
          largest = std::max(
            largest,
            std::hypot(
              state->displacement[dofs[fe.component_to_system_index(0, k)]],
              state->displacement[dofs[fe.component_to_system_index(1, k)]]));
      }
    max_displacement = largest;

    // Degenerate contacts: closed (zero gap) and carrying no force, both to
    // round-off. Where such contacts alone hold a block (a brick balanced on
    // one node), the LCP has other solutions with the same energy and
    // forces but other displacements, and which one a method returns is
    // decided by its path (two exact answers of one running bond wall:
    // README.md, "The masonry scene"). Counted so that the summary can say
    // so.
    double largest_force = 0;
    for (const ConstraintResult &c : constraints)
      largest_force = std::max(largest_force, std::abs(c.contact_force));
    n_degenerate_contacts = 0;
    for (const ConstraintResult &c : constraints)
      n_degenerate_contacts +=
        std::abs(c.normal_gap) <= 1e-10 * max_displacement &&
        std::abs(c.contact_force) <= 1e-10 * largest_force;
  }

  std::vector<NodalDisplacement>
  MasonryScene::nodal_displacements() const
  {
    const dealii::DoFHandler<2> &dof_handler =
      state->discretisation.dof_handler;
    const dealii::FiniteElement<2> &fe      = dof_handler.get_fe();
    const dealii::Mapping<2>       &mapping = *state->discretisation.mapping;
    const auto &unit_points = fe.base_element(0).get_unit_support_points();
    const unsigned int n_nodes_per_cell = unit_points.size();
    std::vector<dealii::types::global_dof_index> dofs(fe.n_dofs_per_cell());
    std::vector<char>                            seen(dof_handler.n_dofs(), 0);
    std::vector<NodalDisplacement>               result;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        for (unsigned int k = 0; k < n_nodes_per_cell; ++k)
          {
            const auto dof_x = dofs[fe.component_to_system_index(0, k)];
            const auto dof_y = dofs[fe.component_to_system_index(1, k)];
            if (seen[dof_x])
              continue;
            seen[dof_x] = 1;
            const dealii::Point<2> p =
              mapping.transform_unit_to_real_cell(cell, unit_points[k]);
            result.push_back(
              {{{p[0], p[1]}},
               cell->material_id(),
               {{state->displacement[dof_x], state->displacement[dof_y]}}});
          }
      }
    return result;
  }

  void
  MasonryScene::print_summary(std::ostream      &out,
                              const lcp::Report &report) const
  {
    const auto   flags     = out.flags();
    const auto   precision = out.precision();
    const Sizes &s         = problem_sizes;
    out << "  masonry: " << state->layout.name
        << ", m = " << parameters.geometry.m << " (H = " << s.block_height
        << "), " << quantity(s.n_blocks, "block") << ", "
        << to_string(parameters.geometry.element) << " on "
        << quantity(s.n_cells, "cell") << " (refinement "
        << parameters.geometry.refinement << ", h = " << s.cell_size << ")\n"
        << "  supports: " << quantity(s.n_dirichlet, "Dirichlet DOF") << ", "
        << quantity(s.n_signorini, "Signorini node")
        << " with gap g = " << s.gap << "; joints: " << s.n_horizontal_joint
        << " horizontal + "
        << quantity(s.n_vertical_joint, "vertical node pair") << "\n";
    print_solver_summary(out, lcp_problem, report);
    out << std::scientific << std::setprecision(6) << "  max displacement "
        << max_displacement << ", " << n_closed_contacts << " of "
        << quantity(s.n_constraints, "contact") << " closed\n";
    if (n_degenerate_contacts > 0)
      out << "  " << quantity(n_degenerate_contacts, "closed contact")
          << (n_degenerate_contacts == 1 ? " carries" : " carry")
          << " no force (degenerate): where such "
             "contacts alone hold a block, other displacements with the same "
             "energy and contact forces solve the problem too\n";
    out.flags(flags);
    out.precision(precision);
  }

  void
  MasonryScene::add_summary(JsonObject &summary) const
  {
    const Sizes &s = problem_sizes;
    summary.set("geometry", state->layout.name)
      .set("m", parameters.geometry.m)
      .set("n_blocks", s.n_blocks)
      .set("refinement", parameters.geometry.refinement)
      .set("element", to_string(parameters.geometry.element))
      .set("block_height", s.block_height)
      .set("cell_size", s.cell_size)
      .set("gap", s.gap)
      .set("relative_gap", parameters.boundary.relative_gap)
      .set("n_cells", s.n_cells)
      .set("n_dofs", s.n_dofs)
      .set("n_dirichlet", s.n_dirichlet)
      .set("n_signorini", s.n_signorini)
      .set("n_horizontal_joint", s.n_horizontal_joint)
      .set("n_vertical_joint", s.n_vertical_joint)
      .set("max_displacement", max_displacement)
      .set("n_closed_contacts", n_closed_contacts)
      .set("n_degenerate_contacts", n_degenerate_contacts);
  }

  std::string
  MasonryScene::failure_description(const lcp::Report &report) const
  {
    if (report.status == lcp::Status::infeasible)
      return "the wall has no equilibrium: its supports and joints cannot "
             "carry the loads (" +
             report.message + ")";
    if (report.status == lcp::Status::singular)
      return "the solver found no configuration in which every block is "
             "held by a support or a closed joint: the wall has no "
             "equilibrium, or a block can move freely (" +
             report.message + ")";
    return Scene::failure_description(report);
  }

  bool
  MasonryScene::large(const std::string &) const
  {
    return parameters.geometry.m * (1L << parameters.geometry.refinement) >=
           100;
  }

  std::string
  MasonryScene::size_parameters() const
  {
    return "'Masonry/Blocks per side' = " +
           std::to_string(parameters.geometry.m) +
           " or 'Masonry/Refinement' = " +
           std::to_string(parameters.geometry.refinement);
  }

  UNILATERAL_REGISTER_SCENE(
    MasonryScene,
    "a wall of elastic blocks in frictionless contact (Ainsworth & Mihai "
    "2006): stack bond, running bond or laminae")
} // namespace unilateral::masonry
