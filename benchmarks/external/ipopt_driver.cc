/**
 * Ipopt (Debian's 3.11, linear solver MUMPS, the only one Debian builds in)
 * through its C interface: the LCP as the bound-constrained QP
 *   min 1/2 u'Au - b'u  subject to  u_S >= l_S
 * (no constraint functions, m = 0), with the exact Hessian A (lower
 * triangle, declared constant) and the gradient Au - b.
 *
 * Method: "qp" (the only one). Options (key=value):
 *   tol=1e-13         Ipopt's tol (scaled NLP error), and, relative to
 *                     ||b||_inf, its absolute dual_inf_tol and compl_inf_tol
 *                     (their defaults, 1 and 1e-4, are far too loose);
 *   max_iterations=3000
 *   mehrotra=no       Ipopt's default monotone barrier strategy; "yes" sets
 *                     mehrotra_algorithm (its predictor-corrector for convex
 *                     QPs, with mu_strategy adaptive). On our problems "no"
 *                     reached smaller KKT residuals (2e-12 against 9e-12 at
 *                     tol 1e-12 on laplacian_m100) in a similar time.
 * Fixed settings: bound_relax_factor = 0 (Ipopt relaxes bounds by 1e-8 by
 * default, which shows as primal infeasibility), honor_original_bounds,
 * hessian_constant, print_level 0.
 */
#include "common/driver.h"

#include <IpStdCInterface.h>

#include <stdexcept>
#include <vector>

namespace
{
  using namespace external;

  struct Data
  {
    const Problem      *problem;
    std::vector<Index>  rows, columns; // lower triangle of A
    std::vector<double> values;
  };

  Bool
  eval_f(Index n, Number *x, Bool, Number *f, UserDataPtr data_pointer)
  {
    const Data                    &data = *static_cast<Data *>(data_pointer);
    const Eigen::Map<const Vector> u(x, n);
    *f = 0.5 * u.dot(data.problem->A * u) - data.problem->b.dot(u);
    return TRUE;
  }

  Bool
  eval_grad_f(Index n, Number *x, Bool, Number *g, UserDataPtr data_pointer)
  {
    const Data                    &data = *static_cast<Data *>(data_pointer);
    const Eigen::Map<const Vector> u(x, n);
    Eigen::Map<Vector>(g, n) = data.problem->A * u - data.problem->b;
    return TRUE;
  }

  Bool
  eval_g(Index, Number *, Bool, Index, Number *, UserDataPtr)
  {
    return TRUE; // no constraint functions
  }

  Bool
  eval_jac_g(Index,
             Number *,
             Bool,
             Index,
             Index,
             Index *,
             Index *,
             Number *,
             UserDataPtr)
  {
    return TRUE;
  }

  Bool
  eval_h(Index,
         Number *,
         Bool,
         Number obj_factor,
         Index,
         Number *,
         Bool,
         Index       nele_hess,
         Index      *iRow,
         Index      *jCol,
         Number     *values,
         UserDataPtr data_pointer)
  {
    const Data &data = *static_cast<Data *>(data_pointer);
    if (values == nullptr)
      for (Index k = 0; k < nele_hess; ++k)
        {
          iRow[k] = data.rows[k];
          jCol[k] = data.columns[k];
        }
    else
      for (Index k = 0; k < nele_hess; ++k)
        values[k] = obj_factor * data.values[k];
    return TRUE;
  }

  const char *
  status_name(const int status)
  {
    switch (status)
      {
        case Solve_Succeeded:
          return "Solve_Succeeded";
        case Solved_To_Acceptable_Level:
          return "Solved_To_Acceptable_Level";
        case Infeasible_Problem_Detected:
          return "Infeasible_Problem_Detected";
        case Search_Direction_Becomes_Too_Small:
          return "Search_Direction_Becomes_Too_Small";
        case Diverging_Iterates:
          return "Diverging_Iterates";
        case Maximum_Iterations_Exceeded:
          return "Maximum_Iterations_Exceeded";
        case Restoration_Failed:
          return "Restoration_Failed";
        case Error_In_Step_Computation:
          return "Error_In_Step_Computation";
        case Not_Enough_Degrees_Of_Freedom:
          return "Not_Enough_Degrees_Of_Freedom";
        case Invalid_Problem_Definition:
          return "Invalid_Problem_Definition";
        case Invalid_Option:
          return "Invalid_Option";
        case Invalid_Number_Detected:
          return "Invalid_Number_Detected";
        case Insufficient_Memory:
          return "Insufficient_Memory";
        default:
          return "Ipopt_error";
      }
  }

  int iterations_seen = 0;

  Bool
  count_iterations(Index,
                   Index iter_count,
                   Number,
                   Number,
                   Number,
                   Number,
                   Number,
                   Number,
                   Number,
                   Number,
                   Index,
                   UserDataPtr)
  {
    iterations_seen = iter_count;
    return TRUE;
  }

  void
  set(IpoptProblem ipopt, const char *key, const char *value)
  {
    if (!AddIpoptStrOption(ipopt,
                           const_cast<char *>(key),
                           const_cast<char *>(value)))
      throw std::runtime_error(std::string("Ipopt rejected option ") + key +
                               " = " + value);
  }

  void
  set(IpoptProblem ipopt, const char *key, const double value)
  {
    if (!AddIpoptNumOption(ipopt, const_cast<char *>(key), value))
      throw std::runtime_error(std::string("Ipopt rejected option ") + key);
  }

  void
  set(IpoptProblem ipopt, const char *key, const int value)
  {
    if (!AddIpoptIntOption(ipopt, const_cast<char *>(key), value))
      throw std::runtime_error(std::string("Ipopt rejected option ") + key);
  }

  void
  solve(const std::string &method,
        const Problem     &problem,
        Options           &options,
        Outcome           &outcome)
  {
    if (method != "qp")
      throw unilateral::InputError("unknown method '" + method +
                                   "'; the Ipopt driver has one: qp");
    const double      tol            = options.number("tol", 1e-13);
    const int         max_iterations = options.integer("max_iterations", 3000);
    const std::string mehrotra       = options.string("mehrotra", "no");
    if (mehrotra != "yes" && mehrotra != "no")
      throw unilateral::InputError("option mehrotra=" + mehrotra +
                                   ": use yes or no");

    const Stopwatch setup;
    const Index     n = problem.size();
    Data            data;
    data.problem = &problem;
    for (Index j = 0; j < n; ++j)
      for (unilateral::lcp::SparseMatrix::InnerIterator it(problem.A, j); it;
           ++it)
        if (it.row() >= j)
          {
            data.rows.push_back(it.row());
            data.columns.push_back(j);
            data.values.push_back(it.value());
          }
    const double        infinity = 1e20;
    std::vector<double> lower(n, -infinity), upper(n, infinity), x(n, 0.0);
    for (Index k = 0; k < problem.n_constrained(); ++k)
      {
        lower[problem.constrained[k]] = problem.lower_bound[k];
        x[problem.constrained[k]]     = std::max(0.0, problem.lower_bound[k]);
      }
    IpoptProblem ipopt =
      CreateIpoptProblem(n,
                         lower.data(),
                         upper.data(),
                         0,
                         nullptr,
                         nullptr,
                         0,
                         static_cast<Index>(data.values.size()),
                         0,
                         eval_f,
                         eval_g,
                         eval_grad_f,
                         eval_jac_g,
                         eval_h);
    if (ipopt == nullptr)
      throw std::runtime_error("CreateIpoptProblem failed");
    const double scale = force_scale(problem);
    set(ipopt, "print_level", 0);
    set(ipopt, "sb", "yes");
    set(ipopt, "tol", tol);
    set(ipopt, "dual_inf_tol", tol * scale);
    set(ipopt, "compl_inf_tol", tol * scale);
    set(ipopt, "max_iter", max_iterations);
    set(ipopt, "bound_relax_factor", 0.0);
    set(ipopt, "honor_original_bounds", "yes");
    set(ipopt, "hessian_constant", "yes");
    set(ipopt, "nlp_lower_bound_inf", -infinity);
    set(ipopt, "nlp_upper_bound_inf", infinity);
    set(ipopt, "linear_solver", "mumps");
    if (mehrotra == "yes")
      {
        set(ipopt, "mehrotra_algorithm", "yes");
        set(ipopt, "mu_strategy", "adaptive");
      }
    SetIntermediateCallback(ipopt, count_iterations);
    outcome.setup_time = setup.seconds();

    const Stopwatch solve_clock;
    double          objective = 0;
    const int       status    = IpoptSolve(
      ipopt, x.data(), nullptr, &objective, nullptr, nullptr, nullptr, &data);
    outcome.solve_time = solve_clock.seconds();
    FreeIpoptProblem(ipopt);

    outcome.iterations = iterations_seen;
    outcome.converged  = status == Solve_Succeeded;
    outcome.status     = status_name(status);
    outcome.message    = "linear solver MUMPS";
    outcome.u          = Eigen::Map<const Vector>(x.data(), n);
  }
} // namespace

int
main(int argc, char **argv)
{
  return external::run(argc, argv, "ipopt", solve);
}
