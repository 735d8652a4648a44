#pragma once

#include <unilateral/lcp/block_matrix.h>
#include <unilateral/lcp/hierarchy.h>
#include <unilateral/lcp/problem.h>

#include <deal.II/lac/vector.h>

#include <memory>

namespace unilateral::lcp
{
  /**
   * Linear multigrid on a Hierarchy, truncated to the unknowns that are not
   * held at a bound (Kornhuber 1994; Graeser & Kornhuber 2009): the inner
   * solver of the multigrid methods for the LCP.
   *
   * The level matrices are Galerkin products, A_l = P_l^T A_{l+1} P_l,
   * kept as node blocks (block_matrix.h). truncate() chooses a top level
   * and the unknowns of it that are held (mask 0): the cycle then works in
   * the space of the free unknowns of the top level, the prolongation to it
   * is truncated, P~ = M P (the coarse functions cut off where the top
   * level is held), and the levels below it are the Galerkin products of
   * the truncated top matrix, M A M, through P~. Levels above the top keep
   * their own matrices (the nested iteration climbs through them).
   *
   * The V-cycle is deal.II's Multigrid, with mg::Matrix over the levels'
   * operators, a symmetric block Gauss-Seidel smoother (forward before the
   * coarse correction, backward after: a symmetric preconditioner) on the
   * nodes' 4 x 4 blocks, and a sparse LDL^T of the coarsest level; solve()
   * accelerates it with deal.II's SolverCG. The W-cycle (two coarse
   * corrections per level, the second on the defect the first leaves) is
   * our own recursion over the same levels, smoothers and coarse solve:
   * deal.II 9.4's Multigrid::level_step starts the second visit of a
   * coarser level from zero on the same defect (the smoother's apply()
   * zeroes the solution) and so discards the first, which makes its
   * W-cycle a V-cycle at twice the coarse cost (corrected in deal.II after
   * 9.4, pull request 19710).
   * deal.II's transfer classes and PreconditionMG need a DoFHandler with
   * level DOFs of a refined Triangulation and an element deal.II can
   * prolongate: the hierarchy here comes as matrices from any builder (the
   * plate's Hermite interpolation is no deal.II element's), so the transfer
   * and the preconditioner's two copies are the few lines below.
   * Vectors are dealii::Vector<double> in node layout.
   */
  class TruncatedMultigrid
  {
  public:
    using LevelVector = dealii::Vector<double>;

    /// One coarse correction per level (V) or two (W).
    enum class Cycle
    {
      v,
      w
    };

    /// The levels of @p hierarchy with @p A on the finest (A_l for the
    /// coarse ones by Galerkin products); @p smoothing_steps Gauss-Seidel
    /// sweeps before and after each coarse correction.
    TruncatedMultigrid(const Hierarchy    &hierarchy,
                       const SparseMatrix &A,
                       unsigned int        smoothing_steps,
                       Cycle               cycle = Cycle::v);

    ~TruncatedMultigrid();

    unsigned int
    n_levels() const;

    /// The length of a node-layout vector on @p level.
    Index
    size(unsigned int level) const;

    /// A_l, the level's own matrix (valid on the top level and above).
    const BlockMatrix &
    matrix(unsigned int level) const;

    /// The unknowns @p u of @p level (in the level's numbering) in node
    /// layout, and back.
    void
    to_nodes(unsigned int level, const Vector &u, LevelVector &x) const;

    Vector
    from_nodes(unsigned int level, const LevelVector &x) const;

    /// @p fine = P @p coarse (not truncated), from @p level to level + 1.
    void
    prolongate(unsigned int       level,
               const LevelVector &coarse,
               LevelVector       &fine) const;

    /// @p coarse = P^T @p fine (not truncated), from level + 1 to @p level.
    void
    restrict_to(unsigned int       level,
                const LevelVector &fine,
                LevelVector       &coarse) const;

    /// Per node of level + 1: whether every node of @p level it is
    /// interpolated from has @p flag set (one per node of @p level).
    std::vector<char>
    all_parents(unsigned int level, const std::vector<char> &flag) const;

    /**
     * Cycle on levels 0..@p top with the entries of @p mask (node layout on
     * @p top) that are 0 held: rebuilds the truncated coarse levels, their
     * smoothers and the coarse factorisation.
     */
    void
    truncate(unsigned int top, const LevelVector &mask);

    /// y = M A_top M x, the truncated top matrix (x held entries are 0).
    void
    vmult(LevelVector &y, const LevelVector &x) const;

    /**
     * d with M A_top M d = M r approximately (d = 0 where held): conjugate
     * gradients preconditioned with one cycle each, from d = 0, until the
     * residual has fallen by @p reduction or after @p max_cycles cycles.
     * Returns the number of cycles.
     */
    unsigned int
    solve(LevelVector       &d,
          const LevelVector &r,
          double             reduction,
          unsigned int       max_cycles);

    /// The levels, their smoothers and the cycle (in the source).
    class Implementation;

  private:
    std::unique_ptr<Implementation> implementation;
  };
} // namespace unilateral::lcp
