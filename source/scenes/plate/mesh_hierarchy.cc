/**
 * The plate's hierarchy of meshes for the multigrid methods
 * (lcp/hierarchy.h): each side, as long as it has at least 8 cells, halved
 * if its count is even, else divided by 3 if it is a multiple of 3, else
 * halved rounded up; so the coarsest mesh has 3 to 7 cells per side (or the
 * fine mesh's own count where that is smaller). Dividing by 2 or 3 gives
 * nested meshes (a bicubic Hermite field on the coarse mesh is one on the
 * mesh refined 2 or 3 times per side: 90 -> 45 -> 15 -> 5, all nested);
 * where an odd count is no multiple of 3 the coarse nodes fall between the
 * fine ones and the spaces are not nested. The transfer is the same either way:
 * the coarse bicubic Hermite field evaluated at the fine nodes (w, w_x, w_y,
 * w_xy), exact where the spaces are nested; the Galerkin coarse problems of
 * the multigrid methods are then variational whatever the meshes.
 */
#include <unilateral/lcp/hierarchy.h>
#include <unilateral/scenes/plate/plate_scene.h>

#include <deal.II/dofs/dof_handler.h>

#include <algorithm>
#include <cmath>

namespace unilateral::plate
{
  namespace
  {
    // A side is coarsened while it has at least this many cells.
    constexpr unsigned int coarsen_from = 8;

    /// The next coarser count of a side: by a factor that keeps the
    /// meshes nested where there is one (2, else 3), else halved rounded up.
    unsigned int
    coarsened(const unsigned int n)
    {
      if (n < coarsen_from)
        return n;
      if (n % 2 == 0)
        return n / 2;
      if (n % 3 == 0)
        return n / 3;
      return (n + 1) / 2;
    }

    /// Per vertex, its four free DOFs (w, w_x, w_y, w_xy; -1 if fixed).
    std::vector<lcp::Index>
    free_dofs_by_vertex(const dealii::DoFHandler<2> &dof_handler,
                        const FreeDofs              &free_dofs)
    {
      constexpr unsigned int size = fe::BognerFoxSchmit::dofs_per_vertex;
      const std::vector<unsigned int> bfs_index =
        fe::bfs_local_indices(dof_handler.get_fe());
      std::vector<lcp::Index> by_vertex(
        size * dof_handler.get_triangulation().n_vertices(), -1);
      std::vector<dealii::types::global_dof_index> local_dofs(
        fe::BognerFoxSchmit::dofs_per_cell);
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          cell->get_dof_indices(local_dofs);
          for (unsigned int i = 0; i < local_dofs.size(); ++i)
            by_vertex[size * cell->vertex_index(bfs_index[i] / size) +
                      bfs_index[i] % size] = free_dofs.index[local_dofs[i]];
        }
      return by_vertex;
    }

    /// The nodes of a level: the vertices with a free DOF, in vertex order.
    std::vector<lcp::Index>
    node_blocks(const std::vector<lcp::Index> &by_vertex)
    {
      constexpr unsigned int  size = fe::BognerFoxSchmit::dofs_per_vertex;
      std::vector<lcp::Index> nodes;
      for (std::size_t v = 0; v < by_vertex.size(); v += size)
        if (std::any_of(by_vertex.begin() + v,
                        by_vertex.begin() + v + size,
                        [](const lcp::Index i) { return i >= 0; }))
          nodes.insert(nodes.end(),
                       by_vertex.begin() + v,
                       by_vertex.begin() + v + size);
      return nodes;
    }
  } // namespace

  lcp::SparseMatrix
  PlateScene::interpolation_to(const PlateScene &fine) const
  {
    const Geometry &geometry = parameters.geometry;
    const double    h_x      = geometry.length_x / geometry.n_x;
    const double    h_y      = geometry.length_y / geometry.n_y;
    const auto      cell_of  = [&](const dealii::Point<2> &p) {
      const auto column =
        std::min(static_cast<unsigned int>(std::max(p[0] / h_x, 0.0)),
                 geometry.n_x - 1);
      const auto row =
        std::min(static_cast<unsigned int>(std::max(p[1] / h_y, 0.0)),
                 geometry.n_y - 1);
      return column + geometry.n_x * row;
    };
    // Each coarse cell: its element and its free DOFs in BFS order.
    constexpr unsigned int n_local = fe::BognerFoxSchmit::dofs_per_cell;
    std::vector<fe::BognerFoxSchmit> elements(
      geometry.n_x * geometry.n_y,
      fe::BognerFoxSchmit(dealii::Point<2>(0, 0), 1, 1));
    std::vector<std::array<lcp::Index, n_local>> cell_dofs(elements.size());
    const std::vector<unsigned int>              bfs_index =
      fe::bfs_local_indices(dof_handler.get_fe());
    std::vector<dealii::types::global_dof_index> local_dofs(n_local);
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        const unsigned int c = cell_of(cell->center());
        elements[c]          = cell_element(cell);
        cell->get_dof_indices(local_dofs);
        for (unsigned int i = 0; i < n_local; ++i)
          cell_dofs[c][bfs_index[i]] = free_dofs.index[local_dofs[i]];
      }

    // Each fine node's free DOFs: the coarse field's value, slopes and
    // twist there, from the coarse cell that holds the node (the field and
    // these derivatives are continuous, so any such cell gives the same).
    const std::vector<lcp::Index> fine_dofs =
      free_dofs_by_vertex(fine.dof_handler, fine.free_dofs);
    const std::vector<dealii::Point<2>> &vertices =
      fine.triangulation.get_vertices();
    std::vector<Eigen::Triplet<double, lcp::Index>> entries;
    std::array<double, n_local>                     values;
    std::array<dealii::Tensor<1, 2>, n_local>       gradients;
    std::array<dealii::Tensor<2, 2>, n_local>       hessians;
    std::array<double, n_local>                     weights;
    for (std::size_t v = 0; v < vertices.size(); ++v)
      {
        const lcp::Index *dofs = &fine_dofs[4 * v];
        if (std::all_of(dofs, dofs + 4, [](const lcp::Index i) {
              return i < 0;
            }))
          continue;
        const unsigned int c = cell_of(vertices[v]);
        elements[c].evaluate(vertices[v], &values, &gradients, &hessians);
        for (unsigned int component = 0; component < 4; ++component)
          {
            if (dofs[component] < 0)
              continue;
            // Between the solvers' unknowns: scaled on either mesh (each
            // by its own element size) where its elements are far from
            // unit length, before the test below, which compares them.
            const double row_scale = fine.unknown_scale.size() > 0 ?
                                       1 / fine.unknown_scale[dofs[component]] :
                                       1.0;
            double       largest   = 0;
            for (unsigned int k = 0; k < n_local; ++k)
              {
                weights[k] = component == 0 ? values[k] :
                             component == 3 ? hessians[k][0][1] :
                                              gradients[k][component - 1];
                weights[k] *= row_scale;
                if (unknown_scale.size() > 0 && cell_dofs[c][k] >= 0)
                  weights[k] *= unknown_scale[cell_dofs[c][k]];
                largest = std::max(largest, std::abs(weights[k]));
              }
            // Weights below round-off of the largest are zeros that the
            // evaluation at a coarse node or edge left inexact.
            for (unsigned int k = 0; k < n_local; ++k)
              if (cell_dofs[c][k] >= 0 &&
                  std::abs(weights[k]) > 1e-13 * largest)
                entries.emplace_back(dofs[component],
                                     cell_dofs[c][k],
                                     weights[k]);
          }
      }
    lcp::SparseMatrix P(fine.free_dofs.size(), free_dofs.size());
    P.setFromTriplets(entries.begin(), entries.end());
    return P;
  }

  std::shared_ptr<const lcp::Hierarchy>
  PlateScene::make_hierarchy() const
  {
    // The coarse meshes, finest first.
    std::vector<std::unique_ptr<PlateScene>> coarse;
    for (Geometry geometry = parameters.geometry;;)
      {
        Geometry next = geometry;
        next.n_x      = coarsened(geometry.n_x);
        next.n_y      = coarsened(geometry.n_y);
        if (next.n_x == geometry.n_x && next.n_y == geometry.n_y)
          break;
        Parameters coarse_parameters = parameters;
        coarse_parameters.geometry   = next;
        coarse.push_back(std::make_unique<PlateScene>(coarse_parameters));
        coarse.back()->coarse_level = true;
        RunContext quiet;
        coarse.back()->set_up(quiet);
        geometry = next;
      }

    auto hierarchy        = std::make_shared<lcp::Hierarchy>();
    hierarchy->block_size = fe::BognerFoxSchmit::dofs_per_vertex;
    for (std::size_t k = coarse.size(); k-- > 0;)
      {
        const PlateScene     &scene = *coarse[k];
        const PlateScene     &finer = k > 0 ? *coarse[k - 1] : *this;
        lcp::Hierarchy::Level level;
        level.n_unknowns = scene.free_dofs.size();
        level.nodes =
          node_blocks(free_dofs_by_vertex(scene.dof_handler, scene.free_dofs));
        level.constrained  = scene.lcp_problem.constrained;
        level.lower_bound  = scene.lcp_problem.lower_bound;
        level.prolongation = scene.interpolation_to(finer);
        hierarchy->levels.push_back(std::move(level));
      }
    lcp::Hierarchy::Level finest;
    finest.n_unknowns = free_dofs.size();
    finest.nodes = node_blocks(free_dofs_by_vertex(dof_handler, free_dofs));
    hierarchy->levels.push_back(std::move(finest));
    return hierarchy;
  }
} // namespace unilateral::plate
