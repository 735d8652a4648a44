#pragma once

#include <unilateral/lcp/report.h>
#include <unilateral/scenes/masonry/change_of_variables.h>
#include <unilateral/scenes/masonry/contact_detection.h>
#include <unilateral/scenes/masonry/free_motions.h>
#include <unilateral/scenes/masonry/parameters.h>
#include <unilateral/scenes/scene.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace unilateral::masonry
{
  /// The sizes of one masonry problem (Tables 1 and 2 of the paper).
  struct Sizes
  {
    unsigned int n_blocks             = 0; ///< n_b
    unsigned int n_cells              = 0;
    unsigned int n_dofs               = 0; ///< before the supports
    unsigned int n_dirichlet          = 0; ///< eliminated DOFs (held, rollers)
    unsigned int n_unknowns           = 0; ///< n = n_dofs - n_dirichlet
    unsigned int n_constraints        = 0; ///< n_c
    unsigned int n_signorini          = 0;
    unsigned int n_horizontal_joint   = 0; ///< node pairs, normal along y
    unsigned int n_vertical_joint     = 0; ///< node pairs, normal along x, z
    unsigned int n_inclined_joint     = 0; ///< node pairs, other normals
    unsigned int max_expansion_length = 0;
    double       block_height         = 0; ///< H (1 for a mesh file)
    double       cell_size            = 0; ///< h = H / 2^r (the smallest)
    /// The smallest distance between two vertices of a cell: the scale of
    /// coincidence and nearness in contact detection (a built-in 3D wall's
    /// leaves may be far thinner than h).
    double smallest_cell_extent = 0;
    double gap                  = 0; ///< g
  };

  /// One unilateral constraint after the solve.
  template <int dim>
  struct ConstraintResult
  {
    ConstraintKind              kind;
    std::array<double, dim>     position;
    std::array<unsigned int, 2> blocks; ///< lower, upper (or the block twice)
    std::array<double, dim>     normal; ///< from lower into upper, or up
    double                      normal_gap;    ///< >= 0; 0 = closed
    double                      contact_force; ///< nodal, >= 0 in compression
    bool                        active;        ///< in the active set
  };

  /// The displacement at one node (support point) of one block.
  template <int dim>
  struct NodalDisplacement
  {
    std::array<double, dim> position;
    unsigned int            block;
    std::array<double, dim> displacement;
  };

  /**
   * What holds the structure: the force (and moment about the origin) each
   * support exerts, the applied loads, and how well they balance.
   */
  template <int dim>
  struct Statics
  {
    /// The applied loads (body force and tractions): total force and
    /// moment (z in 2D).
    std::array<double, dim> load{};
    std::array<double, 3>   load_moment{};
    /// Per support name: force and moment.
    std::vector<std::string>             support;
    std::vector<std::array<double, dim>> reaction;
    std::vector<std::array<double, 3>>   reaction_moment;
    /// Per roller of the ContactSet: its reaction along the roller's
    /// outward normal (negative where the support presses on the block),
    /// for the contact pressure of the output.
    std::vector<double> roller_force;
    /// |loads + reactions| / |loads| (force), the same for the moment over
    /// |loads| times the structure's size.
    double force_imbalance  = 0;
    double moment_imbalance = 0;
  };

  /**
   * The masonry scene of Ainsworth & Mihai (2006), for any assembly of
   * elastic blocks in 2D (plane strain) and 3D: the paper's walls (stack
   * bond, running bond, laminae, with its supports: normal displacement
   * zero on the sides and the held part of the base, Signorini contact
   * with a settled ground on the rest) built in, or blocks from a Gmsh file
   * with supports and loads on its named boundaries; frictionless
   * node-to-node contact on every joint of any orientation, body force and
   * tractions. The contact conditions become simple bounds through the
   * change of variables to normal gaps (Section 3, in frames of the joints'
   * directions: change_of_variables.h), and the LCP goes to the shared
   * solver layer.
   *
   * The stages of Scene::run(), as in the deal.II tutorials: make_grid,
   * setup_system (DOFs, supports, contact detection, change of variables),
   * assemble_system, postprocess, output_results.
   */
  template <int dim>
  class MasonryScene : public Scene
  {
  public:
    static constexpr const char *registered_name = "masonry";

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /// The scene of the parameters (a relative 'Mesh file' starts at the
    /// run's parameter file, RunContext::parameter_file).
    explicit MasonryScene(const Parameters &parameters);

    /**
     * A wall made of the blocks of @p layout instead of the bond named in
     * the parameters (which still give m for nothing, and everything else).
     * The layout's course height plays the role of H.
     */
    MasonryScene(const Parameters &parameters, const Layout &layout);

    ~MasonryScene() override;

    std::string
    size_parameters() const override;

    /// In the structure's terms: no equilibrium, or a block that nothing
    /// holds.
    std::string
    failure_description(const lcp::Report &report) const override;

    /// Each rank writes the blocks of its own contiguous run of block ids.
    bool
    writes_output_in_parallel() const override
    {
      return true;
    }

    /// After set_up(): n and n_c (the Table 2 counts) and the other sizes.
    const Sizes &
    sizes() const
    {
      return problem_sizes;
    }

    /// After set_up(): supports and joints as found on the mesh.
    const ContactSet<dim> &
    contact_set() const;

    /// After set_up(): the change of variables to normal gaps.
    const ChangeOfVariables<dim> &
    change_of_variables() const;

    /// After run(): every constraint with its gap, force and state.
    const std::vector<ConstraintResult<dim>> &
    constraint_results() const
    {
      return constraints;
    }

    /// After run(): the displacement at every node of every block.
    std::vector<NodalDisplacement<dim>>
    nodal_displacements() const;

    /// The coarse-mesh start a run took (n_unknowns 0: none).
    struct CoarseStart
    {
      /// Cells this many times as long along x and y.
      std::array<unsigned int, 2> coarsening{{1, 1}};
      unsigned int                n_unknowns = 0;
      unsigned int                iterations = 0;
      lcp::Status                 status     = lcp::Status::converged;
    };

    /// After run(): the coarse-mesh start taken, if any.
    const CoarseStart &
    coarse_mesh_start_taken() const
    {
      return coarse_start;
    }

    /// After run(): the supports' reactions and the balance of forces.
    const Statics<dim> &
    statics() const
    {
      return balance;
    }

    /// The force unit of the LCP handed to the solvers (problem() and
    /// solution() are in it): the largest Young's modulus divided by 4e3
    /// (the paper's E). A change of the force unit (every E, density,
    /// gravity and traction times k) then hands the solvers the same
    /// numbers, so it cannot change their answer; with the paper's E it is
    /// 1 and nothing is scaled. Energies and forces are reported in the
    /// units of the parameter file.
    double
    force_unit() const;

  protected:
    /// The blocks: a built-in wall's layout meshed block by block (cells of
    /// size h = H / 2^r), or a mesh file's blocks; material_id = block index.
    void
    make_grid(RunContext &context) override;

    /// DOFs, then the supports and joints found on the mesh, then the
    /// change of variables to normal gaps.
    void
    setup_system(RunContext &context) override;

    /// A~ and b~ in the gap variables, in the solvers' force unit.
    void
    assemble_system(RunContext &context) override;

    /// Loads that do work along a free rigid motion (free_motions.h).
    std::string
    proof_of_no_solution() override;

    /// u = C~^-1 u~, each constraint's gap, force and state, the energy in
    /// the parameter file's units, the reactions.
    void
    postprocess(const RunContext &context, lcp::Report &report) override;

    /// In output.cc.
    void
    output_results(const RunContext &context) const override;

    /// The coarse-mesh start where it applies (coarse_mesh_start.cc).
    void
    initial_solution(RunContext &context) override;

    void
    print_summary(std::ostream &out, const lcp::Report &report) const override;

    void
    add_summary(JsonObject &summary) const override;

  private:
    /// What the summary calls the structure ("stack bond", "arch.msh").
    std::string
    structure_name() const;

    void
    compute_statics();

    /// Downgrade a converged @p report whose statics (compute_statics) do
    /// not balance to @p kkt_tolerance, or whose energy's share from the
    /// prescribed displacements is not resolved that finely.
    void
    check_statics(double kkt_tolerance, lcp::Report &report) const;

    /// How many times longer the cells of the coarse-mesh start's mesh are
    /// along x and y ({1, 1}: this run takes no such start).
    std::array<unsigned int, 2>
    coarse_mesh_coarsening(const RunContext &context) const;

    /// Solve this wall on the mesh coarsened by @p coarsening and return
    /// its displacement at this mesh's nodes as a start (LCP unknowns and
    /// first active set); empty if that solve failed.
    lcp::Solution
    coarse_mesh_start(const RunContext                  &context,
                      const std::array<unsigned int, 2> &coarsening);

    /// This (solved) wall's displacement at the nodes of @p fine, in
    /// fine's LCP unknowns, with the constraints it leaves closed (to its
    /// interpolation error) active.
    lcp::Solution
    interpolate_to(const MasonryScene<dim> &fine) const;

    Parameters parameters;
    /// Cells this many times longer along x and y than h (a coarse-mesh
    /// start's mesh).
    std::array<unsigned int, 2> mesh_coarsening{{1, 1}};
    CoarseStart                 coarse_start;
    /// Set if the scene was given its own layout.
    std::unique_ptr<Layout> custom_layout;

    /// Everything with deal.II types, so this header stays light.
    struct State;
    std::unique_ptr<State> state;

    Sizes                              problem_sizes;
    std::vector<ConstraintResult<dim>> constraints;
    Statics<dim>                       balance;
    double                             max_displacement = 0;
    double                             unit             = 1;
    double                             energy_offset    = 0;
    /// Its rounding error: epsilon times the sum of its terms' sizes.
    double       energy_offset_rounding = 0;
    unsigned int n_closed_contacts      = 0;
    /// Closed without force (see postprocess).
    unsigned int n_degenerate_contacts = 0;
    /// The groups of blocks that some rigid motion moves past every support
    /// (free_rigid_motions), one line each.
    std::vector<std::string> free_motions;
    /// Whether the Signorini supports of some group hold it in a motion
    /// its other supports leave free (free_rigid_motions): then the loads
    /// decide whether it stands.
    bool held_by_signorini = false;
    /// A mechanism of the answer's closed contacts (answer_mechanism), or
    /// empty.
    std::string mechanism;
    /// Sets of blocks that can slide along their joints (free_slides).
    std::vector<FreeSlides<dim>> slides;
    /// The proof that the loads drive one of them, or empty.
    std::string driven_motion;

    /// Whether @p report is that proof, found without solving.
    bool
    proved_before_solving(const lcp::Report &report) const
    {
      return report.status == lcp::Status::infeasible &&
             !driven_motion.empty() && report.message == driven_motion;
    }
  };

  /// The scene of the parameter file: MasonryScene<2> or <3> by
  /// 'Masonry/Dimension' (the registry's factory).
  std::unique_ptr<Scene>
  create_masonry_scene(dealii::ParameterHandler &prm);
} // namespace unilateral::masonry
