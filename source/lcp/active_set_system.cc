#include <unilateral/lcp/active_set_system.h>

#include <cmath>

namespace unilateral::lcp
{
  namespace
  {
    unsigned int
    count_changes(const std::vector<char> &a, const std::vector<char> &b)
    {
      unsigned int changes = 0;
      for (std::size_t i = 0; i < a.size(); ++i)
        changes += (a[i] != b[i]);
      return changes;
    }
  } // namespace

  ActiveSetSystem::ActiveSetSystem(
    const SparseMatrix                    &A,
    Counters                              &counters,
    std::shared_ptr<const ActiveSetFactor> inherited)
    : A(A)
    , counters(counters)
    , own(std::make_shared<ActiveSetFactor>(counters))
    , inherited(std::move(inherited))
  {
    const Vector diagonal = A.diagonal();
    double       mean     = diagonal.size() > 0 ? diagonal.mean() : 1.0;
    if (!(mean > 0))
      mean = 1.0;
    fixed_diagonal = diagonal;
    for (Index i = 0; i < fixed_diagonal.size(); ++i)
      if (!(fixed_diagonal[i] > 0))
        fixed_diagonal[i] = mean;
    if (this->inherited && this->inherited->fixed.size() != std::size_t(A.rows()))
      this->inherited.reset();
  }

  std::shared_ptr<const ActiveSetFactor>
  ActiveSetSystem::factor() const
  {
    if (own_valid)
      return own;
    return inherited;
  }

  bool
  ActiveSetSystem::factorise(const std::vector<char> &fixed)
  {
    if (reduced.rows() != A.rows())
      reduced = A;
    // Same pattern as A: zero the coupling of fixed indices, keep a scaled
    // identity on their diagonal so the conditioning is that of A.
    for (Index j = 0; j < A.outerSize(); ++j)
      {
        const Index begin = A.outerIndexPtr()[j];
        const Index end   = A.outerIndexPtr()[j + 1];
        for (Index k = begin; k < end; ++k)
          {
            const Index i = A.innerIndexPtr()[k];
            if (fixed[i] || fixed[j])
              reduced.valuePtr()[k] = (i == j) ? fixed_diagonal[i] : 0.0;
            else
              reduced.valuePtr()[k] = A.valuePtr()[k];
          }
      }
    own->fixed = fixed;
    own_valid  = own->cholesky.factorise(reduced);
    inherited.reset(); // our own factor is closer from now on
    return own_valid;
  }

  void
  ActiveSetSystem::apply(const std::vector<char> &fixed,
                         const DenseMatrix       &Y,
                         DenseMatrix             &KY) const
  {
    DenseMatrix free_part = Y;
    for (Index i = 0; i < A.rows(); ++i)
      if (fixed[i])
        free_part.row(i).setZero();
    KY = A * free_part;
    for (Index i = 0; i < A.rows(); ++i)
      if (fixed[i])
        KY.row(i) = fixed_diagonal[i] * Y.row(i);
  }

  bool
  ActiveSetSystem::preconditioned_cg(const std::vector<char> &fixed,
                                     const ActiveSetFactor   &preconditioner,
                                     const DenseMatrix       &B,
                                     DenseMatrix             &X,
                                     const unsigned int       max_iterations)
  {
    // Start from the preconditioner's answer; then CG on the residual. The
    // tolerance is what a backward-stable direct solve achieves.
    preconditioner.cholesky.solve(B, X);
    DenseMatrix KX;
    apply(fixed, X, KX);
    counters.matrix_vector_products += static_cast<unsigned int>(B.cols());
    DenseMatrix R = B - KX;
    for (Index column = 0; column < B.cols(); ++column)
      {
        const double target =
          1e-14 * (B.col(column).norm() + KX.col(column).norm());
        Vector       r = R.col(column);
        Vector       x = X.col(column);
        if (r.norm() <= target)
          continue;
        Vector z, p, q;
        preconditioner.cholesky.solve(r, z);
        p               = z;
        double rz       = r.dot(z);
        bool   converged = false;
        for (unsigned int iteration = 0; iteration < max_iterations;
             ++iteration)
          {
            DenseMatrix Kp;
            apply(fixed, p, Kp);
            ++counters.matrix_vector_products;
            ++counters.cg_iterations;
            const double curvature = p.dot(Kp.col(0));
            if (!(curvature > 0))
              break; // K(X) not positive definite along p: refactorise
            const double alpha = rz / curvature;
            x += alpha * p;
            r -= alpha * Kp.col(0);
            if (r.norm() <= target)
              {
                converged = true;
                break;
              }
            preconditioner.cholesky.solve(r, z);
            const double rz_next = r.dot(z);
            p                    = z + (rz_next / rz) * p;
            rz                   = rz_next;
          }
        if (!converged)
          return false;
        X.col(column) = x;
      }
    return true;
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
    bool        solved = false;
    if (own_valid && own->fixed == fixed)
      {
        own->cholesky.solve(rhs, solution);
        solved = true;
      }
    else
      {
        // A nearby factor: our own for another active set, or an inherited
        // one (A + eps I) for the same.
        const ActiveSetFactor *nearby =
          own_valid ? own.get() : inherited.get();
        if (nearby != nullptr)
          {
            const unsigned int changes = count_changes(nearby->fixed, fixed);
            if (changes <= max_changes &&
                preconditioned_cg(fixed, *nearby, rhs, solution,
                                  2 * changes + 8))
              {
                ++counters.reused_factorisations;
                solved = true;
              }
          }
      }
    if (!solved)
      {
        if (!factorise(fixed))
          return false;
        own->cholesky.solve(rhs, solution);
      }
    for (Index i = 0; i < n; ++i)
      if (!fixed[i])
        X.row(i) = solution.row(i);
    return true;
  }
} // namespace unilateral::lcp
