/**
 * Siconos numerics (Debian's 4.4): its LCP solvers work on the standard LCP
 *   w = M z + q,  z >= 0,  w >= 0,  z'w = 0
 * with M stored dense. Our LCP is mixed (S may not be everything) and has
 * lower bounds l_S, so the driver builds a standard one first (setup time):
 *
 *  reduction=schur (default): eliminate the unconstrained unknowns E,
 *    M = A_SS - A_SE A_EE^-1 A_ES,  q = M l_S - (b_S - A_SE A_EE^-1 b_E),
 *    z = u_S - l_S, then u_E = A_EE^-1 (b_E - A_ES u_S) afterwards. A_EE is
 *    factorised by Eigen's sparse LDL^T (no unilateral code is used to help
 *    the competitor). Needs A_EE nonsingular; when it is (numerically)
 *    singular the driver falls back to the split form if it fits.
 *  reduction=split: write each unconstrained u_i = z_i+ - z_i-, both >= 0:
 *    M = P'AP with P = [I 0 0; 0 I -I] (size n_c + 2 n_E, positive
 *    semidefinite, fine for Lemke even when A_EE is singular), w_E+ = lambda_E,
 *    w_E- = -lambda_E, so w >= 0 forces lambda_E = 0.
 * When S is everything both are just M = A, q = A l - b.
 *
 * Methods: lemke (lexicographic Lemke), pivot (Siconos' pivot-based method,
 * Lemke pivoting rule by default), pivot_lumod (the same with block-LU
 * updates), newton_min (nonsmooth Newton on min(z, w), dense LU each step),
 * newton_fb (nonsmooth Newton on the Fischer-Burmeister function with line
 * search), newton_minfb (min + FB), pgs (projected Gauss-Seidel), for
 * reference. Dense M: refused above max_dense (default 3000) rows.
 * Tolerance: tol (default 1e-12) is Siconos' own relative error
 * (its lcp_compute_error), max_iterations (default 100000).
 */
#include "common/driver.h"

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>

#include <LCP_Solvers.h>
#include <LinearComplementarityProblem.h>
#include <NonSmoothDrivers.h>
#include <NumericsMatrix.h>
#include <SolverOptions.h>
#include <lcp_cst.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <stdexcept>

namespace
{
  using namespace external;
  using unilateral::lcp::DenseMatrix;
  using unilateral::lcp::SparseMatrix;

  /// The standard LCP (M, q) and how to get u back from z.
  struct Standard
  {
    DenseMatrix        M;
    Vector             q;
    std::string        reduction;
    std::vector<Index> S, E; ///< constrained and unconstrained indices
    SparseMatrix       A_ES; ///< for recovering u_E after the Schur form
  };

  SparseMatrix
  block(const SparseMatrix       &A,
        const std::vector<Index> &rows,
        const std::vector<Index> &columns)
  {
    std::vector<Index> row_position(A.rows(), -1);
    for (std::size_t k = 0; k < rows.size(); ++k)
      row_position[rows[k]] = static_cast<Index>(k);
    std::vector<Eigen::Triplet<double, Index>> entries;
    for (std::size_t k = 0; k < columns.size(); ++k)
      for (SparseMatrix::InnerIterator it(A, columns[k]); it; ++it)
        if (row_position[it.row()] >= 0)
          entries.emplace_back(row_position[it.row()],
                               static_cast<Index>(k),
                               it.value());
    SparseMatrix result(static_cast<Index>(rows.size()),
                        static_cast<Index>(columns.size()));
    result.setFromTriplets(entries.begin(), entries.end());
    return result;
  }

  Vector
  gather(const Vector &v, const std::vector<Index> &indices)
  {
    Vector result(indices.size());
    for (std::size_t k = 0; k < indices.size(); ++k)
      result[k] = v[indices[k]];
    return result;
  }

  /// Returns false (and says why) if A_EE is numerically singular.
  bool
  build_schur(const Problem                       &problem,
              Standard                            &standard,
              Eigen::SimplicialLDLT<SparseMatrix> &factor,
              std::string                         &why)
  {
    const auto  &S   = standard.S;
    const auto  &E   = standard.E;
    const Vector l   = problem.lower_bound;
    DenseMatrix  M   = DenseMatrix(block(problem.A, S, S));
    Vector       rhs = gather(problem.b, S);
    if (!E.empty())
      {
        const SparseMatrix A_EE = block(problem.A, E, E);
        standard.A_ES           = block(problem.A, E, S);
        factor.compute(A_EE);
        const Vector D       = factor.vectorD();
        const double largest = D.cwiseAbs().maxCoeff();
        if (factor.info() != Eigen::Success || D.minCoeff() <= 1e-12 * largest)
          {
            why = "A_EE (the unconstrained block) is singular: smallest LDL' "
                  "pivot " +
                  std::to_string(D.minCoeff()) + " vs largest " +
                  std::to_string(largest);
            return false;
          }
        // M -= A_SE A_EE^-1 A_ES, in blocks of columns.
        const Index n_c   = static_cast<Index>(S.size());
        const Index width = 256;
        for (Index first = 0; first < n_c; first += width)
          {
            const Index       count = std::min(width, n_c - first);
            const DenseMatrix X =
              factor.solve(DenseMatrix(standard.A_ES.middleCols(first, count)));
            M.middleCols(first, count) -= standard.A_ES.transpose() * X;
          }
        const Vector y = factor.solve(gather(problem.b, E));
        rhs -= standard.A_ES.transpose() * y;
        M = 0.5 * (M + M.transpose()); // exact symmetry for the pivoting
      }
    standard.q         = M * l - rhs;
    standard.M         = std::move(M);
    standard.reduction = E.empty() ? "none (all constrained)" : "schur";
    return true;
  }

  void
  build_split(const Problem &problem, Standard &standard)
  {
    const auto        &S     = standard.S;
    const auto        &E     = standard.E;
    const Index        n_c   = static_cast<Index>(S.size());
    const Index        n_e   = static_cast<Index>(E.size());
    std::vector<Index> order = S;
    order.insert(order.end(), E.begin(), E.end());
    const DenseMatrix A = DenseMatrix(block(problem.A, order, order));
    // u = P z + [l; 0],  P = [I 0 0; 0 I -I].
    DenseMatrix P = DenseMatrix::Zero(n_c + n_e, n_c + 2 * n_e);
    P.topLeftCorner(n_c, n_c).setIdentity();
    P.block(n_c, n_c, n_e, n_e).setIdentity();
    P.block(n_c, n_c + n_e, n_e, n_e) = -DenseMatrix::Identity(n_e, n_e);
    Vector shift                      = Vector::Zero(n_c + n_e);
    shift.head(n_c)                   = problem.lower_bound;
    standard.M                        = P.transpose() * A * P;
    standard.q         = P.transpose() * (A * shift - gather(problem.b, order));
    standard.reduction = "split";
  }

  void
  solve(const std::string &method,
        const Problem     &problem,
        Options           &options,
        Outcome           &outcome)
  {
    static const std::map<std::string, int> ids = {
      {"lemke", SICONOS_LCP_LEMKE},
      {"pivot", SICONOS_LCP_PIVOT},
      {"pivot_lumod", SICONOS_LCP_PIVOT_LUMOD},
      {"newton_min", SICONOS_LCP_NEWTONMIN},
      {"newton_fb", SICONOS_LCP_NEWTON_FB_FBLSA},
      {"newton_minfb", SICONOS_LCP_NEWTON_MIN_FBLSA},
      {"pgs", SICONOS_LCP_PGS}};
    const auto id = ids.find(method);
    if (id == ids.end())
      throw unilateral::InputError(
        "unknown method '" + method +
        "'; use lemke, pivot, pivot_lumod, "
        "newton_min, newton_fb, newton_minfb or pgs");
    const double tol            = options.number("tol", 1e-12);
    const int    max_iterations = options.integer("max_iterations", 100000);
    const int    max_dense      = options.integer("max_dense", 3000);
    const std::string reduction = options.string("reduction", "schur");
    if (reduction != "schur" && reduction != "split")
      throw unilateral::InputError("option reduction=" + reduction +
                                   ": use schur or split");

    const Stopwatch setup;
    Standard        standard;
    const auto      mask = problem.constrained_mask();
    for (Index i = 0; i < problem.size(); ++i)
      (mask[i] ? standard.S : standard.E).push_back(i);
    const Index n_c        = problem.n_constrained();
    const Index n_e        = problem.size() - n_c;
    const Index split_size = n_c + 2 * n_e;

    Eigen::SimplicialLDLT<SparseMatrix> factor;
    std::string                         why;
    bool                                built = false;
    if (reduction == "schur")
      {
        if (n_c > max_dense)
          {
            outcome.status    = "too large";
            outcome.converged = false;
            outcome.message =
              "dense M of size n_c = " + std::to_string(n_c) +
              " exceeds max_dense = " + std::to_string(max_dense);
            return;
          }
        built = build_schur(problem, standard, factor, why);
      }
    if (!built)
      {
        if (split_size > max_dense)
          {
            outcome.status =
              reduction == "schur" ? "not applicable" : "too large";
            outcome.converged = false;
            outcome.message =
              (why.empty() ? std::string() : why + "; ") + "the split form " +
              "(size n_c + 2 n_E = " + std::to_string(split_size) +
              ") exceeds max_dense = " + std::to_string(max_dense);
            return;
          }
        build_split(problem, standard);
        if (!why.empty())
          standard.reduction += " (fallback: " + why + ")";
      }

    const int       m = static_cast<int>(standard.q.size());
    NumericsMatrix *M = NM_create(NM_DENSE, m, m);
    std::copy(standard.M.data(),
              standard.M.data() + std::size_t(m) * m,
              M->matrix0);
    std::vector<double>          q(standard.q.data(), standard.q.data() + m);
    std::vector<double>          z(m, 0.0), w(m, 0.0);
    LinearComplementarityProblem lcp;
    lcp.size                      = m;
    lcp.M                         = M;
    lcp.q                         = q.data();
    SolverOptions *solver_options = solver_options_create(id->second);
    solver_options->iparam[SICONOS_IPARAM_MAX_ITER] = max_iterations;
    solver_options->dparam[SICONOS_DPARAM_TOL]      = tol;
    outcome.setup_time                              = setup.seconds();

    const Stopwatch solve_clock;
    const int       info =
      linearComplementarity_driver(&lcp, z.data(), w.data(), solver_options);
    outcome.solve_time = solve_clock.seconds();

    outcome.iterations = solver_options->iparam[SICONOS_IPARAM_ITER_DONE];
    outcome.converged  = info == 0;
    outcome.status = info == 0 ? "converged" : "info " + std::to_string(info);
    outcome.message =
      "reduction " + standard.reduction + ", M " + std::to_string(m) + "x" +
      std::to_string(m) + ", Siconos error " +
      std::to_string(solver_options->dparam[SICONOS_DPARAM_RESIDU]);
    solver_options_delete(solver_options);
    NM_free(M);

    // Back to u (counted in the total, not the solve time).
    Vector zz = Eigen::Map<const Vector>(z.data(), m);
    outcome.u = Vector::Zero(problem.size());
    for (Index k = 0; k < n_c; ++k)
      outcome.u[standard.S[k]] = zz[k] + problem.lower_bound[k];
    if (standard.reduction.rfind("split", 0) == 0)
      {
        for (Index k = 0; k < n_e; ++k)
          outcome.u[standard.E[k]] = zz[n_c + k] - zz[n_c + n_e + k];
      }
    else if (n_e > 0)
      {
        const Vector u_S = gather(outcome.u, standard.S);
        const Vector u_E = factor.solve(
          Vector(gather(problem.b, standard.E) - standard.A_ES * u_S));
        for (Index k = 0; k < n_e; ++k)
          outcome.u[standard.E[k]] = u_E[k];
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  return external::run(argc, argv, "siconos", solve);
}
