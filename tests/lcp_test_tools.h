// Helpers for the solver tests: build small LCPs, solve them with every
// method, and enumerate complementary bases for the exact answer.
#pragma once

#include <unilateral/lcp/problem.h>
#include <unilateral/lcp/solve_lcp.h>
#include <unilateral/lcp/solver.h>

#include "registered_methods.h"

#include <Eigen/Dense>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

namespace test
{
  using namespace unilateral::lcp;

  using Method = registered_methods::MethodRun;

  // Every registered method and variant (registered_methods.h).
  inline std::vector<Method>
  all_methods(const bool has_unconstrained)
  {
    return registered_methods::all(has_unconstrained);
  }

  /// The registered method @p name with its default options.
  inline Method
  method(const std::string &name)
  {
    return {&SolverRegistry::get(name)};
  }

  inline Problem
  make_problem(const DenseMatrix         &A,
               const Vector              &b,
               const std::vector<Index>  &S,
               const std::vector<double> &lower)
  {
    Problem problem;
    problem.A           = A.sparseView();
    problem.b           = b;
    problem.constrained = S;
    problem.lower_bound = Eigen::Map<const Vector>(lower.data(), lower.size());
    check_and_normalise(problem);
    return problem;
  }

  inline Report
  solve_with(const Problem   &problem,
             const Method    &method,
             Vector          &u,
             double           regularisation = -1,
             SolverParameters parameters     = SolverParameters())
  {
    method.apply(parameters);
    parameters.regularisation = regularisation;
    Solution     solution;
    const Report report = solve_lcp(problem, parameters, solution);
    u                   = solution.u;
    return report;
  }

  /// u for the fixed set X (u_X = l_X, lower given on every index), by a
  /// dense solve of A_FF u_F = b_F - A_FX l_X.
  inline Vector
  equality_solution(const DenseMatrix       &A,
                    const Vector            &b,
                    const std::vector<char> &fixed,
                    const Vector            &lower)
  {
    const Index        n = A.rows();
    std::vector<Index> free;
    Vector             u = Vector::Zero(n);
    for (Index i = 0; i < n; ++i)
      if (fixed[i])
        u[i] = lower[i];
      else
        free.push_back(i);
    const Index m = static_cast<Index>(free.size());
    DenseMatrix A_FF(m, m);
    Vector      r(m);
    for (Index a = 0; a < m; ++a)
      {
        r[a] = b[free[a]] - A.row(free[a]).dot(u);
        for (Index c = 0; c < m; ++c)
          A_FF(a, c) = A(free[a], free[c]);
      }
    const Vector u_F = A_FF.ldlt().solve(r);
    for (Index a = 0; a < m; ++a)
      u[free[a]] = u_F[a];
    return u;
  }

  /**
   * The exact solution by enumeration: for every subset X of S (the active
   * set) solve the equality-constrained system with u_X = l_X, and keep the
   * basis whose solution is feasible (u_S >= l_S, lambda_X >= 0). For SPD A
   * exactly one basis qualifies (up to degenerate ties, which give the same
   * u). Returns the number of feasible bases found.
   */
  inline int
  enumerate(const DenseMatrix         &A,
            const Vector              &b,
            const std::vector<Index>  &S,
            const std::vector<double> &lower,
            Vector                    &u_exact)
  {
    const Index n          = A.rows();
    const Index n_c        = static_cast<Index>(S.size());
    Vector      full_lower = Vector::Zero(n);
    for (Index k = 0; k < n_c; ++k)
      full_lower[S[k]] = lower[k];
    int found = 0;
    for (long mask = 0; mask < (1L << n_c); ++mask)
      {
        std::vector<char> fixed(n, 0);
        for (Index k = 0; k < n_c; ++k)
          fixed[S[k]] = (mask >> k) & 1;
        const Vector u        = equality_solution(A, b, fixed, full_lower);
        const Vector lambda   = A * u - b;
        bool         feasible = true;
        for (Index k = 0; k < n_c; ++k)
          {
            const double tolerance = 1e-12 * (1 + std::abs(lower[k]));
            if (fixed[S[k]] ? lambda[S[k]] < -1e-12 :
                              u[S[k]] < lower[k] - tolerance)
              feasible = false;
          }
        if (feasible)
          {
            if (found == 0)
              u_exact = u;
            ++found;
          }
      }
    return found;
  }

  inline double
  relative_difference(const Vector &u, const Vector &v)
  {
    const double size = std::max(v.lpNorm<Eigen::Infinity>(), 1e-300);
    return (u - v).lpNorm<Eigen::Infinity>() / size;
  }

  inline const char *
  yes_no(const bool condition)
  {
    return condition ? "yes" : "NO";
  }
} // namespace test
