#pragma once

#include <unilateral/lcp/sparse_cholesky.h>

#include <memory>
#include <vector>

namespace unilateral::lcp
{
  /**
   * A factorisation of A with a set of indices fixed (their rows and columns
   * replaced by the diagonal), kept so that a later system on a nearby
   * matrix can use it as a preconditioner: the next active set, or the
   * projection step (A instead of A + eps I).
   */
  struct ActiveSetFactor
  {
    explicit ActiveSetFactor(Counters &counters)
      : cholesky(counters)
    {}

    SparseCholesky    cholesky;
    std::vector<char> fixed;
  };

  /**
   * The linear systems of every active-set and pivoting method: for a set X
   * of fixed indices with given values x_X, solve
   *     A_FF x_F = r_F - A_FX x_X,      F = complement of X,
   * i.e. minimise 1/2 x^T A x - r^T x with x_X fixed (the "QEP" of
   * Ainsworth & Mihai, eq. (57) of Fernandes et al.).
   *
   * The reduced matrix K(X) is never extracted: the full pattern is kept and
   * the fixed rows and columns are replaced by their diagonal entry, so one
   * symbolic analysis of A serves every active set.
   *
   * Factorisations are reused. A factor for exactly this X is used directly.
   * A factor for a nearby matrix, one whose fixed set differs in at most
   * max_changes indices (K then differs by a matrix of rank <= 2 changes), or
   * an inherited factor of A + eps I for the same X, preconditions conjugate
   * gradients, which then converge in about 2 changes + 1 iterations. Only
   * if CG does not reach the direct solver's accuracy in its iteration
   * budget is K(X) factorised anew. The rule is deterministic.
   */
  class ActiveSetSystem
  {
  public:
    /// @p inherited: a factor of a nearby matrix (e.g. of A + eps I) to
    /// try first; may be null.
    ActiveSetSystem(const SparseMatrix                     &A,
                    Counters                               &counters,
                    std::shared_ptr<const ActiveSetFactor>  inherited = {});

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

    /// The most recent factor (own or inherited), for a follow-up system.
    std::shared_ptr<const ActiveSetFactor>
    factor() const;

    /// Fixed-set changes up to which a factor is reused through CG.
    static constexpr unsigned int max_changes = 16;

  private:
    bool
    factorise(const std::vector<char> &fixed);

    /// K(X) y: A on the free part, the diagonal on the fixed part.
    void
    apply(const std::vector<char> &fixed, const DenseMatrix &Y,
          DenseMatrix &KY) const;

    /// Preconditioned CG on K(X) X = B with @p preconditioner; true if
    /// every column reached the tolerance within @p max_iterations.
    bool
    preconditioned_cg(const std::vector<char> &fixed,
                      const ActiveSetFactor   &preconditioner,
                      const DenseMatrix       &B,
                      DenseMatrix             &X,
                      unsigned int             max_iterations);

    const SparseMatrix                     &A;
    Counters                               &counters;
    SparseMatrix                            reduced;
    std::shared_ptr<ActiveSetFactor>        own;
    bool                                    own_valid = false;
    std::shared_ptr<const ActiveSetFactor>  inherited;
    /// Diagonal used for fixed rows: A_jj if positive, else the mean diagonal.
    Vector                                  fixed_diagonal;
  };
} // namespace unilateral::lcp
