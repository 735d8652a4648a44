#include <unilateral/base/input_error.h>
#include <unilateral/scenes/plate/assembly.h>
#include <unilateral/scenes/plate/bending.h>

#include <deal.II/base/function.h>
#include <deal.II/base/index_set.h>
#include <deal.II/fe/fe.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

namespace unilateral::plate
{
  FreeDofs
  number_free_dofs(const dealii::types::global_dof_index n_dofs,
                   const dealii::IndexSet               &fixed_dofs)
  {
    FreeDofs free_dofs;
    free_dofs.index.assign(n_dofs, -1);
    free_dofs.dof.reserve(n_dofs - fixed_dofs.n_elements());
    for (dealii::types::global_dof_index i = 0; i < n_dofs; ++i)
      if (!fixed_dofs.is_element(i))
        {
          free_dofs.index[i] = static_cast<lcp::Index>(free_dofs.dof.size());
          free_dofs.dof.push_back(i);
        }
    return free_dofs;
  }

  fe::BognerFoxSchmit
  cell_element(const dealii::DoFHandler<2>::active_cell_iterator &cell)
  {
    return fe::BognerFoxSchmit::from_vertices(
      {{cell->vertex(0), cell->vertex(1), cell->vertex(2), cell->vertex(3)}});
  }

  fe::BognerFoxSchmit::Coefficients
  cell_coefficients(const dealii::DoFHandler<2>::active_cell_iterator &cell,
                    const std::vector<unsigned int> &bfs_index,
                    const dealii::Vector<double>    &dof_values)
  {
    std::vector<dealii::types::global_dof_index> local_dofs(
      fe::BognerFoxSchmit::dofs_per_cell);
    cell->get_dof_indices(local_dofs);
    fe::BognerFoxSchmit::Coefficients coefficients;
    for (unsigned int i = 0; i < local_dofs.size(); ++i)
      coefficients[bfs_index[i]] = dof_values[local_dofs[i]];
    return coefficients;
  }

  namespace
  {
    constexpr unsigned int n_local    = fe::BognerFoxSchmit::dofs_per_cell;
    constexpr unsigned int per_vertex = fe::BognerFoxSchmit::dofs_per_vertex;

    /// What the matrix needs of a cell: its vertices (in BFS local order)
    /// and its element integrals.
    struct CellData
    {
      std::array<unsigned int, 4> vertices;
      const CellIntegrals        *integrals;
    };

    /// What it needs of a vertex: its first deal.II DOF (a vertex's DOFs
    /// are consecutive), which components are free and the free index of
    /// the first of them (the free ones are numbered in component order).
    struct VertexData
    {
      dealii::types::global_dof_index first_dof  = 0;
      lcp::Index                      first_free = -1;
      unsigned char                   free_mask  = 0;
      unsigned char                   n_free     = 0;
    };

    /**
     * C_JJ column by column. The columns of a vertex V couple to the free
     * DOFs of the vertices that share a cell with V (at most 9), whatever
     * the values (the pattern: every coupling of the mesh). Their entries
     * are summed over V's cells in a small dense block and written once,
     * in order: scattering each cell's 256 entries into the compressed
     * matrix (a binary search each), after building the pattern in a
     * DynamicSparsityPattern, took most of the plate's assembly time. C is
     * symmetric, so the columns are its rows.
     */
    void
    assemble_matrix(const std::vector<CellData>   &cells,
                    const std::vector<VertexData> &vertices,
                    const lcp::Index               n,
                    lcp::SparseMatrix             &matrix)
    {
      const std::size_t n_vertices = vertices.size();
      // Per vertex: its cells and its place in each (CSR).
      std::vector<std::size_t> cells_start(n_vertices + 1, 0);
      for (const CellData &cell : cells)
        for (const unsigned int v : cell.vertices)
          ++cells_start[v + 1];
      for (std::size_t v = 0; v < n_vertices; ++v)
        cells_start[v + 1] += cells_start[v];
      std::vector<std::pair<unsigned int, unsigned int>> vertex_cells(
        cells_start.back());
      {
        std::vector<std::size_t> next(cells_start.begin(),
                                      cells_start.end() - 1);
        for (unsigned int c = 0; c < cells.size(); ++c)
          for (unsigned int k = 0; k < 4; ++k)
            vertex_cells[next[cells[c].vertices[k]]++] = {c, k};
      }

      // Per vertex: the vertices it shares a cell with, in DOF order (so
      // the rows come out sorted), and its columns' lengths.
      constexpr unsigned int     max_neighbours = 9;
      std::vector<unsigned int>  neighbours(max_neighbours * n_vertices);
      std::vector<unsigned char> n_neighbours(n_vertices, 0);
      std::vector<lcp::Index>    column_start(n + 1, 0);
      for (std::size_t v = 0; v < n_vertices; ++v)
        {
          if (vertices[v].n_free == 0)
            continue;
          unsigned int *list  = &neighbours[max_neighbours * v];
          unsigned int  count = 0;
          for (std::size_t p = cells_start[v]; p < cells_start[v + 1]; ++p)
            for (const unsigned int w : cells[vertex_cells[p].first].vertices)
              if (std::find(list, list + count, w) == list + count)
                list[count++] = w;
          std::sort(list,
                    list + count,
                    [&](const unsigned int a, const unsigned int b) {
                      return vertices[a].first_dof < vertices[b].first_dof;
                    });
          n_neighbours[v] = static_cast<unsigned char>(count);
          lcp::Index rows = 0;
          for (unsigned int k = 0; k < count; ++k)
            rows += vertices[list[k]].n_free;
          for (unsigned int c = 0; c < vertices[v].n_free; ++c)
            column_start[vertices[v].first_free + c + 1] = rows;
        }
      for (lcp::Index j = 0; j < n; ++j)
        column_start[j + 1] += column_start[j];

      matrix.resize(n, n);
      matrix.resizeNonZeros(column_start[n]);
      std::copy(column_start.begin(),
                column_start.end(),
                matrix.outerIndexPtr());
      lcp::Index *inner  = matrix.innerIndexPtr();
      double     *values = matrix.valuePtr();
      // block[k][r][c]: row component r of neighbour k, column component c
      // of the vertex.
      std::array<std::array<std::array<double, per_vertex>, per_vertex>,
                 max_neighbours>
        block;
      for (std::size_t v = 0; v < n_vertices; ++v)
        {
          const VertexData &vertex = vertices[v];
          if (vertex.n_free == 0)
            continue;
          const unsigned int *list  = &neighbours[max_neighbours * v];
          const unsigned int  count = n_neighbours[v];
          for (unsigned int k = 0; k < count; ++k)
            for (auto &row : block[k])
              row.fill(0.0);
          for (std::size_t p = cells_start[v]; p < cells_start[v + 1]; ++p)
            {
              const CellData &cell = cells[vertex_cells[p].first];
              const dealii::FullMatrix<double> &C = cell.integrals->stiffness;
              const unsigned int a = per_vertex * vertex_cells[p].second;
              for (unsigned int b = 0; b < 4; ++b)
                {
                  const auto k =
                    std::find(list, list + count, cell.vertices[b]) - list;
                  for (unsigned int r = 0; r < per_vertex; ++r)
                    for (unsigned int c = 0; c < per_vertex; ++c)
                      block[k][r][c] += C(per_vertex * b + r, a + c);
                }
            }
          lcp::Index column = vertex.first_free;
          for (unsigned int c = 0; c < per_vertex; ++c)
            {
              if (!(vertex.free_mask & (1U << c)))
                continue;
              lcp::Index q = column_start[column++];
              for (unsigned int k = 0; k < count; ++k)
                {
                  const VertexData &neighbour = vertices[list[k]];
                  lcp::Index        row       = neighbour.first_free;
                  for (unsigned int r = 0; r < per_vertex; ++r)
                    if (neighbour.free_mask & (1U << r))
                      {
                        inner[q]    = row++;
                        values[q++] = block[k][r][c];
                      }
                }
            }
        }
    }
  } // namespace

  void
  assemble_plate_system(const dealii::DoFHandler<2>       &dof_handler,
                        const FreeDofs                    &free_dofs,
                        const dealii::Vector<double>      *fixed_values,
                        const double                       rigidity,
                        const double                       poisson_ratio,
                        const dealii::Function<2, double> &force,
                        const std::string                 &force_description,
                        lcp::SparseMatrix                 &matrix,
                        lcp::Vector                       &rhs)
  {
    rhs = lcp::Vector::Zero(free_dofs.size());

    const std::vector<unsigned int> bfs_index =
      fe::bfs_local_indices(dof_handler.get_fe());
    std::vector<dealii::types::global_dof_index> local_dofs(n_local);
    CellIntegralsCache                           cache(rigidity, poisson_ratio);

    auto force_at = [&](const dealii::Point<2> &p) {
      const double f = force.value(p);
      if (!std::isfinite(f))
        {
          std::ostringstream message;
          message << force_description << ": evaluates to "
                  << (std::isnan(f) ? "nan" :
                      f > 0         ? "inf" :
                                      "-inf")
                  << " at (" << p[0] << ", " << p[1]
                  << "); give a force that is finite on the whole plate";
          throw InputError(message.str());
        }
      return f;
    };

    // The load, cell by cell, and what assemble_matrix needs of the mesh.
    std::vector<CellData>   cells;
    std::vector<VertexData> vertices(
      dof_handler.get_triangulation().n_vertices());
    cells.reserve(dof_handler.get_triangulation().n_active_cells());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(local_dofs);
        const fe::BognerFoxSchmit element = cell_element(cell);
        const CellIntegrals      &integrals =
          cache.get(element.size(0), element.size(1));
        const auto load = integrals.load(element.vertex(0), force_at);
        CellData   data;
        data.integrals = &integrals;
        for (unsigned int k = 0; k < 4; ++k)
          data.vertices[k] = cell->vertex_index(k);
        cells.push_back(data);

        for (unsigned int i = 0; i < n_local; ++i)
          {
            const unsigned int bi        = bfs_index[i];
            const unsigned int component = bi % per_vertex;
            VertexData      &vertex = vertices[data.vertices[bi / per_vertex]];
            const lcp::Index row    = free_dofs.index[local_dofs[i]];
            if (component == 0)
              vertex.first_dof = local_dofs[i];
            if (row < 0)
              continue;
            if (!(vertex.free_mask & (1U << component)))
              {
                vertex.free_mask |= 1U << component;
                ++vertex.n_free;
                vertex.first_free = vertex.first_free < 0 ?
                                      row :
                                      std::min(vertex.first_free, row);
              }
            rhs[row] += load[bi];
            if (fixed_values != nullptr)
              for (unsigned int j = 0; j < n_local; ++j)
                if (free_dofs.index[local_dofs[j]] < 0)
                  rhs[row] -= integrals.stiffness(bi, bfs_index[j]) *
                              (*fixed_values)[local_dofs[j]];
          }
      }
    // The rows come out in the order assemble_matrix assumes only if the
    // DOFs of each vertex are consecutive and numbered by component.
    for (const VertexData &vertex : vertices)
      for (unsigned int c = 0, k = 0; c < per_vertex; ++c)
        if (vertex.free_mask & (1U << c))
          AssertThrow(free_dofs.dof[vertex.first_free + k++] ==
                        vertex.first_dof + c,
                      dealii::ExcInternalError());
    assemble_matrix(cells, vertices, free_dofs.size(), matrix);
  }
} // namespace unilateral::plate
