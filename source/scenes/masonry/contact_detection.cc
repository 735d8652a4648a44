#include <unilateral/base/input_error.h>
#include <unilateral/scenes/masonry/contact_detection.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe.h>
#include <deal.II/grid/tria.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>
#include <type_traits>

namespace unilateral::masonry
{
  static_assert(std::is_same_v<DofIndex, dealii::types::global_dof_index>,
                "DofIndex must match deal.II's global_dof_index");

  std::string
  describe_point(const double x, const double y, const unsigned int block)
  {
    std::ostringstream text;
    text << "(" << x << ", " << y << ") in block " << block;
    return text.str();
  }

  namespace
  {
    // A boundary face of one block: a segment on the line {x_axis = line}
    // with outward normal sign * e_axis, and its three nodes (the ends and
    // the midpoint, as FE_Q(2) and FE_SimplexP(2) order a face).
    struct FaceRecord
    {
      unsigned int block;
      unsigned int axis;   ///< 0: vertical face (normal +-x), 1: horizontal
      int          sign;   ///< outward normal is sign * e_axis
      double       line;   ///< the coordinate along the normal
      double       t0, t1; ///< the extent along the tangent, t0 < t1
      std::array<std::array<DofIndex, 2>, 3> node_dofs; ///< [node][component]
      std::array<double, 3>                  node_t;    ///< tangent coordinate
      bool contact = false; ///< overlaps a face of another block
    };

    // Simpson weights of a quadratic face: its ends and its midpoint.
    constexpr std::array<double, 3> simpson{{1.0 / 6, 1.0 / 6, 4.0 / 6}};

    std::array<double, 2>
    point_on(const FaceRecord &face, const double t)
    {
      return face.axis == 0 ? std::array<double, 2>{{face.line, t}} :
                              std::array<double, 2>{{t, face.line}};
    }

    std::vector<FaceRecord>
    collect_boundary_faces(const dealii::DoFHandler<2, 2> &dof_handler,
                           const double                    tolerance)
    {
      const dealii::FiniteElement<2, 2> &fe = dof_handler.get_fe();
      AssertThrow(fe.n_components() == 2 && fe.n_dofs_per_face() == 6,
                  dealii::ExcMessage("contact detection expects a vector "
                                     "quadratic Lagrange element"));
      // Face DOF i is component c of face node k (0, 1: ends; 2: midpoint).
      std::array<std::pair<unsigned int, unsigned int>, 6> face_node;
      for (unsigned int i = 0; i < 6; ++i)
        face_node[i] = fe.face_system_to_component_index(i);

      std::vector<FaceRecord>                      faces;
      std::vector<dealii::types::global_dof_index> face_dofs(6);
      for (const auto &cell : dof_handler.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          {
            if (!cell->face(f)->at_boundary())
              continue;
            const auto             face = cell->face(f);
            const dealii::Point<2> a    = face->vertex(0);
            const dealii::Point<2> b    = face->vertex(1);
            FaceRecord             record;
            record.block = cell->material_id();
            if (std::abs(a[0] - b[0]) <= tolerance)
              record.axis = 0;
            else if (std::abs(a[1] - b[1]) <= tolerance)
              record.axis = 1;
            else
              {
                std::ostringstream message;
                message << "block " << record.block
                        << " has a boundary face from (" << a[0] << ", " << a[1]
                        << ") to (" << b[0] << ", " << b[1]
                        << ") that is not parallel to an axis; masonry "
                           "blocks must be axis-aligned rectangles";
                throw InputError(message.str());
              }
            const unsigned int axis    = record.axis;
            const unsigned int tangent = 1 - axis;
            record.line                = 0.5 * (a[axis] + b[axis]);
            record.sign   = record.line > cell->center()[axis] ? 1 : -1;
            record.t0     = std::min(a[tangent], b[tangent]);
            record.t1     = std::max(a[tangent], b[tangent]);
            record.node_t = {
              {a[tangent], b[tangent], 0.5 * (a[tangent] + b[tangent])}};
            face->get_dof_indices(face_dofs);
            for (unsigned int i = 0; i < 6; ++i)
              record.node_dofs[face_node[i].second][face_node[i].first] =
                face_dofs[i];
            faces.push_back(record);
          }
      return faces;
    }

    struct BlockExtent
    {
      double x0 = std::numeric_limits<double>::max();
      double x1 = -std::numeric_limits<double>::max();
    };

    void
    throw_non_matching(const FaceRecord &with_node,
                       const double      t,
                       const FaceRecord &without,
                       const double      tolerance)
    {
      const auto         p = point_on(with_node, t);
      std::ostringstream message;
      message << "non-matching nodes on the edge shared by blocks "
              << with_node.block << " and " << without.block << ": the node "
              << "at (" << p[0] << ", " << p[1] << ") of block "
              << with_node.block << " has no coincident node of block "
              << without.block << " (tolerance " << tolerance
              << "); node-to-node contact needs matching nodes, so make the "
                 "block sides multiples of the cell size";
      throw InputError(message.str());
    }
  } // namespace

  ContactSet
  detect_contacts(const dealii::DoFHandler<2, 2> &dof_handler,
                  const double                    signorini_fraction,
                  const double                    gap,
                  const double                    tolerance)
  {
    const DofIndex n_dofs = dof_handler.n_dofs();
    ContactSet     result;
    result.dirichlet.assign(n_dofs, 0);
    result.contact_weight.assign(n_dofs, 0.0);

    std::vector<FaceRecord> faces =
      collect_boundary_faces(dof_handler, tolerance);

    // The bounding box and the x-extent of every block, from the mesh.
    double                   x_min = std::numeric_limits<double>::max();
    double                   x_max = -x_min, y_min = x_min;
    std::vector<BlockExtent> extent;
    for (const FaceRecord &face : faces)
      {
        if (face.block >= extent.size())
          extent.resize(face.block + 1);
        const double x_lo     = face.axis == 0 ? face.line : face.t0;
        const double x_hi     = face.axis == 0 ? face.line : face.t1;
        extent[face.block].x0 = std::min(extent[face.block].x0, x_lo);
        extent[face.block].x1 = std::max(extent[face.block].x1, x_hi);
        x_min                 = std::min(x_min, x_lo);
        x_max                 = std::max(x_max, x_hi);
        y_min = std::min(y_min, face.axis == 1 ? face.line : face.t0);
      }
    const double x_split = x_min + signorini_fraction * (x_max - x_min);

    // Supports: the sides (u_x = 0) and the base (Signorini or u_y = 0).
    std::vector<char> signorini(n_dofs, 0);
    for (FaceRecord &face : faces)
      {
        const bool side =
          face.axis == 0 &&
          ((face.sign < 0 && std::abs(face.line - x_min) <= tolerance) ||
           (face.sign > 0 && std::abs(face.line - x_max) <= tolerance));
        const bool base = face.axis == 1 && face.sign < 0 &&
                          std::abs(face.line - y_min) <= tolerance;
        if (side)
          for (const auto &dofs : face.node_dofs)
            result.dirichlet[dofs[0]] = 1;
        if (base)
          for (unsigned int k = 0; k < 3; ++k)
            {
              const double x        = face.node_t[k];
              const bool   on_split = std::abs(x - x_split) <= tolerance;
              const bool   block_ends_there =
                extent[face.block].x1 <= x_split + tolerance;
              const DofIndex dof = face.node_dofs[k][1];
              if ((x < x_split && !on_split) || (on_split && block_ends_there))
                {
                  signorini[dof] = 1;
                  result.contact_weight[dof] +=
                    simpson[k] * (face.t1 - face.t0);
                }
              else
                result.dirichlet[dof] = 1;
            }
      }

    // Signorini rows, in DOF order. Their position is looked up from the
    // base faces (each Signorini DOF is on one).
    {
      std::vector<std::pair<DofIndex, std::size_t>> base_nodes;
      for (std::size_t f = 0; f < faces.size(); ++f)
        if (faces[f].axis == 1 && faces[f].sign < 0)
          for (unsigned int k = 0; k < 3; ++k)
            if (signorini[faces[f].node_dofs[k][1]])
              base_nodes.emplace_back(faces[f].node_dofs[k][1], f * 3 + k);
      std::sort(base_nodes.begin(), base_nodes.end());
      for (std::size_t i = 0; i < base_nodes.size(); ++i)
        {
          if (i > 0 && base_nodes[i].first == base_nodes[i - 1].first)
            continue;
          const FaceRecord  &face = faces[base_nodes[i].second / 3];
          const unsigned int k    = base_nodes[i].second % 3;
          result.constraints.push_back(
            {ConstraintKind::signorini, base_nodes[i].first, 0, -gap});
          result.position.push_back(point_on(face, face.node_t[k]));
          result.blocks.push_back({{face.block, face.block}});
        }
      result.n_signorini = static_cast<unsigned int>(result.constraints.size());
    }

    // Joints: group the faces by line (sorting, so no quadratic search),
    // then sweep the faces with outward normal +e (the lower or left block)
    // against those with -e (the upper or right block).
    std::vector<std::size_t> order(faces.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      if (faces[a].axis != faces[b].axis)
        return faces[a].axis < faces[b].axis;
      if (faces[a].line != faces[b].line)
        return faces[a].line < faces[b].line;
      return faces[a].t0 < faces[b].t0;
    });

    struct JointPair
    {
      DofIndex              lower, upper;
      ConstraintKind        kind;
      std::array<double, 2> position;
      unsigned int          lower_block, upper_block;
    };
    std::vector<JointPair>   pairs;
    std::vector<std::size_t> plus, minus;

    auto match_nodes =
      [&](FaceRecord &p, FaceRecord &q, const double lo, const double hi) {
        // Every node of either face inside the common segment needs a
        // coincident partner on the other face.
        for (unsigned int k = 0; k < 3; ++k)
          if (q.node_t[k] >= lo - tolerance && q.node_t[k] <= hi + tolerance)
            {
              bool found = false;
              for (unsigned int l = 0; l < 3; ++l)
                found |= std::abs(p.node_t[l] - q.node_t[k]) <= tolerance;
              if (!found)
                throw_non_matching(q, q.node_t[k], p, tolerance);
            }
        for (unsigned int k = 0; k < 3; ++k)
          {
            if (p.node_t[k] < lo - tolerance || p.node_t[k] > hi + tolerance)
              continue;
            int partner = -1;
            for (unsigned int l = 0; l < 3; ++l)
              if (std::abs(p.node_t[k] - q.node_t[l]) <= tolerance)
                partner = static_cast<int>(l);
            if (partner < 0)
              throw_non_matching(p, p.node_t[k], q, tolerance);
            pairs.push_back({p.node_dofs[k][p.axis],
                             q.node_dofs[partner][p.axis],
                             p.axis == 1 ? ConstraintKind::horizontal_joint :
                                           ConstraintKind::vertical_joint,
                             point_on(p, p.node_t[k]),
                             p.block,
                             q.block});
          }
        p.contact = true;
        q.contact = true;
      };

    for (std::size_t begin = 0; begin < order.size();)
      {
        std::size_t end = begin;
        while (end < order.size() &&
               faces[order[end]].axis == faces[order[begin]].axis &&
               faces[order[end]].line - faces[order[begin]].line <= tolerance)
          ++end;
        plus.clear();
        minus.clear();
        for (std::size_t i = begin; i < end; ++i)
          (faces[order[i]].sign > 0 ? plus : minus).push_back(order[i]);
        // Lines equal within the tolerance may interleave in the sort.
        auto by_start = [&](std::size_t a, std::size_t b) {
          return faces[a].t0 < faces[b].t0;
        };
        std::sort(plus.begin(), plus.end(), by_start);
        std::sort(minus.begin(), minus.end(), by_start);
        // Both lists are sorted by t0 and, in a valid layout, disjoint, so
        // one merge-like sweep finds every overlapping pair.
        std::size_t i = 0, j = 0;
        while (i < plus.size() && j < minus.size())
          {
            FaceRecord  &p  = faces[plus[i]];
            FaceRecord  &q  = faces[minus[j]];
            const double lo = std::max(p.t0, q.t0);
            const double hi = std::min(p.t1, q.t1);
            if (hi - lo > tolerance)
              match_nodes(p, q, lo, hi);
            if (p.t1 < q.t1)
              ++i;
            else
              ++j;
          }
        begin = end;
      }

    // A node pair found from two face pairs (at a common face end) counts
    // once.
    std::sort(pairs.begin(),
              pairs.end(),
              [](const JointPair &a, const JointPair &b) {
                return a.lower != b.lower ? a.lower < b.lower :
                                            a.upper < b.upper;
              });
    for (std::size_t i = 0; i < pairs.size(); ++i)
      {
        if (i > 0 && pairs[i].lower == pairs[i - 1].lower &&
            pairs[i].upper == pairs[i - 1].upper)
          continue;
        result.constraints.push_back(
          {pairs[i].kind, pairs[i].lower, pairs[i].upper, 0.0});
        result.position.push_back(pairs[i].position);
        result.blocks.push_back({{pairs[i].lower_block, pairs[i].upper_block}});
        if (pairs[i].kind == ConstraintKind::horizontal_joint)
          ++result.n_horizontal_joint;
        else
          ++result.n_vertical_joint;
      }

    // Simpson weights of the joint faces, for the contact pressure.
    for (const FaceRecord &face : faces)
      if (face.contact)
        for (unsigned int k = 0; k < 3; ++k)
          result.contact_weight[face.node_dofs[k][face.axis]] +=
            simpson[k] * (face.t1 - face.t0);

    result.n_dirichlet = static_cast<unsigned int>(
      std::count(result.dirichlet.begin(), result.dirichlet.end(), 1));
    return result;
  }
} // namespace unilateral::masonry
