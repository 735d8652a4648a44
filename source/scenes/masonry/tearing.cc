#include <unilateral/scenes/masonry/tearing.h>

#include <deal.II/dofs/dof_tools.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <sstream>

namespace unilateral::masonry
{
  namespace
  {
    /// One block: its physical DOFs in the local order, its stiffness and
    /// load, and the positions of its DOFs relative to its centre.
    struct TornBlock
    {
      std::vector<DofIndex>         dofs;
      lcp::DenseMatrix              stiffness;
      lcp::Vector                   load;
      std::vector<dealii::Point<2>> position;
      std::vector<unsigned int>     component;
      unsigned int                  shape = 0;
    };

    /// The rigid motions of a block about its centre: the two translations
    /// and the rotation (-(y - y_c), x - x_c).
    lcp::DenseMatrix
    rigid_motions(const TornBlock &block)
    {
      const std::size_t n = block.dofs.size();
      dealii::Point<2>  centre;
      for (const auto &p : block.position)
        centre += p / static_cast<double>(n);
      lcp::DenseMatrix R = lcp::DenseMatrix::Zero(n, 3);
      for (std::size_t j = 0; j < n; ++j)
        {
          const dealii::Tensor<1, 2> r = block.position[j] - centre;
          R(j, block.component[j])     = 1;
          R(j, 2)                      = block.component[j] == 0 ? -r[1] : r[0];
        }
      return R;
    }
  } // namespace

  std::shared_ptr<const lcp::Tearing>
  tear_into_blocks(const Discretisation    &discretisation,
                   const ContactSet        &contacts,
                   const ChangeOfVariables &change,
                   const LoadData          &loads,
                   const unsigned int       n_blocks,
                   const double             force_unit,
                   const double             tolerance)
  {
    const dealii::DoFHandler<2> &dof_handler = discretisation.dof_handler;
    const unsigned int           n_dofs      = dof_handler.n_dofs();
    const unsigned int dofs_per_cell = discretisation.fe->n_dofs_per_cell();
    std::vector<dealii::Point<2>> support(n_dofs);
    dealii::DoFTools::map_dofs_to_support_points(*discretisation.mapping,
                                                 dof_handler,
                                                 support);

    // Each block's DOFs, numbered by component, then by position (rounded
    // to the tolerance) relative to its lower left corner.
    std::vector<TornBlock>                       blocks(n_blocks);
    std::vector<dealii::types::global_dof_index> dofs(dofs_per_cell);
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          {
            blocks[cell->material_id()].dofs.push_back(dofs[i]);
          }
      }
    std::vector<unsigned int> local_of_dof(n_dofs, 0);
    for (TornBlock &block : blocks)
      {
        std::sort(block.dofs.begin(), block.dofs.end());
        block.dofs.erase(std::unique(block.dofs.begin(), block.dofs.end()),
                         block.dofs.end());
        block.component.assign(block.dofs.size(), 0);
        block.position.assign(block.dofs.size(), dealii::Point<2>());
      }
    // Components of the DOFs.
    std::vector<unsigned int> component_of_dof(n_dofs, 0);
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          component_of_dof[dofs[i]] =
            discretisation.fe->system_to_component_index(i).first;
      }
    for (TornBlock &block : blocks)
      {
        dealii::Point<2> corner = support[block.dofs.front()];
        for (const DofIndex dof : block.dofs)
          for (unsigned int d = 0; d < 2; ++d)
            corner[d] = std::min(corner[d], support[dof][d]);
        const auto key = [&](const DofIndex dof) {
          const dealii::Tensor<1, 2> r = support[dof] - corner;
          return std::make_tuple(component_of_dof[dof],
                                 std::llround(r[1] / tolerance),
                                 std::llround(r[0] / tolerance));
        };
        std::sort(block.dofs.begin(),
                  block.dofs.end(),
                  [&](const DofIndex a, const DofIndex b) {
                    return key(a) < key(b);
                  });
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
    CellSystem cell_system(discretisation, loads);
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        cell_system.reinit(cell);
        TornBlock &block = blocks[cell->material_id()];
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
        TornBlock   &block = blocks[b];
        unsigned int shape = 0;
        for (; shape < representative.size(); ++shape)
          {
            const TornBlock &other = blocks[representative[shape]];
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
        const TornBlock &block = blocks[b];
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

    std::vector<dealii::Point<2>> corner_of_subdomain;
    for (const unsigned int b : order)
      {
        dealii::Point<2> corner = blocks[b].position.front();
        for (const auto &p : blocks[b].position)
          for (unsigned int d = 0; d < 2; ++d)
            corner[d] = std::min(corner[d], p[d]);
        corner_of_subdomain.push_back(corner);
      }
    tearing->describe_subdomain = [order,
                                   corner_of_subdomain](const lcp::Index k) {
      std::ostringstream text;
      text << "block " << order[k] << " (lower left corner ("
           << corner_of_subdomain[k][0] << ", " << corner_of_subdomain[k][1]
           << "))";
      return text.str();
    };

    // B and c: the constraints C_k u >= bound as -C_k x <= -bound, then the
    // fixed DOFs as x_i = 0.
    std::vector<Eigen::Triplet<double, lcp::Index>> rows;
    std::vector<double>                             c;
    const auto add_constraint_row = [&](const UnilateralConstraint &k,
                                        const double                sign,
                                        const lcp::Index            row,
                                        auto                       &entries) {
      if (k.kind == ConstraintKind::signorini)
        entries.emplace_back(row, physical[k.lower], sign);
      else
        {
          entries.emplace_back(row, physical[k.upper], sign);
          entries.emplace_back(row, physical[k.lower], -sign);
        }
    };
    for (std::size_t k = 0; k < contacts.constraints.size(); ++k)
      {
        add_constraint_row(contacts.constraints[k],
                           -1.0,
                           static_cast<lcp::Index>(c.size()),
                           rows);
        c.push_back(-contacts.constraints[k].bound);
        tearing->inequality_unknown.push_back(change.variable_of_constraint(k));
      }
    tearing->n_inequalities = static_cast<lcp::Index>(c.size());
    for (unsigned int dof = 0; dof < n_dofs; ++dof)
      if (contacts.dirichlet[dof])
        {
          rows.emplace_back(static_cast<lcp::Index>(c.size()),
                            physical[dof],
                            1.0);
          c.push_back(0);
        }
    tearing->B.resize(static_cast<lcp::Index>(c.size()), next);
    tearing->B.setFromTriplets(rows.begin(), rows.end());
    tearing->B.makeCompressed();
    tearing->c = Eigen::Map<const lcp::Vector>(c.data(), c.size());

    // The map to the gap variables: u~ = C~ x.
    std::vector<int> constraint_of_variable(change.n_unknowns(), -1);
    for (std::size_t k = 0; k < contacts.constraints.size(); ++k)
      constraint_of_variable[change.variable_of_constraint(k)] =
        static_cast<int>(k);
    std::vector<Eigen::Triplet<double, lcp::Index>> map;
    for (unsigned int dof = 0; dof < n_dofs; ++dof)
      {
        const int variable = change.variable_of_dof(dof);
        if (variable < 0)
          continue;
        const int k = constraint_of_variable[variable];
        if (k < 0)
          map.emplace_back(variable, physical[dof], 1.0);
        else
          add_constraint_row(contacts.constraints[k], 1.0, variable, map);
      }
    tearing->to_problem.resize(change.n_unknowns(), next);
    tearing->to_problem.setFromTriplets(map.begin(), map.end());
    tearing->to_problem.makeCompressed();
    return tearing;
  }
} // namespace unilateral::masonry
