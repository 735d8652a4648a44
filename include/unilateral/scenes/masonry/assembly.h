#pragma once

#include <unilateral/lcp/problem.h>
#include <unilateral/scenes/masonry/change_of_variables.h>
#include <unilateral/scenes/masonry/contact_detection.h>
#include <unilateral/scenes/masonry/discretisation.h>
#include <unilateral/scenes/masonry/parameters.h>

#include <deal.II/fe/fe_values.h>

#include <vector>

namespace unilateral::masonry
{
  /// What the weak form needs besides the mesh: materials and loads.
  struct LoadData
  {
    std::vector<MaterialClass> classes;
    std::vector<unsigned int>  class_of_block;
    double                     gravity = 1;
    std::array<double, 2>      top_traction{{0, 0}};
    /// The top y = y_top carries the traction; faces within tolerance.
    double y_top     = 1;
    double tolerance = 0;
  };

  /**
   * The plane strain stiffness (step-8) and the load (body force, top
   * traction) of one cell in its physical DOFs, deal.II's local numbering:
   * what the LCP's assembly expands into the new variables and the tearing
   * (tearing.h) sums per block.
   */
  class CellSystem
  {
  public:
    CellSystem(const Discretisation &discretisation, const LoadData &loads);

    /// matrix and rhs of @p cell.
    void
    reinit(const dealii::DoFHandler<2>::active_cell_iterator &cell);

  private:
    const LoadData           &loads;
    dealii::FEValues<2>       fe_values;
    dealii::FEFaceValues<2>   fe_face_values;
    const unsigned int        dofs_per_cell;
    std::vector<unsigned int> component;

  public:
    /// Row-major, dofs_per_cell^2.
    std::vector<double> matrix;
    std::vector<double> rhs;
  };

  /**
   * Assemble the LCP in the new variables: A = C~^-T K C~^-1 and
   * b = C~^-T f (plane strain elasticity K, body force and top traction f),
   * S = the constrained variables with bounds 0 (joints) and -g (Signorini).
   * Each cell's local physical DOFs are expanded into their few new
   * variables, like AffineConstraints::distribute_local_to_global but with
   * the expansion lists of @p change, so A stays sparse and no global
   * product is formed; the sparsity pattern comes from the same expansion.
   * Dirichlet DOFs have empty expansions and drop out.
   */
  lcp::Problem
  assemble_lcp(const Discretisation    &discretisation,
               const ChangeOfVariables &change,
               const ContactSet        &contacts,
               const LoadData          &loads);
} // namespace unilateral::masonry
