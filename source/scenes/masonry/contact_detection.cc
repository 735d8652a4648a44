#include <unilateral/base/input_error.h>
#include <unilateral/scenes/masonry/contact_detection.h>
#include <unilateral/scenes/masonry/face_region.h>

#include <deal.II/base/quadrature.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/tria.h>

#include <boost/container/small_vector.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <sstream>
#include <stdexcept>
#include <type_traits>

namespace unilateral::masonry
{
  static_assert(std::is_same_v<DofIndex, dealii::types::global_dof_index>,
                "DofIndex must match deal.II's global_dof_index");

  template <int dim>
  std::string
  describe_point(const std::array<double, dim> &point, const unsigned int block)
  {
    std::ostringstream text;
    text << "(" << point[0];
    for (unsigned int d = 1; d < dim; ++d)
      text << ", " << point[d];
    text << ") in block " << block;
    return text.str();
  }

  template <int dim>
  std::string
  ContactSet<dim>::describe_node(const unsigned int node) const
  {
    return "the node at " +
           describe_point<dim>(node_position[node], node_block[node]);
  }

  namespace
  {
    /// Faces of cells whose normals differ by less than this angle are
    /// one curved surface at a node: their normals are averaged.
    const double same_surface = std::cos(25.0 * M_PI / 180.0);

    template <int dim>
    std::array<double, dim>
    as_array(const dealii::Tensor<1, dim> &t)
    {
      std::array<double, dim> a;
      for (unsigned int d = 0; d < dim; ++d)
        a[d] = t[d];
      return a;
    }

    template <int dim>
    dealii::Tensor<1, dim>
    as_tensor(const std::array<double, dim> &a)
    {
      dealii::Tensor<1, dim> t;
      for (unsigned int d = 0; d < dim; ++d)
        t[d] = a[d];
      return t;
    }

    /// A boundary face of one block.
    template <int dim>
    struct FaceRecord
    {
      typename dealii::DoFHandler<dim>::active_cell_iterator cell;
      unsigned int                                           face_no;
      unsigned int                                           block;
      dealii::types::boundary_id                             boundary;
      std::vector<dealii::Point<dim>>                        vertices;
      dealii::Tensor<1, dim>    normal; ///< outward
      std::vector<unsigned int> nodes;
      double                    diameter;
      /// How far its vertices lie out of one plane, where more than
      /// flatness allows (0: flat). 3D only.
      double warp = 0;
    };

    /**
     * Refuses a warped face where its normal matters: node-to-node contact
     * (a joint, a roller, a Signorini support) constrains every node of a
     * face along one normal, which a twisted face does not have. Elsewhere
     * (a traction-free or loaded surface, a 'Fixed' one: the intrados of a
     * vault meshed by hexahedra) a warped face is accepted. @p use names
     * what needs the normal.
     */
    template <int dim>
    [[noreturn]] void
    refuse_warped(const FaceRecord<dim> &face, const std::string &use)
    {
      dealii::Point<dim> centre;
      for (const auto &v : face.vertices)
        centre += v / static_cast<double>(face.vertices.size());
      std::ostringstream message;
      message << "block " << face.block << " has a warped face centred at ("
              << centre << ") with " << use << ": its vertices are "
              << face.warp
              << " out of one plane, and node-to-node contact constrains "
                 "every node of a face along one normal, so it needs flat "
                 "faces there; mesh that surface with planar "
                 "quadrilaterals (warped faces are accepted only where "
                 "nothing touches them), or, where it is flat but its "
                 "coordinates were written with too few digits, write more "
                 "of them or raise 'Masonry/Coincidence tolerance' past the "
                 "largest such warp over the smallest cell's edge (other "
                 "faces may be warped more than this one)";
      throw InputError(message.str());
    }

    /// A unit normal from the face's vertices, pointing away from the
    /// cell's centre (a warped face's mean normal, its warp in @p warp);
    /// InputError for a degenerate face.
    template <int dim>
    dealii::Tensor<1, dim>
    face_normal(const std::vector<dealii::Point<dim>> &v,
                const dealii::Point<dim>              &cell_centre,
                const unsigned int                     block,
                const double                           tolerance,
                double                                &warp)
    {
      dealii::Tensor<1, dim> n;
      if constexpr (dim == 2)
        {
          const dealii::Tensor<1, 2> t = v[1] - v[0];
          n[0]                         = t[1];
          n[1]                         = -t[0];
        }
      else if (v.size() == 3)
        n = dealii::cross_product_3d(v[1] - v[0], v[2] - v[0]);
      else // deal.II's quadrilateral vertex order: diagonals 0-3 and 1-2
        n = dealii::cross_product_3d(v[3] - v[0], v[2] - v[1]);
      // |n| is the face's length in 2D and twice its area in 3D (a
      // quadrilateral's: the diagonals' cross product); compared with the
      // tolerance (a length) in the same units, so that the test does not
      // change with the mesh's length unit.
      const double size = v[0].distance(v.back());
      if (n.norm() <= tolerance * (dim == 2 ? 1.0 : size))
        {
          std::ostringstream message;
          message << "block " << block << " has a degenerate face at (" << v[0]
                  << "): its vertices do not span a "
                  << (dim == 2 ? "segment" : "surface")
                  << "; remove the collapsed cell from the mesh";
          throw InputError(message.str());
        }
      n /= n.norm();
      dealii::Point<dim> centre;
      for (const auto &p : v)
        centre += p / static_cast<double>(v.size());
      warp = 0;
      for (const auto &p : v)
        if (std::abs((p - centre) * n) > 1e-6 * size + tolerance)
          warp = std::max(warp, std::abs((p - centre) * n));
      if ((centre - cell_centre) * n < 0)
        n = -n;
      return n;
    }

    /// Coordinates in the plane of the direction class d.
    template <int dim>
    struct PlaneBasis
    {
      explicit PlaneBasis(const std::array<double, dim> &d)
      {
        unsigned int smallest = 0;
        for (unsigned int c = 1; c < dim; ++c)
          if (std::abs(d[c]) < std::abs(d[smallest]))
            smallest = c;
        const dealii::Tensor<1, dim> n = as_tensor<dim>(d);
        dealii::Tensor<1, dim>       axis;
        axis[smallest] = 1;
        t1             = axis - (axis * n) * n;
        t1 /= t1.norm();
        if constexpr (dim == 3)
          t2 = dealii::cross_product_3d(n, t1);
      }

      std::array<double, 2>
      operator()(const dealii::Point<dim> &p) const
      {
        return {{p * t1, dim == 3 ? p * t2 : 0.0}};
      }

      dealii::Tensor<1, dim> t1, t2;
    };

    using Polygon = std::vector<std::array<double, 2>>;

    double
    cross(const std::array<double, 2> &o,
          const std::array<double, 2> &a,
          const std::array<double, 2> &b)
    {
      return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
    }

    /// Counter-clockwise order of a convex polygon's vertices (deal.II's
    /// quadrilaterals are numbered lexicographically, not around).
    Polygon
    convex_hull_order(Polygon p)
    {
      if (p.size() == 4)
        std::swap(p[2], p[3]);
      double area = 0;
      for (std::size_t i = 0; i < p.size(); ++i)
        area += cross({{0, 0}}, p[i], p[(i + 1) % p.size()]);
      if (area < 0)
        std::reverse(p.begin(), p.end());
      return p;
    }

    /// The area of the intersection of two convex counter-clockwise
    /// polygons (Sutherland-Hodgman).
    double
    overlap_area(const Polygon &subject, const Polygon &clip)
    {
      Polygon output = subject;
      for (std::size_t i = 0; i < clip.size() && !output.empty(); ++i)
        {
          const auto &a     = clip[i];
          const auto &b     = clip[(i + 1) % clip.size()];
          Polygon     input = output;
          output.clear();
          for (std::size_t j = 0; j < input.size(); ++j)
            {
              const auto  &p  = input[j];
              const auto  &q  = input[(j + 1) % input.size()];
              const double cp = cross(a, b, p), cq = cross(a, b, q);
              if (cp >= 0)
                output.push_back(p);
              if ((cp >= 0) != (cq >= 0))
                {
                  const double t = cp / (cp - cq);
                  output.push_back(
                    {{p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])}});
                }
            }
        }
      double area = 0;
      for (std::size_t i = 0; i < output.size(); ++i)
        area += cross({{0, 0}}, output[i], output[(i + 1) % output.size()]);
      return 0.5 * area;
    }

    /// Whether @p p lies in the closed convex polygon (or segment, 2D),
    /// to @p tolerance.
    bool
    inside(const Polygon               &polygon,
           const std::array<double, 2> &p,
           const double                 tolerance,
           const bool                   segment)
    {
      if (segment)
        return p[0] >= std::min(polygon[0][0], polygon[1][0]) - tolerance &&
               p[0] <= std::max(polygon[0][0], polygon[1][0]) + tolerance;
      for (std::size_t i = 0; i < polygon.size(); ++i)
        {
          const auto  &a      = polygon[i];
          const auto  &b      = polygon[(i + 1) % polygon.size()];
          const double length = std::hypot(b[0] - a[0], b[1] - a[1]);
          if (cross(a, b, p) < -tolerance * length)
            return false;
        }
      return true;
    }

    /// Unit vectors grouped where they differ by less than same_surface,
    /// each group averaged.
    template <int dim>
    struct NormalGroups
    {
      struct Group
      {
        dealii::Tensor<1, dim>   sum;
        std::vector<std::size_t> items;

        std::array<double, dim>
        mean() const
        {
          return as_array<dim>(sum / sum.norm());
        }
      };

      void
      add(const dealii::Tensor<1, dim> &n, const std::size_t item)
      {
        for (Group &group : groups)
          if (n * (group.sum / group.sum.norm()) > same_surface)
            {
              group.sum += n;
              group.items.push_back(item);
              return;
            }
        groups.push_back({n, {item}});
      }

      std::vector<Group> groups;
    };

    /// The faces behind one end of a constraint (one to a few), sorted,
    /// each once: a small vector rather than a std::set, as a wall has
    /// hundreds of thousands of constraints.
    using FaceList = boost::container::small_vector<std::size_t, 2>;

    void
    add_face(FaceList &list, const std::size_t face)
    {
      const auto at = std::lower_bound(list.begin(), list.end(), face);
      if (at == list.end() || *at != face)
        list.insert(at, face);
    }

    /// Per node, what its supports' faces say.
    template <int dim>
    struct NodeConditions
    {
      int                       held_support = -1;
      std::array<double, dim>   held_value{};
      NormalGroups<dim>         rollers, signorini;
      std::vector<unsigned int> roller_support, signorini_support;
      std::vector<std::size_t>  roller_face, signorini_face;
    };

    /// Whether @p a and @p b differ by at most @p tolerance in every
    /// component (the direction classes' measure).
    template <int dim>
    bool
    within_tolerance(const dealii::Tensor<1, dim> &a,
                     const dealii::Tensor<1, dim> &b,
                     const double                  tolerance)
    {
      for (unsigned int c = 0; c < dim; ++c)
        if (std::abs(a[c] - b[c]) > tolerance)
          return false;
      return true;
    }

    /**
     * Boundary faces on a grid of cells as large as the median face (or
     * 1/64 of the largest: a huge face then spans a bounded number of
     * cells, and a cell holds few small faces), each face in every cell its
     * box (grown by near) meets; a face looks for others in the cells its
     * own box meets.
     */
    template <int dim>
    class FaceGrid
    {
    public:
      /// The faces for which @p included is true, on the grid.
      template <typename Predicate>
      FaceGrid(const std::vector<FaceRecord<dim>> &faces,
               const double                        near,
               const Predicate                    &included)
        : near(near)
      {
        std::vector<double> diameters;
        for (const FaceRecord<dim> &face : faces)
          diameters.push_back(face.diameter);
        spacing = near;
        if (!diameters.empty())
          {
            std::nth_element(diameters.begin(),
                             diameters.begin() + diameters.size() / 2,
                             diameters.end());
            spacing = std::max(
              {near,
               diameters[diameters.size() / 2],
               *std::max_element(diameters.begin(), diameters.end()) / 64});
          }
        for (std::size_t f = 0; f < faces.size(); ++f)
          if (included(f))
            for_each_cell(box(faces[f]), [&](const Cell &cell) {
              cells.emplace_back(cell, f);
            });
        std::sort(cells.begin(), cells.end());
      }

      bool
      empty() const
      {
        return cells.empty();
      }

      /// action(f) for every face f on the grid near @p face (a face may
      /// come more than once).
      template <typename Action>
      void
      for_each_near(const FaceRecord<dim> &face, const Action &action) const
      {
        for_each_cell(box(face), [&](const Cell &cell) {
          for (auto at = std::lower_bound(cells.begin(),
                                          cells.end(),
                                          cell,
                                          [](const auto &entry, const Cell &c) {
                                            return entry.first < c;
                                          });
               at != cells.end() && at->first == cell;
               ++at)
            action(at->second);
        });
      }

    private:
      using Cell = std::array<long, dim>;

      std::array<Cell, 2>
      box(const FaceRecord<dim> &face) const
      {
        std::array<Cell, 2> range;
        for (unsigned int c = 0; c < dim; ++c)
          {
            double lo = std::numeric_limits<double>::max(), hi = -lo;
            for (const auto &v : face.vertices)
              {
                lo = std::min(lo, v[c]);
                hi = std::max(hi, v[c]);
              }
            range[0][c] = std::lround(std::floor((lo - near) / spacing));
            range[1][c] = std::lround(std::floor((hi + near) / spacing));
          }
        return range;
      }

      template <typename Action>
      static void
      for_each_cell(const std::array<Cell, 2> &range, const Action &action)
      {
        Cell cell = range[0];
        while (true)
          {
            action(cell);
            unsigned int c = 0;
            for (; c < dim; ++c)
              {
                if (++cell[c] <= range[1][c])
                  break;
                cell[c] = range[0][c];
              }
            if (c == dim)
              return;
          }
      }

      double near;
      double spacing;
      // (grid cell, face) for every cell each face's box meets, sorted:
      // the faces of a cell in their order (a sort, not a map: a wall has
      // hundreds of thousands of faces).
      std::vector<std::pair<Cell, std::size_t>> cells;
    };

    /**
     * Refuses faces of two blocks that nearly coincide but are not
     * parallel: each face's vertices within @p near of the other's plane,
     * facing each other and overlapping by more than @p tolerance, their
     * normals in different direction classes (further apart than
     * @p direction_tolerance). Joints are sought only between faces of one
     * class, so such faces (a face tilted by 1e-7, a mesh written with too
     * few digits) would be left without a joint, and without a word.
     * @p joined: the faces that have a joint; only pairs with a face
     * without one are looked at.
     */
    template <int dim>
    void
    refuse_tilted_faces(const std::vector<FaceRecord<dim>> &faces,
                        const std::vector<unsigned int>    &face_class,
                        const std::vector<char>            &joined,
                        const double                        near,
                        const double                        tolerance,
                        const double                        cell_size,
                        const double                        direction_tolerance)
    {
      // The faces without a joint on a grid; every face looks for them.
      const FaceGrid<dim> unjoined(faces, near, [&](const std::size_t f) {
        return !joined[f];
      });
      if (unjoined.empty())
        return;

      const auto centre = [](const FaceRecord<dim> &face) {
        dealii::Point<dim> x;
        for (const auto &v : face.vertices)
          x += v / static_cast<double>(face.vertices.size());
        return x;
      };
      // Every vertex of a within near of b's plane (of b's mean plane,
      // beyond the warp of either).
      const auto near_plane = [&](const FaceRecord<dim> &a,
                                  const FaceRecord<dim> &b) {
        const dealii::Point<dim> x = centre(b);
        for (const auto &v : a.vertices)
          if (std::abs((v - x) * b.normal) > near + a.warp + b.warp)
            return false;
        return true;
      };
      // The overlap of the faces seen along p's normal: a length in 2D, an
      // area over the larger diameter in 3D (as for joints).
      const auto overlap = [&](const FaceRecord<dim> &p,
                               const FaceRecord<dim> &q) {
        const PlaneBasis<dim> basis(as_array<dim>(p.normal));
        Polygon               a, b;
        for (const auto &v : p.vertices)
          a.push_back(basis(v));
        for (const auto &v : q.vertices)
          b.push_back(basis(v));
        if constexpr (dim == 2)
          return std::min(std::max(a[0][0], a[1][0]),
                          std::max(b[0][0], b[1][0])) -
                 std::max(std::min(a[0][0], a[1][0]),
                          std::min(b[0][0], b[1][0]));
        else
          return overlap_area(convex_hull_order(a), convex_hull_order(b)) /
                 std::max(p.diameter, q.diameter);
      };

      // The first such pair is named; the tolerance to suggest is the
      // largest any pair needs (a review: a block tilted by 1e-7 about one
      // end was told the 1.5e-7 its first face needed, then refused at its
      // far end).
      std::string first_pair;
      double      most_needed = 0;
      for (std::size_t p = 0; p < faces.size(); ++p)
        unjoined.for_each_near(faces[p], [&](const std::size_t q) {
          const FaceRecord<dim> &a = faces[p], &b = faces[q];
          // Faces within the tolerance of each other were compared
          // for a joint (in one class or in neighbouring ones).
          if (a.block == b.block || face_class[p] == face_class[q] ||
              within_tolerance(a.normal, -b.normal, direction_tolerance) ||
              a.normal * b.normal >= 0 || !near_plane(a, b) ||
              !near_plane(b, a) || overlap(a, b) <= tolerance)
            return;
          for (const FaceRecord<dim> *face : {&a, &b})
            if (face->warp > 0)
              refuse_warped(*face,
                            "a joint to block " +
                              std::to_string(face == &a ? b.block : a.block));
          const double angle =
            std::acos(std::max(-1.0, std::min(1.0, -(a.normal * b.normal))));
          double distance = 0;
          for (const auto &v : b.vertices)
            distance = std::max(distance, std::abs((v - centre(a)) * a.normal));
          // Joined if their normals share a class (4 tau) and their
          // nodes coincide (tau of the smallest cell). (Not the distance
          // of each node from the other face's nearest: neighbouring cell
          // faces that overlap a little are a whole cell apart, and the
          // suggestion vanished at tilts of 5e-5, a review.)
          most_needed =
            std::max(most_needed,
                     std::max(angle / 4, distance / cell_size) * 1.5);
          if (!first_pair.empty())
            return;
          std::ostringstream message;
          message << "blocks " << a.block << " and " << b.block
                  << " have faces that nearly coincide (near "
                  << describe_point<dim>(as_array<dim>(
                                           dealii::Tensor<1, dim>(centre(a))),
                                         a.block)
                  << ", at most " << distance
                  << " apart) but are not parallel: their normals differ "
                     "by "
                  << angle << " rad, more than the " << direction_tolerance
                  << " of a joint (4 times 'Masonry/Coincidence "
                     "tolerance'), so no joint would be made between "
                     "them; make the faces coincide (a mesh written with "
                     "few significant digits: write more)";
          first_pair = message.str();
        });
      if (first_pair.empty())
        return;
      std::ostringstream message;
      message << first_pair;
      if (most_needed <= 1e-3)
        message << ", raise 'Masonry/Coincidence tolerance' to "
                << std::setprecision(2) << most_needed
                << " or more if they are meant to touch";
      message << ", or move them further apart (more than " << near << ")";
      throw InputError(message.str());
    }

    /**
     * Whether @p p lies on the face, strictly inside it (beyond 1e-3 of its
     * parameter range from its edges: a node on a shared edge does not
     * count) and within @p near of its surface: the bilinear image of a
     * quadrilateral's vertices (deal.II's order: x(s, t) = v0 (1-s)(1-t) +
     * v1 s (1-t) + v2 (1-s) t + v3 s t), found by Gauss-Newton, or a
     * triangle's plane.
     */
    bool
    on_face(const std::vector<dealii::Point<3>> &v,
            const dealii::Point<3>              &p,
            const double                         near)
    {
      constexpr double edge = 1e-3;
      if (v.size() == 3)
        {
          const dealii::Tensor<1, 3> a = v[1] - v[0], b = v[2] - v[0],
                                     r = p - v[0];
          const double           aa = a * a, ab = a * b, bb = b * b;
          const double           det = aa * bb - ab * ab;
          const double           s   = (bb * (r * a) - ab * (r * b)) / det;
          const double           t   = (aa * (r * b) - ab * (r * a)) / det;
          const dealii::Point<3> x   = v[0] + s * a + t * b;
          return s > edge && t > edge && s + t < 1 - edge &&
                 x.distance(p) <= near;
        }
      double     s = 0.5, t = 0.5;
      const auto at = [&](const double s, const double t) {
        return dealii::Point<3>((1 - s) * (1 - t) * v[0] + s * (1 - t) * v[1] +
                                (1 - s) * t * v[2] + s * t * v[3]);
      };
      for (unsigned int k = 0; k < 20; ++k)
        {
          const dealii::Tensor<1, 3> r = at(s, t) - p;
          const dealii::Tensor<1, 3> xs =
            (v[1] - v[0]) * (1 - t) + (v[3] - v[2]) * t;
          const dealii::Tensor<1, 3> xt =
            (v[2] - v[0]) * (1 - s) + (v[3] - v[1]) * s;
          const double a = xs * xs, b = xs * xt, c = xt * xt;
          const double det = a * c - b * b;
          if (!(det > 0))
            return false;
          s = std::clamp(s - (c * (xs * r) - b * (xt * r)) / det, -1.0, 2.0);
          t = std::clamp(t - (a * (xt * r) - b * (xs * r)) / det, -1.0, 2.0);
        }
      return s > edge && s < 1 - edge && t > edge && t < 1 - edge &&
             at(s, t).distance(p) <= near;
    }

    /**
     * Refuses a warped face that a face of another block touches, whatever
     * their normals: the joints' sweep pairs faces of one direction class,
     * and the check for tilted faces compares planes, which a warped face
     * does not have (a review: a warped face on a neighbour meshed 2 x 2
     * escaped both, and the blocks passed through each other). Touching: a
     * node of either face on the other (on_face), among the faces near it
     * on a FaceGrid.
     */
    template <int dim>
    void
    refuse_touching_warped_faces(
      const std::vector<FaceRecord<dim>>         &faces,
      const std::vector<std::array<double, dim>> &node_position,
      const double                                near)
    {
      if constexpr (dim == 3)
        {
          if (std::none_of(faces.begin(), faces.end(), [](const auto &face) {
                return face.warp > 0;
              }))
            return;
          const FaceGrid<dim> grid(faces, near, [](const std::size_t) {
            return true;
          });
          const auto          touches = [&](const FaceRecord<dim> &a,
                                   const FaceRecord<dim> &b) {
            for (const unsigned int node : b.nodes)
              if (on_face(a.vertices,
                          dealii::Point<3>(node_position[node][0],
                                           node_position[node][1],
                                           node_position[node][2]),
                          near))
                return true;
            return false;
          };
          for (const FaceRecord<dim> &a : faces)
            if (a.warp > 0)
              grid.for_each_near(a, [&](const std::size_t f) {
                if (faces[f].block != a.block &&
                    (touches(a, faces[f]) || touches(faces[f], a)))
                  refuse_warped(a,
                                "a face of block " +
                                  std::to_string(faces[f].block) + " on it");
              });
        }
    }
  } // namespace

  template <int dim>
  ContactSet<dim>
  detect_contacts(const dealii::DoFHandler<dim, dim> &dof_handler,
                  const dealii::Mapping<dim, dim>    &mapping,
                  const Supports<dim>                &supports,
                  const double                        tolerance,
                  const double                        cell_size)
  {
    using Kind                               = typename Support<dim>::Kind;
    const dealii::FiniteElement<dim> &fe     = dof_handler.get_fe();
    const DofIndex                    n_dofs = dof_handler.n_dofs();
    ContactSet<dim>                   result;

    // The nodes, numbered in the order of their first component's DOF, at
    // the element's support points mapped into each cell: what
    // DoFTools::map_dofs_to_support_points computes (the same FEValues),
    // without the std::map of every DOF that it fills first.
    std::vector<dealii::Point<dim>> support_point(n_dofs);
    dealii::FEValues<dim>           support_values(mapping,
                                         fe,
                                         dealii::Quadrature<dim>(
                                           fe.get_unit_support_points()),
                                         dealii::update_quadrature_points);
    const unsigned int n_nodes_per_cell = fe.base_element(0).n_dofs_per_cell();
    std::vector<dealii::types::global_dof_index> dofs(fe.n_dofs_per_cell());
    {
      std::vector<std::array<DofIndex, dim>> dofs_of_first(
        n_dofs, std::array<DofIndex, dim>{});
      std::vector<unsigned int> block_of_first(n_dofs, 0);
      std::vector<char>         first(n_dofs, 0);
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          cell->get_dof_indices(dofs);
          support_values.reinit(cell);
          for (unsigned int k = 0; k < n_nodes_per_cell; ++k)
            {
              const unsigned int i = fe.component_to_system_index(0, k);
              const DofIndex     x = dofs[i];
              first[x]             = 1;
              block_of_first[x]    = cell->material_id();
              support_point[x]     = support_values.quadrature_point(i);
              for (unsigned int c = 0; c < dim; ++c)
                dofs_of_first[x][c] = dofs[fe.component_to_system_index(c, k)];
            }
        }
      result.node_of_dof.assign(n_dofs, 0);
      for (DofIndex i = 0; i < n_dofs; ++i)
        if (first[i])
          {
            const auto node =
              static_cast<unsigned int>(result.node_dofs.size());
            result.node_dofs.push_back(dofs_of_first[i]);
            result.node_position.push_back(
              as_array<dim>(dealii::Tensor<1, dim>(support_point[i])));
            result.node_block.push_back(block_of_first[i]);
            for (const DofIndex dof : dofs_of_first[i])
              result.node_of_dof[dof] = node;
          }
    }
    const std::size_t n_nodes = result.node_dofs.size();

    // The boundary faces, with their nodes.
    std::vector<FaceRecord<dim>>                 faces;
    std::vector<dealii::types::global_dof_index> face_dofs;
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        {
          if (!cell->face(f)->at_boundary())
            continue;
          const auto      face = cell->face(f);
          FaceRecord<dim> record;
          record.cell     = cell;
          record.face_no  = f;
          record.block    = cell->material_id();
          record.boundary = face->boundary_id();
          for (const unsigned int v : face->vertex_indices())
            record.vertices.push_back(face->vertex(v));
          record.normal   = face_normal<dim>(record.vertices,
                                           cell->center(),
                                           record.block,
                                           tolerance,
                                           record.warp);
          record.diameter = face->diameter();
          face_dofs.resize(fe.n_dofs_per_face(f));
          face->get_dof_indices(face_dofs);
          for (unsigned int i = 0; i < face_dofs.size(); ++i)
            if (fe.face_system_to_component_index(i, f).first == 0)
              record.nodes.push_back(result.node_of_dof[face_dofs[i]]);
          faces.push_back(std::move(record));
        }
    // Faces nearer than this to each other touch (or nearly do).
    const double near = 1e-2 * cell_size;
    refuse_touching_warped_faces<dim>(faces, result.node_position, near);

    // int phi over a face of each of its nodes (for the contact pressure).
    const dealii::Quadrature<dim - 1> face_quadrature =
      fe.reference_cell()
        .face_reference_cell(0)
        .template get_gauss_type_quadrature<dim - 1>(3);
    dealii::FEFaceValues<dim> fe_face_values(mapping,
                                             fe,
                                             face_quadrature,
                                             dealii::update_values |
                                               dealii::update_JxW_values);
    // Computed once per face that carries a constraint, on first need: a
    // face is shared by the constraints of all its nodes.
    std::vector<std::vector<std::pair<unsigned int, double>>> face_weights(
      faces.size());
    const auto node_weight = [&](const std::size_t f, const unsigned int node) {
      auto &weights = face_weights[f];
      if (weights.empty())
        {
          const FaceRecord<dim> &face = faces[f];
          fe_face_values.reinit(face.cell, face.face_no);
          face.cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
            if (fe.system_to_component_index(i).first == 0)
              {
                double integral = 0;
                for (unsigned int q = 0; q < fe_face_values.n_quadrature_points;
                     ++q)
                  integral += fe_face_values.shape_value_component(i, q, 0) *
                              fe_face_values.JxW(q);
                weights.emplace_back(result.node_of_dof[dofs[i]], integral);
              }
        }
      double weight = 0;
      bool   found  = false;
      for (const auto &[at, integral] : weights)
        if (at == node)
          {
            weight += integral;
            found = true;
          }
      if (!found)
        throw std::logic_error("detect_contacts: a constraint's node is not "
                               "on its face");
      return weight;
    };

    // Supports, node by node: conditions only for the nodes that have one
    // (a wall's boundary), found through condition_of.
    constexpr auto no_condition = std::numeric_limits<unsigned int>::max();
    std::vector<unsigned int>        condition_of(n_nodes, no_condition);
    std::vector<NodeConditions<dim>> conditions;
    const auto conditions_at = [&](const unsigned int node) -> auto &
    {
      if (condition_of[node] == no_condition)
        {
          condition_of[node] = static_cast<unsigned int>(conditions.size());
          conditions.emplace_back();
        }
      return conditions[condition_of[node]];
    };
    std::map<const Support<dim> *, unsigned int> support_index;
    for (const Support<dim> &support : supports.list)
      if (support.kind != Kind::traction)
        {
          support_index[&support] =
            static_cast<unsigned int>(result.support_names.size());
          result.support_names.push_back(support.name);
        }
    // Whether each support acts at some node; a traction (which the
    // assembly integrates over the faces' parts in its region) whether it
    // loads some face.
    std::set<const Support<dim> *> acting;
    for (std::size_t f = 0; f < faces.size(); ++f)
      for (const Support<dim> *support :
           supports.on_boundary(faces[f].boundary))
        if (support->kind == Kind::traction)
          {
            if (support->region == nullptr ||
                face_touches_region<dim>(
                  faces[f].vertices, [support](const dealii::Point<dim> &x) {
                    return support->region->value(x) > 0.5;
                  }))
              acting.insert(support);
          }
        else
          for (const unsigned int node : faces[f].nodes)
            {
              const dealii::Point<dim> p(
                as_tensor<dim>(result.node_position[node]));
              if (!supports.acts_at(*support, p, faces[f].vertices))
                continue;
              acting.insert(support);
              const unsigned int   index = support_index.at(support);
              NodeConditions<dim> &c     = conditions_at(node);
              if (support->kind == Kind::held)
                {
                  std::array<double, dim> value{};
                  if (support->prescribed)
                    for (unsigned int d = 0; d < dim; ++d)
                      value[d] = supports.displacement->value(p, d);
                  if (c.held_support >= 0)
                    {
                      double difference = 0;
                      for (unsigned int d = 0; d < dim; ++d)
                        difference =
                          std::max(difference,
                                   std::abs(value[d] - c.held_value[d]));
                      if (difference > tolerance)
                        throw InputError(
                          result.describe_node(node) + " lies on '" +
                          result.support_names[c.held_support] + "' and '" +
                          support->name +
                          "', which prescribe different displacements "
                          "there; let the two boundaries meet in different "
                          "blocks or prescribe the same displacement");
                      continue;
                    }
                  c.held_support = static_cast<int>(index);
                  c.held_value   = value;
                }
              else if (faces[f].warp > 0)
                refuse_warped(faces[f], "the support '" + support->name + "'");
              else if (support->kind == Kind::normal_zero)
                {
                  c.rollers.add(faces[f].normal, c.roller_support.size());
                  c.roller_support.push_back(index);
                  c.roller_face.push_back(f);
                }
              else
                {
                  c.signorini.add(faces[f].normal, c.signorini_face.size());
                  c.signorini_support.push_back(index);
                  c.signorini_face.push_back(f);
                }
            }

    for (const Support<dim> &support : supports.list)
      if (support.region != nullptr && acting.count(&support) == 0)
        result.supports_acting_nowhere.push_back(support.description);

    // Resolve: held nodes take nothing else; a roller removes Signorini
    // in its direction.
    struct SignoriniRow
    {
      unsigned int            node;
      std::array<double, dim> normal; ///< into the block
      unsigned int            support;
      double                  bound;
      FaceList                faces;
    };
    std::vector<SignoriniRow> signorini_rows;
    for (std::size_t node = 0; node < n_nodes; ++node)
      {
        if (condition_of[node] == no_condition)
          continue;
        const NodeConditions<dim> &c = conditions[condition_of[node]];
        if (c.held_support >= 0)
          {
            result.held.push_back(
              {static_cast<unsigned int>(node), c.held_value});
            result.held_support.push_back(c.held_support);
            result.n_held_dofs += dim;
            continue;
          }
        for (const auto &group : c.rollers.groups)
          {
            result.rollers.push_back(
              {static_cast<unsigned int>(node), group.mean()});
            result.roller_support.push_back(
              c.roller_support[group.items.front()]);
            // Its weight spans the Signorini faces it takes over too (at the
            // end of a held part of a base, half of the node's faces): the
            // reaction there is their load as well.
            std::set<std::size_t> roller_faces;
            for (const std::size_t item : group.items)
              roller_faces.insert(c.roller_face[item]);
            const dealii::Tensor<1, dim> roller_normal =
              as_tensor<dim>(group.mean());
            for (const auto &signorini : c.signorini.groups)
              if (std::abs(roller_normal * as_tensor<dim>(signorini.mean())) >
                  1 - 1e-9)
                for (const std::size_t item : signorini.items)
                  roller_faces.insert(c.signorini_face[item]);
            double weight = 0;
            for (const std::size_t f : roller_faces)
              weight += node_weight(f, static_cast<unsigned int>(node));
            result.roller_weight.push_back(weight);
          }
        for (const auto &group : c.signorini.groups)
          {
            const dealii::Tensor<1, dim> n      = as_tensor<dim>(group.mean());
            bool                         rolled = false;
            for (const auto &roller : c.rollers.groups)
              rolled = rolled ||
                       std::abs(n * as_tensor<dim>(roller.mean())) > 1 - 1e-9;
            if (rolled)
              continue;
            const dealii::Point<dim> p(
              as_tensor<dim>(result.node_position[node]));
            double gap = supports.gap->value(p);
            if (!std::isfinite(gap))
              throw InputError("parameter 'Masonry/Boundary conditions/"
                               "Signorini gap' is not finite at " +
                               result.describe_node(node));
            // As its help says: a support inside the block would push
            // the wall off at the start, which no settlement means. A gap
            // below zero by less than the coincidence tolerance is zero
            // rounded (an expression of coordinates that vanishes on the
            // support, evaluated at rounded node positions).
            if (gap < 0 && gap >= -tolerance)
              gap = 0;
            if (gap < 0)
              {
                std::ostringstream message;
                message << std::setprecision(12)
                        << "parameter 'Masonry/Boundary conditions/Signorini "
                           "gap' is "
                        << gap << " < 0 at " << result.describe_node(node)
                        << ": the support would lie inside the block; give a "
                           "gap >= 0 (0: the support touches the block; "
                           "above -"
                        << tolerance
                        << ", 'Coincidence tolerance' times the smallest "
                           "cell, counts as 0)";
                throw InputError(message.str());
              }
            FaceList support_faces;
            for (const std::size_t item : group.items)
              add_face(support_faces, c.signorini_face[item]);
            signorini_rows.push_back({static_cast<unsigned int>(node),
                                      as_array<dim>(-n),
                                      c.signorini_support[group.items.front()],
                                      -gap,
                                      support_faces});
          }
      }
    result.n_rollers = static_cast<unsigned int>(result.rollers.size());

    // The main component of a direction (for the DOF order of rows).
    auto main_component = [](const std::array<double, dim> &n) {
      unsigned int best = 0;
      for (unsigned int c = 1; c < dim; ++c)
        if (std::abs(n[c]) > std::abs(n[best]) + 1e-12)
          best = c;
      return best;
    };
    std::stable_sort(
      signorini_rows.begin(),
      signorini_rows.end(),
      [&](const SignoriniRow &a, const SignoriniRow &b) {
        return result.node_dofs[a.node][main_component(a.normal)] <
               result.node_dofs[b.node][main_component(b.normal)];
      });
    // The faces behind each end of each constraint (for the weights).
    std::vector<std::array<FaceList, 2>> constraint_faces;
    for (const SignoriniRow &row : signorini_rows)
      {
        result.constraints.push_back(
          {ConstraintKind::signorini, row.node, 0, row.normal, row.bound});
        result.position.push_back(result.node_position[row.node]);
        result.blocks.push_back(
          {{result.node_block[row.node], result.node_block[row.node]}});
        result.signorini_support.push_back(row.support);
        constraint_faces.push_back({{row.faces, {}}});
      }
    result.n_signorini = static_cast<unsigned int>(signorini_rows.size());

    // Joints. Faces by direction class; within a class, faces with
    // outward +d (the lower block) against faces with -d.
    // Normals within 4 tau (tau = 'Coincidence tolerance') share a class:
    // faces whose nodes coincide to tau of the smallest cell may be tilted
    // by about 2 tau against each other (a mesh written with few digits).
    const double direction_tolerance =
      std::max(1e-9, 4 * tolerance / cell_size);
    DirectionClasses<dim>     classes(direction_tolerance);
    std::vector<unsigned int> face_class(faces.size());
    struct ClassFace
    {
      std::size_t face;
      double      offset; ///< d . x on the face
      double      lo, hi; ///< extent along the first in-plane axis
      bool        plus;
      /// From a neighbouring class: joined only to a face whose normal is
      /// within the direction tolerance of its own.
      bool neighbour = false;
    };
    std::vector<std::vector<ClassFace>> by_class;
    // Twice: the classes are all made in the first pass, and the second
    // gives each face the nearest, so that faces with one normal get one
    // class whatever their order (a class made later may be nearer).
    for (const FaceRecord<dim> &face : faces)
      classes.classify(as_array<dim>(face.normal));
    for (std::size_t f = 0; f < faces.size(); ++f)
      {
        const auto [k, sign] = classes.classify(as_array<dim>(faces[f].normal));
        face_class[f]        = k;
        if (k >= by_class.size())
          by_class.resize(k + 1);
        by_class[k].push_back({f, 0, 0, 0, sign > 0});
      }
    struct JointPairRecord
    {
      dealii::Tensor<1, dim> normal; ///< out of the first node's block
      std::size_t            face_first, face_second;
    };
    // Every (node pair, record) found, grouped by pair below (a sort, not a
    // map: a large wall has hundreds of thousands of pairs).
    std::vector<
      std::pair<std::pair<unsigned int, unsigned int>, JointPairRecord>>
      joint_pairs;
    for (std::size_t k = 0; k < by_class.size(); ++k)
      {
        const std::array<double, dim> &d = classes.directions[k];
        // The class's faces, and the -d faces of the classes near it: two
        // faces within the tolerance of each other may lie in two classes
        // (a class is the nearest to its faces, and nearness does not
        // chain), each within the tolerance of its own.
        std::vector<ClassFace> members = by_class[k];
        for (const auto &[j, orientation] :
             classes.within(d, 3 * direction_tolerance))
          if (j != k && j < by_class.size())
            for (const ClassFace &cf : by_class[j])
              if (cf.plus != (orientation > 0))
                members.push_back({cf.face, 0, 0, 0, false, true});
        const PlaneBasis<dim>        basis(d);
        const dealii::Tensor<1, dim> n = as_tensor<dim>(d);
        std::vector<Polygon>         polygon(members.size());
        double                       longest = 0;
        for (std::size_t i = 0; i < members.size(); ++i)
          {
            ClassFace             &cf   = members[i];
            const FaceRecord<dim> &face = faces[cf.face];
            dealii::Point<dim>     centre;
            for (const auto &v : face.vertices)
              centre += v / static_cast<double>(face.vertices.size());
            cf.offset = centre * n;
            cf.lo     = std::numeric_limits<double>::max();
            cf.hi     = -cf.lo;
            for (const auto &v : face.vertices)
              {
                polygon[i].push_back(basis(v));
                cf.lo = std::min(cf.lo, polygon[i].back()[0]);
                cf.hi = std::max(cf.hi, polygon[i].back()[0]);
              }
            if (dim == 3)
              polygon[i] = convex_hull_order(polygon[i]);
            longest = std::max(longest, cf.hi - cf.lo);
          }
        // The -d faces by plane (buckets of width 4 near in the offset),
        // each bucket sorted by the faces' start along t1: each +d face
        // looks at those that can overlap it.
        const auto bucket_of = [&](const double offset) {
          return std::llround(std::floor(offset / (4 * near)));
        };
        std::map<long long, std::vector<std::size_t>> minus;
        for (std::size_t i = 0; i < members.size(); ++i)
          if (!members[i].plus)
            minus[bucket_of(members[i].offset)].push_back(i);
        for (auto &[bucket, list] : minus)
          std::sort(list.begin(),
                    list.end(),
                    [&](std::size_t a, std::size_t b) {
                      return members[a].lo < members[b].lo;
                    });
        std::vector<std::size_t>                        candidates;
        std::set<std::pair<unsigned int, unsigned int>> noted_pairs;
        for (std::size_t i = 0; i < members.size(); ++i)
          {
            const ClassFace &p = members[i];
            if (!p.plus)
              continue;
            candidates.clear();
            for (long long b = bucket_of(p.offset) - 1;
                 b <= bucket_of(p.offset) + 1;
                 ++b)
              {
                const auto list = minus.find(b);
                if (list == minus.end())
                  continue;
                auto first = std::lower_bound(list->second.begin(),
                                              list->second.end(),
                                              p.lo - longest - tolerance,
                                              [&](std::size_t a, double value) {
                                                return members[a].lo < value;
                                              });
                for (; first != list->second.end() &&
                       members[*first].lo <= p.hi + tolerance;
                     ++first)
                  candidates.push_back(*first);
              }
            for (auto it = candidates.begin(); it != candidates.end(); ++it)
              {
                const ClassFace &q        = members[*it];
                const double     distance = q.offset - p.offset;
                if (std::abs(distance) >= 4 * near ||
                    faces[p.face].block == faces[q.face].block ||
                    (q.neighbour && !within_tolerance(faces[p.face].normal,
                                                      -faces[q.face].normal,
                                                      direction_tolerance)) ||
                    std::min(p.hi, q.hi) - std::max(p.lo, q.lo) <= tolerance)
                  continue;
                const double overlap =
                  dim == 2 ?
                    std::min(p.hi, q.hi) - std::max(p.lo, q.lo) :
                    overlap_area(polygon[i], polygon[*it]) /
                      std::max(faces[p.face].diameter, faces[q.face].diameter);
                if (overlap <= tolerance)
                  continue;
                // Just beyond the refusal band, within the buckets' reach
                // (4 near): no joint, and a note per pair of blocks (a
                // review: two blocks drawn 0.01 apart with cells of 0.5
                // fell apart with no word of the face across the gap).
                if (std::abs(distance) > near)
                  {
                    const auto [a, b] =
                      std::minmax(faces[p.face].block, faces[q.face].block);
                    if (noted_pairs.size() < 10 &&
                        noted_pairs.insert({a, b}).second)
                      {
                        std::ostringstream line;
                        line << "blocks " << faces[p.face].block << " and "
                             << faces[q.face].block << " face each other "
                             << (distance > 0 ? "across a gap of " :
                                                "overlapping by ")
                             << std::abs(distance) << " near "
                             << faces[p.face]
                                  .cell->face(faces[p.face].face_no)
                                  ->center()
                             << ", too far for a joint (faces are joined "
                                "only within 'Masonry/Coincidence "
                                "tolerance' of the smallest cell)";
                        result.nearly_touching.push_back(line.str());
                      }
                    continue;
                  }
                for (const std::size_t f : {p.face, q.face})
                  if (faces[f].warp > 0)
                    refuse_warped(
                      faces[f],
                      "a joint to block " +
                        std::to_string(
                          faces[f == p.face ? q.face : p.face].block));
                if (std::abs(distance) > tolerance)
                  {
                    std::ostringstream message;
                    message
                      << "blocks " << faces[p.face].block << " and "
                      << faces[q.face].block << " "
                      << (distance > 0 ? "leave a gap of " : "overlap by ")
                      << std::abs(distance)
                      << " between faces that nearly coincide (near "
                      << faces[p.face]
                           .cell->face(faces[p.face].face_no)
                           ->center()
                      << "); move them together (to within " << tolerance
                      << ") or further apart (more than " << near << ")";
                    throw InputError(message.str());
                  }
                // Matching nodes: every node of either face inside the
                // other has a coincident partner on it.
                const FaceRecord<dim> &fp    = faces[p.face];
                const FaceRecord<dim> &fq    = faces[q.face];
                auto                   match = [&](const FaceRecord<dim> &a,
                                 const FaceRecord<dim> &b,
                                 const Polygon         &b_polygon,
                                 const bool             a_is_lower) {
                  for (const unsigned int node : a.nodes)
                    {
                      const dealii::Point<dim> x(
                        as_tensor<dim>(result.node_position[node]));
                      if (!inside(b_polygon, basis(x), tolerance, dim == 2))
                        continue;
                      int partner = -1;
                      for (const unsigned int other : b.nodes)
                        if (x.distance(dealii::Point<dim>(as_tensor<dim>(
                              result.node_position[other]))) <= tolerance)
                          partner = static_cast<int>(other);
                      if (partner < 0)
                        throw InputError(
                          "non-matching nodes on the face shared by blocks " +
                          std::to_string(a.block) + " and " +
                          std::to_string(b.block) + ": " +
                          result.describe_node(node) +
                          " has no coincident node of block " +
                          std::to_string(b.block) +
                          "; node-to-node contact needs matching nodes, so "
                                            "mesh the blocks' shared faces alike (block sides "
                                            "multiples of the cell size)");
                      const unsigned int lower =
                        a_is_lower ? node : static_cast<unsigned int>(partner);
                      const unsigned int upper =
                        a_is_lower ? static_cast<unsigned int>(partner) : node;
                      const auto key = std::minmax(lower, upper);
                      joint_pairs.push_back(
                        {{key.first, key.second},
                         {key.first == lower ? n : -n, p.face, q.face}});
                    }
                };
                const std::size_t pairs_before = joint_pairs.size();
                match(fp, fq, polygon[*it], true);
                match(fq, fp, polygon[i], false);
                // Overlapping, yet no node of either on the other (faces
                // crossing like a '+'): no constraint would hold them, and
                // the blocks would pass through each other (a review).
                if (joint_pairs.size() == pairs_before)
                  throw InputError(
                    "non-matching nodes on the face shared by blocks " +
                    std::to_string(fp.block) + " and " +
                    std::to_string(fq.block) + " near " +
                    describe_point<dim>(as_array<dim>(dealii::Tensor<1, dim>(
                                          fp.cell->face(fp.face_no)->center())),
                                        fp.block) +
                    ": the faces overlap, but no node of either lies on the "
                    "other; node-to-node contact needs matching nodes, so "
                    "mesh the blocks' shared faces alike");
              }
          }
      }

    {
      std::vector<char> joined(faces.size(), 0);
      // The block across each joined face.
      std::vector<long> partner_block(faces.size(), -1);
      // The supports judged on joints below, and the faces they are named
      // on (none on the paper's walls, whose joints are nameless).
      const auto judged = [&](const Support<dim> &support) {
        return support.kind == Kind::signorini ||
               (support.kind == Kind::traction && !supports.zero_traction);
      };
      std::vector<char> judged_face(faces.size(), 0);
      for (std::size_t f = 0; f < faces.size(); ++f)
        for (const Support<dim> *support :
             supports.on_boundary(faces[f].boundary))
          judged_face[f] = judged_face[f] || judged(*support);
      // Those faces' nodes in a joint on them (a face may be one in part:
      // a block resting on the middle of another's top).
      std::vector<std::vector<unsigned int>> joint_nodes(faces.size());
      for (const auto &[pair, record] : joint_pairs)
        {
          for (const std::size_t f : {record.face_first, record.face_second})
            for (const unsigned int node : {pair.first, pair.second})
              if (judged_face[f] && std::find(faces[f].nodes.begin(),
                                              faces[f].nodes.end(),
                                              node) != faces[f].nodes.end())
                joint_nodes[f].push_back(node);
          joined[record.face_first] = joined[record.face_second] = 1;
          partner_block[record.face_first]  = faces[record.face_second].block;
          partner_block[record.face_second] = faces[record.face_first].block;
        }
      refuse_tilted_faces<dim>(faces,
                               face_class,
                               joined,
                               near,
                               tolerance,
                               cell_size,
                               direction_tolerance);
      // A Signorini support named on a face that is a joint (the blocks'
      // faces coincide, with nodes of their own: a mesh file's boundary
      // group that also covers a joint, or the built-in 3D walls' collar)
      // would set the block on a rigid support where the other block is;
      // a traction there would load the faces of both blocks, twice the
      // load and inside the structure (a review: 'Traction boundaries =
      // collar'). A Signorini support constrains nodes: refused at any
      // node of the joint. A traction loads the face's area: judged inside
      // the joint, off its edges, so that a region that keeps it to the
      // free part of a face partly a joint (a block resting on the middle
      // of another's top), ending where the joint begins, is accepted (a
      // review). (Rollers and held nodes on
      // joints are two-sided and meant: the symmetry plane of an extruded
      // wall.)
      for (std::size_t f = 0; f < faces.size(); ++f)
        if (!joint_nodes[f].empty())
          {
            // Each node once (a pair has a record from each of its faces).
            std::sort(joint_nodes[f].begin(), joint_nodes[f].end());
            joint_nodes[f].erase(std::unique(joint_nodes[f].begin(),
                                             joint_nodes[f].end()),
                                 joint_nodes[f].end());
            std::vector<dealii::Point<dim>> at_nodes;
            dealii::Point<dim>              middle;
            for (const unsigned int node : joint_nodes[f])
              {
                at_nodes.emplace_back(
                  as_tensor<dim>(result.node_position[node]));
                middle +=
                  at_nodes.back() / static_cast<double>(joint_nodes[f].size());
              }
            // The joint's middle, and points half way from it to each of
            // its nodes: inside the joint, off its edges.
            std::vector<dealii::Point<dim>> inside = {middle};
            for (const dealii::Point<dim> &node : at_nodes)
              inside.push_back(middle + 0.5 * (node - middle));
            for (const Support<dim> *support :
                 supports.on_boundary(faces[f].boundary))
              {
                if (!judged(*support))
                  continue;
                const std::vector<dealii::Point<dim>> &points =
                  support->kind == Kind::signorini ? at_nodes : inside;
                const auto acted_on =
                  std::find_if(points.begin(),
                               points.end(),
                               [&](const dealii::Point<dim> &point) {
                                 return supports.acts_at(*support,
                                                         point,
                                                         faces[f].vertices);
                               });
                if (acted_on == points.end())
                  continue;
                throw InputError(
                  support->description + " acts on a face of block " +
                  std::to_string(faces[f].block) +
                  " that is a joint with block " +
                  std::to_string(partner_block[f]) + " (at " +
                  describe_point<dim>(as_array<dim>(*acted_on),
                                      faces[f].block) +
                  "): " +
                  (support->kind == Kind::signorini ?
                     "it would set the block on a rigid support where "
                     "the other block is; a Signorini support" :
                     "a traction there would act inside the structure, "
                     "on a face another block lies on (on both of them "
                     "where the group covers both); a traction") +
                  " belongs on the structure's outer faces: name another "
                  "boundary, or (in a mesh file) take the joint's faces "
                  "out of the group '" +
                  support->name + "'");
              }
          }
    }

    // One joint constraint per node pair and group of normals (a pair on
    // two faces that make a corner gets two); the normal's canonical sign
    // decides which node is the lower one.
    struct JointRow
    {
      UnilateralConstraint<dim> row;
      std::array<FaceList, 2>   faces;
    };
    std::vector<JointRow> joints;
    // By pair, each pair's records in the order they were found.
    std::stable_sort(joint_pairs.begin(),
                     joint_pairs.end(),
                     [](const auto &a, const auto &b) {
                       return a.first < b.first;
                     });
    // One joint per pair, as a rule (a pair has two records or more: each
    // face of the pair finds it).
    std::size_t n_pairs = 0;
    for (std::size_t r = 0; r < joint_pairs.size(); ++r)
      n_pairs += r == 0 || joint_pairs[r].first != joint_pairs[r - 1].first;
    joints.reserve(n_pairs);
    for (std::size_t first = 0, end = 0; first < joint_pairs.size();
         first = end)
      {
        const auto pair = joint_pairs[first].first;
        for (end = first;
             end < joint_pairs.size() && joint_pairs[end].first == pair;
             ++end)
          ;
        const auto record =
          [&](const std::size_t r) -> const JointPairRecord & {
          return joint_pairs[first + r].second;
        };
        NormalGroups<dim> groups;
        for (std::size_t r = 0; r < end - first; ++r)
          groups.add(record(r).normal, r);
        for (const auto &group : groups.groups)
          {
            std::array<double, dim> n     = group.mean();
            unsigned int            lower = pair.first, upper = pair.second;
            if (classes.classify(n).second < 0)
              {
                std::swap(lower, upper);
                for (double &c : n)
                  c = -c;
              }
            // A joint whose two nodes are both held in its direction (held,
            // or a roller along it) can neither open nor close: its row
            // would repeat the supports' (a dependent row), so it goes.
            auto held_along = [&](const unsigned int node) {
              if (condition_of[node] == no_condition)
                return false;
              const NodeConditions<dim> &c = conditions[condition_of[node]];
              if (c.held_support >= 0)
                return true;
              for (const auto &roller : c.rollers.groups)
                if (std::abs(as_tensor<dim>(roller.mean()) *
                             as_tensor<dim>(n)) > 1 - 1e-9)
                  return true;
              return false;
            };
            if (held_along(lower) && held_along(upper))
              continue;
            JointRow joint{{ConstraintKind::joint, lower, upper, n, 0.0}, {}};
            for (const std::size_t r : group.items)
              for (const std::size_t f :
                   {record(r).face_first, record(r).face_second})
                add_face(
                  joint
                    .faces[faces[f].block == result.node_block[lower] ? 0 : 1],
                  f);
            joints.push_back(std::move(joint));
          }
      }
    // In the DOF order of their rows: the keys computed once and the
    // indices sorted, rather than the rows moved about with their sets.
    std::vector<std::pair<DofIndex, DofIndex>> joint_key(joints.size());
    for (std::size_t j = 0; j < joints.size(); ++j)
      {
        const UnilateralConstraint<dim> &row = joints[j].row;
        const unsigned int               c   = main_component(row.normal);
        joint_key[j]                         = {result.node_dofs[row.lower][c],
                                                result.node_dofs[row.upper][c]};
      }
    std::vector<std::size_t> joint_order(joints.size());
    std::iota(joint_order.begin(), joint_order.end(), 0);
    std::stable_sort(joint_order.begin(),
                     joint_order.end(),
                     [&](const std::size_t a, const std::size_t b) {
                       return joint_key[a] < joint_key[b];
                     });
    constraint_faces.reserve(constraint_faces.size() + joints.size());
    for (const std::size_t j : joint_order)
      {
        JointRow &joint = joints[j];
        result.constraints.push_back(joint.row);
        result.position.push_back(result.node_position[joint.row.lower]);
        result.blocks.push_back({{result.node_block[joint.row.lower],
                                  result.node_block[joint.row.upper]}});
        constraint_faces.push_back(std::move(joint.faces));
        const auto  &n        = joint.row.normal;
        const double vertical = std::abs(n[1]);
        if (vertical > 1 - 1e-12)
          ++result.n_horizontal_joint;
        else if (vertical < 1e-12 &&
                 (std::abs(n[0]) > 1 - 1e-12 ||
                  (dim == 3 && std::abs(n[dim - 1]) > 1 - 1e-12)))
          ++result.n_vertical_joint;
        else
          ++result.n_inclined_joint;
      }

    // The weights: per node and direction class, int phi_node over the
    // union of the faces of all its constraints in that direction (a node
    // with two joints on one face counts the face once).
    // Sorted (node, class, face) triples instead of a map of sets: a wall
    // of a million unknowns has hundreds of thousands of them.
    using NodeClass = std::pair<unsigned int, unsigned int>;
    std::vector<std::pair<NodeClass, std::size_t>> node_faces;
    std::vector<unsigned int> constraint_class(result.constraints.size());
    for (std::size_t k = 0; k < result.constraints.size(); ++k)
      {
        const auto &c       = result.constraints[k];
        constraint_class[k] = classes.classify(c.normal).first;
        for (const std::size_t f : constraint_faces[k][0])
          node_faces.push_back({{c.lower, constraint_class[k]}, f});
        if (c.kind == ConstraintKind::joint)
          for (const std::size_t f : constraint_faces[k][1])
            node_faces.push_back({{c.upper, constraint_class[k]}, f});
      }
    std::sort(node_faces.begin(), node_faces.end());
    node_faces.erase(std::unique(node_faces.begin(), node_faces.end()),
                     node_faces.end());
    std::vector<std::pair<NodeClass, double>> weight_at;
    for (const auto &[key, f] : node_faces)
      {
        if (weight_at.empty() || weight_at.back().first != key)
          weight_at.push_back({key, 0.0});
        weight_at.back().second += node_weight(f, key.first);
      }
    const auto weight_of = [&](const unsigned int node,
                               const unsigned int direction_class) {
      const NodeClass key{node, direction_class};
      const auto      at =
        std::lower_bound(weight_at.begin(),
                         weight_at.end(),
                         key,
                         [](const auto &entry, const NodeClass &k) {
                           return entry.first < k;
                         });
      // A constraint without faces (none is made so) would weigh nothing.
      return at == weight_at.end() || at->first != key ? 0.0 : at->second;
    };
    result.weight.reserve(result.constraints.size());
    for (std::size_t k = 0; k < result.constraints.size(); ++k)
      {
        const auto  &c     = result.constraints[k];
        const double lower = weight_of(c.lower, constraint_class[k]);
        result.weight.push_back({{lower,
                                  c.kind == ConstraintKind::joint ?
                                    weight_of(c.upper, constraint_class[k]) :
                                    lower}});
      }
    return result;
  }

  template struct ContactSet<2>;
  template struct ContactSet<3>;
  template ContactSet<2>
  detect_contacts<2>(const dealii::DoFHandler<2, 2> &,
                     const dealii::Mapping<2, 2> &,
                     const Supports<2> &,
                     double,
                     double);
  template ContactSet<3>
  detect_contacts<3>(const dealii::DoFHandler<3, 3> &,
                     const dealii::Mapping<3, 3> &,
                     const Supports<3> &,
                     double,
                     double);
  template std::string
  describe_point<2>(const std::array<double, 2> &, unsigned int);
  template std::string
  describe_point<3>(const std::array<double, 3> &, unsigned int);
} // namespace unilateral::masonry
