#include <unilateral/lcp/active_set_system.h>

namespace unilateral::lcp
{
  ActiveSetSystem::ActiveSetSystem(const SparseMatrix &A, Counters &counters)
    : A(A)
    , counters(counters)
    , reduced(A)
    , cholesky(counters)
  {
    const Vector diagonal = A.diagonal();
    double       mean     = diagonal.size() > 0 ? diagonal.mean() : 1.0;
    if (!(mean > 0))
      mean = 1.0;
    fixed_diagonal = diagonal;
    for (Index i = 0; i < fixed_diagonal.size(); ++i)
      if (!(fixed_diagonal[i] > 0))
        fixed_diagonal[i] = mean;
  }

  bool
  ActiveSetSystem::factorise(const std::vector<char> &fixed)
  {
    if (factor_valid && fixed == factorised_fixed)
      return true;

    // Same pattern as A: zero the coupling of fixed indices, keep a scaled
    // identity on their diagonal so the conditioning is that of A.
    for (Index j = 0; j < A.outerSize(); ++j)
      {
        SparseMatrix::InnerIterator original(A, j);
        for (SparseMatrix::InnerIterator it(reduced, j); it; ++it, ++original)
          {
            const Index i = it.row();
            if (fixed[i] || fixed[j])
              it.valueRef() = (i == j) ? fixed_diagonal[i] : 0.0;
            else
              it.valueRef() = original.value();
          }
      }
    factorised_fixed = fixed;
    factor_valid     = cholesky.factorise(reduced);
    return factor_valid;
  }

  bool
  ActiveSetSystem::solve(const std::vector<char> &fixed,
                         const Vector            &r,
                         Vector                  &x)
  {
    DenseMatrix X = x;
    const bool  ok = solve(fixed, DenseMatrix(r), X);
    x              = X.col(0);
    return ok;
  }

  bool
  ActiveSetSystem::solve(const std::vector<char> &fixed,
                         const DenseMatrix       &R,
                         DenseMatrix             &X)
  {
    if (!factorise(fixed))
      return false;

    const Index n = A.rows();
    DenseMatrix fixed_part = DenseMatrix::Zero(n, X.cols());
    for (Index i = 0; i < n; ++i)
      if (fixed[i])
        fixed_part.row(i) = X.row(i);
    const DenseMatrix coupling = A * fixed_part;
    counters.matrix_vector_products += static_cast<unsigned int>(X.cols());

    DenseMatrix rhs(n, X.cols());
    for (Index i = 0; i < n; ++i)
      if (fixed[i])
        rhs.row(i) = fixed_diagonal[i] * X.row(i);
      else
        rhs.row(i) = R.row(i) - coupling.row(i);

    DenseMatrix solution;
    cholesky.solve(rhs, solution);
    for (Index i = 0; i < n; ++i)
      if (!fixed[i])
        X.row(i) = solution.row(i);
    return true;
  }
} // namespace unilateral::lcp
