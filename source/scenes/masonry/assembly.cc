#include <unilateral/base/memory.h>
#include <unilateral/scenes/masonry/assembly.h>

#include <deal.II/fe/fe_values.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace unilateral::masonry
{
  namespace
  {
    // The new variables each cell touches: the union of the expansions of
    // its physical DOFs, sorted. Stored for all cells (CSR), since both the
    // sparsity pattern and the assembly walk them.
    void
    collect_cell_variables(const dealii::DoFHandler<2> &dof_handler,
                           const ChangeOfVariables     &change,
                           std::vector<std::size_t>    &start,
                           std::vector<int>            &variables)
    {
      const unsigned int dofs_per_cell = dof_handler.get_fe().n_dofs_per_cell();
      const auto n_cells = dof_handler.get_triangulation().n_active_cells();
      start.assign(n_cells + 1, 0);
      variables.clear();
      variables.reserve(n_cells * dofs_per_cell * 5 / 4);
      std::vector<dealii::types::global_dof_index> dofs(dofs_per_cell);
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          cell->get_dof_indices(dofs);
          const std::size_t first = variables.size();
          for (const auto dof : dofs)
            {
              const auto [begin, end] = change.expansion(dof);
              for (auto term = begin; term != end; ++term)
                variables.push_back(term->variable);
            }
          std::sort(variables.begin() + first, variables.end());
          variables.erase(std::unique(variables.begin() + first,
                                      variables.end()),
                          variables.end());
          start[cell->active_cell_index() + 1] = variables.size();
        }
    }

    // The pattern of A: column j holds every variable that shares a cell
    // with j. Built column by column from the variable-to-cell incidence,
    // with a marker array instead of sets.
    void
    make_pattern(const int                       n,
                 const std::vector<std::size_t> &cell_start,
                 const std::vector<int>         &cell_variables,
                 lcp::SparseMatrix              &A)
    {
      const std::size_t        n_cells = cell_start.size() - 1;
      std::vector<std::size_t> cells_start(n + 1, 0);
      for (const int v : cell_variables)
        ++cells_start[v + 1];
      std::partial_sum(cells_start.begin(),
                       cells_start.end(),
                       cells_start.begin());
      std::vector<unsigned int> cells_of(cells_start.back());
      {
        std::vector<std::size_t> fill(cells_start.begin(),
                                      cells_start.end() - 1);
        for (std::size_t c = 0; c < n_cells; ++c)
          for (std::size_t k = cell_start[c]; k < cell_start[c + 1]; ++k)
            cells_of[fill[cell_variables[k]]++] = static_cast<unsigned int>(c);
      }

      // The pattern is built here and copied into A (indices and values):
      // refuse a wall whose matrix cannot fit before building it. Each cell
      // couples at most its variables squared (shared pairs counted twice).
      double most_entries = 0;
      for (std::size_t c = 0; c < n_cells; ++c)
        most_entries += std::pow(cell_start[c + 1] - cell_start[c], 2.0);
      memory::require(std::min(most_entries, double(n) * n) *
                        (2 * sizeof(lcp::Index) + 8),
                      "the matrix A~ of " + std::to_string(n) + " unknowns");
      std::vector<lcp::Index> outer(n + 1, 0);
      std::vector<lcp::Index> inner;
      inner.reserve(cell_variables.size() * 16);
      std::vector<int> marker(n, -1);
      for (int j = 0; j < n; ++j)
        {
          const std::size_t first = inner.size();
          for (std::size_t k = cells_start[j]; k < cells_start[j + 1]; ++k)
            {
              const unsigned int c = cells_of[k];
              for (std::size_t l = cell_start[c]; l < cell_start[c + 1]; ++l)
                {
                  const int i = cell_variables[l];
                  if (marker[i] != j)
                    {
                      marker[i] = j;
                      inner.push_back(i);
                    }
                }
            }
          // Every variable belongs to some cell, so the diagonal is present.
          std::sort(inner.begin() + first, inner.end());
          outer[j + 1] = static_cast<lcp::Index>(inner.size());
        }

      A.resize(n, n);
      A.makeCompressed();
      A.resizeNonZeros(static_cast<lcp::Index>(inner.size()));
      std::copy(outer.begin(), outer.end(), A.outerIndexPtr());
      std::copy(inner.begin(), inner.end(), A.innerIndexPtr());
      std::fill(A.valuePtr(), A.valuePtr() + inner.size(), 0.0);
    }
  } // namespace

  CellSystem::CellSystem(const Discretisation &discretisation,
                         const LoadData       &loads)
    : loads(loads)
    , fe_values(*discretisation.mapping,
                *discretisation.fe,
                *discretisation.quadrature,
                dealii::update_values | dealii::update_gradients |
                  dealii::update_JxW_values)
    , fe_face_values(*discretisation.mapping,
                     *discretisation.fe,
                     *discretisation.face_quadrature,
                     dealii::update_values | dealii::update_JxW_values)
    , dofs_per_cell(discretisation.fe->n_dofs_per_cell())
    , component(dofs_per_cell)
    , matrix(dofs_per_cell * dofs_per_cell)
    , rhs(dofs_per_cell)
  {
    for (unsigned int i = 0; i < dofs_per_cell; ++i)
      component[i] = discretisation.fe->system_to_component_index(i).first;
  }

  void
  CellSystem::reinit(const dealii::DoFHandler<2>::active_cell_iterator &cell)
  {
    fe_values.reinit(cell);
    const MaterialClass &material =
      loads.classes[loads.class_of_block[cell->material_id()]];
    const double lambda       = material.lambda();
    const double mu           = material.mu();
    const double body_force_y = -material.density * loads.gravity;

    // Plane strain elasticity, as in step-8.
    std::fill(matrix.begin(), matrix.end(), 0.0);
    std::fill(rhs.begin(), rhs.end(), 0.0);
    for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
      {
        const double JxW = fe_values.JxW(q);
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          {
            const unsigned int          ci = component[i];
            const dealii::Tensor<1, 2> &gi = fe_values.shape_grad(i, q);
            for (unsigned int j = i; j < dofs_per_cell; ++j)
              {
                const unsigned int          cj = component[j];
                const dealii::Tensor<1, 2> &gj = fe_values.shape_grad(j, q);
                double value = gi[ci] * gj[cj] * lambda + gi[cj] * gj[ci] * mu;
                if (ci == cj)
                  value += (gi * gj) * mu;
                matrix[i * dofs_per_cell + j] += value * JxW;
              }
            if (ci == 1)
              rhs[i] += fe_values.shape_value(i, q) * body_force_y * JxW;
          }
      }
    for (unsigned int i = 0; i < dofs_per_cell; ++i)
      for (unsigned int j = 0; j < i; ++j)
        matrix[i * dofs_per_cell + j] = matrix[j * dofs_per_cell + i];

    if (loads.top_traction[0] == 0 && loads.top_traction[1] == 0)
      return;
    for (const unsigned int f : cell->face_indices())
      if (cell->face(f)->at_boundary() &&
          std::abs(cell->face(f)->center()[1] - loads.y_top) <=
            loads.tolerance &&
          cell->face(f)->center()[1] > cell->center()[1])
        {
          fe_face_values.reinit(cell, f);
          for (unsigned int q = 0; q < fe_face_values.n_quadrature_points; ++q)
            for (unsigned int i = 0; i < dofs_per_cell; ++i)
              rhs[i] += fe_face_values.shape_value(i, q) *
                        loads.top_traction[component[i]] *
                        fe_face_values.JxW(q);
        }
  }

  lcp::Problem
  assemble_lcp(const Discretisation    &discretisation,
               const ChangeOfVariables &change,
               const ContactSet        &contacts,
               const LoadData          &loads)
  {
    const dealii::DoFHandler<2>    &dof_handler   = discretisation.dof_handler;
    const dealii::FiniteElement<2> &fe            = *discretisation.fe;
    const unsigned int              dofs_per_cell = fe.n_dofs_per_cell();
    const int                       n = static_cast<int>(change.n_unknowns());

    lcp::Problem problem;
    problem.b = lcp::Vector::Zero(n);

    std::vector<std::size_t> cell_start;
    std::vector<int>         cell_variables;
    collect_cell_variables(dof_handler, change, cell_start, cell_variables);
    make_pattern(n, cell_start, cell_variables, problem.A);

    std::vector<dealii::types::global_dof_index> dofs(dofs_per_cell);
    CellSystem                 cell_system(discretisation, loads);
    const std::vector<double> &cell_matrix = cell_system.matrix;
    const std::vector<double> &cell_rhs    = cell_system.rhs;
    std::vector<int>    position(n, -1); // variable -> index in the cell list
    std::vector<double> reduced_matrix, reduced_rhs;
    struct LocalTerm
    {
      unsigned int position;
      double       coefficient;
    };
    std::vector<std::size_t> term_start(dofs_per_cell + 1);
    std::vector<LocalTerm>   local_terms;

    double *const           values = problem.A.valuePtr();
    const lcp::Index *const outer  = problem.A.outerIndexPtr();
    const lcp::Index *const inner  = problem.A.innerIndexPtr();

    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        cell_system.reinit(cell);

        // Expand into the new variables: u_i = sum_t c_t u~_{v_t}, so the
        // local contribution to A~ is sum_ij K_ij c_a c_b at (v_a, v_b).
        const std::size_t  first   = cell_start[cell->active_cell_index()];
        const std::size_t  last    = cell_start[cell->active_cell_index() + 1];
        const unsigned int n_local = static_cast<unsigned int>(last - first);
        for (std::size_t k = first; k < last; ++k)
          position[cell_variables[k]] = static_cast<int>(k - first);
        local_terms.clear();
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          {
            term_start[i]           = local_terms.size();
            const auto [begin, end] = change.expansion(dofs[i]);
            for (auto term = begin; term != end; ++term)
              local_terms.push_back(
                {static_cast<unsigned int>(position[term->variable]),
                 term->coefficient});
          }
        term_start[dofs_per_cell] = local_terms.size();

        reduced_matrix.assign(static_cast<std::size_t>(n_local) * n_local, 0.0);
        reduced_rhs.assign(n_local, 0.0);
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          for (std::size_t s = term_start[i]; s < term_start[i + 1]; ++s)
            {
              const LocalTerm a = local_terms[s];
              reduced_rhs[a.position] += a.coefficient * cell_rhs[i];
              double *row = reduced_matrix.data() +
                            static_cast<std::size_t>(a.position) * n_local;
              for (unsigned int j = 0; j < dofs_per_cell; ++j)
                {
                  const double k_ij =
                    a.coefficient * cell_matrix[i * dofs_per_cell + j];
                  for (std::size_t t = term_start[j]; t < term_start[j + 1];
                       ++t)
                    row[local_terms[t].position] +=
                      k_ij * local_terms[t].coefficient;
                }
            }

        // Scatter: the cell's variables are sorted, and so is every column,
        // so one merge walk per column finds all positions.
        for (unsigned int b = 0; b < n_local; ++b)
          {
            const int  column = cell_variables[first + b];
            lcp::Index p      = outer[column];
            for (unsigned int a = 0; a < n_local; ++a)
              {
                const int row = cell_variables[first + a];
                while (inner[p] != row)
                  ++p;
                values[p] +=
                  reduced_matrix[static_cast<std::size_t>(a) * n_local + b];
              }
            problem.b[column] += reduced_rhs[b];
          }
        for (std::size_t k = first; k < last; ++k)
          position[cell_variables[k]] = -1;
      }

    // S and its bounds: 0 for the gaps of joints, -g for Signorini.
    problem.constrained.resize(contacts.constraints.size());
    problem.lower_bound.resize(contacts.constraints.size());
    for (std::size_t k = 0; k < contacts.constraints.size(); ++k)
      {
        problem.constrained[k] = change.variable_of_constraint(k);
        problem.lower_bound[k] = contacts.constraints[k].bound;
      }
    return problem;
  }
} // namespace unilateral::masonry
