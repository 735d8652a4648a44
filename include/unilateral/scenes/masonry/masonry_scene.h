#pragma once

#include <unilateral/scenes/masonry/change_of_variables.h>
#include <unilateral/scenes/masonry/contact_detection.h>
#include <unilateral/scenes/masonry/parameters.h>
#include <unilateral/scenes/scene.h>

#include <array>
#include <memory>
#include <vector>

namespace unilateral::masonry
{
  /// The sizes of one masonry problem (Tables 1 and 2 of the paper).
  struct Sizes
  {
    unsigned int n_blocks             = 0; ///< n_b
    unsigned int n_cells              = 0;
    unsigned int n_dofs               = 0; ///< before Dirichlet conditions
    unsigned int n_dirichlet          = 0; ///< eliminated DOFs
    unsigned int n_unknowns           = 0; ///< n = n_dofs - n_dirichlet
    unsigned int n_constraints        = 0; ///< n_c
    unsigned int n_signorini          = 0;
    unsigned int n_horizontal_joint   = 0; ///< node pairs on horizontal joints
    unsigned int n_vertical_joint     = 0; ///< node pairs on vertical joints
    unsigned int max_expansion_length = 0;
    double       block_height         = 0; ///< H
    double       cell_size            = 0; ///< h = H / 2^r
    double       gap                  = 0; ///< g
  };

  /// One unilateral constraint after the solve.
  struct ConstraintResult
  {
    ConstraintKind              kind;
    std::array<double, 2>       position;
    std::array<unsigned int, 2> blocks;        ///< lower/left, upper/right
    double                      normal_gap;    ///< >= 0; 0 = closed
    double                      contact_force; ///< nodal, >= 0 in compression
    bool                        active;        ///< in the active set
  };

  /// The displacement at one node (support point) of one block.
  struct NodalDisplacement
  {
    std::array<double, 2> position;
    unsigned int          block;
    std::array<double, 2> displacement;
  };

  /**
   * The masonry scene of Ainsworth & Mihai (2006), Section 5: a wall of
   * elastic blocks on the unit square (stack bond, running bond or laminae),
   * u_x = 0 on the sides, Signorini contact with a settled ground (gap g) on
   * the left half of the base and u_y = 0 on the right half, frictionless
   * node-to-node contact on every joint, self-weight and an optional top
   * traction. The contact conditions become simple bounds through the
   * change of variables to normal gaps (Section 3), and the LCP goes to the
   * shared solver layer.
   *
   * Life cycle as in the deal.II tutorials: make_grid, setup_system (DOFs,
   * contact detection, change of variables), assemble_system, solve,
   * output_results, run.
   */
  class MasonryScene : public Scene
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    explicit MasonryScene(dealii::ParameterHandler &prm);

    explicit MasonryScene(const Parameters &parameters);

    /**
     * A wall made of the blocks of @p layout instead of the bond named in
     * the parameters (which still give m for nothing, and everything else).
     * The layout's course height plays the role of H.
     */
    MasonryScene(const Parameters &parameters, const Layout &layout);

    ~MasonryScene() override;

    lcp::Report
    run(RunContext &context) override;

    /// A is singular (the blocks are free to move): regularise with 1e-9.
    double
    auto_regularisation() const override
    {
      return 1e-9;
    }

    /// A wall is in contact almost everywhere: PDAS starts with every
    /// constraint active (at m = 225 stack bond: 7 iterations instead of 11).
    bool
    auto_pdas_start_all_active() const override
    {
      return true;
    }

    std::string
    size_parameters() const override;

    /**
     * make_grid and setup_system only: n and n_c without assembling or
     * solving (for the Table 2 counts). Timer sections go to
     * @p context.timer if it is set.
     */
    const Sizes &
    set_up(RunContext &context);

    const Sizes &
    sizes() const
    {
      return problem_sizes;
    }

    /// After set_up(): supports and joints as found on the mesh.
    const ContactSet &
    contact_set() const;

    /// After set_up(): the change of variables to normal gaps.
    const ChangeOfVariables &
    change_of_variables() const;

    /// After run(): every constraint with its gap, force and state.
    const std::vector<ConstraintResult> &
    constraint_results() const
    {
      return constraints;
    }

    /// After run(): the displacement at every node of every block.
    std::vector<NodalDisplacement>
    nodal_displacements() const;

    /// After run(): the LCP that was solved, in the solver's force unit:
    /// A and b are the assembled ones divided by force_unit().
    const lcp::Problem &
    problem() const;

    /// After run(): the LCP solution (new variables, multipliers; the
    /// multipliers in the solver's force unit, like problem()).
    const lcp::Solution &
    solution() const;

    /// The force unit of the LCP handed to the solvers: the largest Young's
    /// modulus divided by 4e3 (the paper's E). A change of the force unit
    /// (every E, density, gravity and traction times k) then hands the
    /// solvers the same numbers, so it cannot change their answer; with the
    /// paper's E it is 1 and nothing is scaled. Energies and forces are
    /// reported in the units of the parameter file.
    double
    force_unit() const;

  private:
    void
    make_grid();

    void
    setup_system(const RunContext &context);

    double
    coincidence_tolerance() const;

    void
    assemble_system();

    lcp::Report
    solve(RunContext &context);

    void
    recover_physical_solution();

    void
    output_results(const RunContext &context) const;

    void
    print_summary(std::ostream &out, const lcp::Report &report) const;

    void
    write_summary_file(const RunContext  &context,
                       const lcp::Report &report) const;

    Parameters parameters;
    /// Set if the scene was given its own layout.
    std::unique_ptr<Layout> custom_layout;

    /// Everything with deal.II types, so this header stays light.
    struct State;
    std::unique_ptr<State> state;

    Sizes                         problem_sizes;
    std::vector<ConstraintResult> constraints;
    double                        max_displacement  = 0;
    double                        unit              = 1;
    unsigned int                  n_closed_contacts = 0;
    /// Closed without force (see recover_physical_solution).
    unsigned int                  n_degenerate_contacts = 0;
  };
} // namespace unilateral::masonry
