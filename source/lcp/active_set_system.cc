#include <unilateral/base/memory.h>
#include <unilateral/lcp/active_set_system.h>
#include <unilateral/lcp/problem.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

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

    /// A_{:,J} Y_J for the columns J = {j : fixed[j] == of_fixed}: the
    /// coupling of the fixed values, or A on the free part. A loop over J
    /// alone instead of Eigen's product of a sparse and a dynamic-width
    /// dense matrix, which multiplies every column, the zeros of Y outside
    /// J included (what that cost on the walls:
    /// benchmarks/masonry_tables/README.md, "Design measurements").
    DenseMatrix
    multiply_columns(const SparseMatrix      &A,
                     const std::vector<char> &fixed,
                     const bool               of_fixed,
                     const DenseMatrix       &Y)
    {
      DenseMatrix         result       = DenseMatrix::Zero(A.rows(), Y.cols());
      const auto *const   column_start = A.outerIndexPtr();
      const auto *const   row          = A.innerIndexPtr();
      const double *const value        = A.valuePtr();
      for (Index column = 0; column < Y.cols(); ++column)
        {
          double *const       out = result.col(column).data();
          const double *const y   = Y.col(column).data();
          for (Index j = 0; j < A.outerSize(); ++j)
            if (static_cast<bool>(fixed[j]) == of_fixed && y[j] != 0)
              for (Index k = column_start[j]; k < column_start[j + 1]; ++k)
                out[row[k]] += value[k] * y[j];
        }
      return result;
    }

    /// @p result = A_FF + shift I, F the indices whose @p reduced_index is
    /// not -1 (n_free of them, numbered by it), or its upper triangle alone
    /// if @p upper_only. Written straight into compressed storage, column by
    /// column: the map i -> reduced_index[i] is increasing, so every column
    /// stays sorted. (Eigen's insert() reallocates as it goes, which makes
    /// the assembly quadratic in the size: benchmarks/README.md, "What
    /// looked wrong", item 1.)
    void
    free_block(const SparseMatrix       &A,
               const std::vector<Index> &reduced_index,
               const Index               n_free,
               const double              shift,
               const bool                upper_only,
               SparseMatrix             &result)
    {
      const auto kept = [&](const Index row, const Index column) {
        return reduced_index[row] >= 0 && (!upper_only || row <= column);
      };
      Index n_entries = 0;
      for (Index j = 0; j < A.cols(); ++j)
        if (reduced_index[j] >= 0)
          for (SparseMatrix::InnerIterator it(A, j); it; ++it)
            n_entries += kept(it.row(), j);
      result = SparseMatrix(n_free, n_free);
      result.resizeNonZeros(n_entries);
      auto *const   column_start = result.outerIndexPtr();
      auto *const   row_index    = result.innerIndexPtr();
      double *const value        = result.valuePtr();
      Index         entry        = 0;
      column_start[0]            = 0;
      for (Index j = 0; j < A.cols(); ++j)
        if (reduced_index[j] >= 0)
          {
            for (SparseMatrix::InnerIterator it(A, j); it; ++it)
              if (kept(it.row(), j))
                {
                  row_index[entry] = static_cast<SparseMatrix::StorageIndex>(
                    reduced_index[it.row()]);
                  value[entry] = it.value() + (it.row() == j ? shift : 0.0);
                  ++entry;
                }
            column_start[reduced_index[j] + 1] =
              static_cast<SparseMatrix::StorageIndex>(entry);
          }
    }

    /// Memory of the simplicial copy that row modifications work on, for a
    /// factor of @p factor_nonzeros entries: values and row indices, the
    /// copy's room to grow, and the supernodal copy it is converted from,
    /// about 24 bytes per entry.
    double
    modification_copy_bytes(const double factor_nonzeros)
    {
      return 24 * factor_nonzeros;
    }
  } // namespace

  ActiveSetSystem::ActiveSetSystem(
    const SparseMatrix                    &A,
    Counters                              &counters,
    std::shared_ptr<const ActiveSetFactor> inherited)
    : A(A)
    , counters(counters)
    , own(std::make_shared<ActiveSetFactor>())
    , inherited(std::move(inherited))
  {
    // A_FF must hold every body: a numerically singular factor is refused.
    own->cholesky.minimum_rcond = 1e-14;
    const double mean           = diagonal_scale(A);
    fixed_diagonal              = A.diagonal();
    for (Index i = 0; i < fixed_diagonal.size(); ++i)
      if (!(fixed_diagonal[i] > 0))
        fixed_diagonal[i] = mean;
    // A stage after another on the same pattern (the projection after the
    // regularised solve: A instead of A + eps I, or after an interior point)
    // orders it only once.
    if (this->inherited &&
        this->inherited->ordering_of_A.size() == std::size_t(A.rows()))
      full_ordering = this->inherited->ordering_of_A;
    if (this->inherited && this->inherited->analysis_only)
      analysis_of_A = this->inherited;
    // Only a factor of this A's size can precondition (an ordering or an
    // analysis alone, or a factor that failed, cannot).
    if (this->inherited &&
        (this->inherited->fixed.size() != std::size_t(A.rows()) ||
         !this->inherited->cholesky.has_factor()))
      this->inherited.reset();
    if (this->inherited && !this->inherited->reduced_index.empty())
      reduced_factor_flops = this->inherited->cholesky.factorisation_flops();
  }

  std::shared_ptr<const ActiveSetFactor>
  ActiveSetFactor::analysis_of(SparseCholesky &analysed)
  {
    auto hint           = std::make_shared<ActiveSetFactor>();
    hint->ordering_of_A = analysed.ordering();
    hint->cholesky.take_analysis_from(analysed);
    hint->analysis_only = true;
    return hint;
  }

  void
  ActiveSetSystem::order_once()
  {
    if (!full_ordering.empty())
      return;
    full_ordering      = SparseCholesky::amd_ordering(A, counters);
    own->ordering_of_A = full_ordering;
  }

  std::shared_ptr<const ActiveSetFactor>
  ActiveSetSystem::factor() const
  {
    if (own_valid)
      return own;
    return inherited;
  }

  void
  ActiveSetFactor::solve(const DenseMatrix &B, DenseMatrix &X) const
  {
    if (reduced_index.empty())
      {
        cholesky.solve(B, X);
        return;
      }
    const Index n = static_cast<Index>(fixed.size());
    DenseMatrix B_free(n_free, B.cols()), X_free;
    for (Index i = 0; i < n; ++i)
      if (reduced_index[i] >= 0)
        B_free.row(reduced_index[i]) = B.row(i);
    cholesky.solve(B_free, X_free);
    X.resize(n, B.cols());
    for (Index i = 0; i < n; ++i)
      if (reduced_index[i] >= 0)
        X.row(i) = X_free.row(reduced_index[i]);
      else
        X.row(i) = B.row(i) / fixed_diagonal[i];
  }

  bool
  ActiveSetFactor::inverse_gram(const SparseMatrix &B, DenseMatrix &G) const
  {
    // B in the rows of the factorised matrix (those of A for the full
    // pattern, of A_FF for a reduced one).
    std::vector<Eigen::Triplet<double, Index>> entries;
    entries.reserve(B.nonZeros());
    for (Index c = 0; c < B.outerSize(); ++c)
      for (SparseMatrix::InnerIterator it(B, c); it; ++it)
        {
          if (fixed[it.row()])
            throw std::logic_error("ActiveSetFactor::inverse_gram: B has an "
                                   "entry on a fixed row");
          if (!reduced_index.empty())
            entries.emplace_back(reduced_index[it.row()], c, it.value());
        }
    if (reduced_index.empty())
      return cholesky.inverse_gram(B, G);
    SparseMatrix B_free(n_free, B.cols());
    B_free.setFromTriplets(entries.begin(), entries.end());
    return cholesky.inverse_gram(B_free, G);
  }

  bool
  ActiveSetSystem::factorise(const std::vector<char> &fixed, const double shift)
  {
    const Index n       = A.rows();
    Index       n_fixed = 0;
    for (const char f : fixed)
      n_fixed += f;

    const bool settling = active_set_settling(fixed);
    // An analysis of A's full pattern handed over by the stage before (the
    // interior point's Newton matrix) makes the full pattern the cheaper
    // way while at least half the unknowns are free: each A_FF would need
    // a symbolic pass and a copy of its pattern
    // (benchmarks/masonry_tables/README.md, "Design measurements").
    const bool mostly_free   = n_fixed <= taken_analysis_threshold * n;
    const bool take_analysis = mostly_free && analysis_of_A != nullptr &&
                               analysis_of_A.use_count() == 1 &&
                               !own->cholesky.distributed();
    // A distributed factorisation always takes the full pattern: its
    // symbolic analysis (a parallel ordering over all ranks) is then run
    // once for every active set.
    const bool full_pattern = n_fixed <= reduced_threshold * n || settling ||
                              own->cholesky.distributed() || take_analysis ||
                              (took_analysis_of_A && mostly_free);
    if (take_analysis)
      {
        // Made non-const by its owner, held by no one else: taking its
        // storage changes nothing anyone can see.
        own->cholesky.take_analysis_from(
          const_cast<ActiveSetFactor &>(*analysis_of_A).cholesky);
        took_analysis_of_A = true;
      }
    analysis_of_A.reset();
    // An inherited factor of the full pattern that no one else holds (the
    // regularised solve's, handed to the projection) lends its analysis
    // and memory to ours: the same pattern, so no new analysis and no
    // fresh pages. It was made non-const by its owner and is about to be
    // dropped, so taking its storage changes nothing anyone can see.
    if (full_pattern && inherited != nullptr && inherited.use_count() == 1 &&
        inherited->reduced_index.empty())
      own->cholesky.take_analysis_from(
        const_cast<ActiveSetFactor &>(*inherited).cholesky);
    own->fixed          = fixed;
    own->fixed_diagonal = fixed_diagonal;
    inherited.reset(); // our own factor is closer from now on

    if (full_pattern)
      {
        // The full pattern: zero the coupling of fixed indices, keep a
        // scaled identity on their diagonal (the conditioning of A).
        own->reduced_index.clear();
        own->n_free = n - n_fixed;
        // This factor may be modified row by row (modify_factor): CHOLMOD's
        // own supernodes, as in the interior point's analysis taken over.
        own->cholesky.relaxed_supernodes = false;
        // The one AMD ordering of A serves both ways of factorising: an
        // analysis that orders A again would repeat the ordering of the
        // whole matrix (benchmarks/masonry_tables/README.md, "Design
        // measurements").
        order_once();
        own_valid = own->cholesky.factorise_with_fixed(
          A, fixed, fixed_diagonal, shift, full_ordering, counters);
        // The first factorisation of the full pattern taken for a settling
        // set (A_FF would have been taken otherwise) shows what it costs
        // against A_FF alone.
        if (own_valid && settling && n_fixed > reduced_threshold * n &&
            reduced_factor_flops > 0 &&
            own->cholesky.factorisation_flops() >
              full_pattern_allowance * reduced_factor_flops)
          full_pattern_pays = false;
        return own_valid;
      }

    // A_FF on its own, in the ordering of A restricted to F.
    order_once();
    own->reduced_index.assign(n, -1);
    Index n_free = 0;
    for (Index i = 0; i < n; ++i)
      if (!fixed[i])
        own->reduced_index[i] = n_free++;
    own->n_free = n_free;

    std::vector<Index> ordering;
    ordering.reserve(n_free);
    for (const Index old_index : full_ordering)
      if (!fixed[old_index])
        ordering.push_back(own->reduced_index[old_index]);

    // Its upper triangle alone where CHOLMOD factorises it (MUMPS takes
    // both): half the memory, and CHOLMOD's factorisation, which permutes
    // the whole matrix it is given, no longer passes over the lower half
    // only to skip it (stack bond m = 225: 0.42 -> 0.31 s in 4 calls).
    // A copy for this factorisation alone: CHOLMOD keeps none of it.
    SparseMatrix free_part;
    free_block(A,
               own->reduced_index,
               n_free,
               shift,
               !own->cholesky.distributed(),
               free_part);
    own->cholesky.relaxed_supernodes = true;  // never modified
    took_analysis_of_A               = false; // A_FF's analysis replaces it
    own_valid = own->cholesky.factorise(free_part, ordering, counters);
    if (own_valid)
      reduced_factor_flops = own->cholesky.factorisation_flops();
    return own_valid;
  }

  bool
  ActiveSetSystem::active_set_settling(const std::vector<char> &fixed) const
  {
    const ActiveSetFactor *nearest = own_valid ? own.get() : inherited.get();
    if (!full_pattern_pays || nearest == nullptr ||
        nearest->fixed.size() != fixed.size())
      return false;
    const double changes = count_changes(nearest->fixed, fixed);
    if (changes > settling_fraction * static_cast<double>(fixed.size()))
      return false;
    // The full pattern's factor is larger than A_FF's, and the row
    // modifications it is made for need a copy of it: on the largest
    // problems the smaller factor is what fits. The estimate: the copy of
    // a factor up to twice the nearest one's, twice over as
    // room_for_modified_copy asks. (The nearest factor exists: own_valid,
    // and an inherited factor is kept only with one.)
    return memory::fits(2 * modification_copy_bytes(
                              2 * nearest->cholesky.factor_nonzeros()),
                        false);
  }

  bool
  ActiveSetSystem::room_for_modified_copy() const
  {
    if (own->cholesky.has_modification_copy())
      return true;
    return memory::fits(
      2 * modification_copy_bytes(own->cholesky.factor_nonzeros()), true);
  }

  bool
  ActiveSetSystem::modify_factor(const std::vector<char> &fixed)
  {
    if (!own_valid || !own->reduced_index.empty() ||
        own->cholesky.distributed() || !room_for_modified_copy())
      return false;
    std::vector<Index> newly_fixed, newly_free;
    for (std::size_t i = 0; i < fixed.size(); ++i)
      if (fixed[i] && !own->fixed[i])
        newly_fixed.push_back(static_cast<Index>(i));
      else if (!fixed[i] && own->fixed[i])
        newly_free.push_back(static_cast<Index>(i));
    std::vector<Index> changed = newly_fixed;
    changed.insert(changed.end(), newly_free.begin(), newly_free.end());
    // The cost is predicted from the factor's structure before anything is
    // copied or modified: the first modification converts the factor, which
    // on a large factor is itself expensive and wasted if the update is then
    // abandoned (benchmarks/plate_tables/README.md, "Design measurements").
    const double budget =
      modification_budget * own->cholesky.factorisation_flops();
    if (flops_per_path_entry *
          own->cholesky.modification_path_entries(changed) >
        budget)
      return false;

    // Fixing first, then freeing: each freed column couples only to the
    // indices free at that moment, so K stays consistent at every step.
    const double flops_before = own->cholesky.modification_flops();
    unsigned int processed    = 0;
    // A safeguard only: the prediction is close (checked against CHOLMOD's
    // count in tests/lcp/work_counters; benchmarks/plate_tables/README.md,
    // "Design measurements").
    const auto over_budget = [&]() {
      return own->cholesky.modification_flops() - flops_before > budget;
    };
    std::vector<char>  current = own->fixed;
    bool               ok      = true;
    std::vector<Index> column_rows;
    for (const Index k : newly_fixed)
      {
        column_rows.clear();
        for (SparseMatrix::InnerIterator it(A, k); it; ++it)
          column_rows.push_back(it.row());
        ok = own->cholesky.delete_row(k, fixed_diagonal[k], column_rows) &&
             !over_budget();
        if (!ok)
          break;
        current[k] = 1;
        ++processed;
      }
    std::vector<Index>  rows;
    std::vector<double> values;
    for (std::size_t index = 0; ok && index < newly_free.size(); ++index)
      {
        const Index k = newly_free[index];
        current[k]    = 0;
        rows.clear();
        values.clear();
        for (SparseMatrix::InnerIterator it(A, k); it; ++it)
          if (!current[it.row()])
            {
              rows.push_back(it.row());
              values.push_back(it.value());
            }
        ok = own->cholesky.add_row(k, rows, values) && !over_budget();
        ++processed;
      }
    counters.factor_row_modifications += processed;
    if (processed > 0)
      {
        changed.resize(processed);
        flops_per_path_entry =
          (own->cholesky.modification_flops() - flops_before) /
          own->cholesky.modification_path_entries(changed);
      }
    // The same test of singularity as a fresh factorisation (a freed index
    // may leave a body without support).
    ok =
      ok && own->cholesky.reciprocal_condition() > own->cholesky.minimum_rcond;
    if (!ok)
      {
        own_valid = false;
        return false;
      }
    own->fixed = fixed;
    return true;
  }

  bool
  ActiveSetSystem::prepare_factor(const std::vector<char> &fixed)
  {
    if (own_valid && own->fixed == fixed)
      return true;
    if (modify_factor(fixed))
      {
        ++counters.modified_factorisations;
        return true;
      }
    return factorise(fixed);
  }

  Vector
  ActiveSetSystem::near_null_direction(const std::vector<char> &fixed,
                                       const Vector            *loads,
                                       Vector                  *driven)
  {
    const Index  n    = A.rows();
    const double mean = diagonal_scale(A);
    // The shifted matrix is definite by construction; the singularity test
    // would refuse exactly what is looked for.
    const double minimum_rcond  = own->cholesky.minimum_rcond;
    own->cholesky.minimum_rcond = 0;
    const bool factorised       = factorise(fixed, 1e-10 * mean);
    own->cholesky.minimum_rcond = minimum_rcond;
    Vector direction;
    if (factorised)
      {
        // A fixed pseudo-random start (deterministic runs), zero on X.
        DenseMatrix        start(n, 1);
        unsigned long long state = 0x9e3779b97f4a7c15ULL;
        for (Index i = 0; i < n; ++i)
          {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            start(i, 0) =
              fixed[i] ? 0.0 : static_cast<double>(state % 2001) / 1000.0 - 1.0;
          }
        DenseMatrix result;
        solve_with(*own, start, result);
        direction = result.col(0);
        for (Index i = 0; i < n; ++i)
          if (fixed[i])
            direction[i] = 0;
        const double largest = direction.lpNorm<Eigen::Infinity>();
        if (largest > 0)
          direction /= largest;
        if (loads != nullptr && driven != nullptr && loads->size() == n)
          {
            // Two steps from the loads on the free indices.
            DenseMatrix step(n, 1);
            for (Index i = 0; i < n; ++i)
              step(i, 0) = fixed[i] ? 0.0 : (*loads)[i];
            for (int k = 0; k < 2; ++k)
              {
                solve_with(*own, step, result);
                step = result;
                for (Index i = 0; i < n; ++i)
                  if (fixed[i])
                    step(i, 0) = 0;
                const double size = step.col(0).lpNorm<Eigen::Infinity>();
                if (size > 0)
                  step /= size;
              }
            *driven = step.col(0);
          }
      }
    own_valid = false; // a factor of the shifted matrix
    return direction;
  }

  unsigned int
  ActiveSetSystem::cg_iteration_budget(const SparseCholesky &nearby,
                                       const unsigned int    changes)
  {
    if (changes > max_changes)
      return 0;
    // The same fixed set (A + eps I for A): CG converges in one or two
    // iterations, far cheaper than any factorisation.
    if (changes == 0)
      return 8;
    // CG converges in about 2 changes + 1 iterations, each a pair of
    // triangular solves; do not spend more on it than a factorisation.
    const double break_even =
      nearby.factorisation_flops() /
      (cg_iteration_cost * std::max(nearby.factor_nonzeros(), 1.0));
    const unsigned int expected = 2 * changes + 2;
    if (expected > break_even)
      return 0;
    return std::min(2 * changes + 8, static_cast<unsigned int>(break_even));
  }

  void
  ActiveSetSystem::solve_with(const ActiveSetFactor &factor,
                              const DenseMatrix     &B,
                              DenseMatrix           &X) const
  {
    factor.solve(B, X);
    counters.triangular_solves += static_cast<unsigned int>(B.cols());
  }

  void
  ActiveSetSystem::apply(const std::vector<char> &fixed,
                         const DenseMatrix       &Y,
                         DenseMatrix             &KY) const
  {
    KY = multiply_columns(A, fixed, false, Y);
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
    solve_with(preconditioner, B, X);
    DenseMatrix KX;
    apply(fixed, X, KX);
    counters.matrix_vector_products += static_cast<unsigned int>(B.cols());
    DenseMatrix R = B - KX;
    // The tolerance is what a backward-stable direct solve achieves on the
    // answer (where K x = b), measured separately on the free rows and on
    // the fixed ones: the fixed rows (diagonal times a bound) can be far
    // larger than the forces in the free rows and must not loosen their
    // test. Not relative to K x0: a preconditioner for a nearly floating
    // active set gives a huge x0, which would make any residual look small.
    std::vector<Index> free_rows, fixed_rows;
    for (Index i = 0; i < B.rows(); ++i)
      (fixed[i] ? fixed_rows : free_rows).push_back(i);
    const auto norm_on = [](const std::vector<Index> &rows, const auto &v) {
      double sum = 0;
      for (const Index i : rows)
        sum += v[i] * v[i];
      return std::sqrt(sum);
    };
    for (Index column = 0; column < B.cols(); ++column)
      {
        const Vector b_column = B.col(column);
        // A residual on a fixed row moves the free rows' forces by about
        // as much (its diagonal is A's), so it need be no smaller than the
        // free rows' target: where b is zero on the fixed rows (bounds at
        // zero), a target of their own would demand an exact zero, which
        // round-off grants or not by the BLAS's summation order.
        const double free_target = 2e-14 * norm_on(free_rows, b_column);
        const double fixed_target =
          std::max(2e-14 * norm_on(fixed_rows, b_column), free_target);
        const auto small_enough = [&](const Vector &residual) {
          return norm_on(free_rows, residual) <= free_target &&
                 norm_on(fixed_rows, residual) <= fixed_target;
        };
        Vector r = R.col(column);
        Vector x = X.col(column);
        if (small_enough(r))
          continue;
        DenseMatrix z_matrix;
        solve_with(preconditioner, r, z_matrix);
        Vector z         = z_matrix.col(0), p;
        p                = z;
        double rz        = r.dot(z);
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
            if (small_enough(r))
              {
                converged = true;
                break;
              }
            solve_with(preconditioner, r, z_matrix);
            z                    = z_matrix.col(0);
            const double rz_next = r.dot(z);
            p                    = z + (rz_next / rz) * p;
            rz                   = rz_next;
          }
        if (!converged)
          return false;
        // The recursively updated residual drifts from the true one when K
        // is ill-conditioned (nearly floating bodies): confirm with the true
        // residual, else refactorise.
        DenseMatrix Kx;
        apply(fixed, x, Kx);
        ++counters.matrix_vector_products;
        if (!small_enough(b_column - Kx.col(0)))
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
    DenseMatrix X  = x;
    const bool  ok = solve(fixed, DenseMatrix(r), X);
    x              = X.col(0);
    return ok;
  }

  bool
  ActiveSetSystem::solve(const std::vector<char> &fixed,
                         const DenseMatrix       &R,
                         DenseMatrix             &X)
  {
    const Index       n        = A.rows();
    const DenseMatrix coupling = multiply_columns(A, fixed, true, X);
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
        solve_with(*own, rhs, solution);
        solved = true;
      }
    else if (modify_factor(fixed))
      {
        // The updated factor is exact up to the round-off of the updates:
        // CG started from its answer confirms it in an iteration or two.
        solved = preconditioned_cg(fixed, *own, rhs, solution, 4);
        if (solved)
          ++counters.modified_factorisations;
      }
    else
      {
        // A nearby factor: our own for another active set, or an inherited
        // one (A + eps I) for the same.
        const ActiveSetFactor *nearby = own_valid ? own.get() : inherited.get();
        if (nearby != nullptr)
          {
            const unsigned int changes = count_changes(nearby->fixed, fixed);
            const unsigned int iterations =
              cg_iteration_budget(nearby->cholesky, changes);
            if (iterations > 0 &&
                preconditioned_cg(fixed, *nearby, rhs, solution, iterations))
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
        solve_with(*own, rhs, solution);
      }
    for (Index i = 0; i < n; ++i)
      if (!fixed[i])
        X.row(i) = solution.row(i);
    return true;
  }
} // namespace unilateral::lcp
