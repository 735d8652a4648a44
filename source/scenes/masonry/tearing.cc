#include <unilateral/scenes/masonry/tearing.h>

#include <deal.II/dofs/dof_tools.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <sstream>

namespace unilateral::masonry
{
  namespace
  {
    /// One block: its physical DOFs in the local order, its stiffness and
    /// load, and the positions of its DOFs.
    template <int dim>
    struct TornBlock
    {
      std::vector<DofIndex>           dofs;
      lcp::DenseMatrix                stiffness;
      lcp::Vector                     load;
      std::vector<dealii::Point<dim>> position;
      std::vector<unsigned int>       component;
      unsigned int                    shape = 0;
    };

    /// The rigid motions of a block about its centre: the translations and
    /// the rotations e_k x (x - x_c) (one in 2D, about z; three in 3D).
    template <int dim>
    lcp::DenseMatrix
    rigid_motions(const TornBlock<dim> &block)
    {
      constexpr unsigned int n_rotations = dim == 2 ? 1 : 3;
      const std::size_t      n           = block.dofs.size();
      dealii::Point<dim>     centre;
      for (const auto &p : block.position)
        centre += p / static_cast<double>(n);
      lcp::DenseMatrix R = lcp::DenseMatrix::Zero(n, dim + n_rotations);
      for (std::size_t j = 0; j < n; ++j)
        {
          const dealii::Tensor<1, dim> r = block.position[j] - centre;
          const unsigned int           c = block.component[j];
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
  } // namespace

  template <int dim>
  std::shared_ptr<const lcp::Tearing>
  tear_into_blocks(const Discretisation<dim>    &discretisation,
                   const ContactSet<dim>        &contacts,
                   const ChangeOfVariables<dim> &change,
                   const LoadData<dim>          &loads,
                   const unsigned int            n_blocks,
                   const double                  force_unit,
                   const double                  tolerance)
  {
    const dealii::DoFHandler<dim> &dof_handler = discretisation.dof_handler;
    const unsigned int             n_dofs      = dof_handler.n_dofs();
    const unsigned int dofs_per_cell = discretisation.fe->n_dofs_per_cell();
    std::vector<dealii::Point<dim>> support(n_dofs);
    dealii::DoFTools::map_dofs_to_support_points(*discretisation.mapping,
                                                 dof_handler,
                                                 support);

    // Each block's DOFs and their components.
    std::vector<TornBlock<dim>>                  blocks(n_blocks);
    std::vector<unsigned int>                    component_of_dof(n_dofs, 0);
    std::vector<dealii::types::global_dof_index> dofs(dofs_per_cell);
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          {
            blocks[cell->material_id()].dofs.push_back(dofs[i]);
            component_of_dof[dofs[i]] =
              discretisation.fe->system_to_component_index(i).first;
          }
      }

    // Numbered by component, then by position (rounded to the tolerance)
    // relative to the block's lowest corner, the last coordinate first.
    std::vector<unsigned int> local_of_dof(n_dofs, 0);
    for (TornBlock<dim> &block : blocks)
      {
        std::sort(block.dofs.begin(), block.dofs.end());
        block.dofs.erase(std::unique(block.dofs.begin(), block.dofs.end()),
                         block.dofs.end());
        dealii::Point<dim> corner = support[block.dofs.front()];
        for (const DofIndex dof : block.dofs)
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
        std::sort(block.dofs.begin(),
                  block.dofs.end(),
                  [&](const DofIndex a, const DofIndex b) {
                    return key(a) < key(b);
                  });
        block.component.resize(block.dofs.size());
        block.position.resize(block.dofs.size());
        for (std::size_t j = 0; j < block.dofs.size(); ++j)
          {
            local_of_dof[block.dofs[j]] = static_cast<unsigned int>(j);
            block.component[j]          = component_of_dof[block.dofs[j]];
            block.position[j]           = support[block.dofs[j]];
          }
        block.stiffness =
          lcp::DenseMatrix::Zero(block.dofs.size(), block.dofs.size());
        block.load = lcp::Vector::Zero(block.dofs.size());
      }

    // The stiffness and load of every block: its cells' matrices summed.
    CellSystem<dim> cell_system(discretisation, loads);
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        cell_system.reinit(cell);
        TornBlock<dim> &block = blocks[cell->material_id()];
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          {
            const unsigned int a = local_of_dof[dofs[i]];
            block.load[a] += cell_system.rhs[i] / force_unit;
            for (unsigned int j = 0; j < dofs_per_cell; ++j)
              block.stiffness(a, local_of_dof[dofs[j]]) +=
                cell_system.matrix[i * dofs_per_cell + j] / force_unit;
          }
      }

    // Shapes: blocks with the same stiffness (to round-off) share it.
    auto                      tearing = std::make_shared<lcp::Tearing>();
    std::vector<unsigned int> representative;
    for (unsigned int b = 0; b < n_blocks; ++b)
      {
        TornBlock<dim> &block = blocks[b];
        unsigned int    shape = 0;
        for (; shape < representative.size(); ++shape)
          {
            const TornBlock<dim> &other = blocks[representative[shape]];
            if (other.dofs.size() == block.dofs.size() &&
                other.component == block.component &&
                (other.stiffness - block.stiffness).cwiseAbs().maxCoeff() <=
                  1e-12 * block.stiffness.cwiseAbs().maxCoeff())
              break;
          }
        if (shape == representative.size())
          {
            representative.push_back(b);
            tearing->shapes.push_back({block.stiffness, rigid_motions(block)});
          }
        block.shape = shape;
      }

    // The physical numbering: the blocks of each shape consecutive.
    std::vector<unsigned int> order(n_blocks);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(),
                     order.end(),
                     [&](const unsigned int a, const unsigned int b) {
                       return blocks[a].shape < blocks[b].shape;
                     });
    std::vector<lcp::Index> physical(n_dofs, 0);
    tearing->f.resize(n_dofs);
    lcp::Index next = 0;
    for (const unsigned int b : order)
      {
        const TornBlock<dim> &block = blocks[b];
        if (tearing->groups.empty() ||
            tearing->groups.back().shape != block.shape)
          tearing->groups.push_back({block.shape, next, 0});
        ++tearing->groups.back().n_subdomains;
        for (std::size_t j = 0; j < block.dofs.size(); ++j)
          {
            physical[block.dofs[j]] = next;
            tearing->f[next]        = block.load[j];
            ++next;
          }
      }

    std::vector<dealii::Point<dim>> centre_of_subdomain;
    for (const unsigned int b : order)
      {
        dealii::Point<dim> centre;
        for (const auto &p : blocks[b].position)
          centre += p / static_cast<double>(blocks[b].position.size());
        centre_of_subdomain.push_back(centre);
      }
    tearing->describe_subdomain = [order,
                                   centre_of_subdomain](const lcp::Index k) {
      std::ostringstream text;
      text << "block " << order[k] << " (centre (";
      for (unsigned int d = 0; d < dim; ++d)
        text << (d > 0 ? ", " : "") << centre_of_subdomain[k][d];
      text << "))";
      return text.str();
    };

    // B and c: the constraints n . (u_upper - u_lower) >= bound (joints) and
    // n . u >= bound (Signorini) as -C_k x <= -bound; then the held nodes
    // (x = the prescribed value) and the rollers (n . x = 0) as equalities.
    std::vector<Eigen::Triplet<double, lcp::Index>> rows;
    std::vector<double>                             c;
    const auto add_node_row = [&](const unsigned int    node,
                                  const Direction<dim> &normal,
                                  const double          sign) {
      for (unsigned int d = 0; d < dim; ++d)
        if (normal[d] != 0)
          rows.emplace_back(static_cast<lcp::Index>(c.size()),
                            physical[contacts.node_dofs[node][d]],
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
        tearing->inequality_unknown.push_back(change.variable_of_constraint(k));
      }
    tearing->n_inequalities = static_cast<lcp::Index>(c.size());
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
    tearing->B.resize(static_cast<lcp::Index>(c.size()), next);
    tearing->B.setFromTriplets(rows.begin(), rows.end());
    tearing->B.makeCompressed();
    tearing->c = Eigen::Map<const lcp::Vector>(c.data(), c.size());

    // The map to the LCP's variables: u~ = C~ x.
    std::vector<Eigen::Triplet<double, lcp::Index>> map;
    for (unsigned int variable = 0; variable < change.n_unknowns(); ++variable)
      for (const auto &[dof, coefficient] : change.row(variable))
        map.emplace_back(variable, physical[dof], coefficient);
    tearing->to_problem.resize(change.n_unknowns(), next);
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
                      double);
  template std::shared_ptr<const lcp::Tearing>
  tear_into_blocks<3>(const Discretisation<3> &,
                      const ContactSet<3> &,
                      const ChangeOfVariables<3> &,
                      const LoadData<3> &,
                      unsigned int,
                      double,
                      double);
} // namespace unilateral::masonry
