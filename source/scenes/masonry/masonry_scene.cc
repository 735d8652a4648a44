#include <unilateral/base/input_error.h>
#include <unilateral/base/text.h>
#include <unilateral/scenes/lcp_scene.h>
#include <unilateral/scenes/masonry/assembly.h>
#include <unilateral/scenes/masonry/free_motions.h>
#include <unilateral/scenes/masonry/mechanism.h>
#include <unilateral/scenes/masonry/mesh.h>
#include <unilateral/scenes/masonry/mesh_file.h>
#include <unilateral/scenes/masonry/tearing.h>

#include "scene_state.h"

#include <deal.II/base/parameter_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <ostream>
#include <regex>
#include <sstream>

namespace unilateral::masonry
{
  namespace
  {
    // Why the support @p description ("'Signorini' = 'base where x < s'")
    // acts on no node. 'Signorini part of the base' = 0 or 1 puts s at the
    // left or right end of the structure, and the built-in supports' region
    // 'x < s' or 'x > s' (or 's > x', 's < x') is then empty by the user's
    // own choice, not mistyped. Any other region (x > s + 1, x < s && y > 1)
    // is judged as written.
    std::string
    why_acting_nowhere(const std::string &description,
                       const double       signorini_fraction)
    {
      static const std::regex left_of_s(
        R"(where\s*(x\s*<\s*s|s\s*>\s*x)\s*'$)");
      static const std::regex right_of_s(
        R"(where\s*(x\s*>\s*s|s\s*<\s*x)\s*'$)");
      if (signorini_fraction == 0 && std::regex_search(description, left_of_s))
        return " (as 'Signorini part of the base' = 0 puts s at the "
               "structure's left end)";
      if (signorini_fraction == 1 && std::regex_search(description, right_of_s))
        return " (as 'Signorini part of the base' = 1 puts s at the "
               "structure's right end)";
      return " (its region holds no node of that boundary)";
    }
  } // namespace

  template <int dim>
  void
  MasonryScene<dim>::declare_parameters(dealii::ParameterHandler &prm)
  {
    Parameters::declare_parameters(prm);
  }

  template <int dim>
  MasonryScene<dim>::MasonryScene(const Parameters &parameters)
    : Scene(registered_name)
    , parameters(parameters)
  {}

  template <int dim>
  MasonryScene<dim>::MasonryScene(const Parameters &parameters,
                                  const Layout     &layout)
    : Scene(registered_name)
    , parameters(parameters)
    , custom_layout(std::make_unique<Layout>(layout))
  {}

  template <int dim>
  MasonryScene<dim>::~MasonryScene() = default;

  template <int dim>
  const ContactSet<dim> &
  MasonryScene<dim>::contact_set() const
  {
    return state->contacts;
  }

  template <int dim>
  const ChangeOfVariables<dim> &
  MasonryScene<dim>::change_of_variables() const
  {
    return *state->change;
  }

  template <int dim>
  double
  MasonryScene<dim>::force_unit() const
  {
    return unit;
  }

  template <int dim>
  std::string
  MasonryScene<dim>::structure_name() const
  {
    return state->mesh_file.empty() ? state->layout.name : state->mesh_file;
  }

  namespace
  {
    /// The class of each block of a mesh file, from its physical tag.
    std::vector<unsigned int>
    classes_of_tags(const MaterialParameters &materials,
                    const MeshFileBlocks     &blocks,
                    const std::string        &file)
    {
      std::vector<unsigned int> result(blocks.tag_of_block.size(), 0);
      if (materials.assignment != MaterialAssignment::physical_tag)
        return result;
      for (std::size_t b = 0; b < result.size(); ++b)
        {
          const auto &tags = materials.tags;
          auto        found =
            std::find(tags.begin(), tags.end(), blocks.tag_of_block[b]);
          if (found == tags.end())
            found = std::find(tags.begin(),
                              tags.end(),
                              std::to_string(blocks.tag_number_of_block[b]));
          if (found == tags.end())
            {
              std::string known;
              for (const std::string &tag : tags)
                known += (known.empty() ? "" : ", ") + tag;
              throw InputError(
                "block " + std::to_string(b) + " of '" + file +
                "' has the physical tag '" + blocks.tag_of_block[b] + "'" +
                (blocks.tag_of_block[b] ==
                     std::to_string(blocks.tag_number_of_block[b]) ?
                   "" :
                   " (number " + std::to_string(blocks.tag_number_of_block[b]) +
                     ")") +
                ", which no material class has ('Masonry/Materials/Tags' = " +
                known + "): add it to 'Tags' with its class");
            }
          result[b] = static_cast<unsigned int>(found - tags.begin());
        }
      return result;
    }

    /// Whether the point @p x lies in the bounding box (x_min, x_max).
    template <int dim>
    double
    extent(const dealii::Triangulation<dim> &triangulation,
           const unsigned int                axis,
           const bool                        upper)
    {
      double value = upper ? -std::numeric_limits<double>::max() :
                             std::numeric_limits<double>::max();
      for (const auto &vertex : triangulation.get_vertices())
        value =
          upper ? std::max(value, vertex[axis]) : std::min(value, vertex[axis]);
      return value;
    }
  } // namespace

  template <int dim>
  void
  MasonryScene<dim>::make_grid(RunContext &context)
  {
    const GeometryParameters &geometry = parameters.geometry;
    problem_sizes                      = Sizes();
    ExpressionConstants constants;
    if (geometry.from_mesh_file)
      {
        const std::string path =
          resolve_relative_to(context.parameter_file, geometry.mesh_file);
        dealii::Triangulation<dim> mesh;
        const MeshFileBlocks       blocks = read_mesh_file<dim>(path, mesh);
        mesh.refine_global(geometry.refinement);
        state = std::make_unique<State>(blocks.simplex ? ElementType::p2 :
                                                         ElementType::q2);
        state->discretisation.triangulation.copy_triangulation(mesh);
        state->mesh_file  = std::filesystem::path(path).filename().string();
        state->boundaries = blocks.boundaries;
        state->class_of_block =
          classes_of_tags(parameters.materials, blocks, state->mesh_file);
        problem_sizes.n_blocks =
          static_cast<unsigned int>(blocks.tag_of_block.size());
        problem_sizes.block_height = 1;
      }
    else
      {
        state         = std::make_unique<State>(geometry.element);
        state->layout = custom_layout ? *custom_layout :
                                        make_layout(geometry.bond, geometry.m);
        validate(state->layout);
        const std::vector<unsigned int> classes =
          parameters.materials.classes_of_blocks(state->layout);
        const unsigned int layers =
          dim == 3 ? geometry.blocks_through_thickness : 1;
        for (const unsigned int c : classes)
          state->class_of_block.insert(state->class_of_block.end(), layers, c);
        const double H = state->layout.course_height;
        const double h = H / std::pow(2.0, geometry.refinement);
        build_triangulation<dim>(state->layout,
                                 h,
                                 geometry.element,
                                 geometry.blocks_through_thickness,
                                 geometry.thickness * H,
                                 state->discretisation.triangulation,
                                 mesh_coarsening);
        state->boundaries =
          wall_boundary_names<dim>(state->discretisation.triangulation);
        problem_sizes.n_blocks =
          static_cast<unsigned int>(state->layout.blocks.size()) * layers;
        problem_sizes.block_height = H;
        problem_sizes.cell_size    = h;
      }
    const dealii::Triangulation<dim> &triangulation =
      state->discretisation.triangulation;
    problem_sizes.smallest_cell_extent = std::numeric_limits<double>::max();
    for (const auto &cell : triangulation.active_cell_iterators())
      problem_sizes.smallest_cell_extent =
        std::min(problem_sizes.smallest_cell_extent,
                 cell->minimum_vertex_distance());
    // A mesh file has no h of its own: its smallest cell stands for it.
    if (geometry.from_mesh_file)
      problem_sizes.cell_size = problem_sizes.smallest_cell_extent;
    problem_sizes.n_cells = triangulation.n_active_cells();
    problem_sizes.gap =
      parameters.boundary.relative_gap * problem_sizes.block_height;
    constants.H     = problem_sizes.block_height;
    constants.g     = problem_sizes.gap;
    const double x0 = extent(triangulation, 0, false);
    const double x1 = extent(triangulation, 0, true);
    // Exactly x1 at 1 (x0 + (x1 - x0) may round below it, and 'x > s' would
    // then hold the right end's nodes).
    constants.s = parameters.boundary.signorini_fraction == 1 ?
                    x1 :
                    x0 + parameters.boundary.signorini_fraction * (x1 - x0);
    state->supports =
      make_supports<dim>(parameters.boundary, state->boundaries, constants);
    state->loads.classes        = parameters.materials.classes;
    state->loads.class_of_block = state->class_of_block;
    state->loads.supports       = &state->supports;
    context.stage(registered_name,
                  quantity(problem_sizes.n_blocks, "block") + ", " +
                    quantity(problem_sizes.n_cells, "cell"));
  }

  template <int dim>
  void
  MasonryScene<dim>::setup_system(RunContext &context)
  {
    {
      Discretisation<dim> &discretisation = state->discretisation;
      discretisation.dof_handler.reinit(discretisation.triangulation);
      discretisation.dof_handler.distribute_dofs(*discretisation.fe);
      problem_sizes.n_dofs = discretisation.dof_handler.n_dofs();
    }
    // Less than the walls' peak per DOF, so that the peak does not grow
    // (measured where the touch reaches its 1 GB minimum, m >= 167 at
    // r = 0; the rate: benchmarks/masonry_tables/README.md, "Pages faulted
    // in on the idle core").
    constexpr double pretouched_bytes_per_dof = 2000;
    pretouch(pretouched_bytes_per_dof * problem_sizes.n_dofs);
    context.stage(registered_name,
                  std::to_string(problem_sizes.n_dofs) +
                    " DOFs; detecting contacts");
    state->contacts =
      detect_contacts<dim>(state->discretisation.dof_handler,
                           *state->discretisation.mapping,
                           state->supports,
                           parameters.geometry.coincidence_tolerance *
                             problem_sizes.smallest_cell_extent,
                           problem_sizes.smallest_cell_extent);
    const ContactSet<dim> &contacts = state->contacts;
    if (context.out != nullptr)
      for (const std::string &support : contacts.supports_acting_nowhere)
        *context.out
          << "  " << registered_name << ": note: " << support
          << " acts on no node"
          << why_acting_nowhere(support, parameters.boundary.signorini_fraction)
          << std::endl;
    if (context.out != nullptr)
      for (const std::string &line : contacts.nearly_touching)
        *context.out << "  " << registered_name << ": note: " << line
                     << std::endl;
    state->change = std::make_unique<ChangeOfVariables<dim>>(
      problem_sizes.n_dofs,
      contacts.node_dofs,
      contacts.held,
      contacts.rollers,
      contacts.constraints,
      [&contacts](const unsigned int node) {
        return contacts.describe_node(node);
      });
    problem_sizes.n_dirichlet          = contacts.n_eliminated();
    problem_sizes.n_unknowns           = state->change->n_unknowns();
    problem_sizes.n_constraints        = state->change->n_constraints();
    problem_sizes.n_signorini          = contacts.n_signorini;
    problem_sizes.n_horizontal_joint   = contacts.n_horizontal_joint;
    problem_sizes.n_vertical_joint     = contacts.n_vertical_joint;
    problem_sizes.n_inclined_joint     = contacts.n_inclined_joint;
    problem_sizes.max_expansion_length = state->change->max_expansion_length();
    context.stage(registered_name,
                  "n = " + std::to_string(problem_sizes.n_unknowns) +
                    " unknowns, n_c = " +
                    std::to_string(problem_sizes.n_constraints) +
                    " constraints");
    free_motions = free_rigid_motions(contacts, held_by_signorini);
    slides       = free_slides(contacts);
    for (const std::string &line : free_motions)
      context.stage(registered_name, "note: " + line);
  }

  template <int dim>
  void
  MasonryScene<dim>::assemble_system(RunContext &context)
  {
    context.stage(registered_name, "assembling A~ and b~ in the gap variables");
    lcp_problem = assemble_lcp<dim>(state->discretisation,
                                    *state->change,
                                    state->contacts,
                                    state->loads,
                                    energy_offset,
                                    energy_offset_rounding);
    // The LCP's own check would name an entry of b, which tells the user
    // nothing: name what b is made of.
    if (!lcp_problem.b.allFinite() || !lcp_problem.A.coeffs().allFinite())
      throw InputError(
        "the loads or the stiffness are not finite numbers: check "
        "'Traction', 'Prescribed displacement', 'Gravity', 'Density' and "
        "'Young's modulus' (an expression such as 1/0 or sqrt(-1), or "
        "values beyond double precision such as a modulus of 1e-310)");
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
        lcp_problem.energy_unit = unit;
      }
    else
      unit = 1;

    // The wall torn into its blocks, for a method that works on them.
    if (lcp::SolverRegistry::get(context.solver.method).needs_tearing)
      {
        unsigned int n_cut = 0;
        lcp_problem.tearing =
          tear_into_blocks<dim>(state->discretisation,
                                state->contacts,
                                *state->change,
                                state->loads,
                                problem_sizes.n_blocks,
                                parameters.tearing.largest_aspect_ratio,
                                unit,
                                parameters.geometry.coincidence_tolerance *
                                  problem_sizes.smallest_cell_extent,
                                n_cut);
        if (n_cut > 0)
          context.stage(registered_name,
                        quantity(n_cut, "long block") +
                          " cut into pieces ('Tearing/Largest aspect "
                          "ratio'): " +
                          quantity(lcp_problem.tearing->n_subdomains(),
                                   "subdomain"));
      }
  }

  template <int dim>
  std::string
  MasonryScene<dim>::proof_of_no_solution()
  {
    // The loads cost an assembly of the residual: only where something
    // moves freely, or Signorini supports, which only push, hold it.
    if (free_motions.empty() && slides.empty() && !held_by_signorini)
      return "";
    std::vector<double> load = residual_forces<dim>(
      state->discretisation,
      state->loads,
      std::vector<double>(state->contacts.node_of_dof.size(), 0.0));
    for (double &f : load)
      f = -f;
    driven_motion =
      loads_driving_a_free_motion<dim>(state->contacts, slides, load);
    return driven_motion;
  }

  // u = C~^-1 u~, and for every constraint its normal gap (the gap variable,
  // or n . u + gap on a support), its force lambda and whether it is active.
  template <int dim>
  void
  MasonryScene<dim>::postprocess(const RunContext &context, lcp::Report &report)
  {
    report.energy += energy_offset;
    report.regularisation *= unit;
    const lcp::Solution &solution = lcp_solution;
    state->displacement = state->change->to_physical(solution.u.data());

    std::vector<char> active(lcp_problem.size(), 0);
    for (const lcp::Index i : solution.active_set)
      active[i] = 1;
    const ContactSet<dim> &contacts = state->contacts;
    constraints.resize(contacts.constraints.size());
    n_closed_contacts = 0;
    for (std::size_t k = 0; k < contacts.constraints.size(); ++k)
      {
        const int v    = state->change->variable_of_constraint(k);
        constraints[k] = {contacts.constraints[k].kind,
                          contacts.position[k],
                          contacts.blocks[k],
                          contacts.constraints[k].normal,
                          solution.u[v] - contacts.constraints[k].bound,
                          solution.lambda[v] * unit,
                          active[v] != 0};
        n_closed_contacts += active[v];
      }

    double largest = 0;
    for (const auto &dofs : contacts.node_dofs)
      {
        std::array<double, dim> u;
        for (unsigned int d = 0; d < dim; ++d)
          u[d] = state->displacement[dofs[d]];
        largest = std::max(largest,
                           dim == 2 ? std::hypot(u[0], u[1]) :
                                      std::hypot(u[0], u[1], u[dim - 1]));
      }
    max_displacement = largest;

    // Degenerate contacts: closed (zero gap) and carrying no force, both to
    // round-off. Where such contacts alone hold a block (a brick balanced on
    // one node), the LCP has other solutions with the same energy and
    // forces but other displacements, and which one a method returns is
    // decided by its path (two exact answers of one running bond wall:
    // README.md, "The masonry scene"). Counted so that the summary can say
    // so. "No force" against the loads as well: where every contact force
    // is round-off (a block on rollers in a slot), the largest of them
    // alone made none degenerate (a review).
    double largest_force =
      unit * lcp_problem.b.template lpNorm<Eigen::Infinity>();
    for (const ConstraintResult<dim> &c : constraints)
      largest_force = std::max(largest_force, std::abs(c.contact_force));
    n_degenerate_contacts = 0;
    // Not of the zero displacement given where nothing was solved.
    for (const ConstraintResult<dim> &c : constraints)
      n_degenerate_contacts +=
        !proved_before_solving(report) &&
        std::abs(c.normal_gap) <= 1e-10 * max_displacement &&
        std::abs(c.contact_force) <= 1e-10 * largest_force;

    // Displacements that only a motion of blocks against each other along
    // closed joints leaves open; a motion of a group no support holds is
    // noted already (free_motions).
    mechanism.clear();
    if (report.converged())
      {
        std::vector<char> closed(constraints.size());
        for (std::size_t k = 0; k < constraints.size(); ++k)
          closed[k] = constraints[k].active;
        mechanism = answer_mechanism(contacts, closed, !free_motions.empty());
      }
    // Also where the run did not converge: the loads are then still the
    // loads, and the imbalance says how far the answer given is from
    // equilibrium (summary.json once said load 0 and imbalance 0, which
    // read as balanced; a review).
    compute_statics();
    if (report.converged())
      check_statics(context.solver.kkt_tolerance, report);
  }

  /**
   * With prescribed displacements, the energy's share from them must be
   * resolved, and the answer's reactions must balance the loads, to the
   * KKT tolerance (relative to the total load). The LCP's own checks
   * cannot see what was lost before it: prescribed displacements far
   * larger than the elastic ones enter its right-hand side as f - K c,
   * whose cancellation double precision does not resolve (measured:
   * benchmarks/stress/README.md, "Input checks of 2026-11-27").
   */
  template <int dim>
  void
  MasonryScene<dim>::check_statics(const double kkt_tolerance,
                                   lcp::Report &report) const
  {
    double loads = 0;
    for (const double component : balance.load)
      loads = std::max(loads, std::abs(component));
    const double imbalance =
      std::max(balance.force_imbalance, balance.moment_imbalance);
    std::ostringstream message;
    message << std::setprecision(3);
    // The energy's part from the prescribed displacements,
    // 1/2 c^T K c - f^T c, cancels to far below its terms there.
    if (report.energy != 0 &&
        energy_offset_rounding > kkt_tolerance * std::abs(report.energy))
      message << "the energy is resolved only to "
              << energy_offset_rounding / std::abs(report.energy)
              << " of its size (> 'Solver/KKT tolerance' = " << kkt_tolerance
              << "): the prescribed displacements are many orders larger "
                 "than the elastic ones, and their share of it cancels in "
                 "double precision";
    // Only with prescribed displacements: without them b = f has no
    // cancellation, the LCP's checks already judged the answer, and the
    // statics, summed from K u - f of large rigid motions, carry a
    // rounding of their own, above the tolerance on exact answers of
    // settled walls (the README named above).
    else if (state->change->has_offsets() && loads > 0 &&
             imbalance > kkt_tolerance)
      message << "the supports' reactions balance the loads only to "
              << imbalance << " of the total load (> 'Solver/KKT tolerance' = "
              << kkt_tolerance
              << "), although the LCP's residuals pass: its data lost that "
                 "accuracy before it was solved, where displacements "
                 "(prescribed ones, or settlements) are many orders larger "
                 "than the elastic ones";
    else
      return;
    message << "; prescribe smaller displacements, or give lengths, loads "
               "and stiffness in units closer to each other";
    report.status  = lcp::Status::inaccurate;
    report.message = report.message.empty() ?
                       message.str() :
                       message.str() + "; " + report.message;
  }

  /**
   * The supports' reactions from the solution: a Signorini support's from
   * its multipliers (lambda n), a held node's and a roller's from the
   * residual K u - f at the node less the forces of the constraints there
   * (a roller's projected on its normal). Their sum balances the loads
   * only if the answer is in equilibrium: at every free DOF K u - f = 0, at
   * every joint the residuals of the two nodes are the multiplier's
   * +-lambda n, and at a roller the residual is normal to it.
   */
  template <int dim>
  void
  MasonryScene<dim>::compute_statics()
  {
    const ContactSet<dim>     &contacts = state->contacts;
    const std::vector<double> &u        = state->displacement;
    std::vector<double>        residual =
      residual_forces<dim>(state->discretisation, state->loads, u);
    balance = Statics<dim>();

    // The loads: -residual at zero displacement (body force, tractions).
    const std::vector<double> load =
      residual_forces<dim>(state->discretisation,
                           state->loads,
                           std::vector<double>(u.size(), 0.0));
    auto moment = [](const std::array<double, dim> &x,
                     const std::array<double, dim> &f) {
      if constexpr (dim == 2)
        return std::array<double, 3>{{0, 0, x[0] * f[1] - x[1] * f[0]}};
      else
        return std::array<double, 3>{{x[1] * f[2] - x[2] * f[1],
                                      x[2] * f[0] - x[0] * f[2],
                                      x[0] * f[1] - x[1] * f[0]}};
    };
    auto add = [&](std::array<double, dim>       &force,
                   std::array<double, 3>         &torque,
                   const std::array<double, dim> &x,
                   const std::array<double, dim> &f) {
      const auto m = moment(x, f);
      for (unsigned int d = 0; d < dim; ++d)
        force[d] += f[d];
      for (unsigned int d = 0; d < 3; ++d)
        torque[d] += m[d];
    };
    double size = 0;
    for (std::size_t a = 0; a < contacts.node_dofs.size(); ++a)
      {
        std::array<double, dim> f;
        for (unsigned int d = 0; d < dim; ++d)
          f[d] = -load[contacts.node_dofs[a][d]];
        add(balance.load, balance.load_moment, contacts.node_position[a], f);
        for (unsigned int d = 0; d < dim; ++d)
          size = std::max(size, std::abs(contacts.node_position[a][d]));
      }

    // Remove the constraints' forces from the residual at their nodes.
    balance.support = contacts.support_names;
    balance.reaction.assign(balance.support.size(), {});
    balance.reaction_moment.assign(balance.support.size(), {});
    balance.roller_force.assign(contacts.rollers.size(), 0.0);
    for (std::size_t k = 0; k < constraints.size(); ++k)
      {
        const auto             &c     = contacts.constraints[k];
        const auto             &n     = c.normal;
        const double            force = constraints[k].contact_force;
        std::array<double, dim> f;
        for (unsigned int d = 0; d < dim; ++d)
          f[d] = force * n[d];
        if (c.kind == ConstraintKind::signorini)
          {
            const unsigned int s = contacts.signorini_support[k];
            add(balance.reaction[s],
                balance.reaction_moment[s],
                contacts.node_position[c.lower],
                f);
            for (unsigned int d = 0; d < dim; ++d)
              residual[contacts.node_dofs[c.lower][d]] -= f[d];
          }
        else
          for (unsigned int d = 0; d < dim; ++d)
            {
              residual[contacts.node_dofs[c.upper][d]] -= f[d];
              residual[contacts.node_dofs[c.lower][d]] += f[d];
            }
      }
    for (std::size_t h = 0; h < contacts.held.size(); ++h)
      {
        const unsigned int      node = contacts.held[h].node;
        std::array<double, dim> f;
        for (unsigned int d = 0; d < dim; ++d)
          f[d] = residual[contacts.node_dofs[node][d]];
        add(balance.reaction[contacts.held_support[h]],
            balance.reaction_moment[contacts.held_support[h]],
            contacts.node_position[node],
            f);
      }
    // Rollers: the residual at a node resolved along its rollers' normals
    // (least squares; exact if it lies in their span, as it does at
    // equilibrium).
    for (std::size_t r = 0; r < contacts.rollers.size();)
      {
        const unsigned int node = contacts.rollers[r].node;
        std::size_t        end  = r;
        while (end < contacts.rollers.size() &&
               contacts.rollers[end].node == node)
          ++end;
        const unsigned int n_rollers = static_cast<unsigned int>(end - r);
        dealii::FullMatrix<double> gram(n_rollers, n_rollers);
        dealii::Vector<double>     rhs(n_rollers), coefficient(n_rollers);
        for (unsigned int i = 0; i < n_rollers; ++i)
          {
            const auto &ni = contacts.rollers[r + i].normal;
            for (unsigned int d = 0; d < dim; ++d)
              rhs[i] += ni[d] * residual[contacts.node_dofs[node][d]];
            for (unsigned int j = 0; j < n_rollers; ++j)
              for (unsigned int d = 0; d < dim; ++d)
                gram(i, j) += ni[d] * contacts.rollers[r + j].normal[d];
          }
        gram.gauss_jordan();
        gram.vmult(coefficient, rhs);
        for (unsigned int i = 0; i < n_rollers; ++i)
          {
            balance.roller_force[r + i] = coefficient[i];
            std::array<double, dim> f;
            for (unsigned int d = 0; d < dim; ++d)
              f[d] = coefficient[i] * contacts.rollers[r + i].normal[d];
            add(balance.reaction[contacts.roller_support[r + i]],
                balance.reaction_moment[contacts.roller_support[r + i]],
                contacts.node_position[node],
                f);
          }
        r = end;
      }

    std::array<double, dim> force  = balance.load;
    std::array<double, 3>   torque = balance.load_moment;
    for (std::size_t s = 0; s < balance.support.size(); ++s)
      {
        for (unsigned int d = 0; d < dim; ++d)
          force[d] += balance.reaction[s][d];
        for (unsigned int d = 0; d < 3; ++d)
          torque[d] += balance.reaction_moment[s][d];
      }
    auto norm = [](const auto &v) {
      double sum = 0;
      for (const double x : v)
        sum += x * x;
      return std::sqrt(sum);
    };
    const double loads      = norm(balance.load);
    balance.force_imbalance = loads > 0 ? norm(force) / loads : norm(force);
    balance.moment_imbalance =
      loads > 0 ? norm(torque) / (loads * std::max(size, 1e-300)) :
                  norm(torque);
  }

  template <int dim>
  std::vector<NodalDisplacement<dim>>
  MasonryScene<dim>::nodal_displacements() const
  {
    const ContactSet<dim>              &contacts = state->contacts;
    std::vector<NodalDisplacement<dim>> result(contacts.node_dofs.size());
    for (std::size_t a = 0; a < result.size(); ++a)
      {
        result[a].position = contacts.node_position[a];
        result[a].block    = contacts.node_block[a];
        for (unsigned int d = 0; d < dim; ++d)
          result[a].displacement[d] =
            state->displacement[contacts.node_dofs[a][d]];
      }
    return result;
  }

  template <int dim>
  void
  MasonryScene<dim>::print_summary(std::ostream      &out,
                                   const lcp::Report &report) const
  {
    const auto   flags     = out.flags();
    const auto   precision = out.precision();
    const Sizes &s         = problem_sizes;
    out << "  masonry: " << structure_name();
    if (state->mesh_file.empty())
      out << ", m = " << parameters.geometry.m << " (H = " << s.block_height
          << ")";
    out << (dim == 3 ? ", 3D" : "") << ", " << quantity(s.n_blocks, "block")
        << ", " << to_string(state->discretisation.element) << " on "
        << quantity(s.n_cells, "cell") << " (refinement "
        << parameters.geometry.refinement << ", h = " << s.cell_size << ")\n"
        << "  supports: " << quantity(s.n_dirichlet, "Dirichlet DOF") << ", "
        << quantity(s.n_signorini, "Signorini node") << " with gap ";
    const std::string gap = dealii::Utilities::trim(parameters.boundary.gap);
    // g only where the expression uses it (a mesh file's gap need not).
    static const std::regex uses_g(R"((^|[^A-Za-z0-9_])g([^A-Za-z0-9_]|$))");
    if (gap == "g")
      out << "g = " << s.gap;
    else if (std::regex_search(gap, uses_g))
      out << gap << " (g = " << s.gap << ")";
    else
      out << gap;
    out << "; joints: " << s.n_horizontal_joint << " horizontal + "
        << quantity(s.n_vertical_joint, "vertical node pair");
    if (s.n_inclined_joint > 0)
      out << " + " << s.n_inclined_joint << " inclined";
    out << "\n";
    print_solver_summary(out, lcp_problem, report);
    // A run that did not converge shows its last iterate, which is no
    // answer (a singular Schur complement's zero start read "39 of 39
    // contacts closed", a review).
    if (report.solved)
      out << std::scientific << std::setprecision(6)
          << (report.converged() ? "  " : "  the last iterate, not an answer: ")
          << "max displacement " << max_displacement << ", "
          << n_closed_contacts << " of " << quantity(s.n_constraints, "contact")
          << " closed\n";
    if (report.converged() && n_degenerate_contacts > 0)
      out << "  " << quantity(n_degenerate_contacts, "contact")
          << (n_degenerate_contacts == 1 ? " has" : " have")
          << " zero gap and no force (degenerate: the solver counts them "
             "closed or open by its path): where such "
             "contacts alone hold a block, other displacements with the same "
             "energy and contact forces solve the problem too\n";
    if (report.converged())
      for (const std::string &line : free_motions)
        out << "  note: " << line
            << ": the displacements are determined only up to such a motion "
               "where the loads do no work along it (where they do, there is "
               "no equilibrium, and this answer holds only to 'Solver/KKT "
               "tolerance'); a support that holds it ('Normal displacement "
               "zero', 'Fixed') makes them unique\n";
    if (!mechanism.empty())
      out << "  note: the displacements are one answer of a family: "
          << mechanism
          << ", and the loads do no work along that motion; the energy, the "
             "contact forces and the reactions are the same for every "
             "member, the displacements not (a support or a prescribed "
             "displacement that holds those blocks makes them unique)\n";
    if (report.converged() &&
        std::max(balance.force_imbalance, balance.moment_imbalance) > 1e-8)
      out << std::setprecision(1) << "  warning: the supports' reactions "
          << "balance the loads only to " << balance.force_imbalance
          << " (force) and " << balance.moment_imbalance << " (moment)\n";
    out.flags(flags);
    out.precision(precision);
  }

  template <int dim>
  void
  MasonryScene<dim>::add_summary(JsonObject &summary) const
  {
    const Sizes &s = problem_sizes;
    summary.set("geometry", structure_name()).set("dimension", dim);
    // 'Blocks per side' means nothing to a mesh file's structure.
    if (!parameters.geometry.from_mesh_file)
      summary.set("m", parameters.geometry.m);
    summary.set("n_blocks", s.n_blocks)
      .set("refinement", parameters.geometry.refinement)
      .set("element", to_string(state->discretisation.element))
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
      .set("n_inclined_joint", s.n_inclined_joint)
      .set("max_displacement", max_displacement)
      .set("n_closed_contacts", n_closed_contacts)
      .set("n_degenerate_contacts", n_degenerate_contacts)
      // What relates the exported LCP (Output/Export LCP) to the numbers
      // above: energy = lcp_force_unit * (u'Au/2 - b'u) + lcp_energy_offset.
      .set("lcp_force_unit", unit)
      .set("lcp_energy_offset", energy_offset);
    std::vector<JsonObject> motions(free_motions.size());
    for (std::size_t i = 0; i < free_motions.size(); ++i)
      motions[i].set("description", free_motions[i]);
    summary.set("free_rigid_motions", motions);
    summary.set("mechanism", mechanism);
    // The coarse-mesh start, as the plate's: [] when the run had none.
    std::vector<JsonObject> coarse_levels;
    if (coarse_start.n_unknowns > 0)
      coarse_levels.emplace_back()
        .set("coarsening",
             std::vector<double>(coarse_start.coarsening.begin(),
                                 coarse_start.coarsening.end()))
        .set("n_unknowns", coarse_start.n_unknowns)
        .set("iterations", coarse_start.iterations)
        .set("status",
             coarse_start.status == lcp::Status::inaccurate ?
               "regularised answer" :
               lcp::to_string(coarse_start.status));
    summary.set("coarse_mesh_start", coarse_levels);
    JsonObject &statics = summary.object("statics");
    auto        list    = [](const auto &v) {
      return std::vector<double>(v.begin(), v.end());
    };
    statics.set("load", list(balance.load))
      .set("load_moment", list(balance.load_moment))
      .set("force_imbalance", balance.force_imbalance)
      .set("moment_imbalance", balance.moment_imbalance);
    // Per boundary: the supports on one boundary (the built-in walls' base
    // is a roller on one part and a Signorini support on the other) summed
    // under its name, in the order the boundaries first appear.
    std::vector<std::string>             boundaries;
    std::vector<std::array<double, dim>> forces;
    std::vector<std::array<double, 3>>   moments;
    for (std::size_t k = 0; k < balance.support.size(); ++k)
      {
        const auto found =
          std::find(boundaries.begin(), boundaries.end(), balance.support[k]);
        const std::size_t b = found - boundaries.begin();
        if (found == boundaries.end())
          {
            boundaries.push_back(balance.support[k]);
            forces.push_back({});
            moments.push_back({});
          }
        for (unsigned int d = 0; d < dim; ++d)
          forces[b][d] += balance.reaction[k][d];
        for (unsigned int d = 0; d < 3; ++d)
          moments[b][d] += balance.reaction_moment[k][d];
      }
    JsonObject &reactions = statics.object("reactions");
    for (std::size_t b = 0; b < boundaries.size(); ++b)
      reactions.object(boundaries[b])
        .set("force", list(forces[b]))
        .set("moment", list(moments[b]));
  }

  namespace
  {
    /**
     * Where a run failed and a material is nearly incompressible, that is
     * the likely cause: its volumetric stiffness dwarfs its shear
     * stiffness, displacement elements lock, and A's entries grow so far
     * beyond the forces that double precision no longer resolves them
     * (the stress check then speaks of rigid motions and units, which
     * would not help). Measured on the stack bond: nu = 0.4999 converges,
     * 0.49999 does not; the note names a ratio above 0.4995 (a contrast
     * of 1e3).
     */
    std::string
    nearly_incompressible(const std::vector<MaterialClass> &classes)
    {
      std::ostringstream note;
      note << std::setprecision(3);
      for (std::size_t k = 0; k < classes.size(); ++k)
        {
          const MaterialClass &material = classes[k];
          // (lambda + 2 mu) / mu, the plane-strain wave-speed ratio squared.
          const double contrast =
            (material.lambda() + 2 * material.mu()) / material.mu();
          if (contrast > 1e3)
            {
              note << "; the likely cause: 'Masonry/Materials/Poisson's "
                      "ratio' = "
                   << std::setprecision(12) << material.poissons_ratio
                   << std::setprecision(3) << " (class " << k
                   << ") makes that material's volumetric stiffness "
                   << contrast
                   << " times its shear stiffness, more than displacement "
                      "elements and double precision resolve (other units "
                      "would not help): use a Poisson's ratio below "
                      "0.4995";
              break;
            }
        }
      return note.str();
    }
  } // namespace

  template <int dim>
  std::string
  MasonryScene<dim>::failure_description(const lcp::Report &report) const
  {
    const std::string structure =
      state && !state->mesh_file.empty() ? "the structure" : "the wall";
    // A support that acts nowhere is the likeliest cause of both.
    std::string nowhere;
    if (state)
      {
        for (const std::string &support :
             state->contacts.supports_acting_nowhere)
          nowhere += "; " + support + " acts on no node";
        for (const std::string &line : state->contacts.nearly_touching)
          nowhere += "; " + line;
      }
    // The scene's own proof names the motion; other groups that can move
    // follow it.
    if (proved_before_solving(report))
      {
        std::string others;
        for (const std::string &line : free_motions)
          others += free_motions.size() > 1 ? "; " + line : "";
        return structure + " has no equilibrium: " + report.message + nowhere +
               others;
      }
    std::string unused = nowhere;
    // Blocks that a rigid motion moves past every support float, unless
    // the loads do no work along it. A block held by nothing is, in a mesh
    // file, most likely two faces that nearly touch but do not coincide.
    for (const std::string &line : free_motions)
      unused += "; " + line +
                (line.find("held by no support") != std::string::npos ?
                   " (joints are made only where faces of two blocks "
                   "coincide, to 'Masonry/Coincidence tolerance' of the "
                   "smallest cell)" :
                   "");
    if (report.status == lcp::Status::infeasible)
      return structure +
             " has no equilibrium: its supports and joints cannot "
             "carry the loads" +
             unused + " (" + report.message + ")";
    // A free motion the proof before solving did not take: the loads do
    // no work along it worth a proof, so the structure is in equilibrium
    // but its displacement along that motion is not fixed; the solver did
    // not search for a configuration and fail (TFETI refuses any free
    // motion at once, a review).
    if (report.status == lcp::Status::singular && !free_motions.empty())
      return "the solver met a singular system it could not resolve, and " +
             structure + " is not held against every rigid motion" + unused +
             "; the loads do no measurable work along such a motion, so " +
             "they do not fix the displacement along it: hold it by a "
             "support, or solve with the default solver settings (pdas, "
             "'Solver/Regularisation = auto', the full LCP rather than its "
             "Schur complement), which pick one of the answers (" +
             report.message + ")";
    if (report.status == lcp::Status::singular)
      return "the solver found no configuration in which every block is "
             "held by a support or a closed joint: " +
             structure + " has no equilibrium, or a block can move freely" +
             unused + " (" + report.message + ")";
    // A nearly incompressible material, only where the answer could not be
    // resolved: an iteration limit has other causes (a review: 'Maximum
    // iterations = 1').
    const std::string material =
      report.status == lcp::Status::inaccurate ?
        nearly_incompressible(parameters.materials.classes) :
        "";
    // An answer that is not resolved, where something can move freely: the
    // loads may drive it by less than the solver's proof of no solution
    // needs (a block on a frictionless slope of 1e-5 degrees, a review).
    if (!free_motions.empty())
      return Scene::failure_description(report) + unused +
             ": if the loads do any work along such a motion, " + structure +
             " has no equilibrium" + material;
    return Scene::failure_description(report) + material;
  }

  template <int dim>
  std::string
  MasonryScene<dim>::size_parameters() const
  {
    const std::string refinement =
      ", 'Masonry/Refinement' = " +
      std::to_string(parameters.geometry.refinement);
    if (parameters.geometry.from_mesh_file)
      return "'Masonry/Mesh file' = " + parameters.geometry.mesh_file +
             refinement;
    std::ostringstream thickness;
    if (dim == 3)
      thickness << ", 'Masonry/Thickness' = " << parameters.geometry.thickness
                << ", 'Masonry/Blocks through the thickness' = "
                << parameters.geometry.blocks_through_thickness;
    return "'Masonry/Blocks per side' = " +
           std::to_string(parameters.geometry.m) + thickness.str() + refinement;
  }

  std::unique_ptr<Scene>
  create_masonry_scene(dealii::ParameterHandler &prm)
  {
    Parameters parameters;
    parameters.parse_parameters(prm);
    if (parameters.geometry.dimension == 3)
      return std::make_unique<MasonryScene<3>>(parameters);
    return std::make_unique<MasonryScene<2>>(parameters);
  }

  template class MasonryScene<2>;
  template class MasonryScene<3>;

  namespace
  {
    const bool registered = SceneRegistry::add(
      {MasonryScene<2>::registered_name,
       "assemblies of elastic blocks in frictionless contact, 2D or 3D "
       "(Ainsworth & Mihai 2006): the paper's walls (stack bond, running "
       "bond, laminae) or blocks from a Gmsh file",
       [](dealii::ParameterHandler &prm) {
         MasonryScene<2>::declare_parameters(prm);
       },
       create_masonry_scene});
  } // namespace
} // namespace unilateral::masonry
