#pragma once

#include <unilateral/lcp/sparse_cholesky.h>

#include <vector>

namespace unilateral::lcp
{
  /**
   * The linear systems of every active-set and pivoting method: for a set X
   * of fixed indices with given values x_X, solve
   *     A_FF x_F = r_F - A_FX x_X,      F = complement of X,
   * i.e. minimise 1/2 x^T A x - r^T x with x_X fixed (the "QEP" of
   * Ainsworth & Mihai, eq. (57) of Fernandes et al.).
   *
   * The reduced matrix is never extracted: the full pattern is kept and the
   * fixed rows and columns are replaced by their diagonal entry, so one
   * symbolic analysis of A serves every active set. A factor is reused as long
   * as the fixed set does not change.
   */
  class ActiveSetSystem
  {
  public:
    ActiveSetSystem(const SparseMatrix &A, Counters &counters);

    /**
     * On entry x holds the fixed values on X (other entries are ignored); on
     * exit x_F is the solution. Returns false if A_FF is not positive
     * definite (the reduced system is singular).
     */
    bool
    solve(const std::vector<char> &fixed, const Vector &r, Vector &x);

    /// The same for several right-hand sides (columns of R and X) at once.
    bool
    solve(const std::vector<char> &fixed, const DenseMatrix &R, DenseMatrix &X);

  private:
    bool
    factorise(const std::vector<char> &fixed);

    const SparseMatrix &A;
    Counters           &counters;
    SparseMatrix        reduced;
    SparseCholesky      cholesky;
    std::vector<char>   factorised_fixed;
    bool                factor_valid = false;
    /// Diagonal used for fixed rows: A_jj if positive, else the mean diagonal.
    Vector              fixed_diagonal;
  };
} // namespace unilateral::lcp
