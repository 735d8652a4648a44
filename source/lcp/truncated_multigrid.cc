#include <unilateral/lcp/truncated_multigrid.h>

#include <deal.II/base/mg_level_object.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/multigrid/mg_base.h>
#include <deal.II/multigrid/mg_matrix.h>
#include <deal.II/multigrid/multigrid.h>

#include <Eigen/SparseCholesky>

#include <vector>

namespace unilateral::lcp
{
  namespace
  {
    using LevelVector = TruncatedMultigrid::LevelVector;
    using Block       = BlockMatrix::Block;
    using NodeVector  = BlockMatrix::NodeVector;
    constexpr int B   = BlockMatrix::size;

    /**
     * One level's operator for mg::Matrix: A_l, and on the top level
     * M A_top M (the held entries of x are 0 there, so masking y is all).
     */
    class LevelOperator
    {
    public:
      const BlockMatrix *matrix = nullptr;
      const LevelVector *mask   = nullptr;

      dealii::types::global_dof_index
      m() const
      {
        return static_cast<dealii::types::global_dof_index>(B) *
               matrix->n_rows();
      }

      dealii::types::global_dof_index
      n() const
      {
        return m();
      }

      void
      vmult(LevelVector &y, const LevelVector &x) const
      {
        matrix->vmult(y.begin(), x.begin());
        if (mask != nullptr)
          y.scale(*mask);
      }

      void
      vmult_add(LevelVector &y, const LevelVector &x) const
      {
        scratch.reinit(y.size(), true);
        vmult(scratch, x);
        y += scratch;
      }

      void
      Tvmult(LevelVector &y, const LevelVector &x) const
      {
        vmult(y, x);
      }

      void
      Tvmult_add(LevelVector &y, const LevelVector &x) const
      {
        vmult_add(y, x);
      }

    private:
      mutable LevelVector scratch;
    };

    /// One block Gauss-Seidel sweep for A x = rhs, in residual form:
    /// x_i += D_i^+ (rhs - A x)_i node by node (D_i^+ zero where held).
    void
    block_gauss_seidel(const BlockMatrix      &A,
                       const DiagonalInverses &inverses,
                       double                 *x,
                       const double           *rhs,
                       const bool              forward)
    {
      const Index n = A.n_rows();
      for (Index step = 0; step < n; ++step)
        {
          const Index i = forward ? step : n - 1 - step;
          Eigen::Map<NodeVector>(x + B * i) +=
            inverses[i] * A.row_residual(i, rhs, x);
        }
    }
  } // namespace

  class TruncatedMultigrid::Implementation
  {
  public:
    Implementation(const Hierarchy    &hierarchy,
                   const SparseMatrix &A,
                   unsigned int        smoothing_steps,
                   Cycle               cycle);

    /// Per level: the node layout, the matrix, the transfer to the next
    /// finer level (P and P^T, node blocks; the last: none).
    std::vector<std::vector<Index>>         nodes;
    std::vector<BlockMatrix::NodeMap>       maps;
    unsigned int                            block_size;
    dealii::MGLevelObject<BlockMatrix>      matrices;
    std::vector<BlockMatrix>                prolongations, restrictions;
    dealii::MGLevelObject<DiagonalInverses> inverses;
    dealii::MGLevelObject<LevelOperator>    operators;
    dealii::mg::Matrix<LevelVector>         level_matrices;

    /// The cycle's levels 0..top; the top's mask and truncated transfer.
    unsigned int top = 0;
    LevelVector  mask;
    BlockMatrix  top_prolongation, top_restriction;

    Eigen::SimplicialLDLT<SparseMatrix> coarse_factor;
    unsigned int                        smoothing_steps;
    Cycle                               cycle;

    /// The W-cycle's vectors per level: the defect it is given, the
    /// solution it returns (from zero), a scratch vector and the first
    /// coarse correction kept while the second is computed.
    std::vector<LevelVector> defect, solution, scratch, first_correction;

    const BlockMatrix &
    prolongation(const unsigned int to_level) const
    {
      return to_level == top ? top_prolongation : prolongations[to_level - 1];
    }

    const BlockMatrix &
    restriction(const unsigned int from_level) const
    {
      return from_level == top ? top_restriction : restrictions[from_level - 1];
    }

    /// Whether truncate() ran (the levels below the top are truncated).
    bool truncated = false;

    /// deal.II's cycle on levels 0..top and its parts, made anew when the
    /// top changes (the cycle keeps its level vectors between solves).
    std::unique_ptr<dealii::MGSmootherBase<LevelVector>>   pre, post;
    std::unique_ptr<dealii::MGTransferBase<LevelVector>>   transfer;
    std::unique_ptr<dealii::MGCoarseGridBase<LevelVector>> coarse;
    std::unique_ptr<dealii::Multigrid<LevelVector>>        multigrid;

    void
    factorise_coarsest();

    void
    smooth(const unsigned int level,
           LevelVector       &x,
           const LevelVector &rhs,
           const bool         forward) const
    {
      for (unsigned int k = 0; k < smoothing_steps; ++k)
        block_gauss_seidel(
          matrices[level], inverses[level], x.begin(), rhs.begin(), forward);
    }

    /// solution[level] = W-cycle applied to defect[level], from zero.
    void
    w_cycle(unsigned int level);

    /// The truncated levels built anew for @p top and @p mask.
    void
    truncate_fully(unsigned int top, const LevelVector &mask);

    /// The truncated levels updated where @p mask differs from the last.
    void
    update_truncation(const LevelVector &mask);
  };

  namespace
  {
    using Implementation = TruncatedMultigrid::Implementation;

    class Smoother : public dealii::MGSmootherBase<LevelVector>
    {
    public:
      Smoother(const Implementation &mg, const bool forward)
        : mg(mg)
        , forward(forward)
      {}

      void
      clear() override
      {}

      void
      smooth(const unsigned int level,
             LevelVector       &u,
             const LevelVector &rhs) const override
      {
        mg.smooth(level, u, rhs, forward);
      }

    private:
      const Implementation &mg;
      const bool            forward;
    };

    class Transfer : public dealii::MGTransferBase<LevelVector>
    {
    public:
      explicit Transfer(const Implementation &mg)
        : mg(mg)
      {}

      void
      prolongate(const unsigned int to_level,
                 LevelVector       &dst,
                 const LevelVector &src) const override
      {
        mg.prolongation(to_level).vmult(dst.begin(), src.begin());
      }

      void
      prolongate_and_add(const unsigned int to_level,
                         LevelVector       &dst,
                         const LevelVector &src) const override
      {
        mg.prolongation(to_level).vmult_add(dst.begin(), src.begin());
      }

      void
      restrict_and_add(const unsigned int from_level,
                       LevelVector       &dst,
                       const LevelVector &src) const override
      {
        mg.restriction(from_level).vmult_add(dst.begin(), src.begin());
      }

    private:
      const Implementation &mg;
    };

    class CoarseSolve : public dealii::MGCoarseGridBase<LevelVector>
    {
    public:
      explicit CoarseSolve(const Implementation &mg)
        : mg(mg)
      {}

      void
      operator()(const unsigned int,
                 LevelVector       &dst,
                 const LevelVector &src) const override
      {
        Eigen::Map<Vector>(dst.begin(), dst.size()) = mg.coarse_factor.solve(
          Eigen::Map<const Vector>(src.begin(), src.size()));
      }

    private:
      const Implementation &mg;
    };

    /// The preconditioner: one cycle on levels 0..top for the top's
    /// defect (deal.II's V-cycle, or our W-cycle).
    class Preconditioner
    {
    public:
      explicit Preconditioner(Implementation &mg)
        : mg(mg)
      {}

      void
      vmult(LevelVector &dst, const LevelVector &src) const
      {
        const unsigned int top = mg.top;
        if (mg.cycle == TruncatedMultigrid::Cycle::w)
          {
            mg.defect[top] = src;
            mg.w_cycle(top);
            dst = mg.solution[top];
          }
        else
          {
            dealii::Multigrid<LevelVector> &multigrid = *mg.multigrid;
            for (unsigned int level = 0; level < top; ++level)
              multigrid.defect[level] = 0;
            multigrid.defect[top] = src;
            multigrid.cycle();
            dst = multigrid.solution[top];
          }
        ++cycles;
      }

      mutable unsigned int cycles = 0;

    private:
      Implementation &mg;
    };
  } // namespace

  TruncatedMultigrid::Implementation::Implementation(
    const Hierarchy    &hierarchy,
    const SparseMatrix &A,
    const unsigned int  smoothing_steps,
    const Cycle         cycle)
    : block_size(hierarchy.block_size)
    , smoothing_steps(smoothing_steps)
    , cycle(cycle)
  {
    const auto n_levels = static_cast<unsigned int>(hierarchy.levels.size());
    for (const Hierarchy::Level &level : hierarchy.levels)
      {
        nodes.push_back(level.nodes);
        maps.push_back(BlockMatrix::node_map(level.nodes,
                                             hierarchy.block_size,
                                             level.n_unknowns));
      }
    matrices.resize(0, n_levels - 1);
    inverses.resize(0, n_levels - 1);
    operators.resize(0, n_levels - 1);
    prolongations.resize(n_levels - 1);
    restrictions.resize(n_levels - 1);
    // A is symmetric: the blocks of its transpose are its own.
    matrices[n_levels - 1] =
      BlockMatrix::transpose_of(A, maps.back(), maps.back(), true);
    for (unsigned int level = n_levels - 1; level-- > 0;)
      {
        restrictions[level] =
          BlockMatrix::transpose_of(hierarchy.levels[level].prolongation,
                                    maps[level + 1],
                                    maps[level],
                                    false);
        prolongations[level] = restrictions[level].transpose();
        matrices[level] = matrices[level + 1].galerkin(prolongations[level],
                                                       restrictions[level]);
      }
    for (unsigned int level = 0; level < n_levels; ++level)
      operators[level].matrix = &matrices[level];
    level_matrices.initialize(operators);
  }

  void
  TruncatedMultigrid::Implementation::factorise_coarsest()
  {
    // The coarsest matrix in scalar form, identity where an entry is held
    // or has no unknown (zero diagonal).
    const BlockMatrix &A0 = matrices[0];
    const Index        n  = B * A0.n_rows();
    std::vector<char>  kept(n, 0);
    double             largest = 0;
    for (Index i = 0; i < A0.n_rows(); ++i)
      largest = std::max(largest,
                         A0.diagonal_block(i).diagonal().cwiseAbs().maxCoeff());
    for (Index i = 0; i < A0.n_rows(); ++i)
      for (int c = 0; c < B; ++c)
        kept[B * i + c] = A0.diagonal_block(i)(c, c) > 1e-14 * largest &&
                          (top > 0 || mask[B * i + c] != 0);
    std::vector<Eigen::Triplet<double, Index>> entries;
    for (Index i = 0; i < A0.n_rows(); ++i)
      for (Index p = A0.row_start[i]; p < A0.row_start[i + 1]; ++p)
        for (int a = 0; a < B; ++a)
          for (int b = 0; b < B; ++b)
            {
              const Index row = B * i + a, column = B * A0.column[p] + b;
              if (kept[row] && kept[column] && A0.block(p)(a, b) != 0)
                entries.emplace_back(row, column, A0.block(p)(a, b));
            }
    for (Index i = 0; i < n; ++i)
      if (!kept[i])
        entries.emplace_back(i, i, 1.0);
    SparseMatrix coarse(n, n);
    coarse.setFromTriplets(entries.begin(), entries.end());
    coarse_factor.compute(coarse);
    // The held entries' right-hand sides are 0, so are their solutions.
  }

  void
  TruncatedMultigrid::Implementation::w_cycle(const unsigned int level)
  {
    LevelVector &x = solution[level];
    if (level == 0)
      {
        Eigen::Map<Vector>(x.begin(), x.size()) = coarse_factor.solve(
          Eigen::Map<const Vector>(defect[0].begin(), defect[0].size()));
        return;
      }
    x = 0;
    smooth(level, x, defect[level], true);
    operators[level].vmult(scratch[level], x);
    scratch[level].sadd(-1.0, 1.0, defect[level]);
    restriction(level).vmult(defect[level - 1].begin(), scratch[level].begin());
    w_cycle(level - 1);
    // The second coarse correction, on the defect the first left (the
    // coarsest level's solve is exact: once is enough there).
    if (level - 1 > 0)
      {
        first_correction[level - 1] = solution[level - 1];
        operators[level - 1].vmult(scratch[level - 1], solution[level - 1]);
        defect[level - 1] -= scratch[level - 1];
        w_cycle(level - 1);
        solution[level - 1] += first_correction[level - 1];
      }
    prolongation(level).vmult(scratch[level].begin(),
                              solution[level - 1].begin());
    x += scratch[level];
    smooth(level, x, defect[level], false);
  }

  TruncatedMultigrid::TruncatedMultigrid(const Hierarchy    &hierarchy,
                                         const SparseMatrix &A,
                                         const unsigned int  smoothing_steps,
                                         const Cycle         cycle)
    : implementation(
        std::make_unique<Implementation>(hierarchy, A, smoothing_steps, cycle))
  {}

  TruncatedMultigrid::~TruncatedMultigrid() = default;

  unsigned int
  TruncatedMultigrid::n_levels() const
  {
    return static_cast<unsigned int>(implementation->maps.size());
  }

  Index
  TruncatedMultigrid::size(const unsigned int level) const
  {
    return B * implementation->maps[level].n_nodes;
  }

  const BlockMatrix &
  TruncatedMultigrid::matrix(const unsigned int level) const
  {
    return implementation->matrices[level];
  }

  void
  TruncatedMultigrid::to_nodes(const unsigned int level,
                               const Vector      &u,
                               LevelVector       &x) const
  {
    const std::vector<Index> &nodes = implementation->nodes[level];
    const unsigned int        bs    = implementation->block_size;
    x.reinit(size(level));
    for (std::size_t k = 0; k < nodes.size(); ++k)
      if (nodes[k] >= 0)
        x[B * (k / bs) + k % bs] = u[nodes[k]];
  }

  Vector
  TruncatedMultigrid::from_nodes(const unsigned int level,
                                 const LevelVector &x) const
  {
    const std::vector<Index> &nodes = implementation->nodes[level];
    const unsigned int        bs    = implementation->block_size;
    Vector                    u(implementation->maps[level].node.size());
    for (std::size_t k = 0; k < nodes.size(); ++k)
      if (nodes[k] >= 0)
        u[nodes[k]] = x[B * (k / bs) + k % bs];
    return u;
  }

  void
  TruncatedMultigrid::prolongate(const unsigned int level,
                                 const LevelVector &coarse,
                                 LevelVector       &fine) const
  {
    fine.reinit(size(level + 1), true);
    implementation->prolongations[level].vmult(fine.begin(), coarse.begin());
  }

  void
  TruncatedMultigrid::restrict_to(const unsigned int level,
                                  const LevelVector &fine,
                                  LevelVector       &coarse) const
  {
    coarse.reinit(size(level), true);
    implementation->restrictions[level].vmult(coarse.begin(), fine.begin());
  }

  std::vector<char>
  TruncatedMultigrid::all_parents(const unsigned int       level,
                                  const std::vector<char> &flag) const
  {
    const BlockMatrix &P = implementation->prolongations[level];
    std::vector<char>  result(P.n_rows(), 0);
    for (Index i = 0; i < P.n_rows(); ++i)
      {
        result[i] = P.row_start[i] < P.row_start[i + 1];
        for (Index p = P.row_start[i]; p < P.row_start[i + 1]; ++p)
          result[i] = result[i] && flag[P.column[p]];
      }
    return result;
  }

  namespace
  {
    /// The nodes of the coarser level that @p rows of the finer level
    /// (and their neighbours in @p A) are interpolated from: the rows of
    /// P^T A P that change with those of A or of P.
    std::vector<Index>
    coarse_rows(const std::vector<Index> &rows,
                const BlockMatrix        &A,
                const BlockMatrix        &P)
    {
      std::vector<char> touched(A.n_rows(), 0), marked(P.n_columns(), 0);
      for (const Index k : rows)
        for (Index p = A.row_start[k]; p < A.row_start[k + 1]; ++p)
          touched[A.column[p]] = 1;
      std::vector<Index> result;
      for (Index i = 0; i < A.n_rows(); ++i)
        if (touched[i])
          for (Index p = P.row_start[i]; p < P.row_start[i + 1]; ++p)
            if (!marked[P.column[p]])
              {
                marked[P.column[p]] = 1;
                result.push_back(P.column[p]);
              }
      return result;
    }
  } // namespace

  void
  TruncatedMultigrid::Implementation::truncate_fully(
    const unsigned int new_top,
    const LevelVector &new_mask)
  {
    top  = new_top;
    mask = new_mask;
    for (unsigned int level = 0; level < operators.n_levels(); ++level)
      operators[level].mask = level == top ? &mask : nullptr;
    if (top > 0)
      {
        top_prolongation = prolongations[top - 1].rows_masked(mask.begin());
        top_restriction  = top_prolongation.transpose();
        matrices[top - 1] =
          matrices[top].galerkin(top_prolongation, top_restriction);
        for (unsigned int level = top - 1; level-- > 0;)
          matrices[level] = matrices[level + 1].galerkin(prolongations[level],
                                                         restrictions[level]);
      }
    for (unsigned int level = 0; level <= top; ++level)
      inverses[level].set_all(matrices[level],
                              level == top ? mask.begin() : nullptr);
    factorise_coarsest();
  }

  void
  TruncatedMultigrid::Implementation::update_truncation(
    const LevelVector &new_mask)
  {
    // The top level's nodes whose mask changed: their rows of P~ and
    // columns of P~^T, and their smoothers.
    const BlockMatrix &P =
      prolongations.empty() ? matrices[top] : prolongations[top - 1];
    std::vector<Index> changed;
    for (Index k = 0; k < matrices[top].n_rows(); ++k)
      {
        bool same = true;
        for (int c = 0; c < B; ++c)
          same = same && mask[B * k + c] == new_mask[B * k + c];
        if (same)
          continue;
        changed.push_back(k);
        for (int c = 0; c < B; ++c)
          mask[B * k + c] = new_mask[B * k + c];
        inverses[top].set(matrices[top], k, mask.begin() + B * k);
        if (top == 0)
          continue;
        const Eigen::Map<const NodeVector> m(mask.begin() + B * k);
        for (Index p = P.row_start[k]; p < P.row_start[k + 1]; ++p)
          {
            top_prolongation.set_block(p, m.asDiagonal() * P.block(p));
            top_restriction.set_block(top_restriction.position(P.column[p], k),
                                      top_prolongation.block(p).transpose());
          }
      }
    if (changed.empty())
      return;
    // The coarse levels' rows that depend on them, level by level.
    std::vector<Index> rows = changed;
    for (unsigned int level = top; level-- > 0;)
      {
        const bool         truncated_transfer = level + 1 == top;
        const BlockMatrix &Pl =
          truncated_transfer ? top_prolongation : prolongations[level];
        const BlockMatrix &Rl =
          truncated_transfer ? top_restriction : restrictions[level];
        rows = coarse_rows(rows, matrices[level + 1], Pl);
        matrices[level].galerkin_rows(matrices[level + 1], Pl, Rl, rows);
        for (const Index I : rows)
          inverses[level].set(matrices[level], I, nullptr);
      }
    factorise_coarsest();
  }

  void
  TruncatedMultigrid::truncate(const unsigned int top, const LevelVector &mask)
  {
    Implementation &mg = *implementation;
    // Within one top level only what changed is rebuilt.
    if (mg.truncated && top == mg.top)
      mg.update_truncation(mask);
    else
      {
        mg.truncate_fully(top, mask);
        mg.multigrid.reset();
        mg.pre      = std::make_unique<Smoother>(mg, true);
        mg.post     = std::make_unique<Smoother>(mg, false);
        mg.transfer = std::make_unique<Transfer>(mg);
        mg.coarse   = std::make_unique<CoarseSolve>(mg);
        mg.multigrid =
          std::make_unique<dealii::Multigrid<LevelVector>>(mg.level_matrices,
                                                           *mg.coarse,
                                                           *mg.transfer,
                                                           *mg.pre,
                                                           *mg.post,
                                                           0,
                                                           top);
        for (unsigned int level = 0; level <= top; ++level)
          mg.multigrid->defect[level].reinit(size(level));
        for (auto *vectors :
             {&mg.defect, &mg.solution, &mg.scratch, &mg.first_correction})
          {
            vectors->resize(top + 1);
            for (unsigned int level = 0; level <= top; ++level)
              (*vectors)[level].reinit(size(level));
          }
      }
    mg.truncated = true;
  }

  void
  TruncatedMultigrid::vmult(LevelVector &y, const LevelVector &x) const
  {
    implementation->operators[implementation->top].vmult(y, x);
  }

  unsigned int
  TruncatedMultigrid::solve(LevelVector       &d,
                            const LevelVector &r,
                            const double       reduction,
                            const unsigned int max_cycles)
  {
    Implementation      &mg = *implementation;
    const Preconditioner cycle(mg);

    dealii::ReductionControl      control(max_cycles, 1e-300, reduction);
    dealii::SolverCG<LevelVector> cg(control);
    d.reinit(r.size());
    try
      {
        cg.solve(mg.operators[mg.top], d, r, cycle);
      }
    catch (const dealii::SolverControl::NoConvergence &)
      {
        // The cycles allowed are spent: d is the last iterate, which the
        // caller's line search takes as far as it goes.
      }
    return cycle.cycles;
  }
} // namespace unilateral::lcp
