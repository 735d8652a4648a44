#include <unilateral/base/blas_threads.h>
#include <unilateral/lcp/supernodal_factorisation.h>

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <new>
#include <system_error>
#include <thread>

extern "C"
{
  void
  dsyrk_(const char   *uplo,
         const char   *trans,
         const int    *n,
         const int    *k,
         const double *alpha,
         const double *a,
         const int    *lda,
         const double *beta,
         double       *c,
         const int    *ldc);
  void
  dgemm_(const char   *transa,
         const char   *transb,
         const int    *m,
         const int    *n,
         const int    *k,
         const double *alpha,
         const double *a,
         const int    *lda,
         const double *b,
         const int    *ldb,
         const double *beta,
         double       *c,
         const int    *ldc);
  void
  dpotrf_(const char *uplo, const int *n, double *a, const int *lda, int *info);
  void
  dtrsv_(const char   *uplo,
         const char   *trans,
         const char   *diag,
         const int    *n,
         const double *a,
         const int    *lda,
         double       *x,
         const int    *incx);
  void
  dgemv_(const char   *trans,
         const int    *m,
         const int    *n,
         const double *alpha,
         const double *a,
         const int    *lda,
         const double *x,
         const int    *incx,
         const double *beta,
         double       *y,
         const int    *incy);
  void
  dtrsm_(const char   *side,
         const char   *uplo,
         const char   *transa,
         const char   *diag,
         const int    *m,
         const int    *n,
         const double *alpha,
         const double *a,
         const int    *lda,
         double       *b,
         const int    *ldb);
}

namespace unilateral::lcp
{
  namespace
  {
    /// Supernode s of a factor: its columns k1, k1 + 1, ..., its rows
    /// (the first n_cols are its columns) and its block of L (column-major,
    /// n_rows x n_cols; null in a symbolic factor).
    struct Supernode
    {
      Supernode(const cholmod_factor &L, const Index s)
      {
        const auto *super = static_cast<const Index *>(L.super);
        const auto *pi    = static_cast<const Index *>(L.pi);
        const auto *px    = static_cast<const Index *>(L.px);
        k1                = super[s];
        n_cols            = super[s + 1] - k1;
        n_rows            = pi[s + 1] - pi[s];
        rows_below        = n_rows - n_cols;
        rows              = static_cast<const Index *>(L.s) + pi[s];
        block = L.x != nullptr ? static_cast<double *>(L.x) + px[s] : nullptr;
      }
      Index        k1;
      int          n_cols, n_rows, rows_below;
      const Index *rows;
      double      *block;
    };

    /// The most rows of a supernode of @p L.
    Index
    most_rows(const cholmod_factor &L)
    {
      const auto *pi   = static_cast<const Index *>(L.pi);
      Index       most = 0;
      for (std::size_t s = 0; s < L.nsuper; ++s)
        most = std::max(most, pi[s + 1] - pi[s]);
      return most;
    }

    /// Run task(t) for t = 0, ..., n - 1 at the same time, task(0) on this
    /// thread, each with one BLAS thread; those no thread can be started
    /// for run on this thread after its own.
    template <typename Task>
    void
    on_threads(const unsigned int n, const Task &task)
    {
      blas::ScopedThreads      one_blas_thread(1);
      std::vector<std::thread> others;
      unsigned int             started = 1;
      try
        {
          for (; started < n; ++started)
            others.emplace_back(task, started);
        }
      catch (const std::system_error &)
        {}
      task(0);
      for (unsigned int t = started; t < n; ++t)
        task(t);
      for (auto &other : others)
        other.join();
    }

    /**
     * What one thread needs to factorise supernodes (CHOLMOD's workspace of
     * cholmod_super_numeric, one per thread): the position of each row in
     * the current supernode, the update buffer, and the lists of
     * descendants waiting to update each supernode. The descendants' next
     * row (position) and list links (next) are shared: a supernode belongs
     * to one thread until its subtree is done.
     */
    class Worker
    {
    public:
      Worker(const cholmod_sparse     &A,
             cholmod_factor           &L,
             const std::vector<Index> &supernode_of_column,
             std::vector<Index>       &position,
             std::vector<Index>       &next,
             const std::atomic<bool>  &stop,
             const std::size_t         update_size)
        : A(A)
        , L(L)
        , supernode_of_column(supernode_of_column)
        , position(position)
        , next(next)
        , stop(stop)
        , row_in_supernode(L.n, -1)
        , update(update_size)
        , head(L.nsuper, -1)
      {
        relative_row.resize(most_rows(L));
      }

      /// Factorise supernodes first to last; false where one is not
      /// positive definite (failed_column) or another thread failed.
      bool
      factorise(const Index first, const Index last)
      {
        for (Index s = first; s <= last; ++s)
          if (stop.load(std::memory_order_relaxed) || !factorise(s))
            return false;
        return true;
      }

      /// cholmod_super_numeric's steps for supernode s: its columns of A,
      /// minus its descendants' updates, factorised.
      bool
      factorise(const Index s)
      {
        const Supernode sn(L, s);
        assemble(sn);
        subtract_descendants(sn, s);
        head[s] = -1;
        return factorise_block(sn, s);
      }

      /// Take over another thread's waiting descendants of supernode s.
      void
      adopt_waiting(const Worker &other, const Index s)
      {
        Index d = other.head[s];
        if (d == -1)
          return;
        Index last = d;
        while (next[last] != -1)
          last = next[last];
        next[last] = head[s];
        head[s]    = d;
      }

      /// The first column that was not positive definite, or -1.
      Index failed_column = -1;

    private:
      const cholmod_sparse     &A;
      cholmod_factor           &L;
      const std::vector<Index> &supernode_of_column;
      std::vector<Index>       &position;
      std::vector<Index>       &next;
      const std::atomic<bool>  &stop;
      std::vector<Index>        row_in_supernode;
      std::vector<Index>        relative_row;
      std::vector<double>       update;
      std::vector<Index>        head;

      void
      assemble(const Supernode &sn);

      void
      subtract_descendants(const Supernode &sn, Index s);

      bool
      factorise_block(const Supernode &sn, Index s);
    };

    void
    Worker::assemble(const Supernode &sn)
    {
      const auto *Ap = static_cast<const Index *>(A.p);
      const auto *Ai = static_cast<const Index *>(A.i);
      const auto *Ax = static_cast<const double *>(A.x);
      std::fill(sn.block,
                sn.block + static_cast<std::size_t>(sn.n_rows) * sn.n_cols,
                0.0);
      for (Index k = 0; k < sn.n_rows; ++k)
        row_in_supernode[sn.rows[k]] = k;
      for (Index k = sn.k1; k < sn.k1 + sn.n_cols; ++k)
        for (Index p = Ap[k]; p < Ap[k + 1]; ++p)
          if (Ai[p] >= k)
            {
              const Index local = row_in_supernode[Ai[p]];
              if (local >= 0 && local < sn.n_rows)
                sn.block[local + static_cast<std::size_t>(k - sn.k1) *
                                   sn.n_rows] = Ax[p];
            }
    }

    /// The update of each descendant d waiting for the supernode: d's rows
    /// from position[d] on times its rows among the supernode's columns.
    /// Then d waits for the supernode of its first row below them.
    void
    Worker::subtract_descendants(const Supernode &sn, const Index s)
    {
      const double one  = 1;
      const double zero = 0;
      const Index  k2   = sn.k1 + sn.n_cols;
      for (Index d = head[s], d_next; d != -1; d = d_next)
        {
          d_next = next[d];
          const Supernode dn(L, d);
          const Index    *d_rows    = dn.rows + position[d];
          int             rows_in_s = 0;
          while (position[d] + rows_in_s < dn.n_rows && d_rows[rows_in_s] < k2)
            ++rows_in_s;
          const int     rows_below  = dn.n_rows - position[d];
          const int     rows_beyond = rows_below - rows_in_s;
          const double *L1          = dn.block + position[d];
          dsyrk_("L",
                 "N",
                 &rows_in_s,
                 &dn.n_cols,
                 &one,
                 L1,
                 &dn.n_rows,
                 &zero,
                 update.data(),
                 &rows_below);
          if (rows_beyond > 0)
            dgemm_("N",
                   "C",
                   &rows_beyond,
                   &rows_in_s,
                   &dn.n_cols,
                   &one,
                   L1 + rows_in_s,
                   &dn.n_rows,
                   L1,
                   &dn.n_rows,
                   &zero,
                   update.data() + rows_in_s,
                   &rows_below);
          for (int i = 0; i < rows_below; ++i)
            relative_row[i] = row_in_supernode[d_rows[i]];
          for (int j = 0; j < rows_in_s; ++j)
            {
              double *const column =
                sn.block +
                static_cast<std::size_t>(relative_row[j]) * sn.n_rows;
              const double *const c =
                update.data() + static_cast<std::size_t>(j) * rows_below;
              for (int i = j; i < rows_below; ++i)
                column[relative_row[i]] -= c[i];
            }
          position[d] += rows_in_s;
          if (rows_beyond > 0)
            {
              const Index ancestor = supernode_of_column[d_rows[rows_in_s]];
              next[d]              = head[ancestor];
              head[ancestor]       = d;
            }
        }
    }

    /// L1 L1' = the diagonal block, L2 = the rows below times L1^-T; then
    /// the supernode waits for its parent.
    bool
    Worker::factorise_block(const Supernode &sn, const Index s)
    {
      const double one  = 1;
      int          info = 0;
      dpotrf_("L", &sn.n_cols, sn.block, &sn.n_rows, &info);
      if (info != 0)
        {
          failed_column = sn.k1 + info - 1;
          return false;
        }
      if (sn.rows_below > 0)
        {
          dtrsm_("R",
                 "L",
                 "C",
                 "N",
                 &sn.rows_below,
                 &sn.n_cols,
                 &one,
                 sn.block,
                 &sn.n_rows,
                 sn.block + sn.n_cols,
                 &sn.n_rows);
          position[s]        = sn.n_cols;
          const Index parent = supernode_of_column[sn.rows[sn.n_cols]];
          next[s]            = head[parent];
          head[parent]       = s;
        }
      return true;
    }

    /**
     * The supernodal elimination tree of an analysed factor: each
     * supernode's parent (-1 at a root), its work (the updates of its
     * columns, the squares of their lengths below the diagonal), and its
     * subtree's work and first supernode. CHOLMOD postorders the tree, so
     * a subtree is a range of supernodes; postordered says it is.
     */
    struct EliminationTree
    {
      EliminationTree(const cholmod_factor     &L,
                      const std::vector<Index> &supernode_of_column)
        : parent(L.nsuper, -1)
        , first(L.nsuper)
        , work(L.nsuper, 0.0)
        , children(L.nsuper)
      {
        const auto         n_super = static_cast<Index>(L.nsuper);
        std::vector<Index> size(n_super, 1);
        for (Index s = 0; s < n_super; ++s)
          {
            const Supernode sn(L, s);
            for (Index t = 0; t < sn.n_cols; ++t)
              work[s] += static_cast<double>(sn.n_rows - t) * (sn.n_rows - t);
            if (sn.rows_below > 0)
              parent[s] = supernode_of_column[sn.rows[sn.n_cols]];
            first[s] = s;
            total_work += work[s];
          }
        subtree_work = work;
        for (Index s = 0; s < n_super; ++s)
          {
            const Index p = parent[s];
            if (p == -1)
              roots.push_back(s);
            else if (p <= s)
              return; // not postordered
            else
              {
                children[p].push_back(s);
                subtree_work[p] += subtree_work[s];
                first[p] = std::min(first[p], first[s]);
                size[p] += size[s];
              }
          }
        for (Index s = 0; s < n_super; ++s)
          if (size[s] != s - first[s] + 1)
            return;
        postordered = true;
      }

      std::vector<Index>              parent, first, roots;
      std::vector<double>             work, subtree_work;
      std::vector<std::vector<Index>> children;
      double                          total_work  = 0;
      bool                            postordered = false;
    };

    /// Shares of whole subtrees (their roots), one per thread, and the
    /// supernodes above them, with the time they take: the largest share
    /// plus the rest.
    struct Split
    {
      std::vector<std::vector<Index>> share;
      std::vector<char>               above;
      double                          time;
    };

    /**
     * Open the largest subtree into its children (its root then runs after
     * the threads) while that lowers the time of the split into
     * @p n_threads shares, the subtrees dealt largest first into the
     * lightest share; at most 256 openings.
     */
    Split
    choose_split(const EliminationTree &tree, const unsigned int n_threads)
    {
      std::vector<Index> candidates = tree.roots;
      std::vector<char>  above(tree.parent.size(), 0);
      double             above_work = 0;
      Split              best;
      best.time = tree.total_work;
      for (unsigned int opened = 0; opened < 256; ++opened)
        {
          std::sort(candidates.begin(),
                    candidates.end(),
                    [&](const Index a, const Index b) {
                      return tree.subtree_work[a] > tree.subtree_work[b];
                    });
          Split               split;
          std::vector<double> share_work(n_threads, 0.0);
          split.share.resize(n_threads);
          for (const Index c : candidates)
            {
              const auto lightest =
                std::min_element(share_work.begin(), share_work.end()) -
                share_work.begin();
              share_work[lightest] += tree.subtree_work[c];
              split.share[lightest].push_back(c);
            }
          split.time = *std::max_element(share_work.begin(), share_work.end()) +
                       above_work;
          if (split.time < best.time)
            {
              split.above = above;
              best        = std::move(split);
            }
          const auto widest =
            std::find_if(candidates.begin(), candidates.end(), [&](Index c) {
              return !tree.children[c].empty();
            });
          if (widest == candidates.end() || above_work >= best.time)
            break;
          const Index opened_root = *widest;
          candidates.erase(widest);
          above[opened_root] = 1;
          above_work += tree.work[opened_root];
          candidates.insert(candidates.end(),
                            tree.children[opened_root].begin(),
                            tree.children[opened_root].end());
        }
      return best;
    }
  } // namespace

  void
  SupernodalFactorisation::plan(const cholmod_factor &L,
                                const double          minimum_flops,
                                const unsigned int    n_threads)
  {
    supernode_of_column.clear();
    shares.clear();
    ancestors.clear();
    place_among_ancestors.clear();
    n_ancestor_columns = 0;
    if (!L.is_super || L.nsuper < 2 || n_threads < 2)
      return;
    const auto  n_super = static_cast<Index>(L.nsuper);
    const auto *super   = static_cast<const Index *>(L.super);
    supernode_of_column.resize(L.n);
    for (Index s = 0; s < n_super; ++s)
      std::fill(supernode_of_column.begin() + super[s],
                supernode_of_column.begin() + super[s + 1],
                s);

    const EliminationTree tree(L, supernode_of_column);
    if (!tree.postordered || tree.total_work < minimum_flops)
      {
        supernode_of_column.clear();
        return;
      }
    const Split split = choose_split(tree, n_threads);
    if (split.time > 0.9 * tree.total_work)
      {
        supernode_of_column.clear();
        return;
      }
    for (const auto &share : split.share)
      if (!share.empty())
        {
          shares.emplace_back();
          for (const Index c : share)
            shares.back().emplace_back(tree.first[c], c);
        }
    place_among_ancestors.assign(L.n, -1);
    for (Index s = 0; s < n_super; ++s)
      if (split.above[s])
        {
          ancestors.push_back(s);
          for (Index k = super[s]; k < super[s + 1]; ++k)
            place_among_ancestors[k] = n_ancestor_columns++;
        }
  }

  bool
  SupernodalFactorisation::splits() const
  {
    return shares.size() >= 2;
  }

  namespace
  {
    /// The update buffer a thread needs for @p ranges of supernodes alone
    /// (the first thread, which also factorises the ancestors, needs
    /// CHOLMOD's largest, L.maxcsize): a descendant's update of a
    /// supernode has at most its rows squared entries.
    std::size_t
    update_size(const cholmod_factor                       &L,
                const std::vector<std::pair<Index, Index>> &ranges)
    {
      std::size_t largest = 0;
      for (const auto &[first, last] : ranges)
        for (Index s = first; s <= last; ++s)
          {
            const auto rows = static_cast<std::size_t>(Supernode(L, s).n_rows);
            largest         = std::max(largest, rows * rows);
          }
      return std::min<std::size_t>(largest, L.maxcsize);
    }
  } // namespace

  void
  SupernodalFactorisation::numeric(const cholmod_sparse &A,
                                   cholmod_factor       &L,
                                   cholmod_common       &common) const
  {
    common.status = CHOLMOD_OK;
    if (L.xtype == CHOLMOD_PATTERN &&
        !cholmod_change_factor(CHOLMOD_REAL, 1, 1, 1, 1, &L, &common))
      return; // status says why (out of memory)
    L.is_ll = 1;
    try
      {
        std::vector<Index>  position(L.nsuper, 0), next(L.nsuper, -1);
        std::atomic<bool>   stop{false};
        std::vector<Worker> workers;
        workers.reserve(shares.size());
        for (std::size_t t = 0; t < shares.size(); ++t)
          workers.emplace_back(A,
                               L,
                               supernode_of_column,
                               position,
                               next,
                               stop,
                               t == 0 ? L.maxcsize : update_size(L, shares[t]));
        on_threads(shares.size(), [&](const unsigned int t) {
          for (const auto &[first, last] : shares[t])
            if (!workers[t].factorise(first, last))
              {
                stop = true;
                return;
              }
        });
        if (!stop)
          for (const Index s : ancestors)
            {
              for (std::size_t t = 1; t < workers.size(); ++t)
                workers[0].adopt_waiting(workers[t], s);
              if (!workers[0].factorise(s))
                break;
            }
        Index failed = L.n;
        for (const Worker &w : workers)
          if (w.failed_column >= 0)
            failed = std::min(failed, w.failed_column);
        L.minor = failed;
        if (failed < static_cast<Index>(L.n))
          common.status = CHOLMOD_NOT_POSDEF;
      }
    catch (const std::bad_alloc &)
      {
        common.status = CHOLMOD_OUT_OF_MEMORY;
      }
  }

  namespace
  {
    /**
     * Substitution with the supernodes of a factor: forward (L y = b) adds
     * each supernode's updates of the rows below it into y, or, for the
     * rows of common ancestors while the threads run, into the thread's own
     * updates (summed into y before the ancestors are substituted);
     * backward (L' x = y) reads only rows below, already final.
     */
    class Substitution
    {
    public:
      Substitution(const cholmod_factor     &L,
                   std::vector<double>      &y,
                   const std::vector<Index> *place_among_ancestors,
                   const Index               n_ancestor_columns)
        : L(L)
        , y(y)
        , place_among_ancestors(place_among_ancestors)
        , ancestor_update(place_among_ancestors ? n_ancestor_columns : 0, 0.0)
      {
        below.resize(most_rows(L));
      }

      void
      forward(const Index s)
      {
        const Supernode sn(L, s);
        dtrsv_(
          "L", "N", "N", &sn.n_cols, sn.block, &sn.n_rows, &y[sn.k1], &one);
        if (sn.rows_below == 0)
          return;
        dgemv_("N",
               &sn.rows_below,
               &sn.n_cols,
               &plus,
               sn.block + sn.n_cols,
               &sn.n_rows,
               &y[sn.k1],
               &one,
               &nought,
               below.data(),
               &one);
        for (int i = 0; i < sn.rows_below; ++i)
          {
            const Index row = sn.rows[sn.n_cols + i];
            const Index a =
              place_among_ancestors ? (*place_among_ancestors)[row] : -1;
            (a >= 0 ? ancestor_update[a] : y[row]) -= below[i];
          }
      }

      void
      backward(const Index s)
      {
        const Supernode sn(L, s);
        if (sn.rows_below > 0)
          {
            for (int i = 0; i < sn.rows_below; ++i)
              below[i] = y[sn.rows[sn.n_cols + i]];
            dgemv_("T",
                   &sn.rows_below,
                   &sn.n_cols,
                   &minus,
                   sn.block + sn.n_cols,
                   &sn.n_rows,
                   below.data(),
                   &one,
                   &plus,
                   &y[sn.k1],
                   &one);
          }
        dtrsv_(
          "L", "T", "N", &sn.n_cols, sn.block, &sn.n_rows, &y[sn.k1], &one);
      }

      /// This thread's updates of the ancestors' rows.
      const std::vector<double> &
      ancestor_updates() const
      {
        return ancestor_update;
      }

    private:
      static constexpr int    one    = 1;
      static constexpr double plus   = 1;
      static constexpr double minus  = -1;
      static constexpr double nought = 0;

      const cholmod_factor     &L;
      std::vector<double>      &y;
      const std::vector<Index> *place_among_ancestors;
      std::vector<double>       ancestor_update;
      std::vector<double>       below;
    };
  } // namespace

  void
  SupernodalFactorisation::solve(const cholmod_factor &L,
                                 const double         *b,
                                 double               *x) const
  {
    const auto         *perm = static_cast<const Index *>(L.Perm);
    const Index         n    = L.n;
    std::vector<double> y(n);
    for (Index k = 0; k < n; ++k)
      y[k] = b[perm[k]];
    std::vector<Substitution> threads;
    threads.reserve(shares.size());
    for (std::size_t t = 0; t < shares.size(); ++t)
      threads.emplace_back(L, y, &place_among_ancestors, n_ancestor_columns);
    const auto substitute_subtrees = [&](const bool forward) {
      on_threads(shares.size(), [&](const unsigned int t) {
        for (const auto &[first, last] : shares[t])
          if (forward)
            for (Index s = first; s <= last; ++s)
              threads[t].forward(s);
          else
            for (Index s = last; s >= first; --s)
              threads[t].backward(s);
      });
    };

    substitute_subtrees(true);
    const auto *super = static_cast<const Index *>(L.super);
    for (const Index s : ancestors)
      for (Index k = super[s]; k < super[s + 1]; ++k)
        for (const Substitution &thread : threads)
          y[k] += thread.ancestor_updates()[place_among_ancestors[k]];
    Substitution above(L, y, nullptr, 0);
    for (const Index s : ancestors)
      above.forward(s);
    for (auto s = ancestors.rbegin(); s != ancestors.rend(); ++s)
      above.backward(*s);
    substitute_subtrees(false);
    for (Index k = 0; k < n; ++k)
      x[perm[k]] = y[k];
  }
} // namespace unilateral::lcp
