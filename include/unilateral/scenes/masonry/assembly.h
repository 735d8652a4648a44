#pragma once

#include <unilateral/lcp/problem.h>
#include <unilateral/scenes/masonry/change_of_variables.h>
#include <unilateral/scenes/masonry/contact_detection.h>
#include <unilateral/scenes/masonry/discretisation.h>
#include <unilateral/scenes/masonry/face_region.h>
#include <unilateral/scenes/masonry/parameters.h>
#include <unilateral/scenes/masonry/supports.h>

#include <deal.II/fe/fe_values.h>

#include <vector>

namespace unilateral::masonry
{
  /// What the weak form needs besides the mesh: materials and loads.
  template <int dim>
  struct LoadData
  {
    std::vector<MaterialClass> classes;
    std::vector<unsigned int>  class_of_block;
    /// The gravity, the traction and the boundaries it acts on.
    const Supports<dim> *supports = nullptr;
  };

  /**
   * The stiffness (step-8; plane strain in 2D) and the load (body force,
   * traction) of one cell in its physical DOFs, deal.II's local numbering:
   * what the LCP's assembly expands into the new variables, and what the
   * reactions and the tearing into blocks sum.
   *
   * A cell that is a translation of the last one integrated (its vertices
   * in the same order, their offsets from the first equal to 1e-12 of its
   * diameter), of the same material, has the same stiffness and body force,
   * as the mapping is (bi/tri)linear: they are kept. On the walls nearly
   * every cell is one, and the volume integrals were most of the assembly's
   * and the reactions' time. This is what FEValues's own CellSimilarity
   * does, but deal.II turns that off whenever it may run on several threads
   * (as a serial run here does), and its test allows 1e-12 of the shift
   * between the cells, not of their size; so the test is made here. The
   * terms kept differ from those the cell's own vertices give by 1e-12
   * relative at most: rounding on the built-in walls, and on a mesh file
   * also the noise of its vertices within the tolerance (a far smaller
   * change of the geometry than the discretisation's).
   */
  template <int dim>
  class CellSystem
  {
  public:
    CellSystem(const Discretisation<dim> &discretisation,
               const LoadData<dim>       &loads);

    /// matrix and rhs of @p cell.
    void
    reinit(const typename dealii::DoFHandler<dim>::active_cell_iterator &cell);

  private:
    /// Adds the traction on the part of a face inside its region.
    void
    add_partial_face_load(
      const typename dealii::DoFHandler<dim>::active_cell_iterator &cell,
      const FaceRegionRule<dim>                                    &part);

    /// The stiffness and the body force of the cell fe_values was last
    /// reinitialised on.
    void
    integrate_volume_terms(const MaterialClass &material);

    const Discretisation<dim> &discretisation;
    const LoadData<dim>       &loads;
    dealii::FEValues<dim>      fe_values;
    dealii::FEFaceValues<dim>  fe_face_values;
    const unsigned int         dofs_per_cell;
    std::vector<unsigned int>  component;
    /// The traction supports, by boundary id.
    std::vector<std::vector<const Support<dim> *>> traction_on;
    /// The cell and material whose volume terms volume_rhs and matrix hold
    /// (none before the first cell).
    typename dealii::Triangulation<dim>::cell_iterator integrated_cell;
    const MaterialClass *integrated_material = nullptr;
    std::vector<double>  volume_rhs;

  public:
    /// Row-major, dofs_per_cell^2.
    std::vector<double> matrix;
    std::vector<double> rhs;
  };

  /**
   * Assemble the LCP in the new variables: A = C~^-T K C~^-1 and
   * b = C~^-T (f - K c) (elasticity K, body force and traction f, c the
   * prescribed displacements), S = the constrained variables with their
   * bounds (0 for joints, -gap for Signorini).
   * Each cell's local physical DOFs are expanded into their few new
   * variables, like AffineConstraints::distribute_local_to_global but with
   * the expansion lists of @p change, so A stays sparse and no global
   * product is formed; the sparsity pattern comes from the same expansion.
   * DOFs without variables (held, rollers) have no terms and drop out.
   * @p energy_offset is set to 1/2 c^T K c - f^T c, the physical energy
   * minus the LCP's, and @p offset_rounding to the rounding error of that
   * sum (epsilon times the sum of its terms' sizes): where prescribed
   * displacements are many orders larger than the elastic ones, the
   * terms cancel to far below their size, and double precision keeps the
   * energy only to that.
   */
  template <int dim>
  lcp::Problem
  assemble_lcp(const Discretisation<dim>    &discretisation,
               const ChangeOfVariables<dim> &change,
               const ContactSet<dim>        &contacts,
               const LoadData<dim>          &loads,
               double                       &energy_offset,
               double                       &offset_rounding);

  /**
   * The residual R = K u - f of the physical displacement @p u at every
   * DOF: the force each support (and each joint) exerts on a node, up to
   * its sign.
   */
  template <int dim>
  std::vector<double>
  residual_forces(const Discretisation<dim> &discretisation,
                  const LoadData<dim>       &loads,
                  const std::vector<double> &u);
} // namespace unilateral::masonry
