#include <unilateral/scenes/masonry/tearing.h>

#include <deal.II/base/bounding_box.h>
#include <deal.II/dofs/dof_tools.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <numeric>
#include <sstream>
#include <unordered_map>

namespace unilateral::masonry
{
  namespace
  {
    /// One subdomain (a block, or a piece of a long block): its physical
    /// DOFs in the local order, its stiffness and load, and the positions
    /// of its DOFs.
    template <int dim>
    struct Piece
    {
      unsigned int                    block = 0;
      std::vector<DofIndex>           dofs;
      lcp::DenseMatrix                stiffness;
      lcp::Vector                     load;
      std::vector<dealii::Point<dim>> position;
      std::vector<unsigned int>       component;
      unsigned int                    shape = 0;
    };

    /// The mean of a piece's DOF positions.
    template <int dim>
    dealii::Point<dim>
    centre(const Piece<dim> &piece)
    {
      dealii::Point<dim> result;
      for (const auto &p : piece.position)
        result += p / static_cast<double>(piece.position.size());
      return result;
    }

    /// The rigid motions of a piece about its centre: the translations and
    /// the rotations e_k x (x - x_c) (one in 2D, about z; three in 3D).
    template <int dim>
    lcp::DenseMatrix
    rigid_motions(const Piece<dim> &piece)
    {
      constexpr unsigned int   n_rotations = dim == 2 ? 1 : 3;
      const std::size_t        n           = piece.dofs.size();
      const dealii::Point<dim> centre      = masonry::centre(piece);
      lcp::DenseMatrix         R = lcp::DenseMatrix::Zero(n, dim + n_rotations);
      for (std::size_t j = 0; j < n; ++j)
        {
          const dealii::Tensor<1, dim> r = piece.position[j] - centre;
          const unsigned int           c = piece.component[j];
          R(j, c)                        = 1;
          if constexpr (dim == 2)
            R(j, 2) = c == 0 ? -r[1] : r[0];
          else
            for (unsigned int k = 0; k < 3; ++k)
              {
                // (e_k x r)_c
                dealii::Tensor<1, 3> axis;
                axis[k]     = 1;
                R(j, 3 + k) = dealii::cross_product_3d(axis, r)[c];
              }
        }
      return R;
    }

    /**
     * The piece of every cell (indexed by active_cell_index), and the
     * block of every piece. A block whose bounding box is longer than
     * @p largest_aspect_ratio times its shortest side s is cut by a grid of
     * round(L_d / s) slices along each side L_d, each cell going to the
     * slice of its centre; the pieces are then split into their
     * face-connected parts, so that each floats with the rigid motions
     * alone (a mesh file's odd block may leave a slice in two parts). A
     * block that is not cut is one piece. @p n_cut counts the cut blocks.
     */
    template <int dim>
    std::vector<unsigned int>
    cut_into_pieces(const dealii::DoFHandler<dim> &dof_handler,
                    const unsigned int             n_blocks,
                    const double                   largest_aspect_ratio,
                    std::vector<unsigned int>     &block_of_piece,
                    unsigned int                  &n_cut)
    {
      const auto &triangulation = dof_handler.get_triangulation();
      std::vector<dealii::BoundingBox<dim>> box(n_blocks);
      std::vector<char>                     seen(n_blocks, 0);
      for (const auto &cell : triangulation.active_cell_iterators())
        {
          const auto cell_box = cell->bounding_box();
          const auto b        = cell->material_id();
          if (seen[b])
            box[b].merge_with(cell_box);
          else
            box[b] = cell_box;
          seen[b] = 1;
        }
      // The slices of each block along each side (1 where not cut).
      std::vector<std::array<unsigned int, dim>> slices(n_blocks);
      n_cut = 0;
      for (unsigned int b = 0; b < n_blocks; ++b)
        {
          double shortest = box[b].side_length(0), longest = shortest;
          for (unsigned int d = 1; d < dim; ++d)
            {
              shortest = std::min(shortest, box[b].side_length(d));
              longest  = std::max(longest, box[b].side_length(d));
            }
          // A block exactly at the ratio (a 2H x H brick at 2) stays whole,
          // whatever the rounding of its cells' coordinates.
          const bool cut =
            largest_aspect_ratio > 0 &&
            longest > largest_aspect_ratio * shortest * (1 + 1e-8);
          n_cut += cut;
          for (unsigned int d = 0; d < dim; ++d)
            slices[b][d] =
              cut ?
                std::max(1L, std::lround(box[b].side_length(d) / shortest)) :
                1;
        }
      const auto slice_of = [&](const auto &cell) {
        const unsigned int       b      = cell->material_id();
        const dealii::Point<dim> centre = cell->center();
        unsigned int             index  = 0;
        for (unsigned int d = 0; d < dim; ++d)
          {
            const double t = (centre[d] - box[b].lower_bound(d)) /
                             box[b].side_length(d) * slices[b][d];
            const unsigned int k =
              std::min(slices[b][d] - 1,
                       static_cast<unsigned int>(std::max(0.0, t)));
            index = index * slices[b][d] + k;
          }
        return std::make_pair(b, index);
      };

      // Face-connected parts of each (block, slice): a flood fill through
      // the faces between cells of the same block and slice.
      const unsigned int        unset = dealii::numbers::invalid_unsigned_int;
      std::vector<unsigned int> piece(triangulation.n_active_cells(), unset);
      block_of_piece.clear();
      std::vector<typename dealii::DoFHandler<dim>::active_cell_iterator> stack;
      for (const auto &start : dof_handler.active_cell_iterators())
        if (piece[start->active_cell_index()] == unset)
          {
            const unsigned int p = block_of_piece.size();
            block_of_piece.push_back(start->material_id());
            const auto slice                  = slice_of(start);
            piece[start->active_cell_index()] = p;
            stack.assign(1, start);
            while (!stack.empty())
              {
                const auto cell = stack.back();
                stack.pop_back();
                for (const unsigned int f : cell->face_indices())
                  if (!cell->at_boundary(f))
                    {
                      const auto neighbour = cell->neighbor(f);
                      if (neighbour->is_active() &&
                          piece[neighbour->active_cell_index()] == unset &&
                          slice_of(neighbour) == slice)
                        {
                          piece[neighbour->active_cell_index()] = p;
                          stack.push_back(neighbour);
                        }
                    }
              }
          }
      return piece;
    }

    /**
     * Each piece's DOFs, numbered by component and then by position
     * (rounded to @p tolerance) relative to the piece's lowest corner, the
     * last coordinate first, so that translated copies number alike (a DOF
     * on a cut has a number in each of its pieces); and its stiffness and
     * load, its cells' summed and divided by @p force_unit.
     */
    template <int dim>
    std::vector<Piece<dim>>
    assemble_pieces(const Discretisation<dim>       &discretisation,
                    const LoadData<dim>             &loads,
                    const std::vector<unsigned int> &piece_of_cell,
                    const std::vector<unsigned int> &block_of_piece,
                    const double                     force_unit,
                    const double                     tolerance)
    {
      const dealii::DoFHandler<dim> &dof_handler = discretisation.dof_handler;
      const unsigned int             n_dofs      = dof_handler.n_dofs();
      const unsigned int dofs_per_cell = discretisation.fe->n_dofs_per_cell();
      std::vector<dealii::Point<dim>> support(n_dofs);
      dealii::DoFTools::map_dofs_to_support_points(*discretisation.mapping,
                                                   dof_handler,
                                                   support);

      std::vector<Piece<dim>> pieces(block_of_piece.size());
      for (std::size_t p = 0; p < pieces.size(); ++p)
        pieces[p].block = block_of_piece[p];
      std::vector<unsigned int>                    component_of_dof(n_dofs, 0);
      std::vector<dealii::types::global_dof_index> dofs(dofs_per_cell);
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs_per_cell; ++i)
            {
              pieces[piece_of_cell[cell->active_cell_index()]].dofs.push_back(
                dofs[i]);
              component_of_dof[dofs[i]] =
                discretisation.fe->system_to_component_index(i).first;
            }
        }

      std::vector<std::unordered_map<DofIndex, unsigned int>> local_of_dof(
        pieces.size());
      for (std::size_t p = 0; p < pieces.size(); ++p)
        {
          Piece<dim> &piece = pieces[p];
          std::sort(piece.dofs.begin(), piece.dofs.end());
          piece.dofs.erase(std::unique(piece.dofs.begin(), piece.dofs.end()),
                           piece.dofs.end());
          dealii::Point<dim> corner = support[piece.dofs.front()];
          for (const DofIndex dof : piece.dofs)
            for (unsigned int d = 0; d < dim; ++d)
              corner[d] = std::min(corner[d], support[dof][d]);
          const auto key = [&](const DofIndex dof) {
            std::array<long long, dim + 1> k;
            k[0] = component_of_dof[dof];
            for (unsigned int d = 0; d < dim; ++d)
              k[1 + d] = std::llround(
                (support[dof][dim - 1 - d] - corner[dim - 1 - d]) / tolerance);
            return k;
          };
          std::sort(piece.dofs.begin(),
                    piece.dofs.end(),
                    [&](const DofIndex a, const DofIndex b) {
                      return key(a) < key(b);
                    });
          piece.component.resize(piece.dofs.size());
          piece.position.resize(piece.dofs.size());
          local_of_dof[p].reserve(piece.dofs.size());
          for (std::size_t j = 0; j < piece.dofs.size(); ++j)
            {
              local_of_dof[p][piece.dofs[j]] = static_cast<unsigned int>(j);
              piece.component[j]             = component_of_dof[piece.dofs[j]];
              piece.position[j]              = support[piece.dofs[j]];
            }
          piece.stiffness =
            lcp::DenseMatrix::Zero(piece.dofs.size(), piece.dofs.size());
          piece.load = lcp::Vector::Zero(piece.dofs.size());
        }

      CellSystem<dim>           cell_system(discretisation, loads);
      std::vector<unsigned int> local(dofs_per_cell);
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          cell->get_dof_indices(dofs);
          cell_system.reinit(cell);
          const unsigned int p     = piece_of_cell[cell->active_cell_index()];
          Piece<dim>        &piece = pieces[p];
          for (unsigned int i = 0; i < dofs_per_cell; ++i)
            local[i] = local_of_dof[p].at(dofs[i]);
          for (unsigned int i = 0; i < dofs_per_cell; ++i)
            {
              piece.load[local[i]] += cell_system.rhs[i] / force_unit;
              for (unsigned int j = 0; j < dofs_per_cell; ++j)
                piece.stiffness(local[i], local[j]) +=
                  cell_system.matrix[i * dofs_per_cell + j] / force_unit;
            }
        }
      return pieces;
    }

    /// Pieces with the same stiffness (to round-off) share a shape of
    /// @p tearing, with their rigid motions.
    template <int dim>
    void
    share_shapes(std::vector<Piece<dim>> &pieces, lcp::Tearing &tearing)
    {
      std::vector<const Piece<dim> *> representative;
      for (Piece<dim> &piece : pieces)
        {
          unsigned int shape = 0;
          for (; shape < representative.size(); ++shape)
            {
              const Piece<dim> &other = *representative[shape];
              if (other.dofs.size() == piece.dofs.size() &&
                  other.component == piece.component &&
                  (other.stiffness - piece.stiffness).cwiseAbs().maxCoeff() <=
                    1e-12 * piece.stiffness.cwiseAbs().maxCoeff())
                break;
            }
          if (shape == representative.size())
            {
              representative.push_back(&piece);
              tearing.shapes.push_back({piece.stiffness, rigid_motions(piece)});
            }
          piece.shape = shape;
        }
    }

    /// The physical DOFs: the pieces (in @p order) numbered one after the
    /// other, and what each DOF of the mesh is numbered and glued to.
    struct PhysicalNumbering
    {
      std::vector<unsigned int> order;
      /// The first copy of each DOF of the mesh: the one the constraints
      /// and the map to the LCP take.
      std::vector<lcp::Index> physical;
      /// (first copy, further copy) of each DOF on a cut.
      std::vector<std::pair<lcp::Index, lcp::Index>> glued;
      lcp::Index                                     n_physical = 0;
    };

    /// The physical numbering, the pieces of each shape consecutive (the
    /// groups of @p tearing), and the load f in it.
    template <int dim>
    PhysicalNumbering
    number_pieces(const std::vector<Piece<dim>> &pieces,
                  const unsigned int             n_dofs,
                  lcp::Tearing                  &tearing)
    {
      PhysicalNumbering numbering;
      numbering.order.resize(pieces.size());
      std::iota(numbering.order.begin(), numbering.order.end(), 0);
      std::stable_sort(numbering.order.begin(),
                       numbering.order.end(),
                       [&](const unsigned int a, const unsigned int b) {
                         return pieces[a].shape < pieces[b].shape;
                       });
      const lcp::Index unset = -1;
      numbering.physical.assign(n_dofs, unset);
      std::vector<double> load;
      lcp::Index          next = 0;
      for (const unsigned int p : numbering.order)
        {
          const Piece<dim> &piece = pieces[p];
          if (tearing.groups.empty() ||
              tearing.groups.back().shape != piece.shape)
            tearing.groups.push_back({piece.shape, next, 0});
          ++tearing.groups.back().n_subdomains;
          for (std::size_t j = 0; j < piece.dofs.size(); ++j)
            {
              lcp::Index &first = numbering.physical[piece.dofs[j]];
              if (first == unset)
                first = next;
              else
                numbering.glued.emplace_back(first, next);
              load.push_back(piece.load[j]);
              ++next;
            }
        }
      numbering.n_physical = next;
      tearing.f = Eigen::Map<const lcp::Vector>(load.data(), load.size());
      return numbering;
    }

    /// "block 7 (centre (x, y))", or "a piece of block 7 (...)", for
    /// subdomain k in the physical order.
    template <int dim>
    std::function<std::string(lcp::Index)>
    describer(const std::vector<Piece<dim>>   &pieces,
              const std::vector<unsigned int> &order,
              const unsigned int               n_blocks)
    {
      std::vector<unsigned int> pieces_of_block(n_blocks, 0);
      for (const Piece<dim> &piece : pieces)
        ++pieces_of_block[piece.block];
      std::vector<dealii::Point<dim>> centre_of_subdomain;
      std::vector<unsigned int>       block_of_subdomain;
      std::vector<char>               whole_block;
      for (const unsigned int p : order)
        {
          centre_of_subdomain.push_back(centre(pieces[p]));
          block_of_subdomain.push_back(pieces[p].block);
          whole_block.push_back(pieces_of_block[pieces[p].block] == 1);
        }
      return [block_of_subdomain, centre_of_subdomain, whole_block](
               const lcp::Index k) {
        std::ostringstream text;
        text << (whole_block[k] ? "block " : "a piece of block ")
             << block_of_subdomain[k] << " (centre (";
        for (unsigned int d = 0; d < dim; ++d)
          text << (d > 0 ? ", " : "") << centre_of_subdomain[k][d];
        text << "))";
        return text.str();
      };
    }

    /**
     * B and c: the constraints n . (u_upper - u_lower) >= bound (joints) and
     * n . u >= bound (Signorini) as -C_k x <= -bound; then as equalities
     * the held nodes (x = the prescribed value), the rollers (n . x = 0)
     * and the gluing of the copies of a DOF on a cut (x_first - x_copy =
     * 0: one row per further copy, so that B keeps full row rank).
     */
    template <int dim>
    void
    write_multipliers(const ContactSet<dim>        &contacts,
                      const ChangeOfVariables<dim> &change,
                      const PhysicalNumbering      &numbering,
                      lcp::Tearing                 &tearing)
    {
      std::vector<Eigen::Triplet<double, lcp::Index>> rows;
      std::vector<double>                             c;
      const auto add_node_row = [&](const unsigned int    node,
                                    const Direction<dim> &normal,
                                    const double          sign) {
        for (unsigned int d = 0; d < dim; ++d)
          if (normal[d] != 0)
            rows.emplace_back(static_cast<lcp::Index>(c.size()),
                              numbering.physical[contacts.node_dofs[node][d]],
                              sign * normal[d]);
      };
      for (std::size_t k = 0; k < contacts.constraints.size(); ++k)
        {
          const UnilateralConstraint<dim> &constraint = contacts.constraints[k];
          if (constraint.kind == ConstraintKind::signorini)
            add_node_row(constraint.lower, constraint.normal, -1.0);
          else
            {
              add_node_row(constraint.upper, constraint.normal, -1.0);
              add_node_row(constraint.lower, constraint.normal, 1.0);
            }
          c.push_back(-constraint.bound);
          tearing.inequality_unknown.push_back(
            change.variable_of_constraint(k));
        }
      tearing.n_inequalities = static_cast<lcp::Index>(c.size());
      for (const HeldNode<dim> &held : contacts.held)
        for (unsigned int d = 0; d < dim; ++d)
          {
            Direction<dim> axis{};
            axis[d] = 1;
            add_node_row(held.node, axis, 1.0);
            c.push_back(held.value[d]);
          }
      for (const Roller<dim> &roller : contacts.rollers)
        {
          add_node_row(roller.node, roller.normal, 1.0);
          c.push_back(0);
        }
      for (const auto &[first, copy] : numbering.glued)
        {
          const auto row = static_cast<lcp::Index>(c.size());
          rows.emplace_back(row, first, 1.0);
          rows.emplace_back(row, copy, -1.0);
          c.push_back(0);
        }
      tearing.B.resize(static_cast<lcp::Index>(c.size()), numbering.n_physical);
      tearing.B.setFromTriplets(rows.begin(), rows.end());
      tearing.B.makeCompressed();
      tearing.c = Eigen::Map<const lcp::Vector>(c.data(), c.size());
    }
  } // namespace

  template <int dim>
  std::shared_ptr<const lcp::Tearing>
  tear_into_blocks(const Discretisation<dim>    &discretisation,
                   const ContactSet<dim>        &contacts,
                   const ChangeOfVariables<dim> &change,
                   const LoadData<dim>          &loads,
                   const unsigned int            n_blocks,
                   const double                  largest_aspect_ratio,
                   const double                  force_unit,
                   const double                  tolerance,
                   unsigned int                 &n_cut_blocks)
  {
    std::vector<unsigned int>       block_of_piece;
    const std::vector<unsigned int> piece_of_cell =
      cut_into_pieces(discretisation.dof_handler,
                      n_blocks,
                      largest_aspect_ratio,
                      block_of_piece,
                      n_cut_blocks);
    std::vector<Piece<dim>> pieces  = assemble_pieces(discretisation,
                                                     loads,
                                                     piece_of_cell,
                                                     block_of_piece,
                                                     force_unit,
                                                     tolerance);
    auto                    tearing = std::make_shared<lcp::Tearing>();
    share_shapes(pieces, *tearing);
    const PhysicalNumbering numbering =
      number_pieces(pieces, discretisation.dof_handler.n_dofs(), *tearing);
    tearing->describe_subdomain = describer(pieces, numbering.order, n_blocks);
    write_multipliers(contacts, change, numbering, *tearing);

    // The map to the LCP's variables: u~ = C~ x.
    std::vector<Eigen::Triplet<double, lcp::Index>> map;
    for (unsigned int variable = 0; variable < change.n_unknowns(); ++variable)
      for (const auto &[dof, coefficient] : change.row(variable))
        map.emplace_back(variable, numbering.physical[dof], coefficient);
    tearing->to_problem.resize(change.n_unknowns(), numbering.n_physical);
    tearing->to_problem.setFromTriplets(map.begin(), map.end());
    tearing->to_problem.makeCompressed();
    return tearing;
  }

  template std::shared_ptr<const lcp::Tearing>
  tear_into_blocks<2>(const Discretisation<2> &,
                      const ContactSet<2> &,
                      const ChangeOfVariables<2> &,
                      const LoadData<2> &,
                      unsigned int,
                      double,
                      double,
                      double,
                      unsigned int &);
  template std::shared_ptr<const lcp::Tearing>
  tear_into_blocks<3>(const Discretisation<3> &,
                      const ContactSet<3> &,
                      const ChangeOfVariables<3> &,
                      const LoadData<3> &,
                      unsigned int,
                      double,
                      double,
                      double,
                      unsigned int &);
} // namespace unilateral::masonry
