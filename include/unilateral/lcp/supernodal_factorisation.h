#pragma once

#include <unilateral/lcp/problem.h>

#include <cholmod.h>

#include <utility>
#include <vector>

namespace unilateral::lcp
{
  /**
   * CHOLMOD's numeric supernodal Cholesky factorisation
   * (cholmod_super_numeric: left-looking, each supernode gathers the updates
   * of its descendants before it is factorised), with disjoint subtrees of
   * the supernodal elimination tree factorised on several threads at once
   * and their common ancestors after them.
   *
   * Why our own loop over CHOLMOD's supernodes: CHOLMOD 4 (SuiteSparse 5.12)
   * factorises on one thread and reaches a second core only through the
   * BLAS, whose threads split each supernode's dense calls and mostly wait
   * for each other; the second core then adds nothing to the factorisations
   * that take most of a large wall's time (benchmarks/masonry_tables/
   * README.md, "Design measurements"). Subtrees with no common ancestor
   * write disjoint columns and read none of each other's, so they can be
   * factorised at the same time. The steps of each supernode are
   * CHOLMOD's own (the same BLAS and LAPACK calls on the same blocks), and
   * the result is a CHOLMOD factor like any other: CHOLMOD's solves, copies
   * and row modifications take it unchanged. Only the order in which a
   * supernode sums its descendants' updates differs, within rounding.
   */
  class SupernodalFactorisation
  {
  public:
    /**
     * Split the analysed supernodal factor @p L between @p n_threads
     * threads: whole subtrees of its elimination tree, in shares of about
     * equal work, and the supernodes above them. No split (splits() false)
     * where the factorisation costs fewer than @p minimum_flops (a thread
     * would not pay) or the threads would save less than a tenth of it.
     */
    void
    plan(const cholmod_factor &L, double minimum_flops, unsigned int n_threads);

    /// Whether plan() found a split worth more than one thread.
    bool
    splits() const;

    /**
     * L = chol(A) for A the lower triangle (stype -1, packed) of the
     * permuted matrix whose pattern @p L was analysed for, as
     * cholmod_super_numeric(A, nullptr, 0, L, common) does it, after
     * plan(L). A matrix that is not positive definite leaves
     * common.status == CHOLMOD_NOT_POSDEF and L.minor < L.n (a column
     * where a thread stopped, where CHOLMOD gives the first); workspace
     * that cannot be had leaves CHOLMOD_OUT_OF_MEMORY.
     */
    void
    numeric(const cholmod_sparse &A,
            cholmod_factor       &L,
            cholmod_common       &common) const;

    /**
     * x = A^-1 b with a numeric supernodal factor @p L of the analysis
     * planned for (numeric()'s or CHOLMOD's): L's permutation, then the
     * forward and the backward substitution supernode by supernode, as
     * CHOLMOD's supernodal solve of one right-hand side does, with the
     * subtrees of the threads at the same time. A solve reads the
     * whole factor once each way and is bound by memory traffic, which a
     * second core nearly doubles on this machine (benchmarks/masonry_tables/
     * README.md, "Design measurements").
     */
    void
    solve(const cholmod_factor &L, const double *b, double *x) const;

  private:
    /// The supernode holding each column.
    std::vector<Index> supernode_of_column;
    /// Each thread's subtrees, as ranges [first, last] of supernodes (the
    /// supernodes are in postorder, so a subtree is a range).
    std::vector<std::vector<std::pair<Index, Index>>> shares;
    /// The supernodes above all subtrees, in order.
    std::vector<Index> ancestors;
    /// For each column of an ancestor its place among those columns, -1
    /// for the others (where a thread's forward substitution keeps its
    /// updates of the ancestors' rows apart).
    std::vector<Index> place_among_ancestors;
    Index              n_ancestor_columns = 0;
  };
} // namespace unilateral::lcp
