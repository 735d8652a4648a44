#pragma once

#include <unilateral/fe/bogner_fox_schmit.h>
#include <unilateral/lcp/problem.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace dealii
{
  class IndexSet;
}

/**
 * Assembly of the plate's stiffness C and load F on a mesh of
 * Bogner-Fox-Schmit rectangles numbered by a DoFHandler with
 * FESystem<2>(FE_Q<2>(1), 4) (see fe/bogner_fox_schmit.h), restricted to the
 * free DOFs J: the LCP needs C_JJ and F_J, with the fixed DOFs L eliminated
 * rather than kept as identity rows.
 */
namespace unilateral::plate
{
  /// The free DOFs J, numbered 0..|J|-1 in increasing deal.II DOF order.
  struct FreeDofs
  {
    /// Per deal.II DOF: its index in J, or -1 if it is fixed (in L).
    std::vector<lcp::Index> index;
    /// Per index in J: the deal.II DOF.
    std::vector<dealii::types::global_dof_index> dof;

    lcp::Index
    size() const
    {
      return static_cast<lcp::Index>(dof.size());
    }
  };

  FreeDofs
  number_free_dofs(dealii::types::global_dof_index n_dofs,
                   const dealii::IndexSet         &fixed_dofs);

  /// The element of a cell (axis-aligned rectangle; throws otherwise).
  fe::BognerFoxSchmit
  cell_element(const dealii::DoFHandler<2>::active_cell_iterator &cell);

  /// The cell's 16 coefficients, in BFS order, from a vector of all DOFs.
  fe::BognerFoxSchmit::Coefficients
  cell_coefficients(const dealii::DoFHandler<2>::active_cell_iterator &cell,
                    const std::vector<unsigned int> &bfs_index,
                    const dealii::Vector<double>    &dof_values);

  /**
   * A = C_JJ (both triangles, compressed, pattern = all couplings of the
   * mesh) and b = F_J - C_JL z_L, with z_L = @p fixed_values on the fixed
   * DOFs (nullptr: z_L = 0, the clamped plate). C and F are integrated
   * exactly (CellIntegrals): C^e from D [nu Delta z Delta w + (1 - nu)
   * z_,ab w_,ab], F^e from f w. @p force is evaluated at Gauss points; a
   * non-finite value throws InputError starting with @p force_description
   * (say "parameter 'Plate/Load/Force' = 1/x").
   */
  void
  assemble_plate_system(const dealii::DoFHandler<2>       &dof_handler,
                        const FreeDofs                    &free_dofs,
                        const dealii::Vector<double>      *fixed_values,
                        double                             rigidity,
                        double                             poisson_ratio,
                        const dealii::Function<2, double> &force,
                        const std::string                 &force_description,
                        lcp::SparseMatrix                 &matrix,
                        lcp::Vector                       &rhs);
} // namespace unilateral::plate
