#include <unilateral/base/input_error.h>
#include <unilateral/base/memory.h>
#include <unilateral/scenes/masonry/mesh.h>

#include <deal.II/grid/tria.h>

#include <algorithm>
#include <array>
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

    // Node i of n + 1 along [a, b]; the ends are a and b exactly, so faces
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

    /// A box block [x0, x1] x [y0, y1] (x [z0, z1]) and its cell counts.
    struct Box
    {
      std::array<double, 3>       lo, hi;
      std::array<unsigned int, 3> n;
    };

    /// Six tetrahedra around the main diagonal 0-7 of a cube (vertex i at
    /// bit 0: x, bit 1: y, bit 2: z), each by a path 0 -> 7 along edges.
    constexpr std::array<std::array<unsigned int, 4>, 6> kuhn = {
      {{{0, 1, 3, 7}},
       {{0, 1, 5, 7}},
       {{0, 2, 3, 7}},
       {{0, 2, 6, 7}},
       {{0, 4, 5, 7}},
       {{0, 4, 6, 7}}}};

    template <int dim>
    void
    add_cells(const Box                          &box,
              const unsigned int                  block,
              const bool                          simplex,
              std::vector<dealii::Point<dim>>    &vertices,
              std::vector<dealii::CellData<dim>> &cells)
    {
      const auto         first = static_cast<unsigned int>(vertices.size());
      const unsigned int nz    = dim == 3 ? box.n[2] : 0;
      for (unsigned int k = 0; k <= nz; ++k)
        for (unsigned int j = 0; j <= box.n[1]; ++j)
          for (unsigned int i = 0; i <= box.n[0]; ++i)
            {
              dealii::Point<dim> p;
              p[0] = along(box.lo[0], box.hi[0], i, box.n[0]);
              p[1] = along(box.lo[1], box.hi[1], j, box.n[1]);
              if constexpr (dim == 3)
                p[2] = along(box.lo[2], box.hi[2], k, box.n[2]);
              vertices.push_back(p);
            }
      auto vertex =
        [&](const unsigned int i, const unsigned int j, const unsigned int k) {
          return first + (k * (box.n[1] + 1) + j) * (box.n[0] + 1) + i;
        };
      auto add = [&](std::vector<unsigned int> cell_vertices) {
        if constexpr (dim == 3)
          if (cell_vertices.size() == 4)
            {
              // Positive orientation, as deal.II's tetrahedra need.
              const auto                &v = vertices;
              const dealii::Tensor<1, 3> a =
                v[cell_vertices[1]] - v[cell_vertices[0]];
              const dealii::Tensor<1, 3> b =
                v[cell_vertices[2]] - v[cell_vertices[0]];
              const dealii::Tensor<1, 3> c =
                v[cell_vertices[3]] - v[cell_vertices[0]];
              if (dealii::cross_product_3d(a, b) * c < 0)
                std::swap(cell_vertices[1], cell_vertices[2]);
            }
        dealii::CellData<dim> cell(cell_vertices.size());
        cell.vertices    = cell_vertices;
        cell.material_id = static_cast<dealii::types::material_id>(block);
        cells.push_back(std::move(cell));
      };
      for (unsigned int k = 0; k < std::max(nz, 1u); ++k)
        for (unsigned int j = 0; j < box.n[1]; ++j)
          for (unsigned int i = 0; i < box.n[0]; ++i)
            {
              std::array<unsigned int, 8> v;
              for (unsigned int corner = 0; corner < (dim == 2 ? 4u : 8u);
                   ++corner)
                v[corner] = vertex(i + (corner & 1),
                                   j + ((corner >> 1) & 1),
                                   k + ((corner >> 2) & 1));
              if (!simplex)
                // deal.II's lexicographic vertex order is the bit order.
                add(std::vector<unsigned int>(v.begin(),
                                              v.begin() + (1u << dim)));
              else if (dim == 2)
                {
                  // Two counter-clockwise triangles split by the rising
                  // diagonal, so every Jacobian is positive.
                  add({v[0], v[1], v[3]});
                  add({v[0], v[3], v[2]});
                }
              else
                for (const auto &tet : kuhn)
                  add({v[tet[0]], v[tet[1]], v[tet[2]], v[tet[3]]});
            }
    }
  } // namespace

  template <int dim>
  BoundaryNames
  wall_boundary_names(const dealii::Triangulation<dim, dim> &triangulation)
  {
    BoundaryNames names;
    names.source = "the built-in wall";
    names.fix =
      "check its spelling (by number: left 1, right 2, base 3, top 4; in 3D "
      "front 5, back 6, collar 7)";
    names.id_of_name = {{"left", wall_boundary::left},
                        {"right", wall_boundary::right},
                        {"base", wall_boundary::base},
                        {"top", wall_boundary::top}};
    if (dim == 3)
      {
        names.id_of_name["front"]  = wall_boundary::front;
        names.id_of_name["back"]   = wall_boundary::back;
        names.id_of_name["collar"] = wall_boundary::collar;
        names.optional.insert("collar");
      }
    for (const auto id : triangulation.get_boundary_ids())
      names.ids_on_boundary.insert(id);
    return names;
  }

  template <int dim>
  void
  build_triangulation(const Layout                    &layout,
                      const double                     cell_size,
                      const ElementType                element,
                      const unsigned int               blocks_through_thickness,
                      const double                     thickness,
                      dealii::Triangulation<dim, dim> &triangulation,
                      const std::array<unsigned int, 2> &coarsening)
  {
    const double       x_size  = cell_size * coarsening[0];
    const double       y_size  = cell_size * coarsening[1];
    const bool         simplex = element == ElementType::p2;
    const unsigned int layers  = dim == 3 ? blocks_through_thickness : 1;
    const unsigned int nz =
      dim == 3 ? n_cells_along(thickness / layers, cell_size) : 1;

    // Count first, so the vertex and cell arrays are allocated once.
    std::size_t n_vertices = 0, n_boxes = 0;
    for (const Block &block : layout.blocks)
      {
        const unsigned int nx = n_cells_along(block.width(), x_size);
        const unsigned int ny = n_cells_along(block.height(), y_size);
        n_vertices += static_cast<std::size_t>(nx + 1) * (ny + 1) *
                      (dim == 3 ? nz + 1 : 1) * layers;
        n_boxes += static_cast<std::size_t>(nx) * ny * nz * layers;
      }
    // Refused before anything is built where the set-up alone (mesh, DOFs,
    // contact detection) would not fit, by a lower bound per cell (the
    // measured set-up: benchmarks/stress/README.md, "Input checks of
    // 2026-11-27"); a huge 'Thickness' would otherwise allocate until the
    // kernel kills the run.
    const std::size_t n_cells_built =
      simplex ? (dim == 2 ? 2 : 6) * n_boxes : n_boxes;
    memory::require(static_cast<double>(n_cells_built) * (dim == 2 ? 1e3 : 2e3),
                    "the mesh of " + std::to_string(n_cells_built) +
                      " cells and its set-up");
    std::vector<dealii::Point<dim>>    vertices;
    std::vector<dealii::CellData<dim>> cells;
    vertices.reserve(n_vertices);
    cells.reserve(simplex ? (dim == 2 ? 2 : 6) * n_boxes : n_boxes);

    for (std::size_t b = 0; b < layout.blocks.size(); ++b)
      {
        const Block &block = layout.blocks[b];
        for (unsigned int layer = 0; layer < layers; ++layer)
          {
            Box box;
            box.lo = {{block.x0, block.y0, along(0, thickness, layer, layers)}};
            box.hi = {
              {block.x1, block.y1, along(0, thickness, layer + 1, layers)}};
            box.n = {{n_cells_along(block.width(), x_size),
                      n_cells_along(block.height(), y_size),
                      nz}};
            add_cells<dim>(box,
                           static_cast<unsigned int>(b * layers + layer),
                           simplex,
                           vertices,
                           cells);
          }
      }
    triangulation.clear();
    triangulation.create_triangulation(vertices, cells, dealii::SubCellData());

    // The faces on the bounding box get their side's id.
    const BoundingBox box       = layout.bounding_box();
    const double      tolerance = 1e-8 * cell_size;
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          {
            const dealii::Point<dim> c      = cell->face(f)->center();
            const dealii::Point<dim> inside = cell->center();
            auto on = [&](const unsigned int axis, const double value) {
              return std::abs(c[axis] - value) <= tolerance &&
                     std::abs(inside[axis] - value) > tolerance;
            };
            dealii::types::boundary_id id = 0;
            if (on(0, box.x0))
              id = wall_boundary::left;
            else if (on(0, box.x1))
              id = wall_boundary::right;
            else if (on(1, box.y0))
              id = wall_boundary::base;
            else if (on(1, box.y1))
              id = wall_boundary::top;
            else if (dim == 3 && on(dim - 1, 0.0))
              id = wall_boundary::front;
            else if (dim == 3 && on(dim - 1, thickness))
              id = wall_boundary::back;
            else
              for (unsigned int layer = 1; layer < layers; ++layer)
                if (dim == 3 && on(dim - 1, along(0, thickness, layer, layers)))
                  id = wall_boundary::collar;
            cell->face(f)->set_boundary_id(id);
          }
  }

  template BoundaryNames
  wall_boundary_names<2>(const dealii::Triangulation<2, 2> &);
  template BoundaryNames
  wall_boundary_names<3>(const dealii::Triangulation<3, 3> &);
  template void
  build_triangulation<2>(const Layout &,
                         double,
                         ElementType,
                         unsigned int,
                         double,
                         dealii::Triangulation<2, 2> &,
                         const std::array<unsigned int, 2> &);
  template void
  build_triangulation<3>(const Layout &,
                         double,
                         ElementType,
                         unsigned int,
                         double,
                         dealii::Triangulation<3, 3> &,
                         const std::array<unsigned int, 2> &);
} // namespace unilateral::masonry
