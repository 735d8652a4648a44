#pragma once

#include <unilateral/lcp/problem.h>
#include <unilateral/lcp/report.h>

#include <cstdint>
#include <memory>
#include <vector>

namespace unilateral::lcp
{
  /**
   * Sparse Cholesky factorisation through SuiteSparse CHOLMOD, with the
   * three phases of the plate paper kept apart: Analyse (fill-reducing
   * ordering and symbolic factorisation) runs once per sparsity pattern;
   * every numeric factorisation of a matrix with the same pattern reuses it.
   *
   * Matrices are given with both triangles stored; CHOLMOD reads the upper
   * one, so unless distributed() the upper triangle alone will do.
   * factorise() counts its work in the Counters it is given; solves are
   * counted by the caller (a factor may be shared with a later solve).
   *
   * Why CHOLMOD's C API and not a deal.II wrapper (SparseDirectUMFPACK, the
   * Trilinos or PETSc direct solvers): the active-set methods need what
   * only CHOLMOD's own API offers, a symbolic analysis kept across numeric
   * factorisations of one pattern, row deletions and additions of an
   * existing factor (rowdel/rowadd), and partial forward solves along the
   * elimination tree (inverse_gram); the wrappers factorise from scratch.
   *
   * Made inside a DistributedFactorisations scope (an MPI run with 'Solver/
   * Factorisation' = mumps, or auto on several ranks), the object factorises
   * and solves through a DistributedCholesky over the scope's ranks instead:
   * the same answers, without what only CHOLMOD offers (row modifications
   * report an infinite cost and fail, inverse_gram declines, a given
   * ordering is ignored), which every caller already falls back from.
   */
  class SparseCholesky
  {
  public:
    SparseCholesky();
    ~SparseCholesky();
    SparseCholesky(const SparseCholesky &) = delete;
    SparseCholesky &
    operator=(const SparseCholesky &) = delete;

    /**
     * Numeric factorisation of @p A. Runs the symbolic analysis first only
     * if the pattern differs from the one analysed last. Returns false (and
     * keeps no factor) if A is not numerically positive definite.
     */
    bool
    factorise(const SparseMatrix &A, Counters &counters);

    /**
     * The same with a given fill-reducing ordering (new-to-old, as CHOLMOD's
     * Perm): the symbolic analysis, run only when the pattern changed, then
     * skips the ordering step (the plate paper's "ordering established in
     * the Analyse phase", restricted to a submatrix).
     */
    bool
    factorise(const SparseMatrix       &A,
              const std::vector<Index> &ordering,
              Counters                 &counters);

    /**
     * Numeric factorisation of the full-pattern system of an active-set
     * method: A with the rows and columns of the indices marked in
     * @p fixed replaced by those of a diagonal matrix (@p fixed_diagonal
     * there), and @p shift added to the rest of the diagonal; delete_row
     * and add_row then move single indices between the two kinds. Analysed
     * on A's pattern, which every active set shares, and formed straight in
     * the permuted triangle CHOLMOD factorises: no copy of A is made (on the
     * largest walls the copy and CHOLMOD's permuted copy of it set the run's
     * peak memory, benchmarks/masonry_tables/README.md, "Design
     * measurements").
     */
    bool
    factorise_with_fixed(const SparseMatrix       &A,
                         const std::vector<char>  &fixed,
                         const Vector             &fixed_diagonal,
                         double                    shift,
                         const std::vector<Index> &ordering,
                         Counters                 &counters);

    /**
     * Numeric factorisation of A + diag(@p shift), the Newton matrix of an
     * interior-point iteration, formed as factorise_with_fixed forms its
     * matrix: straight from A, without a copy of it. A stores every
     * diagonal entry (a Problem's A does).
     */
    bool
    factorise_shifted(const SparseMatrix &A,
                      const Vector       &shift,
                      Counters           &counters);

    /// The fill-reducing ordering of the last analysis (new-to-old).
    std::vector<Index>
    ordering() const;

    /// The AMD ordering of A (new-to-old) alone, without a factorisation.
    static std::vector<Index>
    amd_ordering(const SparseMatrix &A, Counters &counters);

    /// Solve A x = b with the current factor.
    void
    solve(const Vector &b, Vector &x) const;

    /// Solve A X = B for several right-hand sides at once.
    void
    solve(const DenseMatrix &B, DenseMatrix &X) const;

    bool
    has_factor() const;

    /**
     * Take over @p other's symbolic analysis and factor storage, leaving
     * @p other empty and this without a valid factor until the next
     * factorise(): a factorisation of the same pattern then needs no new
     * analysis and no new memory (a system that follows another on the
     * same pattern, as the projection follows the regularised solve).
     * Nothing happens if either runs over several ranks.
     */
    void
    take_analysis_from(SparseCholesky &other);

    /// Whether this factorisation runs over several ranks (MUMPS).
    bool
    distributed() const;

    /**
     * G = B' A^-1 B for sparse columns B (n x k, in the indices of A): with
     * P A P' = L L' (or L D L'), G = Y' Y (Y' D^-1 Y) for Y = L^-1 P B.
     * Forward only, and only along the elimination-tree paths from the
     * entries of B: the Schur complement of a few hundred indices, which k
     * full solves cost a dense forward and backward pass each, costs a
     * fraction of one per index. Columns go in blocks of 32, grouped by
     * where they enter the tree. False (G unset) without a factor or if the
     * kept forward solutions would exceed @p max_entries doubles; the
     * caller then solves in full.
     */
    bool
    inverse_gram(const SparseMatrix &B,
                 DenseMatrix        &G,
                 double              max_entries = 2.5e8) const;

    /**
     * @name Row modifications (CHOLMOD's Modify module)
     *
     * The factor of a matrix whose k-th row and column become those of a
     * diagonal matrix (delete_row), or whose k-th row and column, so far
     * diagonal, become the given column (add_row), is updated in place
     * rather than recomputed: the active-set methods change a few rows per
     * iteration. The first modification after a numeric factorisation works
     * on a simplicial LDL' copy of the factor; the analysed (supernodal)
     * factor keeps its structure, not its values, for the next factorise().
     * Indices are those of the matrix, not of the fill-reducing ordering.
     * Each returns false if CHOLMOD fails (the factor is then unusable until
     * factorise()).
     */
    /// @{
    ///
    /// @p column_rows: the rows of column k of the analysed matrix (its
    /// pattern; the values do not matter). They give CHOLMOD the pattern of
    /// row k of L, which it otherwise finds by searching every column
    /// before k, for every deleted row (what that cost:
    /// benchmarks/masonry_tables/README.md, "Design measurements").
    bool
    delete_row(Index k, double diagonal, const std::vector<Index> &column_rows);

    /// @p rows, @p values: the new column k (the diagonal included), with
    /// entries only where the other rows are not themselves diagonal.
    bool
    add_row(Index                      k,
            const std::vector<Index>  &rows,
            const std::vector<double> &values);

    /// Whether the simplicial copy for modifications exists (it is made by
    /// the first modification after a numeric factorisation).
    bool
    has_modification_copy() const;

    /// Floating-point operations of one numeric factorisation of the
    /// analysed pattern (CHOLMOD's estimate from the analysis).
    double
    factorisation_flops() const;

    /// Entries of L that modifications of the rows @p indices rewrite: for
    /// each, its column and those of its ancestors in the elimination tree
    /// (CHOLMOD's update follows that path). Known before any modification
    /// is made, from the analysed factor alone.
    double
    modification_path_entries(const std::vector<Index> &indices) const;

    /// Floating-point operations of the modifications since the last
    /// numeric factorisation.
    double
    modification_flops() const;

    /// CHOLMOD's reciprocal condition estimate of the current factor.
    double
    reciprocal_condition() const;
    /// @}

    /// Number of nonzeros in the factor L (0 if none).
    double
    factor_nonzeros() const;

    /**
     * Supernodes of the next symbolic analysis: relaxed (CHOLMOD's
     * amalgamation parameters nrelax = 16, 64, 128 and zrelax = 0.9, 0.3,
     * 0.1 instead of 4, 16, 48 and 0.8, 0.1, 0.05) merges more columns into
     * each supernode, storing some zeros of L, so that dense kernels do more
     * of the work: a faster factorisation for somewhat more memory. Factors
     * that are modified row by row keep CHOLMOD's default: the simplicial
     * copy and every update would carry the stored zeros too, and lose more
     * than the factorisation gains. So does the interior point's matrix
     * (ShiftedSystem), which is factorised on two threads, where the smaller
     * supernodes are the faster (all measured on the walls:
     * benchmarks/masonry_tables/README.md, "Design measurements").
     */
    bool relaxed_supernodes = true;

    /**
     * For a pattern that is factorised many times (the interior point's
     * matrix): when AMD's ordering leaves large dense fronts (at least 500
     * flops per entry of L, the threshold at which CHOLMOD's default
     * strategy considers METIS), also analyse in METIS's nested dissection
     * and keep the ordering with fewer flops (a METIS analysis that fails
     * leaves AMD's). A METIS ordering costs several times AMD's, which only
     * the savings of many factorisations repay, and only where AMD's fronts
     * are large: the running bond's interior-point matrix, not the stack
     * bond's or the laminae's (benchmarks/masonry_tables/README.md, "Design
     * measurements"). Off by default: a pattern factorised once (A_FF of
     * one active set) cannot repay the ordering.
     */
    bool try_nested_dissection = false;

    /// The flops per entry of L from which try_nested_dissection tries
    /// METIS. 0: always, for a factor solved with many times, whose
    /// entries set the cost of a solve (TFETI's coarse matrix).
    double nested_dissection_fronts = 500;

    /// A factor with a smaller estimate counts as singular (0: never).
    /// Active-set systems set it: their A_FF must hold every body. The
    /// interior-point systems do not: A + diag(lambda / s) is badly scaled
    /// near the end by design, and harmlessly.
    double minimum_rcond = 0;

    /// A supernodal factorisation of at least this many flops runs its
    /// independent subtrees on as many threads as OpenBLAS may run, at most
    /// one per core (SupernodalFactorisation); below it a thread does not
    /// pay.
    double minimum_flops_for_threads = 2e8;

  private:
    struct Implementation;
    struct Changes;

    /// factorise() of A, or of A with @p changes made (null: A itself).
    bool
    factorise(const SparseMatrix       &A,
              const std::vector<Index> &ordering,
              const Changes            *changes,
              Counters                 &counters);

    /// The working copy for modifications, made on first need; false if
    /// there is no valid factor or CHOLMOD fails.
    bool
                                    prepare_modification();
    std::unique_ptr<Implementation> implementation;
  };
} // namespace unilateral::lcp
