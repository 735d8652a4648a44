/**
 * The plate's coarse-mesh start (nested iteration): solve on a mesh with half
 * as many cells per side, evaluate that solution at the nodes of this mesh
 * and start the solver there. The contact set of the coarse plate is the fine
 * one up to a band about one coarse cell wide, so PDAS on the fine mesh
 * starts near the answer instead of swinging through thousands of nodes
 * (benchmarks/plate_tables/README.md, "Iterations and time"), and the rest
 * of the work is done on meshes a quarter, a sixteenth... the size.
 */
#include <unilateral/lcp/solve_lcp.h>
#include <unilateral/scenes/plate/plate_scene.h>

#include <deal.II/dofs/dof_handler.h>

#include <algorithm>
#include <cmath>
#include <ostream>

namespace unilateral::plate
{
  namespace
  {
    // Coarse meshes have at least this many cells per side.
    constexpr unsigned int coarsest_cells = 8;
  } // namespace

  bool
  PlateScene::uses_coarse_mesh_start(const RunContext &context) const
  {
    return parameters.coarse_mesh_start && obstacle != nullptr &&
           std::min(parameters.geometry.n_x, parameters.geometry.n_y) >=
             2 * coarsest_cells &&
           lcp::SolverRegistry::get(context.solver.method).warm_start &&
           // A method on the hierarchy of meshes climbs it by itself.
           !lcp::SolverRegistry::get(context.solver.method).needs_hierarchy;
  }

  lcp::Solution
  PlateScene::coarse_mesh_start(const RunContext &context)
  {
    Parameters coarse_parameters = parameters;
    Geometry  &coarse_geometry   = coarse_parameters.geometry;
    coarse_geometry.n_x          = (parameters.geometry.n_x + 1) / 2;
    coarse_geometry.n_y          = (parameters.geometry.n_y + 1) / 2;
    PlateScene coarse(coarse_parameters);
    coarse.coarse_level = true;
    RunContext quiet; // the coarse levels' stages are this run's "solve"
    coarse.set_up(quiet);
    coarse.assemble(quiet);
    if (coarse.uses_coarse_mesh_start(context))
      coarse.lcp_solution = coarse.coarse_mesh_start(context);

    const lcp::Report report =
      lcp::solve_lcp(coarse.lcp_problem, context.solver, coarse.lcp_solution);
    coarse_levels = coarse.coarse_levels;
    coarse_levels.insert(coarse_levels.begin(),
                         {coarse_geometry.n_x,
                          coarse_geometry.n_y,
                          report.iterations,
                          report.status});
    if (context.progress != nullptr)
      *context.progress << "  coarse-mesh start: " << coarse_geometry.n_x
                        << " x " << coarse_geometry.n_y << " cells, "
                        << report.solver << " " << lcp::to_string(report.status)
                        << " after " << report.iterations << " iterations"
                        << std::endl;
    // A failed coarse solve is no start at all: the method's own is safer.
    if (!report.converged())
      return lcp::Solution();
    return coarse.interpolate_to(*this);
  }

  lcp::Solution
  PlateScene::interpolate_to(const PlateScene &fine) const
  {
    // The field of this (coarse) mesh, cell by cell.
    dealii::Vector<double> coarse_values(dof_handler.n_dofs());
    const lcp::Vector      coarse_dofs = dofs_of(lcp_solution.u);
    for (lcp::Index k = 0; k < free_dofs.size(); ++k)
      coarse_values[free_dofs.dof[k]] = coarse_dofs[k];
    const Geometry &geometry = parameters.geometry;
    const double    h_x      = geometry.length_x / geometry.n_x;
    const double    h_y      = geometry.length_y / geometry.n_y;
    const auto      column   = [&](const double x) {
      return std::min(static_cast<unsigned int>(std::max(x / h_x, 0.0)),
                      geometry.n_x - 1);
    };
    const auto row = [&](const double y) {
      return std::min(static_cast<unsigned int>(std::max(y / h_y, 0.0)),
                      geometry.n_y - 1);
    };
    std::vector<dealii::DoFHandler<2>::active_cell_iterator> cell_at(
      geometry.n_x * geometry.n_y);
    for (const auto &cell : dof_handler.active_cell_iterators())
      cell_at[column(cell->center()[0]) +
              geometry.n_x * row(cell->center()[1])] = cell;
    const std::vector<unsigned int> coarse_bfs =
      fe::bfs_local_indices(dof_handler.get_fe());
    // Each free DOF of the fine mesh: the value or derivative it stands
    // for, at its node, from the coarse cell that holds the node (C1 field:
    // any of the cells around a coarse node gives the same w, w_x, w_y; w_xy
    // is taken from the cell up and to the right).
    lcp::Vector                     u(fine.free_dofs.size());
    const std::vector<unsigned int> fine_bfs =
      fe::bfs_local_indices(fine.dof_handler.get_fe());
    std::vector<dealii::types::global_dof_index> local_dofs(
      fe::BognerFoxSchmit::dofs_per_cell);
    for (const auto &cell : fine.dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(local_dofs);
        for (unsigned int i = 0; i < local_dofs.size(); ++i)
          {
            const lcp::Index free = fine.free_dofs.index[local_dofs[i]];
            if (free < 0)
              continue;
            const dealii::Point<2> node = cell->vertex(fine_bfs[i] / 4);
            const auto             coarse_cell =
              cell_at[column(node[0]) + geometry.n_x * row(node[1])];
            const fe::BognerFoxSchmit element = cell_element(coarse_cell);
            const auto                coefficients =
              cell_coefficients(coarse_cell, coarse_bfs, coarse_values);
            switch (fine_bfs[i] % 4)
              {
                case fe::BognerFoxSchmit::deflection:
                  u[free] = element.value(coefficients, node);
                  break;
                case fe::BognerFoxSchmit::slope_x:
                  u[free] = element.gradient(coefficients, node)[0];
                  break;
                case fe::BognerFoxSchmit::slope_y:
                  u[free] = element.gradient(coefficients, node)[1];
                  break;
                default:
                  u[free] = element.hessian(coefficients, node)[0][1];
              }
          }
      }
    // The first active set: the fine nodes where the interpolated coarse
    // plate lies on psi or within 2.4 (h/L)^2 of its largest deflection
    // above it, a band of the size of the O(h^2) interpolation error (3e-4
    // at 90 x 90); the test on u would not do, for
    // lambda = A u - b of an interpolated field is noise of either sign.
    // Measured on psi1-psi3, the band gives fewer and smaller changes than
    // the coarse contact set itself (benchmarks/plate_tables/README.md,
    // "Design measurements"). Those nodes start on psi.
    double largest_deflection = 0;
    for (const lcp::Index i : fine.lcp_problem.constrained)
      largest_deflection = std::max(largest_deflection, std::abs(u[i]));
    const double h =
      std::max(fine.parameters.geometry.length_x / fine.parameters.geometry.n_x,
               fine.parameters.geometry.length_y /
                 fine.parameters.geometry.n_y) /
      std::max(fine.parameters.geometry.length_x,
               fine.parameters.geometry.length_y);
    const double  contact_band = 2.4 * h * h * largest_deflection;
    lcp::Solution start;
    start.u = fine.unknowns_of(u); // the bounds' w are not scaled
    for (lcp::Index k = 0; k < fine.lcp_problem.n_constrained(); ++k)
      {
        const lcp::Index i = fine.lcp_problem.constrained[k];
        if (u[i] - fine.lcp_problem.lower_bound[k] <= contact_band)
          {
            start.active_set.push_back(i);
            start.u[i] = fine.lcp_problem.lower_bound[k];
          }
      }
    return start;
  }
} // namespace unilateral::plate
