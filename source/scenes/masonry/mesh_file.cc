#include <unilateral/base/disjoint_sets.h>
#include <unilateral/base/input_error.h>
#include <unilateral/scenes/masonry/mesh_file.h>

#include <deal.II/base/utilities.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>
#include <memory>
#include <regex>
#include <sstream>

namespace unilateral::masonry
{
  namespace
  {
    /// One cell of the file: its geometric entity and physical tag, and
    /// its centroid (to find it among GridIn's cells).
    template <int dim>
    struct FileCell
    {
      int                entity;
      int                physical;
      dealii::Point<dim> centroid;
    };

    /// What GridIn does not keep: the entities of the cells and the names
    /// of the physical tags.
    template <int dim>
    struct GmshScan
    {
      std::vector<FileCell<dim>> cells;
      std::map<int, std::string> cell_tag_names;
      std::map<std::string, int> boundary_tag_names;
      double                     smallest_edge = 0;
      /// The largest coordinate of a cell's node.
      double farthest = 0;
      bool   simplex  = false;
      /// The file's format, 2.2 or 4.1.
      double version = 0;
      /**
       * A whole-numbered point near the mesh's centre where the mesh lies
       * far from the origin, else zero. deal.II checks each new cell's
       * volume by a formula in its vertices' coordinates (cubic in 3D),
       * which cancels far from the origin (a box of edge 0.5 at (1e5, 1e5,
       * 1e5) read as inverted, a turned one as tangled, where double
       * precision keeps its geometry to 4e-11): its meshes are therefore
       * built with this point subtracted from every node and moved back.
       */
      dealii::Tensor<1, dim> local_origin;

      /// How far double precision keeps the cells' geometry far from the
      /// origin, relative to their size: epsilon |x| / h.
      double
      geometry_precision() const
      {
        return std::numeric_limits<double>::epsilon() * farthest /
               smallest_edge;
      }

      /// "its nodes lie up to 1e+05 from the origin, 2e+05 times its
      /// shortest edge", for messages.
      std::string
      distance_text() const
      {
        std::ostringstream text;
        text << std::setprecision(3) << "its nodes lie up to " << farthest
             << " from the origin, " << farthest / smallest_edge
             << " times its shortest edge";
        return text.str();
      }
    };

    [[noreturn]] void
    fail(const std::string &file, const std::string &what)
    {
      throw InputError("mesh file '" + file + "': " + what);
    }

    /// gmsh's linear element types: (dimension, number of nodes).
    const std::map<int, std::pair<int, int>> linear_elements = {{1, {1, 2}},
                                                                {15, {0, 1}},
                                                                {2, {2, 3}},
                                                                {3, {2, 4}},
                                                                {4, {3, 4}},
                                                                {5, {3, 8}},
                                                                {6, {3, 6}},
                                                                {7, {3, 5}}};

    /// The number of vertices of a linear cell of gmsh type @p type in
    /// dimension @p dim (2: triangle, 3: quadrilateral, 4: tetrahedron,
    /// 5: hexahedron), 0 for lower-dimensional elements; InputError for
    /// other cells of dimension dim.
    int
    cell_vertices(const int type, const int dim, const std::string &file)
    {
      const auto found = linear_elements.find(type);
      if (found == linear_elements.end())
        fail(file,
             "element type " + std::to_string(type) +
               " is not a linear cell; mesh with first-order elements "
               "(gmsh -order 1): quadrilaterals or triangles in 2D, "
               "hexahedra or tetrahedra in 3D");
      if (found->second.first != dim)
        return 0;
      if (type == 6 || type == 7)
        fail(file,
             "prisms and pyramids are not supported: mesh the blocks with "
             "hexahedra or tetrahedra");
      return found->second.second;
    }

    /// A measure of the area (volume) of a linear gmsh cell of type @p type
    /// with nodes @p p, in gmsh's node order: zero for a collapsed cell
    /// alone (GridIn reorients clockwise cells; tangled ones are refused
    /// later, by their corners' Jacobians).
    double
    element_measure(const int type, const std::vector<dealii::Point<3>> &p)
    {
      using dealii::cross_product_3d;
      if (type == 2)
        return 0.5 * cross_product_3d(p[1] - p[0], p[2] - p[0]).norm();
      // A quadrilateral: its four corner triangles, so that only four
      // nodes on a line give zero (not a tangled, bow-tie cell).
      if (type == 3)
        return 0.25 * (cross_product_3d(p[1] - p[0], p[3] - p[0]).norm() +
                       cross_product_3d(p[2] - p[1], p[0] - p[1]).norm() +
                       cross_product_3d(p[3] - p[2], p[1] - p[2]).norm() +
                       cross_product_3d(p[0] - p[3], p[2] - p[3]).norm());
      if (type == 4)
        return std::abs(cross_product_3d(p[1] - p[0], p[2] - p[0]) *
                        (p[3] - p[0])) /
               6;
      // A hexahedron: the tetrahedra from its centre to its faces' halves,
      // each counted positive (zero only for eight nodes in a plane).
      dealii::Point<3> centre;
      for (const auto &point : p)
        centre += point / 8.0;
      const unsigned int faces[6][4] = {{0, 3, 2, 1},
                                        {0, 1, 5, 4},
                                        {0, 4, 7, 3},
                                        {1, 2, 6, 5},
                                        {2, 3, 7, 6},
                                        {4, 5, 6, 7}};
      double             volume      = 0;
      for (const auto &f : faces)
        for (const unsigned int k : {1u, 2u})
          volume +=
            std::abs(cross_product_3d(p[f[0]] - centre, p[f[k]] - centre) *
                     (p[f[k + 1]] - centre)) /
            6;
      return volume;
    }

    template <int dim>
    GmshScan<dim>
    scan_gmsh(const std::string &file)
    {
      std::ifstream                      in(file);
      GmshScan<dim>                      scan;
      std::string                        section;
      double                             version = 0;
      std::map<long, dealii::Point<3>>   nodes;
      std::map<std::pair<int, int>, int> entity_physical; // (dim, tag)
      struct Element
      {
        long              tag;
        int               entity, physical, type;
        std::vector<long> nodes;
      };
      std::vector<Element> elements;
      // The cells and the boundary elements (curves in 2D, surfaces in 3D)
      // by their sorted nodes: one listed twice is refused.
      std::map<std::vector<long>, long> cell_elements, boundary_elements;
      auto                              read_or_fail = [&](auto &value) {
        if (!(in >> value))
          fail(file, "unexpected end or bad number in section " + section);
      };
      while (in >> section)
        {
          if (section == "$MeshFormat")
            {
              int binary = 0, size = 0;
              read_or_fail(version);
              read_or_fail(binary);
              read_or_fail(size);
              if (binary != 0)
                fail(file, "binary files are not read: save it as ASCII");
              if (version != 2.2 && version != 4.1)
                {
                  std::ostringstream v;
                  v << version;
                  fail(file,
                       "format " + v.str() +
                         " is not read: save it in format 2.2 or 4.1 (gmsh "
                         "-format msh22 or msh41)");
                }
            }
          else if (section == "$PhysicalNames")
            {
              int n = 0;
              read_or_fail(n);
              for (int i = 0; i < n; ++i)
                {
                  int         d = 0, tag = 0;
                  std::string name;
                  read_or_fail(d);
                  read_or_fail(tag);
                  std::getline(in, name);
                  name = dealii::Utilities::trim(name);
                  if (name.size() >= 2 && name.front() == '"')
                    name = name.substr(1, name.size() - 2);
                  if (d == dim)
                    scan.cell_tag_names[tag] = name;
                  else if (d == dim - 1)
                    {
                      // Two boundary groups of one name: a support given
                      // by that name would take one of them silently.
                      const auto [where, added] =
                        scan.boundary_tag_names.emplace(name, tag);
                      if (!added && where->second != tag)
                        fail(file,
                             "physical name '" + name + "' names groups " +
                               std::to_string(where->second) + " and " +
                               std::to_string(tag) +
                               "; give each group its own name");
                    }
                }
            }
          else if (section == "$Entities")
            {
              std::array<long, 4> counts{};
              for (long &c : counts)
                read_or_fail(c);
              for (int d = 0; d < 4; ++d)
                for (long e = 0; e < counts[d]; ++e)
                  {
                    int    tag = 0;
                    double box = 0;
                    long   n   = 0;
                    read_or_fail(tag);
                    for (int k = 0; k < (d == 0 ? 3 : 6); ++k)
                      read_or_fail(box);
                    read_or_fail(n);
                    // GridIn reads one physical tag per entity; a block
                    // or a support boundary in two groups is ambiguous.
                    if (n > 1 && (d == dim || d == dim - 1))
                      fail(file,
                           std::string(d == 3 ? "volume " :
                                       d == 2 ? "surface " :
                                                "curve ") +
                             std::to_string(tag) + " belongs to " +
                             std::to_string(n) +
                             " physical groups: put each into one physical "
                             "group (a block's, or a boundary's)");
                    for (long k = 0; k < n; ++k)
                      {
                        int physical = 0;
                        read_or_fail(physical);
                        if (k == 0)
                          entity_physical[{d, tag}] = physical;
                      }
                    if (d > 0)
                      {
                        read_or_fail(n);
                        for (long k = 0; k < n; ++k)
                          read_or_fail(box);
                      }
                  }
            }
          else if (section == "$Nodes")
            {
              // A tag listed twice would move whatever cell names it to
              // the last of its positions: refused, as an undefined one.
              const auto add_node = [&](const long              tag,
                                        const dealii::Point<3> &p) {
                if (!nodes.emplace(tag, p).second)
                  fail(file,
                       "node " + std::to_string(tag) +
                         " is defined twice in $Nodes; give every node its "
                         "own tag");
              };
              if (version == 2.2)
                {
                  long n = 0;
                  read_or_fail(n);
                  for (long i = 0; i < n; ++i)
                    {
                      long             tag = 0;
                      dealii::Point<3> p;
                      read_or_fail(tag);
                      for (unsigned int d = 0; d < 3; ++d)
                        read_or_fail(p[d]);
                      add_node(tag, p);
                    }
                }
              else
                {
                  long blocks = 0, n = 0, lo = 0, hi = 0;
                  read_or_fail(blocks);
                  read_or_fail(n);
                  read_or_fail(lo);
                  read_or_fail(hi);
                  for (long b = 0; b < blocks; ++b)
                    {
                      int  entity_dim = 0, tag = 0, parametric = 0;
                      long count = 0;
                      read_or_fail(entity_dim);
                      read_or_fail(tag);
                      read_or_fail(parametric);
                      read_or_fail(count);
                      if (parametric != 0)
                        fail(file,
                             "parametric node coordinates are not read: save "
                             "without them (Mesh.SaveParametric = 0)");
                      std::vector<long> tags(count);
                      for (long &t : tags)
                        read_or_fail(t);
                      for (const long t : tags)
                        {
                          dealii::Point<3> p;
                          for (unsigned int d = 0; d < 3; ++d)
                            read_or_fail(p[d]);
                          add_node(t, p);
                        }
                    }
                }
            }
          else if (section == "$Elements")
            {
              auto read_element = [&](const long tag,
                                      const int  entity,
                                      const int  physical,
                                      const int  type) {
                Element   element{tag, entity, physical, type, {}};
                const int n = cell_vertices(type, dim, file);
                element.nodes.resize(linear_elements.at(type).second);
                for (long &node : element.nodes)
                  read_or_fail(node);
                const bool cell = n > 0;
                if (cell || linear_elements.at(type).first == dim - 1)
                  {
                    // A cell listed twice would count its weight and
                    // stiffness twice (and GridIn, given it with another
                    // vertex order, never returns).
                    std::vector<long> key = element.nodes;
                    std::sort(key.begin(), key.end());
                    if (cell &&
                        std::adjacent_find(key.begin(), key.end()) != key.end())
                      fail(file,
                           "element " + std::to_string(tag) +
                             " names one node twice (a collapsed cell): "
                             "remesh it");
                    const auto [first, added] =
                      (cell ? cell_elements : boundary_elements)
                        .emplace(key, tag);
                    if (!added)
                      fail(file,
                           "elements " + std::to_string(first->second) +
                             " and " + std::to_string(tag) + " are one " +
                             (cell     ? "cell" :
                              dim == 2 ? "boundary segment" :
                                         "boundary face") +
                             " (the same nodes), listed twice" +
                             (cell ? ": its weight and stiffness would count "
                                     "twice" :
                                     "") +
                             "; gmsh's format 2.2 lists a " +
                             (cell ? (dim == 2 ? "surface" : "volume") :
                                     (dim == 2 ? "curve" : "surface")) +
                             "'s " + (cell ? "cells" : "elements") +
                             " once for each physical group it belongs to: "
                             "put each into one physical group");
                  }
                if (cell)
                  elements.push_back(std::move(element));
              };
              if (version == 2.2)
                {
                  long n = 0;
                  read_or_fail(n);
                  for (long i = 0; i < n; ++i)
                    {
                      long tag  = 0;
                      int  type = 0, n_tags = 0, physical = 0, entity = 0;
                      read_or_fail(tag);
                      read_or_fail(type);
                      read_or_fail(n_tags);
                      for (int t = 0; t < n_tags; ++t)
                        {
                          int value = 0;
                          read_or_fail(value);
                          if (t == 0)
                            physical = value;
                          else if (t == 1)
                            entity = value;
                        }
                      read_element(tag, entity, physical, type);
                    }
                }
              else
                {
                  long blocks = 0, n = 0, lo = 0, hi = 0;
                  read_or_fail(blocks);
                  read_or_fail(n);
                  read_or_fail(lo);
                  read_or_fail(hi);
                  for (long b = 0; b < blocks; ++b)
                    {
                      int  entity_dim = 0, entity = 0, type = 0;
                      long count = 0;
                      read_or_fail(entity_dim);
                      read_or_fail(entity);
                      read_or_fail(type);
                      read_or_fail(count);
                      const auto physical =
                        entity_physical.find({entity_dim, entity});
                      for (long i = 0; i < count; ++i)
                        {
                          long tag = 0;
                          read_or_fail(tag);
                          read_element(tag,
                                       entity,
                                       physical == entity_physical.end() ?
                                         0 :
                                         physical->second,
                                       type);
                        }
                    }
                }
            }
        }
      if (version == 0)
        fail(file, "no $MeshFormat section: not a Gmsh mesh");
      scan.version = version;
      if (elements.empty())
        fail(file,
             "no cells of dimension " + std::to_string(dim) +
               " (quadrilaterals or triangles in 2D, hexahedra or tetrahedra "
               "in 3D): check 'Masonry/Dimension' and the file");
      scan.simplex = elements.front().type == 2 || elements.front().type == 4;
      scan.smallest_edge = std::numeric_limits<double>::max();
      dealii::Tensor<1, dim> lowest, highest;
      for (unsigned int d = 0; d < dim; ++d)
        {
          lowest[d]  = std::numeric_limits<double>::max();
          highest[d] = std::numeric_limits<double>::lowest();
        }
      for (const Element &element : elements)
        {
          if ((element.type == 2 || element.type == 4) != scan.simplex)
            fail(file,
                 "mixes simplices and hypercubes: mesh every block with "
                 "quadrilaterals or every block with triangles (hexahedra or "
                 "tetrahedra in 3D)");
          FileCell<dim> cell{element.entity, element.physical, {}};
          for (const long node : element.nodes)
            {
              const auto found = nodes.find(node);
              if (found == nodes.end())
                fail(file,
                     "an element refers to node " + std::to_string(node) +
                       ", which the file does not define");
              if (dim == 2 && std::abs(found->second[2]) > 0)
                {
                  std::ostringstream z;
                  z << std::setprecision(6) << found->second[2];
                  fail(file,
                       "a 2D mesh must lie in the plane z = 0 (node " +
                         std::to_string(node) + " has z = " + z.str() +
                         "): write z = 0 for every node, or, for a 3D mesh "
                         "(hexahedra or tetrahedra), set 'Masonry/Dimension "
                         "= 3'");
                }
              for (unsigned int d = 0; d < dim; ++d)
                {
                  cell.centroid[d] += found->second[d] /
                                      static_cast<double>(element.nodes.size());
                  scan.farthest =
                    std::max(scan.farthest, std::abs(found->second[d]));
                  lowest[d]  = std::min(lowest[d], found->second[d]);
                  highest[d] = std::max(highest[d], found->second[d]);
                }
            }
          for (std::size_t a = 1; a < element.nodes.size(); ++a)
            scan.smallest_edge = std::min(scan.smallest_edge,
                                          nodes[element.nodes[a]].distance(
                                            nodes[element.nodes[0]]));
          std::vector<dealii::Point<3>> corners;
          double                        diameter = 0;
          for (const long node : element.nodes)
            {
              corners.push_back(nodes[node]);
              for (const auto &corner : corners)
                diameter = std::max(diameter, corner.distance(nodes[node]));
            }
          if (element_measure(element.type, corners) <=
              1e-10 * std::pow(diameter, dim))
            {
              std::ostringstream where;
              where << cell.centroid;
              fail(file,
                   "element " + std::to_string(element.tag) + " (at (" +
                     where.str() + ")) has no " +
                     (dim == 2 ? "area: its nodes lie on a line" :
                                 "volume: its nodes lie in a plane") +
                     "; remesh it");
            }
          scan.cells.push_back(cell);
        }
      if (scan.farthest > 1e4 * scan.smallest_edge)
        for (unsigned int d = 0; d < dim; ++d)
          scan.local_origin[d] = std::nearbyint(0.5 * (lowest[d] + highest[d]));
      return scan;
    }

    /**
     * The text of gmsh file @p file with @p shift added to its nodes'
     * first dim coordinates (for GridIn, see GmshScan::local_origin). The
     * $Nodes section is read word by word by its grammar in format @p
     * version (scan_gmsh has checked it), whatever its lines hold, and
     * written a node to a line; the other sections are copied.
     */
    template <int dim>
    std::string
    with_nodes_moved(const std::string            &file,
                     const double                  version,
                     const dealii::Tensor<1, dim> &shift)
    {
      std::ifstream      in(file);
      std::ostringstream out;
      out << std::setprecision(17);
      std::string line;
      while (std::getline(in, line))
        {
          out << line << '\n';
          if (dealii::Utilities::trim(line) != "$Nodes")
            continue;
          std::vector<std::string> words;
          for (std::string word; in >> word && word != "$EndNodes";)
            words.push_back(word);
          std::size_t at   = 0;
          const auto  next = [&words, &at]() { return words.at(at++); };
          const auto  node = [&]() {
            for (unsigned int d = 0; d < 3; ++d)
              out << std::stod(next()) + (d < dim ? shift[d] : 0.0)
                  << (d < 2 ? ' ' : '\n');
          };
          if (version == 2.2)
            {
              const long n = std::stol(next());
              out << n << '\n';
              for (long i = 0; i < n; ++i)
                {
                  out << next() << ' ';
                  node();
                }
            }
          else
            {
              const long blocks = std::stol(next());
              out << blocks;
              for (unsigned int w = 0; w < 3; ++w)
                out << ' ' << next();
              out << '\n';
              for (long b = 0; b < blocks; ++b)
                {
                  for (unsigned int w = 0; w < 3; ++w)
                    out << next() << ' ';
                  const long count = std::stol(next());
                  out << count << '\n';
                  for (long i = 0; i < count; ++i)
                    out << next() << '\n';
                  for (long i = 0; i < count; ++i)
                    node();
                }
            }
          out << "$EndNodes\n";
        }
      return out.str();
    }

    /// Rounded coordinates, for finding points again.
    template <int dim>
    std::array<long long, dim>
    grid_key(const dealii::Point<dim> &p, const double spacing)
    {
      std::array<long long, dim> key;
      for (unsigned int d = 0; d < dim; ++d)
        key[d] = std::llround(std::floor(p[d] / spacing));
      return key;
    }

    /// The entry of @p map nearest to @p p within @p spacing (probing the
    /// neighbouring grid cells), or nullptr.
    template <int dim, typename T>
    const T *
    find_near(
      const std::map<std::array<long long, dim>,
                     std::vector<std::pair<dealii::Point<dim>, T>>> &map,
      const dealii::Point<dim>                                      &p,
      const double                                                   spacing)
    {
      const auto key      = grid_key<dim>(p, spacing);
      const T   *best     = nullptr;
      double     distance = spacing;
      for (unsigned int probe = 0; probe < (dim == 2 ? 9u : 27u); ++probe)
        {
          auto neighbour = key;
          for (unsigned int d = 0, q = probe; d < dim; ++d, q /= 3)
            neighbour[d] += static_cast<long long>(q % 3) - 1;
          const auto found = map.find(neighbour);
          if (found == map.end())
            continue;
          for (const auto &[point, value] : found->second)
            if (point.distance(p) < distance)
              {
                distance = point.distance(p);
                best     = &value;
              }
        }
      return best;
    }

    /// Whether every corner of @p cell is positively oriented (hypercubes)
    /// or the simplex has positive volume.
    template <int dim>
    bool
    positively_oriented(const std::vector<dealii::Point<dim>> &v)
    {
      auto det = [](const dealii::Tensor<1, dim> &a,
                    const dealii::Tensor<1, dim> &b,
                    const dealii::Tensor<1, dim> &c) {
        if constexpr (dim == 2)
          return a[0] * b[1] - a[1] * b[0] + 0 * c[0];
        else
          return dealii::cross_product_3d(a, b) * c;
      };
      const dealii::Tensor<1, dim> none;
      if (v.size() == dim + 1)
        return det(v[1] - v[0], v[2] - v[0], dim == 3 ? v[dim] - v[0] : none) >
               0;
      // Each corner's edges along x, y (, z) in the lexicographic order.
      for (unsigned int corner = 0; corner < v.size(); ++corner)
        {
          std::array<dealii::Tensor<1, dim>, dim> edge;
          for (unsigned int d = 0; d < dim; ++d)
            {
              const unsigned int other = corner ^ (1u << d);
              edge[d] = (corner & (1u << d)) ? v[corner] - v[other] :
                                               v[other] - v[corner];
            }
          if (det(edge[0], edge[1], dim == 3 ? edge[dim - 1] : none) <= 0)
            return false;
        }
      return true;
    }

    /**
     * The active cells of a mesh by the grid cells their bounding boxes
     * touch, for finding the cells near a point or near another cell. The
     * spacing is the largest side of a box, so that a box touches at most
     * two grid cells along each axis and is found through those of its
     * corners. (A cell's diameter is not enough: a flat trapezoid's box is
     * wider than its diagonals, and a block beside its middle was never
     * compared.)
     */
    template <int dim>
    struct BoxGrid
    {
      using Cell = typename dealii::Triangulation<dim>::active_cell_iterator;
      using Key  = std::array<long long, dim>;

      std::vector<Cell>                        cells;
      double                                   spacing = 0;
      std::map<Key, std::vector<unsigned int>> grid;

      explicit BoxGrid(const dealii::Triangulation<dim> &triangulation)
      {
        for (const auto &cell : triangulation.active_cell_iterators())
          {
            cells.push_back(cell);
            const auto box = cell->bounding_box().get_boundary_points();
            for (unsigned int d = 0; d < dim; ++d)
              spacing = std::max(spacing, box.second[d] - box.first[d]);
          }
        for (unsigned int i = 0; i < cells.size(); ++i)
          for (const Key &k : box_keys(cells[i]))
            grid[k].push_back(i);
      }

      /// The grid cells @p cell's bounding box touches.
      std::vector<Key>
      box_keys(const Cell &cell) const
      {
        const auto       box = cell->bounding_box().get_boundary_points();
        const Key        lo  = grid_key<dim>(box.first, spacing);
        const Key        hi  = grid_key<dim>(box.second, spacing);
        std::vector<Key> keys;
        for (unsigned int probe = 0; probe < (1u << dim); ++probe)
          {
            Key k;
            for (unsigned int d = 0; d < dim; ++d)
              k[d] = (probe >> d) & 1 ? hi[d] : lo[d];
            keys.push_back(k);
          }
        std::sort(keys.begin(), keys.end());
        keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
        return keys;
      }

      /// The cells whose boxes touch the grid cell of @p p.
      const std::vector<unsigned int> &
      near(const dealii::Point<dim> &p) const
      {
        static const std::vector<unsigned int> none;
        const auto found = grid.find(grid_key<dim>(p, spacing));
        return found == grid.end() ? none : found->second;
      }
    };

    /**
     * Blocks that overlap: a vertex or the centre of a cell strictly inside
     * a cell of another block (by more than a millionth of the cell, in its
     * reference coordinates). Cells are found through a grid of their
     * bounding boxes.
     */
    template <int dim>
    void
    check_no_overlap(const BoxGrid<dim> &boxes,
                     const bool          simplex,
                     const std::string  &file)
    {
      std::unique_ptr<dealii::Mapping<dim>> mapping;
      if (simplex)
        mapping =
          std::make_unique<dealii::MappingFE<dim>>(dealii::FE_SimplexP<dim>(1));
      else
        mapping = std::make_unique<dealii::MappingQ<dim>>(1);
      const auto      &cells           = boxes.cells;
      constexpr double margin          = 1e-6;
      auto             strictly_inside = [&](const dealii::Point<dim> &unit) {
        double sum = 0;
        for (unsigned int d = 0; d < dim; ++d)
          {
            if (unit[d] <= margin || (!simplex && unit[d] >= 1 - margin))
              return false;
            sum += unit[d];
          }
        return !simplex || sum < 1 - margin;
      };
      for (const auto &cell : cells)
        {
          // The centre, the vertices and the points half-way between.
          std::vector<dealii::Point<dim>> points{cell->center()};
          for (const unsigned int v : cell->vertex_indices())
            {
              points.push_back(cell->vertex(v));
              points.push_back(0.5 * (cell->vertex(v) + cell->center()));
            }
          for (const auto &p : points)
            {
              for (const unsigned int other : boxes.near(p))
                {
                  const auto &o = cells[other];
                  if (o->material_id() == cell->material_id() ||
                      !o->bounding_box().point_inside(p))
                    continue;
                  dealii::Point<dim> unit;
                  try
                    {
                      unit = mapping->transform_real_to_unit_cell(o, p);
                    }
                  catch (...)
                    {
                      continue; // outside: the inverse does not converge
                    }
                  if (strictly_inside(unit))
                    {
                      std::ostringstream where;
                      where << p;
                      fail(file,
                           "blocks " + std::to_string(cell->material_id()) +
                             " and " + std::to_string(o->material_id()) +
                             " overlap (a point of the first at (" +
                             where.str() +
                             ") lies inside the second): blocks may touch, "
                             "not overlap");
                    }
                }
            }
        }
    }

    /// The axes along which two convex cells may be told apart: the normals
    /// of their faces (of both triangles of each diagonal of a quadrilateral
    /// face in 3D, so that a face that is not plane is covered by the convex
    /// hull of its vertices) and, with @p edges in 3D, the cross products
    /// of their edges and face diagonals.
    template <int dim>
    std::vector<dealii::Tensor<1, dim>>
    separating_axes(
      const typename dealii::Triangulation<dim>::active_cell_iterator &a,
      const typename dealii::Triangulation<dim>::active_cell_iterator &b,
      const bool                                                       edges)
    {
      std::vector<dealii::Tensor<1, dim>> axes;
      if constexpr (dim == 2)
        {
          (void)edges;
          for (const auto &cell : {a, b})
            for (const unsigned int l : cell->line_indices())
              {
                const auto t =
                  cell->line(l)->vertex(1) - cell->line(l)->vertex(0);
                axes.push_back(dealii::Tensor<1, 2>({-t[1], t[0]}));
              }
        }
      else
        {
          std::array<std::vector<dealii::Tensor<1, 3>>, 2> directions;
          for (unsigned int k = 0; k < 2; ++k)
            {
              const auto &cell = k == 0 ? a : b;
              for (const unsigned int f : cell->face_indices())
                {
                  const auto face = cell->face(f);
                  auto v = [&](unsigned int i) { return face->vertex(i); };
                  if (face->n_vertices() == 3)
                    axes.push_back(
                      dealii::cross_product_3d(v(1) - v(0), v(2) - v(0)));
                  else
                    {
                      // deal.II's lexicographic order: diagonals 0-3, 1-2.
                      const unsigned int triangles[4][3] = {{0, 1, 3},
                                                            {0, 3, 2},
                                                            {0, 1, 2},
                                                            {1, 3, 2}};
                      for (const auto &t : triangles)
                        axes.push_back(
                          dealii::cross_product_3d(v(t[1]) - v(t[0]),
                                                   v(t[2]) - v(t[0])));
                      directions[k].push_back(v(3) - v(0));
                      directions[k].push_back(v(2) - v(1));
                    }
                }
              for (const unsigned int l : cell->line_indices())
                directions[k].push_back(cell->line(l)->vertex(1) -
                                        cell->line(l)->vertex(0));
            }
          if (edges)
            for (const auto &s : directions[0])
              for (const auto &t : directions[1])
                axes.push_back(dealii::cross_product_3d(s, t));
        }
      return axes;
    }

    /// How far the convex hulls of @p a and @p b overlap along every one
    /// of @p axes at least: at or below zero, an axis separates them.
    template <int dim>
    double
    overlap_depth(const std::vector<dealii::Point<dim>>     &a,
                  const std::vector<dealii::Point<dim>>     &b,
                  const std::vector<dealii::Tensor<1, dim>> &axes)
    {
      double depth = std::numeric_limits<double>::infinity();
      for (const auto &axis : axes)
        {
          const double length = axis.norm();
          if (!(length > 0))
            continue;
          auto range = [&](const std::vector<dealii::Point<dim>> &points) {
            double lo = std::numeric_limits<double>::infinity(), hi = -lo;
            for (const auto &p : points)
              {
                lo = std::min(lo, p * axis / length);
                hi = std::max(hi, p * axis / length);
              }
            return std::make_pair(lo, hi);
          };
          const auto [a_lo, a_hi] = range(a);
          const auto [b_lo, b_hi] = range(b);
          depth = std::min(depth, std::min(a_hi, b_hi) - std::max(a_lo, b_lo));
          if (depth <= 0)
            break;
        }
      return depth;
    }

    /**
     * Blocks that overlap by a region: two cells of different blocks whose
     * convex hulls no axis separates, by more than 5e-3 of the smaller
     * cell (the check of points above misses an overlap whose
     * points all lie on the other block's cell edges, as two stacked blocks
     * pushed into each other along a course). Cells that share a face
     * (a joint) are not compared: a face that is not plane makes their
     * hulls overlap by its warp. Smaller overlaps are left to the contact
     * detection, which refuses faces that nearly coincide (to 1e-2 of a
     * cell) with their distance.
     */
    template <int dim>
    void
    check_cells_separated(const BoxGrid<dim> &boxes, const std::string &file)
    {
      using Cell        = typename BoxGrid<dim>::Cell;
      const auto &cells = boxes.cells;

      auto vertices = [](const Cell &cell) {
        std::vector<dealii::Point<dim>> v;
        for (const unsigned int i : cell->vertex_indices())
          v.push_back(cell->vertex(i));
        return v;
      };
      for (unsigned int i = 0; i < cells.size(); ++i)
        {
          const Cell               &a = cells[i];
          std::vector<unsigned int> near;
          for (const auto &k : boxes.box_keys(a))
            for (const unsigned int j : boxes.grid.at(k))
              if (j > i && cells[j]->material_id() != a->material_id())
                near.push_back(j);
          std::sort(near.begin(), near.end());
          near.erase(std::unique(near.begin(), near.end()), near.end());
          const auto   a_vertices = vertices(a);
          const auto   a_box      = a->bounding_box().get_boundary_points();
          const double a_size     = a->minimum_vertex_distance();
          for (const unsigned int j : near)
            {
              const Cell  &b = cells[j];
              const double size =
                std::min(a_size, b->minimum_vertex_distance());
              const double allowed = 5e-3 * size;
              // Most neighbours are told apart by their bounding boxes.
              const auto b_box     = b->bounding_box().get_boundary_points();
              bool       separated = false;
              for (unsigned int d = 0; d < dim; ++d)
                separated =
                  separated || std::min(a_box.second[d], b_box.second[d]) -
                                   std::max(a_box.first[d], b_box.first[d]) <=
                                 allowed;
              if (separated)
                continue;
              const auto b_vertices = vertices(b);
              // A face of a whose every vertex is one of b's: a joint.
              bool joint = false;
              for (const unsigned int f : a->face_indices())
                {
                  bool all = true;
                  for (const unsigned int v : a->face(f)->vertex_indices())
                    all =
                      all &&
                      std::any_of(b_vertices.begin(),
                                  b_vertices.end(),
                                  [&](const auto &p) {
                                    return p.distance(a->face(f)->vertex(v)) <=
                                           1e-6 * size;
                                  });
                  joint = joint || all;
                }
              if (joint ||
                  overlap_depth<dim>(a_vertices,
                                     b_vertices,
                                     separating_axes<dim>(a, b, false)) <=
                    allowed)
                continue;
              const double depth =
                overlap_depth<dim>(a_vertices,
                                   b_vertices,
                                   separating_axes<dim>(a, b, true));
              if (depth <= allowed)
                continue;
              std::ostringstream message;
              message << "blocks " << a->material_id() << " and "
                      << b->material_id() << " overlap by " << depth
                      << " (their cells at (" << a->center() << ") and ("
                      << b->center()
                      << ")): blocks may touch, not overlap; move them "
                         "apart";
              fail(file, message.str());
            }
        }
    }
  } // namespace

  template <int dim>
  MeshFileBlocks
  read_mesh_file(const std::string               &file_name,
                 dealii::Triangulation<dim, dim> &triangulation)
  {
    std::error_code error;
    if (!std::filesystem::is_regular_file(file_name, error))
      fail(file_name,
           std::filesystem::exists(file_name, error) ?
             "not a file" :
             "no such file: check 'Masonry/Mesh file' (a relative path is "
             "taken from the parameter file's folder)");
    const GmshScan<dim> scan = scan_gmsh<dim>(file_name);

    // The mesh as GridIn reads it, vertices shared between blocks.
    dealii::Triangulation<dim, dim> file_mesh;
    try
      {
        dealii::GridIn<dim, dim> grid_in;
        grid_in.attach_triangulation(file_mesh);
        if (scan.local_origin.norm() > 0)
          {
            std::istringstream in(with_nodes_moved<dim>(file_name,
                                                        scan.version,
                                                        -scan.local_origin));
            grid_in.read_msh(in);
            dealii::GridTools::shift(scan.local_origin, file_mesh);
          }
        else
          {
            std::ifstream in(file_name);
            grid_in.read_msh(in);
          }
      }
    catch (const InputError &)
      {
        throw;
      }
    catch (const std::exception &exception)
      {
        std::string reason = exception.what();
        const auto  at     = reason.find("Additional information:");
        if (at != std::string::npos)
          reason = reason.substr(at + 23);
        reason = std::regex_replace(reason, std::regex(R"(\s+)"), " ");
        // Its message names vertex indices of its own and is followed by a
        // stack trace: the cases a user meets are said in their terms.
        if (reason.find("boundary id for an internal face") !=
            std::string::npos)
          fail(file_name,
               std::string("an element of a ") +
                 (dim == 2 ? "curve" : "surface") +
                 " lies between two cells that share its nodes (a joint "
                 "between blocks that share nodes is in a physical group, or "
                 "the file has none or was saved with Mesh.SaveAll, and gmsh "
                 "saved every " +
                 (dim == 2 ? "curve" : "surface") +
                 ", the joints' too); save without SaveAll, put the blocks "
                 "into physical " +
                 (dim == 2 ? "surfaces" : "volumes") +
                 " and only the outer boundaries the supports name into "
                 "physical " +
                 (dim == 2 ? "curves" : "surfaces"));
        const auto trace = reason.find("Stacktrace:");
        if (trace != std::string::npos)
          reason.erase(trace);
        // deal.II's ExcInternalError says, at length, to write to its
        // mailing list.
        if (reason.find("which is used in many places") != std::string::npos)
          reason = "an internal check of deal.II failed";
        // Far from the origin GridIn's own checks of the cells failed with
        // an internal error (a 3D box of edge 0.5 at 1e5, before it was
        // read around GmshScan::local_origin): say so where that may be
        // why.
        const std::string far =
          scan.smallest_edge > 0 && scan.geometry_precision() > 1e-12 ?
            " (" + scan.distance_text() +
              ", where deal.II's checks of the cells lose precision: move "
              "the mesh near the origin, subtracting a point of the "
              "structure from every node)" :
            "";
        fail(file_name,
             "deal.II's GridIn cannot read it: " +
               dealii::Utilities::trim(reason) + far);
      }

    // Far from the origin, double precision keeps a node's coordinates
    // only to epsilon |x|, and the cells' Jacobians (differences of them)
    // to epsilon |x| / h relative: the stiffness with them (measured:
    // benchmarks/stress/README.md, "Input checks of 2026-11-27"). Refused
    // where that exceeds the default KKT tolerance.
    // (A collapsed edge is refused below, with its own message.)
    if (scan.smallest_edge > 0 && scan.geometry_precision() > 1e-8)
      {
        std::ostringstream message;
        message << std::setprecision(3) << scan.distance_text()
                << ": double precision keeps the cells' geometry only to "
                << scan.geometry_precision()
                << " of their size, and the stiffness with it; move the "
                   "mesh near the origin (subtract a point of the "
                   "structure from every node)";
        fail(file_name, message.str());
      }

    // The entity and physical tag of each of GridIn's cells, found by its
    // centroid.
    const double spacing = 1e-3 * scan.smallest_edge;
    std::map<std::array<long long, dim>,
             std::vector<std::pair<dealii::Point<dim>, std::size_t>>>
      by_centroid;
    for (std::size_t c = 0; c < scan.cells.size(); ++c)
      by_centroid[grid_key<dim>(scan.cells[c].centroid, spacing)].push_back(
        {scan.cells[c].centroid, c});
    const auto                             n_cells = file_mesh.n_active_cells();
    std::vector<std::size_t>               file_cell(n_cells);
    std::vector<std::vector<unsigned int>> cells_at_vertex(
      file_mesh.n_vertices());
    for (const auto &cell : file_mesh.active_cell_iterators())
      {
        dealii::Point<dim> centroid;
        for (const unsigned int v : cell->vertex_indices())
          centroid += cell->vertex(v) / static_cast<double>(cell->n_vertices());
        const std::size_t *found =
          find_near<dim>(by_centroid, centroid, spacing);
        if (found == nullptr)
          fail(file_name,
               "a cell GridIn read was not found among the file's "
               "elements (duplicate or overlapping elements?)");
        file_cell[cell->active_cell_index()] = *found;
        for (const unsigned int v : cell->vertex_indices())
          cells_at_vertex[cell->vertex_index(v)].push_back(
            cell->active_cell_index());
      }

    // Blocks: cells sharing a vertex, with the same entity and tag.
    DisjointSets by_vertex(n_cells);
    auto         same_body = [&](const unsigned int a, const unsigned int b) {
      const FileCell<dim> &x = scan.cells[file_cell[a]];
      const FileCell<dim> &y = scan.cells[file_cell[b]];
      return x.entity == y.entity && x.physical == y.physical;
    };
    for (const auto &cells : cells_at_vertex)
      for (std::size_t i = 1; i < cells.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
          if (same_body(cells[i], cells[j]))
            by_vertex.unite(cells[i], cells[j]);
    std::vector<int> block_of_root(n_cells, -1);
    MeshFileBlocks   result;
    result.simplex = scan.simplex;
    std::vector<unsigned int> block(n_cells);
    for (const auto &cell : file_mesh.active_cell_iterators())
      {
        const unsigned int c    = cell->active_cell_index();
        const std::size_t  root = by_vertex.find(c);
        if (block_of_root[root] < 0)
          {
            block_of_root[root] = static_cast<int>(result.tag_of_block.size());
            const int  tag      = scan.cells[file_cell[c]].physical;
            const auto name     = scan.cell_tag_names.find(tag);
            result.tag_of_block.push_back(name != scan.cell_tag_names.end() ?
                                            name->second :
                                            std::to_string(tag));
            result.tag_number_of_block.push_back(
              static_cast<unsigned int>(tag));
          }
        block[c] = static_cast<unsigned int>(block_of_root[root]);
      }

    // The blocks' own vertices, and the boundary ids by face centre.
    std::vector<dealii::Point<dim>>                               vertices;
    std::vector<dealii::CellData<dim>>                            cells;
    std::map<std::pair<unsigned int, unsigned int>, unsigned int> new_vertex;
    // Within a block, cells share their nodes: two nodes of one block at
    // one position (a node duplicated in the file) would cut a
    // traction-free slit through it.
    std::map<std::pair<unsigned int, std::array<long long, dim>>, unsigned int>
      node_at;
    std::map<std::array<long long, dim>,
             std::vector<
               std::pair<dealii::Point<dim>,
                         std::pair<unsigned int, dealii::types::boundary_id>>>>
      boundary_faces;
    for (const auto &cell : file_mesh.active_cell_iterators())
      {
        const unsigned int              b = block[cell->active_cell_index()];
        dealii::CellData<dim>           data(cell->n_vertices());
        std::vector<dealii::Point<dim>> corners;
        for (const unsigned int v : cell->vertex_indices())
          {
            const auto key = std::make_pair(b, cell->vertex_index(v));
            auto       it  = new_vertex.find(key);
            if (it == new_vertex.end())
              {
                if (!node_at
                       .emplace(std::make_pair(
                                  b, grid_key<dim>(cell->vertex(v), spacing)),
                                cell->vertex_index(v))
                       .second)
                  {
                    std::ostringstream message;
                    message << "block " << b << " has two nodes at ("
                            << cell->vertex(v)
                            << "): cells of one block must share their nodes "
                               "(a duplicated node cuts a slit into the "
                               "block); merge them (gmsh: Coherence)";
                    fail(file_name, message.str());
                  }
                it = new_vertex
                       .emplace(key, static_cast<unsigned int>(vertices.size()))
                       .first;
                vertices.push_back(cell->vertex(v));
              }
            data.vertices[v] = it->second;
            corners.push_back(cell->vertex(v));
          }
        if (!positively_oriented<dim>(corners))
          {
            std::ostringstream where;
            where << cell->center();
            fail(file_name,
                 "the cell at (" + where.str() + ") of block " +
                   std::to_string(b) +
                   " is inverted or tangled (a corner with a non-positive "
                   "Jacobian): fix its vertex order or shape");
          }
        data.material_id = b;
        cells.push_back(std::move(data));
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() != 0)
            boundary_faces[grid_key<dim>(cell->face(f)->center(), spacing)]
              .push_back(
                {cell->face(f)->center(), {b, cell->face(f)->boundary_id()}});
      }
    // Cells of one body that meet only at a vertex (in 3D also only along
    // an edge) are not one block: they would turn about that node as one
    // body, where two blocks touching at a corner make no joint (a review:
    // the upper of two squares of one entity touching at a corner ended
    // 'converged', hung from that node). Refused: a block's cells share
    // faces. After the test of duplicated nodes, which part a block so too
    // and are named as such.
    {
      DisjointSets by_faces(n_cells);
      for (const auto &cell : file_mesh.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (!cell->at_boundary(f) &&
              same_body(cell->active_cell_index(),
                        cell->neighbor(f)->active_cell_index()))
            by_faces.unite(cell->active_cell_index(),
                           cell->neighbor(f)->active_cell_index());
      for (unsigned int v = 0; v < cells_at_vertex.size(); ++v)
        for (const unsigned int c : cells_at_vertex[v])
          for (const unsigned int d : cells_at_vertex[v])
            if (block[c] == block[d] && by_faces.find(c) != by_faces.find(d))
              {
                std::ostringstream message;
                message << "cells of block " << block[c] << " (physical group '"
                        << result.tag_of_block[block[c]]
                        << "') meet only at a corner"
                        << (dim == 3 ? " or an edge" : "") << ", at the node ("
                        << file_mesh.get_vertices()[v]
                        << "), not along a face: a block's cells must share "
                           "faces; put each part into its own entity or "
                           "physical group (two blocks touching at a corner), "
                           "or mesh them as one region";
                fail(file_name, message.str());
              }
    }

    triangulation.clear();
    try
      {
        for (dealii::Point<dim> &vertex : vertices)
          vertex -= scan.local_origin;
        triangulation.create_triangulation(vertices,
                                           cells,
                                           dealii::SubCellData());
        dealii::GridTools::shift(scan.local_origin, triangulation);
      }
    catch (const std::exception &exception)
      {
        std::string reason = exception.what();
        std::replace(reason.begin(), reason.end(), '\n', ' ');
        fail(file_name,
             "its blocks do not form a valid mesh: " +
               dealii::Utilities::trim(reason));
      }
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          {
            cell->face(f)->set_boundary_id(0);
            const dealii::Point<dim> centre = cell->face(f)->center();
            const auto               key    = grid_key<dim>(centre, spacing);
            for (unsigned int probe = 0; probe < (dim == 2 ? 9u : 27u); ++probe)
              {
                auto neighbour = key;
                for (unsigned int d = 0, q = probe; d < dim; ++d, q /= 3)
                  neighbour[d] += static_cast<long long>(q % 3) - 1;
                const auto found = boundary_faces.find(neighbour);
                if (found != boundary_faces.end())
                  for (const auto &[point, id] : found->second)
                    if (id.first == cell->material_id() &&
                        point.distance(centre) < spacing)
                      cell->face(f)->set_boundary_id(id.second);
              }
          }

    {
      const BoxGrid<dim> boxes(triangulation);
      check_no_overlap<dim>(boxes, scan.simplex, file_name);
      check_cells_separated<dim>(boxes, file_name);
    }

    BoundaryNames &names = result.boundaries;
    names.source         = std::filesystem::path(file_name).filename().string();
    names.fix = "the defaults name the built-in walls' boundaries: set this "
                "parameter for your mesh";
    for (const auto &[name, tag] : scan.boundary_tag_names)
      names.id_of_name[name] = static_cast<dealii::types::boundary_id>(tag);
    for (const auto id : triangulation.get_boundary_ids())
      names.ids_on_boundary.insert(id);
    return result;
  }

  template MeshFileBlocks
  read_mesh_file<2>(const std::string &, dealii::Triangulation<2, 2> &);
  template MeshFileBlocks
  read_mesh_file<3>(const std::string &, dealii::Triangulation<3, 3> &);
} // namespace unilateral::masonry
