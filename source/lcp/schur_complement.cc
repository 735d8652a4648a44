#include <unilateral/base/input_error.h>
#include <unilateral/lcp/schur_complement.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace unilateral::lcp
{
  SchurComplement::SchurComplement(const Problem     &problem,
                                   const unsigned int max_dense_size,
                                   Counters          &counters)
    : problem(problem)
    , fixed(problem.constrained_mask())
  {
    const Index n   = problem.size();
    const Index n_c = problem.n_constrained();
    if (static_cast<unsigned int>(n_c) > max_dense_size)
      throw InputError(
        "the Schur complement would be a dense " + std::to_string(n_c) + " x " +
        std::to_string(n_c) +
        " matrix, larger than 'Solver/Maximum dense size' = " +
        std::to_string(max_dense_size) +
        ": solve the full LCP (Schur complement = false) or raise the limit");

    eliminated = std::make_unique<ActiveSetSystem>(problem.A, counters);

    // b_hat: x_S = 0, x_E = A_EE^-1 b_E; then b_hat = b_S - A_SE x_E.
    Vector x = Vector::Zero(n);
    if (!eliminated->solve(fixed, problem.b, x))
      {
        is_singular = true;
        return;
      }
    const Vector Ax = problem.A * x;
    // The terms of each b_hat_k, whose rounding it carries.
    const Vector terms = absolute_product(problem.A, x);
    reduced.b.resize(n_c);
    for (Index k = 0; k < n_c; ++k)
      {
        const Index i       = problem.constrained[k];
        reduced.b[k]        = problem.b[i] - Ax[i];
        all_loads_round_off = all_loads_round_off &&
                              std::abs(reduced.b[k]) <=
                                1e3 * std::numeric_limits<double>::epsilon() *
                                  (std::abs(problem.b[i]) + terms[i]);
      }

    // Columns of A_hat in blocks: x_S = e_j, x_E = -A_EE^-1 A_Ej, then
    // A_hat e_j = (A x)_S.
    DenseMatrix dense(n_c, n_c);
    const Index block = 128;
    for (Index first = 0; first < n_c; first += block)
      {
        const Index width = std::min(block, n_c - first);
        DenseMatrix X     = DenseMatrix::Zero(n, width);
        for (Index k = 0; k < width; ++k)
          X(problem.constrained[first + k], k) = 1.0;
        eliminated->solve(fixed, DenseMatrix::Zero(n, width), X);
        const DenseMatrix AX = problem.A * X;
        for (Index k = 0; k < width; ++k)
          for (Index i = 0; i < n_c; ++i)
            dense(i, first + k) = AX(problem.constrained[i], k);
      }
    // Symmetrise away round-off so the reduced problem passes the checks,
    // and clamp what round-off made of a vanishing diagonal.
    dense = 0.5 * (dense + dense.transpose()).eval();
    clamp_rounded_diagonal(dense, problem.A, problem.constrained);

    reduced.A = dense.sparseView(0.0, 0.0);
    // sparseView drops exact zeros; keep the diagonal in the pattern.
    reduced.constrained.resize(n_c);
    for (Index k = 0; k < n_c; ++k)
      reduced.constrained[k] = k;
    reduced.lower_bound = problem.lower_bound;
    // The same constraints, so what the builder knew of them holds.
    reduced.mostly_active = problem.mostly_active;
    reduced.eliminated    = true;
    check_and_normalise(reduced);
  }

  Vector
  SchurComplement::recover(const Vector &u_S)
  {
    Vector u = Vector::Zero(problem.size());
    for (Index k = 0; k < problem.n_constrained(); ++k)
      u[problem.constrained[k]] = u_S[k];
    eliminated->solve(fixed, problem.b, u);
    return u;
  }
} // namespace unilateral::lcp
