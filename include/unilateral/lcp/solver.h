#pragma once

#include <unilateral/base/registry.h>
#include <unilateral/lcp/problem.h>
#include <unilateral/lcp/report.h>

#include <functional>
#include <iosfwd>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace dealii
{
  class ParameterHandler;
}

/**
 * The solver layer's plugin interface. Every LCP method lives in one file
 * under source/lcp/solvers/: its algorithm, its parameters (a subsection of
 * "Solver" that it declares and parses itself) and its registration, which
 * states as data what the driver needs to know of it (whether it needs a
 * definite matrix, whether its answer is exact, what follows when it fails).
 * The driver (solve_lcp.h), the parameter file and the tests learn about
 * methods from the registry only.
 */
namespace unilateral::lcp
{
  /**
   * The options of one method, in its own subsection of "Solver". A method's
   * parameters derive from this (through MethodParametersBase), keep their
   * defaults as member initialisers, and bind each member to an entry with
   * ParameterHandler::add_parameter: the default --print-parameters shows is
   * then the member's initial value, written once.
   */
  class MethodParameters
  {
  public:
    virtual ~MethodParameters() = default;

    virtual std::unique_ptr<MethodParameters>
    clone() const = 0;

    /// Declare the entries in the current subsection, bound to the members.
    virtual void
    add_parameters(dealii::ParameterHandler &prm) = 0;

    /**
     * What a pattern cannot express (an open interval). Throws InputError
     * naming the parameter; @p section is the subsection's path
     * ("Solver/PDAS").
     */
    virtual void
    check(const std::string &section) const;
  };

  /// clone() for a method's parameters @p Derived.
  template <typename Derived>
  class MethodParametersBase : public MethodParameters
  {
  public:
    std::unique_ptr<MethodParameters>
    clone() const override
    {
      return std::make_unique<Derived>(static_cast<const Derived &>(*this));
    }
  };

  /// The parameters of a method that has none.
  class NoParameters : public MethodParametersBase<NoParameters>
  {
  public:
    void
    add_parameters(dealii::ParameterHandler &) override
    {}
  };

  /**
   * The options of a solve: those every method shares (subsection "Solver")
   * and each registered method's own (its subsection inside "Solver"), all
   * at their defaults until parsed or set.
   */
  struct SolverInfo;

  class SolverParameters
  {
  public:
    /// The default method, and every method's options at their defaults.
    SolverParameters();

    SolverParameters(const SolverParameters &other);

    SolverParameters &
    operator=(const SolverParameters &other);

    ~SolverParameters();

    /// The selected method ('Solver/Method').
    std::string method;
    /// Solve the reduced Schur-complement LCP (Ainsworth-Mihai 3.13-3.18).
    bool schur_complement = false;
    /// Regularisation eps relative to the mean diagonal of A; negative means
    /// "auto" (see Problem::floating_bodies).
    double regularisation = -1;
    bool   projection     = true;
    /// 0 means each method's own default.
    unsigned int max_iterations = 0;
    /// Largest dimension a dense path (Graves, dense Schur complement) takes.
    unsigned int max_dense_size = 6000;
    /// Final check: relative KKT residuals above this make a run "inaccurate".
    double kkt_tolerance = 1e-8;
    /// Where sparse factorisations run: "auto", "cholmod" (each rank
    /// alone) or "mumps" (over the ranks of the run).
    std::string factorisation = "auto";

    /// Whether @p method's factorisations run over the ranks of the run
    /// (a DistributedFactorisations scope around its solve).
    bool
    factorises_over_ranks(const SolverInfo &method) const;

    /// The options of the registered method @p name.
    const MethodParameters &
    of(const std::string &name) const;

    /**
     * Set one option of a method as a parameter file would: @p entry is
     * "<subsection>/<entry>" ("PDAS/Safeguard", "Interior point/Variant").
     * Throws InputError if there is no such entry or the value does not
     * match its pattern.
     */
    void
    set(const std::string &entry, const std::string &value);

    /// The current value of one option of a method, as set() takes it
    /// ("<subsection>/<entry>"). Throws InputError if there is no such
    /// entry.
    std::string
    get(const std::string &entry) const;

    /**
     * Declare subsection "Solver" with every method's subsection. The
     * methods' entries are bound to this object's options
     * (ParameterHandler::add_parameter): parsing a file into @p prm fills
     * them, and parse_parameters() then reads the shared ones. This object
     * must outlive @p prm's parsing.
     */
    void
    declare_parameters(dealii::ParameterHandler &prm);

    void
    parse_parameters(dealii::ParameterHandler &prm);

  private:
    /// One entry per registered method, keyed by its name.
    std::map<std::string, std::unique_ptr<MethodParameters>> methods;
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
    iteration_limit(const unsigned int method_default) const
    {
      return parameters.max_iterations > 0 ? parameters.max_iterations :
                                             method_default;
    }

    /// The shared options; a method's own come to its constructor.
    const SolverParameters &parameters;
  };

  /**
   * What the driver does when an attempt with a method ends with a given
   * status, declared by the method (see SolverInfo::follow_ups).
   */
  struct FollowUp
  {
    enum class Kind
    {
      /// Continue with another method from its own start (or from this
      /// one's iterate: from_iterate), in place of this one (PDAS that
      /// cycles continues from the interior point; TNNMG stopped by
      /// round-off, from PDAS): the iterations and work of both count, the
      /// answer is the other's.
      hand_over,
      /// Check this method's outcome with another method (Graves' "no
      /// solution" with PDAS, PDAS's singular system with Graves): if that
      /// one solves the LCP, its answer is given; if it proves that there
      /// is no solution, the status says so; the note says why.
      verification
    };

    Kind kind = Kind::hand_over;
    /// The status of the attempt that calls for it.
    Status when = Status::iteration_limit;
    /// Only at the method's default iteration limit: a limit the user set
    /// is the user's answer.
    bool only_at_default_limit = false;
    /// The registered name of the method that follows.
    std::string method;
    /// A hand-over that continues from this method's last iterate (where
    /// it is near the answer, and the next method takes a start), not
    /// from the next method's own start.
    bool from_iterate = false;
    /// Options set for it, as "<subsection>/<entry>" and value.
    std::vector<std::pair<std::string, std::string>> settings;
    /// Chosen by how the projection step after the method ended (@p when),
    /// where the method itself converged, rather than by the method's own
    /// status; taken once per run (the next attempt's projection may end
    /// alike), and only where its settings, numbers, tighten the run's
    /// (each below the current value: a user's tighter one stays).
    bool after_projection = false;
  };

  /// Options of a method worth running as a method of their own.
  struct Variant
  {
    /// A short name ("predictor-corrector").
    std::string name;
    /// As "<subsection>/<entry>" and value.
    std::vector<std::pair<std::string, std::string>> settings;
  };

  /**
   * What the registry knows about a method: named properties, set by the
   * method's own file (a static properties() function of its class).
   */
  struct SolverInfo
  {
    /// For the registry's messages.
    static constexpr const char *parameter = "Solver/Method";
    static constexpr const char *kind      = "method";

    std::string name;
    /// The name in prose, as the papers write it ("PDAS"), for messages.
    std::string label;
    std::string description;
    /// The method's own parameter subsection inside "Solver"; empty if it
    /// has no options.
    std::string subsection;
    /// Its default iteration limit in words, for the help of 'Maximum
    /// iterations' ("500", "10|S| + 100").
    std::string default_iterations;
    /// The default of 'Solver/Method' (exactly one method sets it).
    bool is_default = false;
    /// PSOR, LSSNN, PDAS need A + eps I (and the projection step) when A is
    /// only semidefinite; interior-point methods and Graves do not.
    bool needs_definite_matrix = false;
    /// Dense methods refuse problems larger than max_dense_size.
    bool dense = false;
    /// Solves only LCPs in which every unknown is constrained (Graves):
    /// others take it on the Schur complement.
    bool every_unknown_constrained = false;
    /// Ends on an exact complementary basis (active-set and pivoting
    /// methods). Approximate methods (PSOR, interior point) get the
    /// projection step afterwards when 'Projection' is on.
    bool exact = true;
    /// The relative eps 'Regularisation = auto' uses at least, when the
    /// problem needs regularisation.
    double preferred_regularisation = 0;
    /// Starts from a given iterate u; the others ignore it.
    bool warm_start = false;
    /// A stationary iteration (PSOR): the iterations it needs grow like the
    /// condition number of A, very many on ill-conditioned problems.
    bool stationary = false;
    /// Moves one index (or two) per iteration (LSSNN, Graves): at least as
    /// many iterations as indices change side.
    bool single_pivot = false;
    /// Works on the problem torn into subdomains (Problem::tearing, which
    /// the scenes that can build one build for such a method); refuses a
    /// problem without one.
    bool needs_tearing = false;
    /// Its answer comes with the active set it ended on
    /// (solution.active_set), which the projection step starts from instead
    /// of a test on u: TFETI's multipliers tell which contacts close, where
    /// u's tiny gaps and its A u - b cannot.
    bool gives_active_set = false;
    /// Works on the problem's hierarchy of meshes (Problem::hierarchy,
    /// which the scenes that can build one build for such a method);
    /// refuses a problem without one.
    bool needs_hierarchy = false;

    /// An interior-point method: approximate, on A itself and the whole
    /// problem (not torn, not on a hierarchy). Its iterates follow the
    /// central path, so where a floating body's solutions form an unbounded
    /// set they follow it off (it is then given A + eps d I), and its end
    /// is read by interior_point_active_set() (projection.h).
    bool
    follows_central_path() const
    {
      return !needs_definite_matrix && !exact && !needs_tearing &&
             !needs_hierarchy;
    }

    /// The method of the projection step: exact, warm-started, it finishes
    /// an approximate or regularised answer on A itself (exactly one method
    /// sets it).
    bool finishes_approximate_answers = false;
    /// What follows an attempt with this method that ends with a given
    /// status, in order; the first that applies is taken.
    std::vector<FollowUp> follow_ups;
    /// Its variants (the tests run each, beside the default).
    std::vector<Variant> variants;

    /// The method's parameters at their defaults (set by the registration).
    std::function<std::unique_ptr<MethodParameters>()> make_parameters;
    /// The method with the shared options and its own (set by the
    /// registration).
    std::function<std::unique_ptr<Solver>(const SolverParameters &,
                                          const MethodParameters &)>
      create;
  };

  using SolverRegistry = Registry<SolverInfo>;

  /// The default method ('is_default').
  const SolverInfo &
  default_method();

  /// "a, b and c": the registered methods with @p property, for help texts
  /// (which thus never name a method themselves).
  std::string
  methods_where(const std::function<bool(const SolverInfo &)> &property);

  /// The method of the projection step ('finishes_approximate_answers').
  const SolverInfo &
  projection_method();

  /**
   * Register class @p Method, which provides
   *   using Parameters = ...;   // a MethodParameters, or NoParameters
   *   static SolverInfo properties();
   *   Method(const SolverParameters &, const Parameters &);
   */
  template <typename Method>
  bool
  register_solver()
  {
    SolverInfo info      = Method::properties();
    info.make_parameters = []() -> std::unique_ptr<MethodParameters> {
      return std::make_unique<typename Method::Parameters>();
    };
    info.create = [](const SolverParameters &parameters,
                     const MethodParameters &own) -> std::unique_ptr<Solver> {
      return std::make_unique<Method>(
        parameters, dynamic_cast<const typename Method::Parameters &>(own));
    };
    return SolverRegistry::add(std::move(info));
  }

#define UNILATERAL_REGISTER_SOLVER(Method)          \
  namespace                                         \
  {                                                 \
    const bool registered_solver_##Method =         \
      ::unilateral::lcp::register_solver<Method>(); \
  }
} // namespace unilateral::lcp

namespace unilateral
{
  // One registry, in the core library (not one per translation unit).
  extern template class Registry<lcp::SolverInfo>;
} // namespace unilateral
