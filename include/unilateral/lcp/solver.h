#pragma once

#include <unilateral/lcp/problem.h>
#include <unilateral/lcp/report.h>

#include <functional>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

namespace unilateral::lcp
{
  /**
   * Every option of every algorithm, with the papers' defaults. Declared in
   * the parameter file as subsection "Solver".
   */
  struct SolverParameters
  {
    std::string method = "pdas";
    /// Solve the reduced Schur-complement LCP (Ainsworth-Mihai 3.13-3.18).
    bool schur_complement = false;
    /// Regularisation eps relative to the mean diagonal of A; negative means
    /// "auto" (the scene's choice).
    double regularisation = -1;
    bool   projection     = true;
    /// 0 means each method's own default.
    unsigned int max_iterations = 0;
    /// Largest dimension a dense path (Graves, dense Schur complement) takes.
    unsigned int max_dense_size = 6000;
    /// Final check: relative KKT residuals above this make a run "inaccurate".
    double kkt_tolerance = 1e-8;

    struct
    {
      double omega     = 0; ///< 0: 2 / (1 + sin(pi / n))
      double tolerance = 0; ///< 0: n * machine epsilon
    } psor;

    enum class PdasStart
    {
      automatic, ///< the scene's choice (zero when there is no scene)
      zero,      ///< u0 = 0, as Ainsworth & Mihai
      all_active ///< u0 minimises the energy with every bound active
    };

    struct
    {
      double    tau   = 1e-3;
      PdasStart start = PdasStart::automatic;
      /// Relative rounding tolerance of the active-set test: an index moves
      /// only if it violates its side by more than this times the size of
      /// the terms of its multiplier (a closed contact with zero force can
      /// otherwise flip sides on round-off forever).
      double round_off = 1e-12;
      /// Judice-Pires safeguard: after this many iterations without fewer
      /// violations than the best so far, change one index at a time by
      /// Murty's least-index rule until there are fewer (finite termination
      /// for positive definite A). 0 switches it off (the paper's PDAS).
      unsigned int safeguard = 10;
    } pdas;

    struct
    {
      double initial_point   = 1e-2; ///< u0 = eps e, Sigma0 = -eps e
      double tolerance_gap   = 0;    ///< tol1; 0: n_c * machine epsilon
      double tolerance_residual = 0; ///< tol2; 0: n * sqrt(machine epsilon)
      bool   diagonal_scaling = true;
      /// Fraction of a step to the boundary that is taken (1: the paper).
      double step_to_boundary = 0.9995;
    } pdpc;

    struct
    {
      double centering               = 0.1;     ///< delta in (42)
      double step_factor             = 0.99995; ///< beta in (50)
      double residual_tolerance      = 1e-10;   ///< epsilon_1 in (55)
      double complementarity_tolerance = 1e-8;  ///< epsilon_2 in (56)
      /// Mehrotra's predictor-corrector instead of the paper's fixed
      /// centring (the hand-over from cycling PDAS always uses it).
      bool   predictor_corrector = false;
      /// Gondzio's centrality correctors per predictor-corrector iteration.
      unsigned int centrality_correctors = 2;
    } interior_point;

    struct
    {
      unsigned int p         = 10;
      double       tolerance = 1e-6; ///< epsilon in (67)
    } block_pivoting;

    static void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);
  };

  /**
   * An LCP algorithm. solve() starts from solution.u if it is non-empty
   * (otherwise from the method's own starting point), and on return sets
   * solution.u and report.status, .iterations and .message. The driver
   * (solve_lcp) derives lambda, the active set, KKT residuals and energy from
   * u itself, so every method is judged by the same yardstick.
   */
  class Solver
  {
  public:
    explicit Solver(const SolverParameters &parameters)
      : parameters(parameters)
    {}

    virtual ~Solver() = default;

    virtual void
    solve(const Problem &problem,
          Solution      &solution,
          Report        &report,
          std::ostream  *progress) = 0;

  protected:
    /// max_iterations if set, else @p method_default.
    unsigned int
    iteration_limit(unsigned int method_default) const
    {
      return parameters.max_iterations > 0 ? parameters.max_iterations :
                                             method_default;
    }

    const SolverParameters &parameters;
  };

  /// What the registry knows about a method.
  struct SolverInfo
  {
    std::string name;
    std::string description;
    /// PSOR, LSSNN, PDAS need A + eps I (and the projection step) when A is
    /// only semidefinite; interior-point methods and Graves do not.
    bool needs_definite_matrix = false;
    /// Dense methods refuse problems larger than max_dense_size.
    bool dense = false;
    /// Ends on an exact complementary basis (active-set and pivoting
    /// methods). Approximate methods (PSOR, interior point) get the
    /// projection step afterwards when 'Projection' is on.
    bool exact = true;
    /// The relative eps 'Regularisation = auto' uses at least, when the
    /// scene needs regularisation (0: the scene's value).
    double preferred_regularisation = 0;
    /// Starts from a given iterate u (PDAS, PSOR); the others ignore it.
    bool warm_start = false;
    std::function<std::unique_ptr<Solver>(const SolverParameters &)> create;
  };

  /// Registered methods, in registration order; adding one touches one file.
  class SolverRegistry
  {
  public:
    static bool
    add(SolverInfo info);

    /// Throws InputError naming the unknown method and the known ones.
    static const SolverInfo &
    get(const std::string &name);

    static std::vector<std::string>
    names();

    /// "a|b|c" for Patterns::Selection.
    static std::string
    selection();

    static std::string
    documentation();

  private:
    static std::vector<SolverInfo> &
    entries();
  };

#define UNILATERAL_REGISTER_SOLVER(                                              \
  classname, name, description, definite, dense, exact, preferred_eps, warm)     \
  namespace                                                                      \
  {                                                                              \
    const bool registered_##classname = ::unilateral::lcp::SolverRegistry::add( \
      {name,                                                                     \
       description,                                                              \
       definite,                                                                 \
       dense,                                                                    \
       exact,                                                                    \
       preferred_eps,                                                            \
       warm,                                                                     \
       [](const ::unilateral::lcp::SolverParameters &parameters)                 \
         -> std::unique_ptr<::unilateral::lcp::Solver> {                         \
         return std::make_unique<classname>(parameters);                         \
       }});                                                                      \
  }

  /**
   * Solve @p problem with the method and options in @p parameters:
   *  - methods that need a definite matrix get A + eps I (eps relative to the
   *    mean diagonal; "auto" takes @p auto_regularisation, or the method's
   *    preferred eps if larger) and then the projection step (PDAS on A from
   *    u_eps, continued in eps if it meets a singular system) that recovers
   *    the exact solution;
   *    approximate methods (PSOR, interior point) get the projection too;
   *  - with schur_complement, the reduced LCP on S is formed (dense) and
   *    solved, and u_E recovered;
   *  - the report gets KKT residuals, energy and active set of the final u
   *    against the original problem, and the status is downgraded to
   *    "inaccurate" if the method's own test passed but the KKT residuals
   *    exceed kkt_tolerance.
   * @p problem must have passed check_and_normalise().
   */
  Report
  solve_lcp(const Problem          &problem,
            const SolverParameters &parameters,
            Solution               &solution,
            std::ostream           *progress            = nullptr,
            double                  auto_regularisation = 0);
} // namespace unilateral::lcp
