#include <unilateral/base/input_error.h>
#include <unilateral/base/ranks.h>
#include <unilateral/lcp/distributed_cholesky.h>
#include <unilateral/lcp/solver.h>

#include <deal.II/base/parameter_handler.h>

namespace unilateral
{
  template class Registry<lcp::SolverInfo>;
} // namespace unilateral

namespace unilateral::lcp
{
  namespace
  {
    // The one registered method with @p property, or an error naming it:
    // a build without it is broken, not the user's input.
    const SolverInfo &
    unique_method(bool SolverInfo::*property, const std::string &what)
    {
      const SolverInfo *found = nullptr;
      for (const SolverInfo &info : SolverRegistry::all())
        if (info.*property)
          {
            if (found != nullptr)
              throw std::logic_error("two methods are registered as " + what +
                                     ": " + found->name + " and " + info.name);
            found = &info;
          }
      if (found == nullptr)
        throw std::logic_error("no method is registered as " + what);
      return *found;
    }

    // "a: 500, b: 10|S| + 100" (for the help of 'Maximum iterations').
    std::string
    default_iteration_limits()
    {
      std::string result;
      for (const SolverInfo &info : SolverRegistry::all())
        if (!info.default_iterations.empty())
          result += (result.empty() ? "" : ", ") + info.name + ": " +
                    info.default_iterations;
      return result;
    }

    // "pdas that stops as cycling continues from interior_point's answer"
    // (for the help of 'Maximum iterations').
    std::string
    hand_overs_at_default_limit()
    {
      std::string result;
      for (const SolverInfo &info : SolverRegistry::all())
        for (const FollowUp &follow_up : info.follow_ups)
          if (follow_up.kind == FollowUp::Kind::hand_over &&
              follow_up.only_at_default_limit)
            result += (result.empty() ? "" : "; ") + info.name +
                      " that stops without settling continues from " +
                      follow_up.method + "'s answer";
      return result.empty() ? "no method hands over" : result;
    }
  } // namespace

  std::string
  methods_where(const std::function<bool(const SolverInfo &)> &property)
  {
    std::vector<std::string> names;
    for (const SolverInfo &info : SolverRegistry::all())
      if (property(info))
        names.push_back(info.name);
    std::string result;
    for (std::size_t k = 0; k < names.size(); ++k)
      result += (k == 0                ? "" :
                 k + 1 == names.size() ? " and " :
                                         ", ") +
                names[k];
    return result;
  }

  const SolverInfo &
  default_method()
  {
    return unique_method(&SolverInfo::is_default, "the default method");
  }

  const SolverInfo &
  projection_method()
  {
    return unique_method(&SolverInfo::finishes_approximate_answers,
                         "the projection step's method");
  }

  void
  MethodParameters::check(const std::string &) const
  {}

  SolverParameters::SolverParameters()
    : method(default_method().name)
  {
    for (const SolverInfo &info : SolverRegistry::all())
      methods[info.name] = info.make_parameters();
  }

  SolverParameters::SolverParameters(const SolverParameters &other)
  {
    *this = other;
  }

  SolverParameters &
  SolverParameters::operator=(const SolverParameters &other)
  {
    if (this == &other)
      return *this;
    method           = other.method;
    schur_complement = other.schur_complement;
    regularisation   = other.regularisation;
    projection       = other.projection;
    max_iterations   = other.max_iterations;
    max_dense_size   = other.max_dense_size;
    kkt_tolerance    = other.kkt_tolerance;
    factorisation    = other.factorisation;
    methods.clear();
    for (const auto &[name, options] : other.methods)
      methods[name] = options->clone();
    return *this;
  }

  SolverParameters::~SolverParameters() = default;

  bool
  SolverParameters::factorises_over_ranks(const SolverInfo &method) const
  {
    if (method.needs_tearing || factorisation == "cholmod")
      return false;
    return factorisation == "mumps" || ranks::n_ranks() > 1;
  }

  const MethodParameters &
  SolverParameters::of(const std::string &name) const
  {
    const auto found = methods.find(name);
    if (found == methods.end())
      return *methods.at(SolverRegistry::get(name).name); // throws
    return *found->second;
  }

  namespace
  {
    // "<subsection>/<entry>" split, with the method whose subsection it
    // names (nullptr: none).
    const SolverInfo *
    method_of_entry(const std::string &entry,
                    std::string       &subsection,
                    std::string       &name)
    {
      const std::size_t slash = entry.rfind('/');
      subsection = slash == std::string::npos ? "" : entry.substr(0, slash);
      name       = entry.substr(slash + 1);
      for (const SolverInfo &info : SolverRegistry::all())
        if (!subsection.empty() && info.subsection == subsection)
          return &info;
      return nullptr;
    }
  } // namespace

  std::string
  SolverParameters::get(const std::string &entry) const
  {
    std::string subsection, name;
    if (const SolverInfo *info = method_of_entry(entry, subsection, name))
      {
        // A copy's entries, declared with its current values as defaults.
        dealii::ParameterHandler          prm;
        std::unique_ptr<MethodParameters> options =
          methods.at(info->name)->clone();
        options->add_parameters(prm);
        try
          {
            return prm.get(name);
          }
        catch (const std::exception &)
          {}
      }
    throw InputError("parameter 'Solver/" + entry + "': no such entry");
  }

  void
  SolverParameters::set(const std::string &entry, const std::string &value)
  {
    std::string       subsection, name;
    const SolverInfo *info = method_of_entry(entry, subsection, name);
    if (info == nullptr)
      throw InputError("parameter 'Solver/" + entry +
                       "': no method has the subsection '" + subsection + "'");
    // A handler of this method's entries alone, bound to its options
    // (their current values are the defaults): set() runs the binding.
    dealii::ParameterHandler prm;
    MethodParameters        &options = *methods.at(info->name);
    options.add_parameters(prm);
    try
      {
        prm.set(name, value);
      }
    catch (const std::exception &)
      {
        throw InputError("parameter 'Solver/" + entry + "' = " + value +
                         ": no such entry, or the value does not match "
                         "its pattern; see unilateral --print-parameters");
      }
    options.check("Solver/" + subsection);
  }

  void
  SolverParameters::declare_parameters(dealii::ParameterHandler &prm)
  {
    using namespace dealii::Patterns;
    prm.enter_subsection("Solver");
    prm.declare_entry("Method",
                      default_method().name,
                      Selection(SolverRegistry::selection()),
                      "The LCP algorithm.\n" + SolverRegistry::documentation());
    prm.declare_entry(
      "Schur complement",
      "false",
      Bool(),
      "Eliminate the unconstrained unknowns E and solve the reduced, dense "
      "LCP on the constrained set S (Ainsworth & Mihai, eqs. 3.13-3.18), "
      "then recover u_E = A_EE^-1 (b_E - A_ES u_S). Needs A_EE nonsingular "
      "and |S| <= 'Maximum dense size'.");
    prm.declare_entry(
      "Regularisation",
      "auto",
      Anything(),
      "eps of the regularised matrix A + eps d I, where d is the mean of the "
      "diagonal of A (so eps is unit-free). Used only by methods that need a "
      "positive definite matrix (" +
        methods_where(
          [](const SolverInfo &info) { return info.needs_definite_matrix; }) +
        ") and, where bodies can float, by the interior-point methods (" +
        methods_where(
          [](const SolverInfo &info) { return info.follows_central_path(); }) +
        ": a floating body's solutions can form an unbounded set, which "
        "their iterates would follow), each followed by the projection "
        "step. 'auto' takes 1e-9 where the "
        "scene's bodies can float (masonry: blocks are free to move, so A is "
        "singular) and 0 elsewhere (the plate, LCP files), where 1e-9 follows "
        "if the method meets a singular system. A number >= 0 overrides it.");
    prm.declare_entry(
      "Projection",
      "true",
      Bool(),
      "After solving the regularised problem, run " +
        projection_method().label +
        " on the original A from u_eps (Ainsworth & Mihai, Section 4): it "
        "recovers the exact solution, usually in one iteration. The same "
        "step follows the approximate methods (" +
        methods_where([](const SolverInfo &info) { return !info.exact; }) +
        "), as Ainsworth & Mihai suggest for PDPC, and an exact method whose "
        "answer fails the KKT check. Switch it off to see a method's own "
        "answer (a regularised one is then reported 'inaccurate').");
    prm.declare_entry(
      "Maximum iterations",
      "0",
      Integer(0),
      "Iteration limit of the method; 0 takes each method's default (" +
        default_iteration_limits() +
        "). Reaching it is reported as status 'iteration limit', never as a "
        "solution; at 0, " +
        hand_overs_at_default_limit() + ".");
    prm.declare_entry(
      "Maximum dense size",
      "6000",
      Integer(1),
      "Largest number of unknowns a dense path takes (" +
        methods_where([](const SolverInfo &info) { return info.dense; }) +
        ", Schur complement); larger problems are refused with a message "
        "instead of exhausting memory. Memory is about 16 n^2 bytes.");
    prm.declare_entry(
      "KKT tolerance",
      "1e-8",
      Double(0),
      "A method that reports convergence while the relative KKT residuals "
      "of its answer exceed this gets status 'inaccurate': no wrong answer "
      "is printed as converged. 0 < tolerance < 1 (a relative residual of 1 "
      "checks nothing).");
    prm.declare_entry(
      "Factorisation",
      "auto",
      Selection("auto|cholmod|mumps"),
      "Where the sparse factorisations of the direct methods run. cholmod: "
      "on each rank alone (SuiteSparse CHOLMOD, with row updates of a factor "
      "between active sets). mumps: spread over the ranks of the MPI run "
      "(MUMPS through PETSc; needs mpirun, also for one rank), every rank "
      "holding a share of each factor and of its work, the same answer. "
      "auto: mumps when the run has more than one rank, cholmod otherwise. "
      "Methods that tear the problem into subdomains (" +
        methods_where(
          [](const SolverInfo &info) { return info.needs_tearing; }) +
        ") share their subdomains among the ranks themselves and always "
        "factorise with cholmod.");
    for (const SolverInfo &info : SolverRegistry::all())
      if (!info.subsection.empty())
        {
          prm.enter_subsection(info.subsection);
          methods.at(info.name)->add_parameters(prm);
          prm.leave_subsection();
        }
    prm.leave_subsection();
  }

  void
  SolverParameters::parse_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Solver");
    method                = prm.get("Method");
    schur_complement      = prm.get_bool("Schur complement");
    const std::string eps = prm.get("Regularisation");
    if (eps == "auto")
      regularisation = -1;
    else
      {
        std::size_t used = 0;
        try
          {
            regularisation = std::stod(eps, &used);
          }
        catch (const std::exception &)
          {
            used = 0;
          }
        check_parameter(used == eps.size() && used > 0,
                        "Solver",
                        "Regularisation",
                        eps,
                        "must be 'auto' or a number >= 0");
        check_parameter(regularisation >= 0,
                        "Solver",
                        "Regularisation",
                        eps,
                        "must be >= 0 (eps < 0 would make A + eps I "
                        "indefinite)");
        check_parameter(std::isfinite(regularisation),
                        "Solver",
                        "Regularisation",
                        eps,
                        "must be a finite number (an infinite eps leaves "
                        "nothing of A); 'auto' chooses it");
      }
    projection     = prm.get_bool("Projection");
    max_iterations = prm.get_integer("Maximum iterations");
    max_dense_size = prm.get_integer("Maximum dense size");
    kkt_tolerance  = prm.get_double("KKT tolerance");
    factorisation  = prm.get("Factorisation");
    if (factorisation == "mumps")
      DistributedCholesky::require_available();
    check_parameter(kkt_tolerance > 0 && kkt_tolerance < 1,
                    "Solver",
                    "KKT tolerance",
                    kkt_tolerance,
                    "must be > 0 and < 1: a floating-point answer is never "
                    "exact to the last bit, and a residual as large as the "
                    "forces checks nothing (1e-8, the default, or 1e-10 are "
                    "usual)");
    prm.leave_subsection();
    // The methods' own entries were parsed into their options by the
    // bindings of declare_parameters(); what patterns cannot check:
    for (const SolverInfo &info : SolverRegistry::all())
      if (!info.subsection.empty())
        methods.at(info.name)->check("Solver/" + info.subsection);
    // The Selection pattern admits only registered names; the registry's
    // message is the better one if that ever changes.
    const SolverInfo &info = SolverRegistry::get(method);
    // Refused here, before a scene makes its run directory, as well as by
    // solve_lcp for callers that build their parameters in code.
    check_parameter(!schur_complement ||
                      !(info.needs_tearing || info.needs_hierarchy),
                    "Solver",
                    "Schur complement",
                    "true",
                    "method '" + method +
                      "' works on the whole problem (its subdomains or its "
                      "meshes), not on the Schur complement on the "
                      "constrained unknowns: set it to false");
  }
} // namespace unilateral::lcp
