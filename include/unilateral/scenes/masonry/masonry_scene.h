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
   * The stages of Scene::run(), as in the deal.II tutorials: make_grid,
   * setup_system (DOFs, contact detection, change of variables),
   * assemble_system, postprocess, output_results.
   */
  class MasonryScene : public Scene
  {
  public:
    static constexpr const char *registered_name = "masonry";

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

    std::string
    size_parameters() const override;

    /// In the wall's terms: no equilibrium, or a block that nothing holds.
    std::string
    failure_description(const lcp::Report &report) const override;

    /// m 2^r >= 100: smaller walls gain less from huge pages than the
    /// restart costs (measured: README.md, "How the solve works").
    bool
    large(const std::string &parameter_file) const override;

    /// After set_up(): n and n_c (the Table 2 counts) and the other sizes.
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
    /// The layout of the chosen bond and its mesh: every block meshed on its
    /// own with cells of size h = H / 2^r, material_id = block index.
    void
    make_grid(RunContext &context) override;

    /// DOFs, then the supports and joints found on the mesh, then the
    /// change of variables to normal gaps.
    void
    setup_system(RunContext &context) override;

    /// A~ and b~ in the gap variables, in the solvers' force unit.
    void
    assemble_system(RunContext &context) override;

    /// u = C~^-1 u~, each constraint's gap, force and state, the energy in
    /// the parameter file's units.
    void
    postprocess(const RunContext &context, lcp::Report &report) override;

    /// In output.cc.
    void
    output_results(const RunContext &context) const override;

    void
    print_summary(std::ostream &out, const lcp::Report &report) const override;

    void
    add_summary(JsonObject &summary) const override;

  private:
    double
    coincidence_tolerance() const;

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
    /// Closed without force (see postprocess).
    unsigned int n_degenerate_contacts = 0;
  };
} // namespace unilateral::masonry
