/**
 * The masonry scene's coarse-mesh start (nested iteration, as the plate's):
 * solve the same wall (the same blocks, supports and loads) on a mesh whose
 * cells are k times as long along slender blocks with many cells along them
 * (the laminae: m cells along each lamina), and start the solver from that
 * displacement evaluated at the nodes of this mesh. A joint that the coarse
 * wall leaves closed (to its interpolation error) starts closed, so PDAS
 * starts near the answer instead of swinging through thousands of contacts
 * along the bending laminae
 * (benchmarks/masonry_tables/README.md, "The coarse-mesh start (laminae)").
 * A wall with one or two cells per block side (the paper's stack and running
 * bond) has no coarser mesh with matching nodes and keeps the method's own
 * start.
 */
#include <unilateral/lcp/solve_lcp.h>

#include "scene_state.h"

#include <deal.II/fe/fe.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/grid_tools_cache.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <tuple>

namespace unilateral::masonry
{
  namespace
  {
    // A coarsened side of a block keeps at least this many cells: enough
    // to place where a lamina lifts off to a few percent of its length
    // (the sizes tried: the README named above).
    constexpr unsigned int coarsest_cells = 20;

    /**
     * Per axis (x, y), the largest k such that cells k h long keep every
     * block corner a node (node-to-node contact needs matching nodes on
     * both sides of every joint) and leave at least coarsest_cells along
     * each block's side; 1 where no k > 1 does, and along an axis that not
     * every block is at least twice as long in as in the other. Slender
     * blocks bend, and where they lift off is what PDAS otherwise finds a
     * swing at a time; blocks as wide as high move almost rigidly, and the
     * all-active start is within a few contacts of their answer, closer
     * than a coarse mesh's (measured: the README named above).
     */
    std::array<unsigned int, 2>
    coarsening_of(const Layout &layout, const double h)
    {
      const BoundingBox           box = layout.bounding_box();
      std::array<unsigned int, 2> result{{1, 1}};
      for (unsigned int axis = 0; axis < 2; ++axis)
        {
          // Block corners in cells from the wall's corner; the fewest
          // cells along a block's side.
          std::vector<double> corners;
          double              fewest  = std::numeric_limits<double>::max();
          bool                slender = true;
          for (const Block &block : layout.blocks)
            {
              const double along  = axis == 0 ? block.width() : block.height();
              const double across = axis == 0 ? block.height() : block.width();
              slender             = slender && along >= 2 * across;
              const double lo =
                axis == 0 ? block.x0 - box.x0 : block.y0 - box.y0;
              const double hi =
                axis == 0 ? block.x1 - box.x0 : block.y1 - box.y0;
              corners.push_back(lo / h);
              corners.push_back(hi / h);
              fewest = std::min(fewest, (hi - lo) / h);
            }
          if (!slender)
            continue;
          const auto is_multiple = [](const double cells, const unsigned k) {
            const double ratio = cells / k;
            return std::abs(ratio - std::round(ratio)) <= 1e-6 * (1 + ratio);
          };
          for (unsigned int k = 2; k * coarsest_cells <= fewest + 1e-6; ++k)
            if (std::all_of(corners.begin(), corners.end(), [&](double c) {
                  return is_multiple(c, k);
                }))
              result[axis] = k;
        }
      return result;
    }
  } // namespace

  template <int dim>
  std::array<unsigned int, 2>
  MasonryScene<dim>::coarse_mesh_coarsening(const RunContext &context) const
  {
    const lcp::SolverInfo &method =
      lcp::SolverRegistry::get(context.solver.method);
    if (!parameters.coarse_mesh_start || parameters.geometry.from_mesh_file ||
        !method.warm_start || method.needs_tearing || method.needs_hierarchy)
      return {{1, 1}};
    return coarsening_of(state->layout, problem_sizes.cell_size);
  }

  template <int dim>
  void
  MasonryScene<dim>::initial_solution(RunContext &context)
  {
    const std::array<unsigned int, 2> coarsening =
      coarse_mesh_coarsening(context);
    if (coarsening[0] > 1 || coarsening[1] > 1)
      lcp_solution = coarse_mesh_start(context, coarsening);
  }

  template <int dim>
  lcp::Solution
  MasonryScene<dim>::coarse_mesh_start(
    const RunContext                  &context,
    const std::array<unsigned int, 2> &coarsening)
  {
    MasonryScene<dim> coarse(parameters);
    if (custom_layout)
      coarse.custom_layout = std::make_unique<Layout>(*custom_layout);
    coarse.mesh_coarsening = coarsening;
    RunContext quiet; // the coarse wall's stages are this run's "solve"
    quiet.parameter_file = context.parameter_file;
    quiet.solver         = context.solver;
    // A start needs no exact answer: the regularised solve's is as good,
    // and a status of inaccurate (no projection, so no exact KKT) is no
    // failure here.
    quiet.solver.projection = false;
    coarse.set_up(quiet);
    coarse.assemble(quiet);
    const lcp::Report report =
      lcp::solve_lcp(coarse.lcp_problem, quiet.solver, coarse.lcp_solution);
    const bool usable =
      report.converged() || report.status == lcp::Status::inaccurate;
    coarse_start = {coarsening,
                    coarse.problem_sizes.n_unknowns,
                    report.iterations,
                    report.status};
    if (context.progress != nullptr)
      *context.progress << "  coarse-mesh start: cells " << coarsening[0]
                        << " x " << coarsening[1] << " times as long, "
                        << coarse.problem_sizes.n_unknowns << " unknowns, "
                        << report.solver << " "
                        << (usable ? "regularised answer" :
                                     lcp::to_string(report.status))
                        << " after " << report.iterations << " iterations"
                        << std::endl;
    // A failed coarse solve is no start at all: the method's own is safer.
    if (!usable)
      return lcp::Solution();
    return coarse.interpolate_to(*this);
  }

  template <int dim>
  lcp::Solution
  MasonryScene<dim>::interpolate_to(const MasonryScene<dim> &fine) const
  {
    const Discretisation<dim> &coarse_discretisation = state->discretisation;
    const Discretisation<dim> &fine_discretisation = fine.state->discretisation;
    const std::vector<double>  coarse_displacement =
      state->change->to_physical(lcp_solution.u.data());
    // The meshes are nested: each fine cell lies in the coarse cell that
    // holds its centre (GridTools::compute_point_locations).
    std::vector<dealii::Point<dim>> centres;
    centres.reserve(fine_discretisation.triangulation.n_active_cells());
    for (const auto &cell :
         fine_discretisation.triangulation.active_cell_iterators())
      centres.push_back(cell->center());
    const dealii::GridTools::Cache<dim> cache(
      coarse_discretisation.triangulation, *coarse_discretisation.mapping);
    const auto located =
      dealii::GridTools::compute_point_locations(cache, centres);
    const auto &holding_cells = std::get<0>(located);
    const auto &centres_held  = std::get<2>(located);
    std::vector<typename dealii::DoFHandler<dim>::active_cell_iterator>
      coarse_cell_of(centres.size());
    for (std::size_t c = 0; c < holding_cells.size(); ++c)
      for (const unsigned int index : centres_held[c])
        coarse_cell_of[index] =
          typename dealii::DoFHandler<dim>::active_cell_iterator(
            &coarse_discretisation.triangulation,
            holding_cells[c]->level(),
            holding_cells[c]->index(),
            &coarse_discretisation.dof_handler);

    // Each fine cell's DOFs get the coarse field at their support points.
    const dealii::FiniteElement<dim> &coarse_fe = *coarse_discretisation.fe;
    const dealii::FiniteElement<dim> &fine_fe   = *fine_discretisation.fe;
    const std::vector<dealii::Point<dim>> &support =
      fine_fe.get_unit_support_points();
    std::vector<double> fine_displacement(fine.problem_sizes.n_dofs, 0.0);
    std::vector<dealii::types::global_dof_index> fine_dofs(
      fine_fe.n_dofs_per_cell());
    std::vector<dealii::types::global_dof_index> coarse_dofs(
      coarse_fe.n_dofs_per_cell());
    for (const auto &cell :
         fine_discretisation.dof_handler.active_cell_iterators())
      {
        const auto &coarse_cell = coarse_cell_of[cell->active_cell_index()];
        if (coarse_cell.state() != dealii::IteratorState::valid)
          throw std::logic_error("coarse-mesh start: no coarse cell holds the "
                                 "centre of a fine cell (the meshes are not "
                                 "nested)");
        coarse_cell->get_dof_indices(coarse_dofs);
        cell->get_dof_indices(fine_dofs);
        for (unsigned int i = 0; i < fine_dofs.size(); ++i)
          {
            const dealii::Point<dim> point =
              fine_discretisation.mapping->transform_unit_to_real_cell(
                cell, support[i]);
            const dealii::Point<dim> unit =
              coarse_discretisation.mapping->transform_real_to_unit_cell(
                coarse_cell, point);
            const unsigned int component =
              fine_fe.system_to_component_index(i).first;
            double value = 0;
            for (unsigned int j = 0; j < coarse_dofs.size(); ++j)
              if (coarse_fe.system_to_component_index(j).first == component)
                value += coarse_displacement[coarse_dofs[j]] *
                         coarse_fe.shape_value_component(j, unit, component);
            fine_displacement[fine_dofs[i]] = value;
          }
      }

    // The fine LCP unknowns u~ = C~ u, and the first active set: the
    // constraints closed in the coarse field (to round-off).
    const ChangeOfVariables<dim> &change = *fine.state->change;
    lcp::Solution                 start;
    start.u        = lcp::Vector::Zero(change.n_unknowns());
    double largest = 0;
    for (const double value : fine_displacement)
      largest = std::max(largest, std::abs(value));
    for (unsigned int v = 0; v < change.n_unknowns(); ++v)
      for (const auto &[dof, coefficient] : change.row(v))
        start.u[v] += coefficient * fine_displacement[dof];
    // Closed: a gap within the coarse mesh's interpolation error of zero,
    // (coarse cell length / block length)^2 times the largest
    // displacement, as the plate's band; a joint closed in the coarse
    // answer has a gap of round-off. The band halves PDAS's iterations on
    // the laminae at m = 225 against closing only what the coarse answer
    // closes (measured: the README named above).
    double relative_cell = 0;
    for (unsigned int axis = 0; axis < 2; ++axis)
      if (mesh_coarsening[axis] > 1)
        {
          double longest = 0;
          for (const Block &block : state->layout.blocks)
            longest =
              std::max(longest, axis == 0 ? block.width() : block.height());
          relative_cell =
            std::max(relative_cell,
                     mesh_coarsening[axis] * problem_sizes.cell_size / longest);
        }
    const double        band    = relative_cell * relative_cell * largest;
    const lcp::Problem &problem = fine.lcp_problem;
    for (lcp::Index k = 0; k < problem.n_constrained(); ++k)
      {
        const lcp::Index i = problem.constrained[k];
        if (start.u[i] - problem.lower_bound[k] <= band)
          {
            start.active_set.push_back(i);
            start.u[i] = problem.lower_bound[k];
          }
      }
    return start;
  }

  template std::array<unsigned int, 2>
  MasonryScene<2>::coarse_mesh_coarsening(const RunContext &) const;
  template std::array<unsigned int, 2>
  MasonryScene<3>::coarse_mesh_coarsening(const RunContext &) const;
  template void
  MasonryScene<2>::initial_solution(RunContext &);
  template void
  MasonryScene<3>::initial_solution(RunContext &);
  template lcp::Solution
  MasonryScene<2>::coarse_mesh_start(const RunContext &,
                                     const std::array<unsigned int, 2> &);
  template lcp::Solution
  MasonryScene<3>::coarse_mesh_start(const RunContext &,
                                     const std::array<unsigned int, 2> &);
  template lcp::Solution
  MasonryScene<2>::interpolate_to(const MasonryScene<2> &) const;
  template lcp::Solution
  MasonryScene<3>::interpolate_to(const MasonryScene<3> &) const;
} // namespace unilateral::masonry
