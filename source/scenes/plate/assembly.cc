#include <unilateral/base/input_error.h>
#include <unilateral/scenes/plate/assembly.h>
#include <unilateral/scenes/plate/bending.h>

#include <deal.II/base/function.h>
#include <deal.II/base/index_set.h>
#include <deal.II/fe/fe.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <algorithm>
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
    // The pattern of C_JJ: every pair of free DOFs that share a cell. Built
    // row by row in a DynamicSparsityPattern (sorted rows) and copied into
    // the compressed column arrays of the Eigen matrix; C is symmetric, so
    // the rows are its columns.
    void
    make_pattern(const dealii::DoFHandler<2> &dof_handler,
                 const FreeDofs              &free_dofs,
                 lcp::SparseMatrix           &matrix)
    {
      const lcp::Index                             n = free_dofs.size();
      dealii::DynamicSparsityPattern               pattern(n, n);
      std::vector<dealii::types::global_dof_index> local_dofs(
        fe::BognerFoxSchmit::dofs_per_cell);
      std::vector<dealii::types::global_dof_index> local_free;
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          cell->get_dof_indices(local_dofs);
          local_free.clear();
          for (const auto dof : local_dofs)
            if (free_dofs.index[dof] >= 0)
              local_free.push_back(free_dofs.index[dof]);
          std::sort(local_free.begin(), local_free.end());
          for (const auto row : local_free)
            pattern.add_entries(row,
                                local_free.begin(),
                                local_free.end(),
                                true);
        }

      matrix.resize(n, n);
      matrix.resizeNonZeros(
        static_cast<lcp::Index>(pattern.n_nonzero_elements()));
      lcp::Index *outer = matrix.outerIndexPtr();
      lcp::Index *inner = matrix.innerIndexPtr();
      outer[0]          = 0;
      for (lcp::Index j = 0; j < n; ++j)
        {
          lcp::Index k = outer[j];
          for (auto entry = pattern.begin(j); entry != pattern.end(j); ++entry)
            inner[k++] = static_cast<lcp::Index>(entry->column());
          outer[j + 1] = k;
        }
      std::fill(matrix.valuePtr(), matrix.valuePtr() + matrix.nonZeros(), 0.0);
    }

    // Position of entry (row, column) in the compressed arrays; it is in the
    // pattern by construction.
    inline lcp::Index
    position(const lcp::SparseMatrix &matrix,
             const lcp::Index         row,
             const lcp::Index         column)
    {
      const lcp::Index *begin =
        matrix.innerIndexPtr() + matrix.outerIndexPtr()[column];
      const lcp::Index *end =
        matrix.innerIndexPtr() + matrix.outerIndexPtr()[column + 1];
      return static_cast<lcp::Index>(std::lower_bound(begin, end, row) -
                                     matrix.innerIndexPtr());
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
    make_pattern(dof_handler, free_dofs, matrix);
    rhs            = lcp::Vector::Zero(free_dofs.size());
    double *values = matrix.valuePtr();

    const std::vector<unsigned int> bfs_index =
      fe::bfs_local_indices(dof_handler.get_fe());
    constexpr unsigned int n_local = fe::BognerFoxSchmit::dofs_per_cell;
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

    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(local_dofs);
        const fe::BognerFoxSchmit element = cell_element(cell);
        const CellIntegrals      &integrals =
          cache.get(element.size(0), element.size(1));
        const auto load = integrals.load(element.vertex(0), force_at);

        for (unsigned int i = 0; i < n_local; ++i)
          {
            const lcp::Index row = free_dofs.index[local_dofs[i]];
            if (row < 0)
              continue;
            const unsigned int bi = bfs_index[i];
            rhs[row] += load[bi];
            for (unsigned int j = 0; j < n_local; ++j)
              {
                const double     entry  = integrals.stiffness(bi, bfs_index[j]);
                const lcp::Index column = free_dofs.index[local_dofs[j]];
                if (column >= 0)
                  values[position(matrix, row, column)] += entry;
                else if (fixed_values != nullptr)
                  rhs[row] -= entry * (*fixed_values)[local_dofs[j]];
              }
          }
      }
  }
} // namespace unilateral::plate
