#include <unilateral/base/input_error.h>
#include <unilateral/scenes/masonry/mesh.h>

#include <deal.II/grid/tria.h>

#include <algorithm>
#include <cmath>

namespace unilateral::masonry
{
  namespace
  {
    unsigned int
    n_cells_along(const double length, const double cell_size)
    {
      return static_cast<unsigned int>(
        std::max(1.0, std::round(length / cell_size)));
    }

    // Node i of n + 1 along [a, b]; the ends are a and b exactly, so edges
    // shared by two blocks get bitwise equal end coordinates.
    double
    along(const double       a,
          const double       b,
          const unsigned int i,
          const unsigned int n)
    {
      if (i == 0)
        return a;
      if (i == n)
        return b;
      return a + (b - a) * static_cast<double>(i) / static_cast<double>(n);
    }
  } // namespace

  void
  build_triangulation(const Layout                &layout,
                      const double                 cell_size,
                      const ElementType            element,
                      dealii::Triangulation<2, 2> &triangulation)
  {
    // Count first, so the vertex and cell arrays are allocated once.
    std::size_t n_vertices = 0, n_squares = 0;
    for (const Block &block : layout.blocks)
      {
        const unsigned int nx = n_cells_along(block.width(), cell_size);
        const unsigned int ny = n_cells_along(block.height(), cell_size);
        n_vertices += static_cast<std::size_t>(nx + 1) * (ny + 1);
        n_squares += static_cast<std::size_t>(nx) * ny;
      }
    const bool simplex = element == ElementType::p2;

    std::vector<dealii::Point<2>>    vertices;
    std::vector<dealii::CellData<2>> cells;
    vertices.reserve(n_vertices);
    cells.reserve(simplex ? 2 * n_squares : n_squares);

    for (std::size_t b = 0; b < layout.blocks.size(); ++b)
      {
        const Block       &block = layout.blocks[b];
        const unsigned int nx    = n_cells_along(block.width(), cell_size);
        const unsigned int ny    = n_cells_along(block.height(), cell_size);
        const auto         first = static_cast<unsigned int>(vertices.size());
        for (unsigned int j = 0; j <= ny; ++j)
          for (unsigned int i = 0; i <= nx; ++i)
            vertices.emplace_back(along(block.x0, block.x1, i, nx),
                                  along(block.y0, block.y1, j, ny));
        auto vertex = [&](const unsigned int i, const unsigned int j) {
          return first + j * (nx + 1) + i;
        };
        for (unsigned int j = 0; j < ny; ++j)
          for (unsigned int i = 0; i < nx; ++i)
            {
              const unsigned int v00 = vertex(i, j), v10 = vertex(i + 1, j),
                                 v01 = vertex(i, j + 1),
                                 v11 = vertex(i + 1, j + 1);
              if (!simplex)
                {
                  dealii::CellData<2> cell(4);
                  // deal.II's lexicographic quadrilateral vertex order.
                  cell.vertices    = {v00, v10, v01, v11};
                  cell.material_id = static_cast<dealii::types::material_id>(b);
                  cells.push_back(std::move(cell));
                }
              else
                {
                  // Two counter-clockwise triangles split by the rising
                  // diagonal, so every Jacobian is positive.
                  for (const auto &triangle :
                       {std::vector<unsigned int>{v00, v10, v11},
                        std::vector<unsigned int>{v00, v11, v01}})
                    {
                      dealii::CellData<2> cell(3);
                      cell.vertices = triangle;
                      cell.material_id =
                        static_cast<dealii::types::material_id>(b);
                      cells.push_back(std::move(cell));
                    }
                }
            }
      }

    triangulation.clear();
    triangulation.create_triangulation(vertices, cells, dealii::SubCellData());
  }
} // namespace unilateral::masonry
