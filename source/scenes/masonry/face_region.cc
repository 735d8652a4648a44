#include <unilateral/base/input_error.h>
#include <unilateral/scenes/masonry/face_region.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/grid/reference_cell.h>

#include <algorithm>
#include <array>
#include <sstream>

namespace unilateral::masonry
{
  namespace
  {
    // Samples per side of a face: 16 to tell a face that is all inside or
    // all outside, 64 along the lines of a face the region's edge cuts.
    constexpr unsigned int samples      = 16;
    constexpr unsigned int line_samples = 64;
    constexpr unsigned int bisections   = 52; // to 2^-52 of the face
    // Halvings of a piece in s while the area inside it is not converged.
    constexpr unsigned int max_halvings = 24;
    // The most points a face's rule may have (face_region_rule).
    constexpr std::size_t max_points = 100000;

    // Where value(x) changes on [0, length]: n + 1 samples find the
    // changes, bisection places each to 2^-52 of the length.
    template <typename Value>
    std::vector<double>
    changes(const double                              length,
            const unsigned int                        n,
            const std::function<Value(const double)> &value)
    {
      std::vector<double> found;
      Value               before = value(0);
      for (unsigned int k = 1; k <= n; ++k)
        {
          double      low  = length * (k - 1) / n;
          double      high = length * k / n;
          const Value now  = value(high);
          if (now == before)
            continue;
          for (unsigned int b = 0; b < bisections; ++b)
            {
              const double middle                    = 0.5 * (low + high);
              (value(middle) == before ? low : high) = middle;
            }
          found.push_back(0.5 * (low + high));
          before = now;
        }
      return found;
    }

    // The parts of [0, length] where inside(s) holds.
    std::vector<std::pair<double, double>>
    inside_intervals(const double                             length,
                     const std::function<bool(const double)> &inside)
    {
      std::vector<std::pair<double, double>> parts;
      bool                                   in    = inside(0);
      double                                 start = 0;
      for (const double edge : changes<bool>(length, line_samples, inside))
        {
          if (in)
            parts.emplace_back(start, edge);
          else
            start = edge;
          in = !in;
        }
      if (in)
        parts.emplace_back(start, length);
      return parts;
    }

    // The pattern of a line of samples, for comparing two lines.
    std::vector<bool>
    sample_pattern(const double                             length,
                   const std::function<bool(const double)> &inside,
                   const unsigned int                       n)
    {
      std::vector<bool> pattern(n + 1);
      for (unsigned int k = 0; k <= n; ++k)
        pattern[k] = inside(length * k / n);
      return pattern;
    }

    // The length of the parts.
    double
    total_length(const std::vector<std::pair<double, double>> &parts)
    {
      double length = 0;
      for (const auto &[a, b] : parts)
        length += b - a;
      return length;
    }

    // A face by its corners (deal.II's vertex order of a face: a line, a
    // lexicographic quadrilateral or a triangle) and a region: the real
    // point of (s, t) is interpolated from the corners, bilinearly on a
    // quadrilateral and linearly on a line or triangle, which is what the
    // masonry scene's mappings (MappingQ(1), MappingFE of P1) do. The face
    // is seen as lines of the last parameter: in 2D the face itself, in 3D
    // the lines of constant s, of length 1 (or 1 - s on a triangle).
    template <int dim>
    struct FacePatch
    {
      const std::vector<dealii::Point<dim>>                 &corner;
      const std::function<bool(const dealii::Point<dim> &)> &inside;

      bool
      triangle() const
      {
        return dim == 3 && corner.size() == 3;
      }

      bool
      inside_at(const double s, const double t) const
      {
        dealii::Point<dim> x = corner[0] + s * (corner[1] - corner[0]);
        if constexpr (dim == 3)
          {
            x += t * (corner[2] - corner[0]);
            if (!triangle())
              x += s * t * (corner[3] - corner[2] - corner[1] + corner[0]);
          }
        return inside(x);
      }

      double
      line_length(const double s) const
      {
        return triangle() ? 1 - s : 1.0;
      }

      std::function<bool(double)>
      line(const double s) const
      {
        if constexpr (dim == 2)
          return [this](const double u) { return inside_at(u, 0); };
        else
          return [this, s](const double t) { return inside_at(s, t); };
      }

      // Whole, none or partial, from samples 1/16 of the face apart.
      typename FaceRegionRule<dim>::Coverage
      coverage() const
      {
        using Coverage   = typename FaceRegionRule<dim>::Coverage;
        bool any_inside  = false;
        bool any_outside = false;
        for (unsigned int i = 0; i <= (dim == 3 ? samples : 0); ++i)
          {
            const double s = double(i) / samples;
            for (const bool value :
                 sample_pattern(line_length(s), line(s), samples))
              (value ? any_inside : any_outside) = true;
          }
        return !any_inside  ? Coverage::none :
               !any_outside ? Coverage::whole :
                              Coverage::partial;
      }
    };
  } // namespace

  template <int dim>
  bool
  face_touches_region(
    const std::vector<dealii::Point<dim>>                 &corners,
    const std::function<bool(const dealii::Point<dim> &)> &inside)
  {
    return FacePatch<dim>{corners, inside}.coverage() !=
           FaceRegionRule<dim>::Coverage::none;
  }

  template <int dim>
  FaceRegionRule<dim>
  face_region_rule(
    const typename dealii::DoFHandler<dim>::active_cell_iterator &cell,
    const unsigned int                                            face,
    const std::function<bool(const dealii::Point<dim> &)>        &inside)
  {
    using Rule = FaceRegionRule<dim>;
    Rule rule;

    // x(s, t) = p0 + s (p1 - p0) + t (p2 - p0) in the reference cell, t up
    // to 1 on a quadrilateral, 1 - s on a triangle.
    const dealii::ReferenceCell reference = cell->reference_cell();
    const dealii::ReferenceCell face_reference =
      reference.face_reference_cell(face);
    const auto vertex = [&](const unsigned int v) {
      return reference.template vertex<dim>(
        reference.face_to_cell_vertices(face, v, 1));
    };
    const dealii::Point<dim> origin = vertex(0);
    for (unsigned int d = 1; d < dim; ++d)
      rule.tangents.push_back(vertex(d) - origin);
    const auto reference_point = [&](const double s, const double t) {
      dealii::Point<dim> p = origin + s * rule.tangents[0];
      if constexpr (dim == 3)
        p += t * rule.tangents[1];
      return p;
    };
    std::vector<dealii::Point<dim>> corner;
    for (unsigned int v = 0; v < face_reference.n_vertices(); ++v)
      corner.push_back(
        cell->vertex(reference.face_to_cell_vertices(face, v, 1)));
    const FacePatch<dim> patch{corner, inside};

    rule.coverage = patch.coverage();
    if (rule.coverage != Rule::Coverage::partial)
      return rule;

    const dealii::QGauss<1> gauss(4);
    // A Gauss rule on [a, b] of the inner parameter at outer (s, w_s).
    const auto add_line =
      [&](const double                                  s,
          const double                                  w_s,
          const std::vector<std::pair<double, double>> &parts) {
        // A region whose edge winds through the face more than sampling
        // can follow (sin(300 x z) > 0): refused rather than let the rule
        // grow without bound.
        if (rule.points.size() > max_points)
          {
            dealii::Point<dim> centre;
            for (const auto &c : corner)
              centre += c / static_cast<double>(corner.size());
            std::ostringstream where;
            where << centre;
            throw InputError(
              "the region of a traction crosses the face centred at (" +
              where.str() + ") so often that more than " +
              std::to_string(max_points) +
              " points would integrate it: give a region with fewer "
              "crossings per cell, or smaller cells");
          }
        for (const auto &[a, b] : parts)
          for (unsigned int q = 0; q < gauss.size(); ++q)
            {
              const double u = a + (b - a) * gauss.point(q)[0];
              rule.points.push_back(dim == 3 ? reference_point(s, u) :
                                               reference_point(u, 0));
              rule.weights.push_back(w_s * (b - a) * gauss.weight(q));
            }
      };

    if constexpr (dim == 2)
      add_line(0, 1, inside_intervals(1.0, patch.line(0)));
    else
      {
        // Cut [0, 1] in s where the line's parts change in kind: their
        // number, or whether an end of the line is inside (the region's
        // edge crosses a face edge or turns back). Between such cuts the
        // parts inside move smoothly with s.
        const auto kind = [&](const double s) {
          const auto parts =
            inside_intervals(patch.line_length(s), patch.line(s));
          return std::array<double, 3>{
            {double(parts.size()),
             double(!parts.empty() && parts.front().first == 0),
             double(!parts.empty() &&
                    parts.back().second == patch.line_length(s))}};
        };
        using Kind = std::array<double, 3>;
        std::vector<double> cuts{0};
        for (const double cut : changes<Kind>(
               1.0, line_samples, std::function<Kind(double)>(kind)))
          cuts.push_back(cut);
        cuts.push_back(1);
        // On each piece, Gauss points in s, halving a piece while its area
        // inside differs from its halves' (a curved edge's chord behaves
        // like a square root near where it touches a line of constant s).
        struct Piece
        {
          double                                              a, b;
          std::vector<std::vector<std::pair<double, double>>> lines;
          double                                              area;
        };
        const auto make_piece = [&](const double a, const double b) {
          Piece piece{a, b, {}, 0};
          for (unsigned int q = 0; q < gauss.size(); ++q)
            {
              const double s = a + (b - a) * gauss.point(q)[0];
              piece.lines.push_back(
                inside_intervals(patch.line_length(s), patch.line(s)));
              piece.area +=
                (b - a) * gauss.weight(q) * total_length(piece.lines.back());
            }
          return piece;
        };
        const std::function<void(const Piece &, unsigned int)> refine =
          [&](const Piece &piece, const unsigned int depth) {
            const double middle = 0.5 * (piece.a + piece.b);
            const Piece  left   = make_piece(piece.a, middle);
            const Piece  right  = make_piece(middle, piece.b);
            if (depth >= max_halvings ||
                std::abs(left.area + right.area - piece.area) <=
                  1e-12 * (piece.b - piece.a))
              for (const Piece *half : {&left, &right})
                for (unsigned int q = 0; q < gauss.size(); ++q)
                  add_line(half->a + (half->b - half->a) * gauss.point(q)[0],
                           (half->b - half->a) * gauss.weight(q),
                           half->lines[q]);
            else
              {
                refine(left, depth + 1);
                refine(right, depth + 1);
              }
          };
        for (std::size_t piece = 0; piece + 1 < cuts.size(); ++piece)
          refine(make_piece(cuts[piece], cuts[piece + 1]), 0);
      }
    return rule;
  }

  template bool
  face_touches_region(const std::vector<dealii::Point<2>> &,
                      const std::function<bool(const dealii::Point<2> &)> &);
  template bool
  face_touches_region(const std::vector<dealii::Point<3>> &,
                      const std::function<bool(const dealii::Point<3> &)> &);
  template FaceRegionRule<2>
  face_region_rule(const dealii::DoFHandler<2>::active_cell_iterator &,
                   unsigned int,
                   const std::function<bool(const dealii::Point<2> &)> &);
  template FaceRegionRule<3>
  face_region_rule(const dealii::DoFHandler<3>::active_cell_iterator &,
                   unsigned int,
                   const std::function<bool(const dealii::Point<3> &)> &);
} // namespace unilateral::masonry
