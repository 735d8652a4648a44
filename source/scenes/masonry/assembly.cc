#include <unilateral/base/memory.h>
#include <unilateral/scenes/masonry/assembly.h>

#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace unilateral::masonry
{
  namespace
  {
    // The new variables each cell touches: the union of the expansions of
    // its physical DOFs, sorted. Stored for all cells (CSR), since both the
    // sparsity pattern and the assembly walk them.
    template <int dim>
    void
    collect_cell_variables(const dealii::DoFHandler<dim> &dof_handler,
                           const ChangeOfVariables<dim>  &change,
                           std::vector<std::size_t>      &start,
                           std::vector<int>              &variables)
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
    // with a marker array instead of sets, in two passes (count, then
    // write into A's own arrays), so that no pattern is built beside A's
    // and A's size is known exactly before it is allocated.
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

      // Calls visit(i) once for each variable i coupled with j.
      std::vector<int> marker(n, -1);
      const auto       for_each_coupled = [&](const int j, auto &&visit) {
        for (std::size_t k = cells_start[j]; k < cells_start[j + 1]; ++k)
          {
            const unsigned int c = cells_of[k];
            for (std::size_t l = cell_start[c]; l < cell_start[c + 1]; ++l)
              if (const int i = cell_variables[l]; marker[i] != j)
                {
                  marker[i] = j;
                  visit(i);
                }
          }
      };

      std::size_t entries = 0;
      for (int j = 0; j < n; ++j)
        for_each_coupled(j, [&entries](int) { ++entries; });
      if (entries >
          static_cast<std::size_t>(std::numeric_limits<lcp::Index>::max()))
        throw OutOfMemory("the matrix A~ of " + std::to_string(n) +
                          " unknowns has " + std::to_string(entries) +
                          " entries, more than 32-bit indices can count");
      memory::require(static_cast<double>(entries) *
                        (sizeof(lcp::Index) + sizeof(double)),
                      "the matrix A~ of " + std::to_string(n) + " unknowns");

      A.resize(n, n);
      A.makeCompressed();
      A.resizeNonZeros(static_cast<lcp::Index>(entries));
      lcp::Index *const outer = A.outerIndexPtr();
      lcp::Index *const inner = A.innerIndexPtr();
      std::fill(marker.begin(), marker.end(), -1);
      outer[0] = 0;
      for (int j = 0; j < n; ++j)
        {
          lcp::Index end = outer[j];
          for_each_coupled(j, [&](const int i) { inner[end++] = i; });
          // Every variable belongs to some cell, so the diagonal is present.
          std::sort(inner + outer[j], inner + end);
          outer[j + 1] = end;
        }
      std::fill(A.valuePtr(), A.valuePtr() + entries, 0.0);
    }

    /// Whether @p cell is @p other shifted: as many vertices, and each one's
    /// offset from the first equal to @p other's to 1e-12 of the cell's
    /// diameter. (deal.II's is_translation_of allows 1e-12 of the shift,
    /// which between far-apart cells is far more than rounding.)
    template <int dim>
    bool
    translation_of(
      const typename dealii::Triangulation<dim>::cell_iterator &cell,
      const typename dealii::Triangulation<dim>::cell_iterator &other)
    {
      if (cell->n_vertices() != other->n_vertices())
        return false;
      const double tolerance = 1e-12 * cell->diameter();
      for (unsigned int i = 1; i < cell->n_vertices(); ++i)
        if (((cell->vertex(i) - cell->vertex(0)) -
             (other->vertex(i) - other->vertex(0)))
              .norm() > tolerance)
          return false;
      return true;
    }
  } // namespace

  template <int dim>
  CellSystem<dim>::CellSystem(const Discretisation<dim> &discretisation,
                              const LoadData<dim>       &loads)
    : discretisation(discretisation)
    , loads(loads)
    , fe_values(*discretisation.mapping,
                *discretisation.fe,
                *discretisation.quadrature,
                dealii::update_values | dealii::update_gradients |
                  dealii::update_JxW_values)
    , fe_face_values(*discretisation.mapping,
                     *discretisation.fe,
                     *discretisation.face_quadrature,
                     dealii::update_values | dealii::update_JxW_values |
                       dealii::update_quadrature_points)
    , dofs_per_cell(discretisation.fe->n_dofs_per_cell())
    , component(dofs_per_cell)
    , volume_rhs(dofs_per_cell)
    , matrix(dofs_per_cell * dofs_per_cell)
    , rhs(dofs_per_cell)
  {
    for (unsigned int i = 0; i < dofs_per_cell; ++i)
      component[i] = discretisation.fe->system_to_component_index(i).first;
    for (const Support<dim> &support : loads.supports->list)
      if (support.kind == Support<dim>::Kind::traction)
        {
          if (support.boundary >= traction_on.size())
            traction_on.resize(support.boundary + 1);
          traction_on[support.boundary].push_back(&support);
        }
  }

  template <int dim>
  void
  CellSystem<dim>::reinit(
    const typename dealii::DoFHandler<dim>::active_cell_iterator &cell)
  {
    const MaterialClass &material =
      loads.classes[loads.class_of_block[cell->material_id()]];
    if (integrated_material != &material ||
        !translation_of<dim>(cell, integrated_cell))
      {
        fe_values.reinit(cell);
        integrate_volume_terms(material);
        integrated_cell = cell;
      }
    rhs = volume_rhs;

    if (traction_on.empty() || loads.supports->zero_traction)
      return;
    for (const unsigned int f : cell->face_indices())
      {
        if (!cell->face(f)->at_boundary() ||
            cell->face(f)->boundary_id() >= traction_on.size() ||
            traction_on[cell->face(f)->boundary_id()].empty())
          continue;
        // Where several traction entries cover a point, it is loaded once.
        const auto &supports = traction_on[cell->face(f)->boundary_id()];
        const bool  everywhere =
          std::any_of(supports.begin(), supports.end(), [](const auto *s) {
            return s->region == nullptr;
          });
        const auto inside = [&supports](const dealii::Point<dim> &x) {
          return std::any_of(supports.begin(),
                             supports.end(),
                             [&x](const Support<dim> *support) {
                               return support->region->value(x) > 0.5;
                             });
        };
        FaceRegionRule<dim> part;
        part.coverage = FaceRegionRule<dim>::Coverage::whole;
        if (!everywhere)
          part = face_region_rule<dim>(cell, f, inside);
        if (part.coverage == FaceRegionRule<dim>::Coverage::none)
          continue;
        if (part.coverage == FaceRegionRule<dim>::Coverage::partial)
          {
            add_partial_face_load(cell, part);
            continue;
          }
        fe_face_values.reinit(cell, f);
        dealii::Vector<double> t(dim);
        for (unsigned int q = 0; q < fe_face_values.n_quadrature_points; ++q)
          {
            loads.supports->traction->vector_value(
              fe_face_values.quadrature_point(q), t);
            for (unsigned int i = 0; i < dofs_per_cell; ++i)
              rhs[i] += fe_face_values.shape_value(i, q) * t[component[i]] *
                        fe_face_values.JxW(q);
          }
      }
  }

  template <int dim>
  void
  CellSystem<dim>::integrate_volume_terms(const MaterialClass &material)
  {
    const double                 lambda = material.lambda();
    const double                 mu     = material.mu();
    const dealii::Tensor<1, dim> body_force =
      material.density * loads.supports->gravity;

    // Linear elasticity, as in step-8 (plane strain in 2D).
    std::fill(matrix.begin(), matrix.end(), 0.0);
    std::fill(volume_rhs.begin(), volume_rhs.end(), 0.0);
    for (unsigned int q = 0; q < fe_values.n_quadrature_points; ++q)
      {
        const double JxW = fe_values.JxW(q);
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          {
            const unsigned int            ci = component[i];
            const dealii::Tensor<1, dim> &gi = fe_values.shape_grad(i, q);
            for (unsigned int j = i; j < dofs_per_cell; ++j)
              {
                const unsigned int            cj = component[j];
                const dealii::Tensor<1, dim> &gj = fe_values.shape_grad(j, q);
                double value = gi[ci] * gj[cj] * lambda + gi[cj] * gj[ci] * mu;
                if (ci == cj)
                  value += (gi * gj) * mu;
                matrix[i * dofs_per_cell + j] += value * JxW;
              }
            if (body_force[ci] != 0)
              volume_rhs[i] +=
                fe_values.shape_value(i, q) * body_force[ci] * JxW;
          }
      }
    for (unsigned int i = 0; i < dofs_per_cell; ++i)
      for (unsigned int j = 0; j < i; ++j)
        matrix[i * dofs_per_cell + j] = matrix[j * dofs_per_cell + i];
    integrated_material = &material;
  }

  template <int dim>
  void
  CellSystem<dim>::add_partial_face_load(
    const typename dealii::DoFHandler<dim>::active_cell_iterator &cell,
    const FaceRegionRule<dim>                                    &part)
  {
    dealii::FEValues<dim> values(*discretisation.mapping,
                                 *discretisation.fe,
                                 dealii::Quadrature<dim>(part.points,
                                                         part.weights),
                                 dealii::update_values |
                                   dealii::update_jacobians |
                                   dealii::update_quadrature_points);
    values.reinit(cell);
    dealii::Vector<double> t(dim);
    for (unsigned int q = 0; q < values.n_quadrature_points; ++q)
      {
        // The face's measure from its reference tangents (face_region.h).
        const dealii::DerivativeForm<1, dim, dim> &J = values.jacobian(q);
        const dealii::Tensor<1, dim>               e_s =
          dealii::apply_transformation(J, part.tangents[0]);
        double measure = e_s.norm();
        if constexpr (dim == 3)
          measure = dealii::cross_product_3d(
                      e_s, dealii::apply_transformation(J, part.tangents[1]))
                      .norm();
        loads.supports->traction->vector_value(values.quadrature_point(q), t);
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          rhs[i] += values.shape_value(i, q) * t[component[i]] *
                    part.weights[q] * measure;
      }
  }

  template <int dim>
  lcp::Problem
  assemble_lcp(const Discretisation<dim>    &discretisation,
               const ChangeOfVariables<dim> &change,
               const ContactSet<dim>        &contacts,
               const LoadData<dim>          &loads,
               double                       &energy_offset,
               double                       &offset_rounding)
  {
    const dealii::DoFHandler<dim> &dof_handler = discretisation.dof_handler;
    const unsigned int dofs_per_cell = discretisation.fe->n_dofs_per_cell();
    const int          n             = static_cast<int>(change.n_unknowns());

    lcp::Problem problem;
    problem.b = lcp::Vector::Zero(n);

    std::vector<std::size_t> cell_start;
    std::vector<int>         cell_variables;
    collect_cell_variables(dof_handler, change, cell_start, cell_variables);
    make_pattern(n, cell_start, cell_variables, problem.A);

    std::vector<dealii::types::global_dof_index> dofs(dofs_per_cell);
    CellSystem<dim>            cell_system(discretisation, loads);
    const std::vector<double> &cell_matrix = cell_system.matrix;
    const std::vector<double> &cell_rhs    = cell_system.rhs;
    std::vector<int>    position(n, -1); // variable -> index in the cell list
    std::vector<double> reduced_matrix, reduced_rhs, load(dofs_per_cell);
    struct LocalTerm
    {
      unsigned int position;
      double       coefficient;
    };
    std::vector<LocalTerm>   local_terms;
    std::vector<std::size_t> term_start(dofs_per_cell + 1);

    const lcp::Index *outer  = problem.A.outerIndexPtr();
    const lcp::Index *inner  = problem.A.innerIndexPtr();
    double           *values = problem.A.valuePtr();
    energy_offset            = 0;
    offset_rounding          = 0;

    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        cell_system.reinit(cell);

        // The load less what the prescribed displacements c take:
        // f - K c, and the energy's constant part 1/2 c'Kc - f'c.
        std::copy(cell_rhs.begin(), cell_rhs.end(), load.begin());
        if (change.has_offsets())
          for (unsigned int i = 0; i < dofs_per_cell; ++i)
            {
              const double c_i = change.offset(dofs[i]);
              for (unsigned int j = 0; j < dofs_per_cell; ++j)
                {
                  const double K_ij_c_j =
                    cell_matrix[i * dofs_per_cell + j] * change.offset(dofs[j]);
                  load[i] -= K_ij_c_j;
                  energy_offset += 0.5 * c_i * K_ij_c_j;
                  offset_rounding += std::abs(0.5 * c_i * K_ij_c_j);
                }
              energy_offset -= cell_rhs[i] * c_i;
              offset_rounding += std::abs(cell_rhs[i] * c_i);
            }

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
              reduced_rhs[a.position] += a.coefficient * load[i];
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

    // S and its bounds: 0 for the gaps of joints, -gap for Signorini.
    problem.constrained.resize(contacts.constraints.size());
    problem.lower_bound.resize(contacts.constraints.size());
    for (std::size_t k = 0; k < contacts.constraints.size(); ++k)
      {
        problem.constrained[k] = change.variable_of_constraint(k);
        problem.lower_bound[k] = contacts.constraints[k].bound;
      }
    offset_rounding *= std::numeric_limits<double>::epsilon();
    return problem;
  }

  template <int dim>
  std::vector<double>
  residual_forces(const Discretisation<dim> &discretisation,
                  const LoadData<dim>       &loads,
                  const std::vector<double> &u)
  {
    const unsigned int  dofs_per_cell = discretisation.fe->n_dofs_per_cell();
    std::vector<double> residual(u.size(), 0.0);
    std::vector<dealii::types::global_dof_index> dofs(dofs_per_cell);
    CellSystem<dim> cell_system(discretisation, loads);
    for (const auto &cell : discretisation.dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        cell_system.reinit(cell);
        for (unsigned int i = 0; i < dofs_per_cell; ++i)
          {
            double r = -cell_system.rhs[i];
            for (unsigned int j = 0; j < dofs_per_cell; ++j)
              r += cell_system.matrix[i * dofs_per_cell + j] * u[dofs[j]];
            residual[dofs[i]] += r;
          }
      }
    return residual;
  }

  template class CellSystem<2>;
  template class CellSystem<3>;
  template lcp::Problem
  assemble_lcp<2>(const Discretisation<2> &,
                  const ChangeOfVariables<2> &,
                  const ContactSet<2> &,
                  const LoadData<2> &,
                  double &,
                  double &);
  template lcp::Problem
  assemble_lcp<3>(const Discretisation<3> &,
                  const ChangeOfVariables<3> &,
                  const ContactSet<3> &,
                  const LoadData<3> &,
                  double &,
                  double &);
  template std::vector<double>
  residual_forces<2>(const Discretisation<2> &,
                     const LoadData<2> &,
                     const std::vector<double> &);
  template std::vector<double>
  residual_forces<3>(const Discretisation<3> &,
                     const LoadData<3> &,
                     const std::vector<double> &);
} // namespace unilateral::masonry
