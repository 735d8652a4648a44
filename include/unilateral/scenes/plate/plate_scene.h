#pragma once

#include <unilateral/lcp/hierarchy.h>
#include <unilateral/lcp/problem.h>
#include <unilateral/lcp/report.h>
#include <unilateral/scenes/plate/assembly.h>
#include <unilateral/scenes/plate/parameters.h>
#include <unilateral/scenes/scene.h>

#include <deal.II/base/function.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace unilateral::plate
{
  /**
   * The "plate" scene: a thin elastic plate [0, L1] x [0, L2], clamped on
   * its boundary, pressed by a transverse force f onto a rigid obstacle psi
   * (Fernandes, Figueiredo & Judice 2002). Kirchhoff bending, discretised
   * with n1 x n2 Bogner-Fox-Schmit rectangles (4 DOFs per node: w, w_x, w_y,
   * w_xy; fe/bogner_fox_schmit.h).
   *
   * Mapping onto the LCP of lcp/problem.h (the paper's MLCP (32)-(35)):
   *  - u = z_J, the nodal DOFs that are not fixed by the clamping: J. The
   *    fixed DOFs L (w, w_x, w_y at boundary nodes, and w_xy too when fully
   *    clamped) are eliminated, so the LCP has exactly |J| unknowns,
   *    numbered 0..|J|-1 in deal.II's DOF order;
   *  - A = C_JJ, the bending stiffness D [nu Delta z Delta w + (1 - nu)
   *    z_,ab w_,ab] with D = E t^3 / (12 (1 - nu^2)); symmetric positive
   *    definite, so the automatic regularisation is 0;
   *  - b = F_J, the load int f w;
   *  - S = J1, the w DOFs of the interior nodes, with lower bound
   *    l = psi(node): the obstacle acts at the nodes, as in the paper (24);
   *  - lambda = A u - b is the paper's w: the contact force at each interior
   *    node (in the force unit of Plate/Units), >= 0 and zero where the
   *    plate does not touch.
   * cn, the number of interior nodes in contact, is the size of the solver's
   * active set.
   *
   * Output (unless Output/Write VTU = false): plate.vtu/.pvd, the bicubic
   * deflection interpolated exactly into FE_Q(3) and written with
   * subdivisions, with its slopes, the obstacle, the gap w - psi and the
   * bending moments; nodes.vtu/.pvd, the LCP at the mesh nodes (w, w_x,
   * w_y, w_xy, psi, gap, contact 0/1, contact force). Between nodes the gap
   * can be slightly negative: the discrete plate only has to stay above psi
   * at the nodes.
   */
  class PlateScene : public Scene
  {
  public:
    static constexpr const char *registered_name = "plate";

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    explicit PlateScene(dealii::ParameterHandler &prm);

    explicit PlateScene(const Parameters &parameters);

    std::string
    size_parameters() const override
    {
      return "'Plate/Geometry/Elements x' = " +
             std::to_string(parameters.geometry.n_x) +
             ", 'Elements y' = " + std::to_string(parameters.geometry.n_y);
    }

    /// A clamped plate's stiffness is positive definite: 'singular' can
    /// only be the factorisation's condition test, which says why.
    std::string
    failure_description(const lcp::Report &report) const override;

    /// One mesh of the coarse-mesh start (nested iteration), coarsest last.
    struct CoarseLevel
    {
      unsigned int n_x = 0, n_y = 0;
      unsigned int iterations = 0;
      lcp::Status  status     = lcp::Status::converged;
    };

    /// What a run found, in the paper's terms (valid after run()).
    struct Results
    {
      unsigned int n_elements = 0; ///< n1 n2
      unsigned int n_free     = 0; ///< |J|
      unsigned int n_bounds   = 0; ///< |J1|
      unsigned int n_contact  = 0; ///< cn
      double       rigidity   = 0; ///< D (force times length)
      /// Smallest nodal deflection, and w at the plate's centre.
      double min_deflection    = 0;
      double centre_deflection = 0;
    };

    const Results &
    results() const
    {
      return plate_results;
    }

    /// The coarse meshes this run started from, finest first (none: empty).
    const std::vector<CoarseLevel> &
    coarse_mesh_levels() const
    {
      return coarse_levels;
    }

    /// All BFS DOFs of the solution (deal.II numbering, fixed ones zero).
    const dealii::Vector<double> &
    nodal_values() const
    {
      return dof_values;
    }

    const dealii::DoFHandler<2> &
    get_dof_handler() const
    {
      return dof_handler;
    }

    /// The free DOFs (w, w_x, w_y, w_xy in J's order) of the solvers'
    /// unknowns @p u, and the reverse: they differ where the elements are
    /// far from unit length (see unknown_scale).
    lcp::Vector
    dofs_of(const lcp::Vector &u) const;
    lcp::Vector
    unknowns_of(const lcp::Vector &dofs) const;

  protected:
    /// The plate [0, L1] x [0, L2] as n1 x n2 equal rectangles.
    void
    make_grid(RunContext &context) override;

    /// Number the DOFs, eliminate the clamped ones and find J1, the w DOFs
    /// of the interior nodes, with the obstacle's value at each of them.
    void
    setup_system(RunContext &context) override;

    /// A = C_JJ and b = F_J.
    void
    assemble_system(RunContext &context) override;

    /// The coarse-mesh start, where it applies.
    void
    initial_solution(RunContext &context) override;

    /// The full DOF vector, cn, the smallest nodal deflection, and w at the
    /// centre of the plate.
    void
    postprocess(const RunContext &context, lcp::Report &report) override;

    /// In output.cc: the VTU/PVD files.
    void
    output_results(const RunContext &context) const override;

    void
    print_summary(std::ostream &out, const lcp::Report &report) const override;

    void
    add_summary(JsonObject &summary) const override;

  private:
    /// In coarse_mesh_start.cc: whether this run starts from a coarser mesh.
    bool
    uses_coarse_mesh_start(const RunContext &context) const;

    /// The start from the mesh with half as many cells per side (itself
    /// started the same way): u and the first active set on this mesh;
    /// empty if that solve failed. Records the levels in coarse_levels.
    lcp::Solution
    coarse_mesh_start(const RunContext &context);

    /// This mesh's solution at the free DOFs of @p fine, with the nodes
    /// where it touches or dips below the obstacle as active set.
    lcp::Solution
    interpolate_to(const PlateScene &fine) const;

    /// In mesh_hierarchy.cc: this mesh's unknowns carried to the unknowns
    /// of @p fine, a finer mesh of the same plate: the bicubic field
    /// evaluated at its nodes (w, w_x, w_y, w_xy, each scaled as the
    /// solvers' unknowns are on either mesh), as a |J_fine| x |J| matrix.
    lcp::SparseMatrix
    interpolation_to(const PlateScene &fine) const;

    /// In mesh_hierarchy.cc: this plate on coarser meshes, for a method
    /// that works on a hierarchy of meshes.
    std::shared_ptr<const lcp::Hierarchy>
    make_hierarchy() const;

    /**
     * The solvers' unknowns are this plate's free DOFs divided by
     * unknown_scale (empty: not scaled). Where the elements are far from
     * unit length in the plate's units, a node's unknowns differ in size by
     * powers of h (w, h w_x, h w_y and h^2 w_xy are alike) and so do A's
     * diagonal entries, by h^-4 between w and w_xy: at h = 1e-3 (a 10 cm
     * plate in metres) PDAS's and block pivoting's factorisations judged A
     * singular. There the solvers get w, h_x w_x, h_y w_y and h_x h_y w_xy,
     * all lengths of the deflection's size: A becomes S A S and b S b with
     * S = diag(1, 1 / h_x, 1 / h_y, 1 / (h_x h_y)), the bounds (on w) and
     * the contact forces stay as they are. Within a factor 100 of unit
     * length nothing is scaled, as with the force unit below: the paper's
     * plates (h = 1.1-5 mm) and TNNMG's levels in the multigrid benchmark
     * (h = 0.1-50 mm) keep their numbers. Unscaled, the factorisations
     * failed from about 1e-3 and 1e3 on, limits that move inwards as the
     * mesh is refined (benchmarks/plate_tables/README.md, "Element size").
     * The exported LCP and solution are the solvers'.
     */
    lcp::Vector unknown_scale;
    /// unknown_scale of a node's w, w_x, w_y, w_xy (summary.json:
    /// lcp_unknown_scale; all 1 where nothing is scaled).
    std::array<double, 4> component_scale = {{1, 1, 1, 1}};

    Parameters parameters;
    double     rigidity;
    /// The force unit of the LCP handed to the solvers (see
    /// assemble_system): 1 within a factor 1e3 of the paper's steel plate.
    double                                       unit = 1;
    std::unique_ptr<dealii::Function<2, double>> obstacle; ///< null: none
    /// The obstacle's largest value just inside the clamped edge where it
    /// rises there slower than the plate can (0: nowhere), and the point
    /// just inside the edge it is taken at (set up with the bounds).
    double           obstacle_on_edge = 0;
    dealii::Point<2> obstacle_on_edge_at;
    /// A coarser mesh that this plate builds for a start or a hierarchy:
    /// its nodes are not the user's (see setup_system).
    bool                                         coarse_level = false;
    std::unique_ptr<dealii::Function<2, double>> force;

    dealii::Triangulation<2> triangulation;
    dealii::FESystem<2>      fe; ///< FE_Q(1)^4: numbers w, w_x, w_y, w_xy
    dealii::DoFHandler<2>    dof_handler;

    FreeDofs free_dofs;
    /// Per index in J1 (in S order): the vertex index of the node.
    std::vector<unsigned int> bound_vertex;

    dealii::Vector<double>   dof_values;
    Results                  plate_results;
    std::vector<CoarseLevel> coarse_levels;
  };
} // namespace unilateral::plate
