#include <unilateral/base/blas_threads.h>
#include <unilateral/base/memory.h>
#include <unilateral/base/openmp_regions.h>
#include <unilateral/lcp/distributed_cholesky.h>
#include <unilateral/lcp/sparse_cholesky.h>
#include <unilateral/lcp/supernodal_factorisation.h>

#include <cholmod.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <thread>

namespace unilateral::lcp
{
  namespace
  {
    // Parent of column j in the elimination tree of a simplicial factor:
    // the first row below the diagonal (CHOLMOD keeps the diagonal first
    // and the rows of each column sorted), -1 at a root.
    Index
    simplicial_parent(const cholmod_factor *L, const Index j)
    {
      const auto *Lp  = static_cast<const Index *>(L->p);
      const auto *Li  = static_cast<const Index *>(L->i);
      const auto *Lnz = static_cast<const Index *>(L->nz);
      return Lnz[j] > 1 ? Li[Lp[j] + 1] : -1;
    }
  } // namespace

  struct SparseCholesky::Implementation
  {
    cholmod_common  common;
    cholmod_factor *factor       = nullptr;
    bool            factor_valid = false;
    // The factorisation over the ranks that replaces CHOLMOD's when this
    // object was made inside a DistributedFactorisations scope.
    std::unique_ptr<DistributedCholesky> distributed;
    // The simplicial LDL' copy of factor that row modifications work on,
    // null until the first one after a factorisation.
    cholmod_factor *modified = nullptr;
    // Position of each index in the fill-reducing ordering (old-to-new).
    std::vector<Index> inverse_ordering;
    // For each position of the ordering: the entries of L in its column and
    // in the columns of all its ancestors in the elimination tree (the
    // columns a row modification at that position rewrites).
    std::vector<double> path_entries;
    // tril(P A P') of the analysed pattern, kept once a pattern is
    // factorised a second time, and the entry of A each of its entries
    // takes its value from: cholmod_factorize permutes A afresh on every
    // call, a transpose of the whole matrix that a pattern factorised many
    // times would pay every time (benchmarks/masonry_tables/README.md,
    // "Design measurements").
    cholmod_sparse    *permuted = nullptr;
    std::vector<Index> permuted_source;
    unsigned int       factorisations_of_pattern = 0;
    // Marks for row_pattern (all zero between calls) and its result.
    std::vector<char>  row_mark;
    std::vector<Index> row_pattern_positions;
    double             analysis_flops     = 0;
    double             modification_flops = 0;
    // The analysed factor's subtrees for several threads.
    SupernodalFactorisation subtrees;
    // Fingerprint of the analysed pattern (size, nonzeros, hash).
    Index         pattern_size     = -1;
    Index         pattern_nonzeros = -1;
    std::uint64_t pattern_hash     = 0;
    bool          pattern_relaxed  = false;

    /// CHOLMOD's supernode amalgamation for the next analysis (see
    /// SparseCholesky::relaxed_supernodes).
    void
    set_amalgamation(const bool relaxed)
    {
      const std::size_t nrelax[2][3] = {{4, 16, 48}, {16, 64, 128}};
      const double      zrelax[2][3] = {{0.8, 0.1, 0.05}, {0.9, 0.3, 0.1}};
      for (unsigned int i = 0; i < 3; ++i)
        {
          common.nrelax[i] = nrelax[relaxed][i];
          common.zrelax[i] = zrelax[relaxed][i];
        }
    }

    Implementation()
    {
      cholmod_start(&common);
      // Errors become return codes we check, never prints to stderr.
      common.print                      = 0;
      common.error_handler              = nullptr;
      common.quick_return_if_not_posdef = 1;
      // Orderings: AMD (set per analysis below). METIS's nested dissection
      // takes several times as long and saves few flops on the stack bond
      // and laminae walls (benchmarks/masonry_tables/README.md, "Design
      // measurements"); only a pattern factorised many times tries METIS
      // too, and only where AMD's fronts are large (try_nested_dissection).
    }

    ~Implementation()
    {
      if (permuted != nullptr)
        cholmod_free_sparse(&permuted, &common);
      if (modified != nullptr)
        cholmod_free_factor(&modified, &common);
      if (factor != nullptr)
        cholmod_free_factor(&factor, &common);
      cholmod_finish(&common);
    }

    /// AMD works on the pattern of A + A' with elbow room and a few
    /// arrays of length n: refuse an ordering that cannot fit.
    static void
    require_ordering_memory(const SparseMatrix &A)
    {
      memory::require(sizeof(Index) * (2.4 * A.nonZeros() + 10.0 * A.rows()),
                      "the fill-reducing ordering of a system with " +
                        std::to_string(A.rows()) + " unknowns",
                      true);
    }

    /// A failed CHOLMOD call of @p step on a system with @p n unknowns:
    /// OutOfMemory if that is what it reports.
    [[noreturn]] void
    throw_failure(const std::string &step, const Index n) const
    {
      if (common.status == CHOLMOD_OUT_OF_MEMORY)
        throw OutOfMemory("CHOLMOD ran out of memory in the " + step +
                          " of a system with " + std::to_string(n) +
                          " unknowns");
      throw std::runtime_error("CHOLMOD " + step + " failed (status " +
                               std::to_string(common.status) + ")");
    }

    /// The threads a factorisation may run on: as many as OpenBLAS may
    /// (one on ranks sharing a machine, or under an address-space limit:
    /// blas_threads.h, start_up.h), at most the cores.
    static unsigned int
    factorisation_threads()
    {
      return std::min<unsigned int>(std::max(blas::threads(), 1),
                                    std::thread::hardware_concurrency());
    }

    /// Whether the analysed factor is factorised and solved with on
    /// several threads: where it is split and OpenBLAS may still run more
    /// than one.
    bool
    on_several_threads() const
    {
      return factor != nullptr && factor->is_super && subtrees.splits() &&
             factorisation_threads() >= 2;
    }

    // The factor solves and modifications use.
    cholmod_factor *
    current() const
    {
      return modified != nullptr ? modified : factor;
    }

    // A view of an Eigen matrix as a CHOLMOD matrix (no copy).
    static cholmod_sparse
    view(const SparseMatrix &A)
    {
      cholmod_sparse matrix{};
      matrix.nrow   = A.rows();
      matrix.ncol   = A.cols();
      matrix.nzmax  = A.nonZeros();
      matrix.p      = const_cast<Index *>(A.outerIndexPtr());
      matrix.i      = const_cast<Index *>(A.innerIndexPtr());
      matrix.x      = const_cast<double *>(A.valuePtr());
      matrix.stype  = 1; // symmetric, upper triangle used
      matrix.itype  = CHOLMOD_INT;
      matrix.xtype  = CHOLMOD_REAL;
      matrix.dtype  = CHOLMOD_DOUBLE;
      matrix.sorted = 1;
      matrix.packed = 1;
      return matrix;
    }

    // An n x 1 CHOLMOD column with the given (permuted, unsorted) rows and
    // values, or only the pattern if @p values is null; @p column_start
    // holds {0, number of entries}.
    static cholmod_sparse
    column_view(const std::size_t n,
                Index            *column_start,
                Index            *rows,
                double           *values)
    {
      cholmod_sparse column{};
      column.nrow   = n;
      column.ncol   = 1;
      column.nzmax  = std::max<std::size_t>(1, column_start[1]);
      column.p      = column_start;
      column.i      = rows;
      column.x      = values;
      column.stype  = 0;
      column.itype  = CHOLMOD_INT;
      column.xtype  = values != nullptr ? CHOLMOD_REAL : CHOLMOD_PATTERN;
      column.dtype  = CHOLMOD_DOUBLE;
      column.sorted = 0;
      column.packed = 1;
      return column;
    }

    // Position of index k in the fill-reducing ordering; the inverse of
    // the analysis' ordering is computed on first need.
    Index
    position_of(const Index k)
    {
      if (inverse_ordering.empty())
        {
          const Index *perm = static_cast<const Index *>(factor->Perm);
          inverse_ordering.resize(factor->n);
          for (std::size_t position = 0; position < factor->n; ++position)
            inverse_ordering[perm[position]] = static_cast<Index>(position);
        }
      return inverse_ordering[k];
    }

    void
    compute_path_entries();

    void
    analyse(const SparseMatrix       &A,
            const std::vector<Index> &ordering,
            std::uint64_t             hash,
            bool                      relaxed_supernodes,
            double                    nested_dissection_fronts,
            double                    minimum_flops_for_threads,
            Counters                 &counters);

    bool
    build_permuted(const SparseMatrix &A);

    void
    fill_permuted(const SparseMatrix &A, const Changes *changes);

    bool
    row_pattern(Index position, const std::vector<Index> &column_rows);

    static std::uint64_t
    hash_pattern(const SparseMatrix &A)
    {
      std::uint64_t hash = 1469598103934665603ull;
      auto          mix  = [&hash](std::uint64_t value) {
        hash ^= value;
        hash *= 1099511628211ull;
      };
      for (Index j = 0; j <= A.cols(); ++j)
        mix(A.outerIndexPtr()[j]);
      for (Index k = 0; k < A.nonZeros(); ++k)
        mix(A.innerIndexPtr()[k]);
      return hash;
    }
  };

  /// What factorise_with_fixed and factorise_shifted do to A's entries.
  struct SparseCholesky::Changes
  {
    /// Rows and columns made those of a diagonal matrix (null: none).
    const std::vector<char> *fixed          = nullptr;
    const Vector            *fixed_diagonal = nullptr;
    /// Added to the diagonal of the other rows (null: nothing).
    const Vector *shifts = nullptr;
    double        shift  = 0;

    /// Entry (i, j) of the factorised matrix, @p a that of A.
    double
    value(const Index i, const Index j, const double a) const
    {
      if (fixed != nullptr && ((*fixed)[i] || (*fixed)[j]))
        return i == j ? (*fixed_diagonal)[i] : 0.0;
      if (i != j)
        return a;
      return a + shift + (shifts != nullptr ? (*shifts)[i] : 0.0);
    }

    /// The factorised matrix as a copy of A (both triangles).
    SparseMatrix
    applied_to(const SparseMatrix &A) const
    {
      SparseMatrix result = A;
      for (Index j = 0; j < result.outerSize(); ++j)
        for (SparseMatrix::InnerIterator it(result, j); it; ++it)
          it.valueRef() = value(it.row(), j, it.value());
      return result;
    }
  };

  SparseCholesky::SparseCholesky()
    : implementation(std::make_unique<Implementation>())
  {
    if (const MPI_Comm *communicator = DistributedFactorisations::current())
      implementation->distributed =
        std::make_unique<DistributedCholesky>(*communicator);
  }

  bool
  SparseCholesky::distributed() const
  {
    return implementation->distributed != nullptr;
  }

  SparseCholesky::~SparseCholesky() = default;

  void
  SparseCholesky::take_analysis_from(SparseCholesky &other)
  {
    if (distributed() || other.distributed())
      return;
    std::swap(implementation, other.implementation);
    implementation->factor_valid       = false;
    other.implementation->factor_valid = false;
  }

  /**
   * The symbolic analysis of A's pattern: the fill-reducing ordering (a
   * given one, or AMD, and METIS's nested dissection as well where AMD
   * leaves large dense fronts, keeping the one with fewer flops), the
   * memory check of the factor it implies, and the bookkeeping of the
   * analysed pattern.
   */
  void
  SparseCholesky::Implementation::analyse(
    const SparseMatrix       &A,
    const std::vector<Index> &ordering,
    const std::uint64_t       hash,
    const bool                relaxed_supernodes,
    const double              nested_dissection_fronts,
    const double              minimum_flops_for_threads,
    Counters                 &counters)
  {
    cholmod_sparse matrix = view(A);
    if (factor != nullptr)
      cholmod_free_factor(&factor, &common);
    // The old pattern's permuted triangle goes here, before the new
    // factor's memory check, which would otherwise count it.
    if (permuted != nullptr)
      cholmod_free_sparse(&permuted, &common);
    set_amalgamation(relaxed_supernodes);
    if (ordering.empty())
      {
        Implementation::require_ordering_memory(A);
        common.nmethods           = 1;
        common.method[0].ordering = CHOLMOD_AMD;
        factor                    = cholmod_analyze(&matrix, &common);
        const double amd_flops    = common.fl;
        const double amd_lnz      = common.lnz;
        if (nested_dissection_fronts >= 0 && factor != nullptr &&
            amd_flops >= nested_dissection_fronts * amd_lnz)
          {
            common.method[0].ordering = CHOLMOD_METIS;
            cholmod_factor *nested    = cholmod_analyze(&matrix, &common);
            if (nested != nullptr && common.fl < amd_flops)
              std::swap(factor, nested);
            else
              {
                // Keep AMD's analysis and its statistics.
                common.fl  = amd_flops;
                common.lnz = amd_lnz;
              }
            if (nested != nullptr)
              cholmod_free_factor(&nested, &common);
            ++counters.symbolic_analyses;
          }
      }
    else
      {
        common.nmethods           = 1;
        common.method[0].ordering = CHOLMOD_GIVEN;
        factor                    = cholmod_analyze_p(
          &matrix, const_cast<Index *>(ordering.data()), nullptr, 0, &common);
      }
    if (factor == nullptr)
      throw_failure("analysis", A.rows());
    // The numeric factor is allocated next: refuse it here, with a
    // message, rather than be killed by the kernel half-way (and leave
    // no analysis behind that a later call could take for this one's).
    const double factor_bytes = factor->is_super ?
                                  8.0 * static_cast<double>(factor->xsize) :
                                  (8.0 + sizeof(Index)) * common.lnz;
    try
      {
        memory::require(factor_bytes,
                        "the Cholesky factor of a system with " +
                          std::to_string(A.rows()) + " unknowns",
                        true);
      }
    catch (const OutOfMemory &)
      {
        cholmod_free_factor(&factor, &common);
        throw;
      }
    subtrees.plan(*factor, minimum_flops_for_threads, factorisation_threads());
    pattern_size     = A.rows();
    pattern_nonzeros = A.nonZeros();
    pattern_hash     = hash;
    pattern_relaxed  = relaxed_supernodes;
    analysis_flops   = common.fl;
    inverse_ordering.clear(); // both computed on first need
    path_entries.clear();
    factorisations_of_pattern = 0;
    ++counters.symbolic_analyses;
  }

  bool
  SparseCholesky::factorise(const SparseMatrix &A, Counters &counters)
  {
    return factorise(A, {}, counters);
  }

  bool
  SparseCholesky::factorise(const SparseMatrix       &A,
                            const std::vector<Index> &ordering,
                            Counters                 &counters)
  {
    return factorise(A, ordering, nullptr, counters);
  }

  bool
  SparseCholesky::factorise_with_fixed(const SparseMatrix       &A,
                                       const std::vector<char>  &fixed,
                                       const Vector             &fixed_diagonal,
                                       const double              shift,
                                       const std::vector<Index> &ordering,
                                       Counters                 &counters)
  {
    Changes changes;
    changes.fixed          = &fixed;
    changes.fixed_diagonal = &fixed_diagonal;
    changes.shift          = shift;
    return factorise(A, ordering, &changes, counters);
  }

  bool
  SparseCholesky::factorise_shifted(const SparseMatrix &A,
                                    const Vector       &shift,
                                    Counters           &counters)
  {
    Changes changes;
    changes.shifts = &shift;
    return factorise(A, {}, &changes, counters);
  }

  bool
  SparseCholesky::factorise(const SparseMatrix       &A,
                            const std::vector<Index> &ordering,
                            const Changes            *changes,
                            Counters                 &counters)
  {
    if (!A.isCompressed())
      throw std::logic_error("SparseCholesky needs a compressed matrix");
    auto &impl = *implementation;
    // CHOLMOD's small OpenMP regions run on this thread without a team
    // (openmp::run_regions_serially says why; a setting of the thread's);
    // the dense kernels keep BLAS's own threads.
    openmp::run_regions_serially();
    // The factorised matrix as a whole, where it must be given so: to MUMPS,
    // or to CHOLMOD for a simplicial factor (or with no room to permute).
    SparseMatrix applied;
    const auto   whole = [&]() -> const SparseMatrix   &{
      if (changes == nullptr)
        return A;
      applied = changes->applied_to(A);
      return applied;
    };
    if (impl.distributed) // MUMPS orders the matrix itself
      return impl.factor_valid =
               impl.distributed->factorise(whole(), minimum_rcond, counters);
    if (A.rows() == 0) // nothing to factorise (CHOLMOD rejects 0 x 0)
      {
        impl.factor_valid = true;
        return true;
      }

    const std::uint64_t hash = Implementation::hash_pattern(A);
    if (impl.factor == nullptr || impl.pattern_size != A.rows() ||
        impl.pattern_nonzeros != A.nonZeros() || impl.pattern_hash != hash ||
        impl.pattern_relaxed != relaxed_supernodes)
      impl.analyse(A,
                   ordering,
                   hash,
                   relaxed_supernodes,
                   try_nested_dissection ? nested_dissection_fronts : -1.0,
                   minimum_flops_for_threads,
                   counters);

    if (impl.modified != nullptr)
      cholmod_free_factor(&impl.modified, &impl.common);
    impl.modification_flops = 0;
    // A pattern factorised again (the full pattern for every active set,
    // the interior point's matrix in every iteration) is permuted once, and
    // so is A with changes, which is never copied, and a factor split
    // between threads; a pattern used once (A_FF of one active set) is
    // otherwise left to CHOLMOD.
    const bool on_threads = impl.on_several_threads();
    if (impl.factor->is_super &&
        (impl.factorisations_of_pattern > 0 || changes != nullptr ||
         on_threads) &&
        (impl.permuted != nullptr || impl.build_permuted(A)))
      {
        impl.fill_permuted(A, changes);
        if (on_threads)
          impl.subtrees.numeric(*impl.permuted, *impl.factor, impl.common);
        else
          {
            double zero[2] = {0, 0};
            cholmod_super_numeric(
              impl.permuted, nullptr, zero, impl.factor, &impl.common);
          }
      }
    else
      {
        cholmod_sparse matrix = Implementation::view(whole());
        cholmod_factorize(&matrix, impl.factor, &impl.common);
      }
    ++impl.factorisations_of_pattern;
    ++counters.numeric_factorisations;
    impl.factor_valid = (impl.common.status == CHOLMOD_OK &&
                         impl.factor->minor == impl.factor->n);
    // A simplicial LDL' factorisation (CHOLMOD's choice for small sparse
    // matrices) stops only at a zero pivot: a negative one, an indefinite
    // A, completes. Positive definite means D > 0 (D is the first entry of
    // each column).
    if (impl.factor_valid && !impl.factor->is_super && !impl.factor->is_ll)
      {
        const auto *Lp = static_cast<const Index *>(impl.factor->p);
        const auto *Lx = static_cast<const double *>(impl.factor->x);
        for (std::size_t j = 0; j < impl.factor->n && impl.factor_valid; ++j)
          impl.factor_valid = Lx[Lp[j]] > 0;
      }
    if (impl.common.status == CHOLMOD_OUT_OF_MEMORY)
      impl.throw_failure("factorisation", A.rows());
    // A factorisation that completes can still be numerically singular: a
    // body held by no constraint leaves a pivot at round-off, and the solve
    // then moves it by 1e10 with a backward error that looks perfect. Such
    // a factor is refused (CHOLMOD's estimate: (min L_ii / max L_ii)^2).
    if (impl.factor_valid && minimum_rcond > 0)
      {
        impl.factor_valid =
          cholmod_rcond(impl.factor, &impl.common) > minimum_rcond;
      }
    return impl.factor_valid;
  }

  bool
  SparseCholesky::prepare_modification()
  {
    auto &impl = *implementation;
    if (!impl.factor_valid || impl.factor == nullptr || impl.distributed)
      return false;
    if (impl.modified == nullptr)
      {
        impl.modified = cholmod_copy_factor(impl.factor, &impl.common);
        if (impl.modified == nullptr)
          return false;
        // From here on the copy serves the solves, and the next
        // factorise() writes new values: a supernodal factor keeps only its
        // structure, so that the conversion below does not hold three
        // factors at once (the run's peak memory on the largest walls). It
        // only frees; should it fail, the values merely stay. (A simplicial
        // factor, small, keeps them: dropping its values would drop the
        // columns compute_path_entries reads too.)
        if (impl.factor->is_super)
          cholmod_change_factor(CHOLMOD_PATTERN,
                                impl.factor->is_ll,
                                true,
                                true,
                                true,
                                impl.factor,
                                &impl.common);
        // Simplicial LDL', columns not packed so that they can grow.
        if (!cholmod_change_factor(CHOLMOD_REAL,
                                   false,
                                   false,
                                   false,
                                   false,
                                   impl.modified,
                                   &impl.common))
          {
            cholmod_free_factor(&impl.modified, &impl.common);
            impl.factor_valid = false;
            return false;
          }
      }
    return true;
  }

  void
  SparseCholesky::Implementation::compute_path_entries()
  {
    const cholmod_factor &L = *factor;
    const std::size_t     n = L.n;
    path_entries.assign(n, 0.);
    // Parents have larger positions than their children: one backward pass.
    if (L.is_super)
      {
        const auto *super    = static_cast<const Index *>(L.super);
        const auto *row_from = static_cast<const Index *>(L.pi);
        const auto *rows     = static_cast<const Index *>(L.s);
        for (std::size_t s = L.nsuper; s-- > 0;)
          {
            const Index columns = super[s + 1] - super[s];
            const Index length  = row_from[s + 1] - row_from[s];
            // The parent of the supernode's last column: its first row
            // below the diagonal block. Column j of the supernode holds
            // length - (j - first) entries.
            double tail =
              length > columns ? path_entries[rows[row_from[s] + columns]] : 0.;
            for (Index j = super[s + 1]; j-- > super[s];)
              {
                tail += length - (j - super[s]);
                path_entries[j] = tail;
              }
          }
      }
    else
      {
        const auto *column_start = static_cast<const Index *>(L.p);
        const auto *rows         = static_cast<const Index *>(L.i);
        const auto *entries      = static_cast<const Index *>(L.nz);
        for (std::size_t j = n; j-- > 0;)
          {
            Index parent = -1;
            for (Index e = column_start[j] + 1;
                 e < column_start[j] + entries[j];
                 ++e)
              if (parent < 0 || rows[e] < parent)
                parent = rows[e];
            path_entries[j] =
              entries[j] + (parent >= 0 ? path_entries[parent] : 0.);
          }
      }
  }

  double
  SparseCholesky::modification_path_entries(
    const std::vector<Index> &indices) const
  {
    auto &impl = *implementation;
    if (impl.distributed) // not modified row by row
      return std::numeric_limits<double>::infinity();
    if (impl.factor == nullptr)
      return 0;
    if (impl.path_entries.empty())
      impl.compute_path_entries();
    double total = 0;
    for (const Index k : indices)
      total += impl.path_entries[impl.position_of(k)];
    return total;
  }

  /**
   * tril(P A P') as CHOLMOD's factorisation forms it from the upper
   * triangle of A: entry (i, j), i <= j, goes to row max(p_i, p_j) and
   * column min(p_i, p_j) of the permuted matrix. The entries are ordered by
   * row first (a counting sort), then placed column by column, so every
   * column comes out sorted. False (and nothing kept) if CHOLMOD cannot
   * allocate it.
   */
  bool
  SparseCholesky::Implementation::build_permuted(const SparseMatrix &A)
  {
    const Index n = A.rows();
    position_of(0); // the inverse ordering
    const auto *const column_start = A.outerIndexPtr();
    const auto *const row          = A.innerIndexPtr();
    // Upper entries of A by the row they take in the permuted matrix.
    std::vector<Index> start_of_row(n + 1, 0);
    Index              n_entries = 0;
    for (Index j = 0; j < n; ++j)
      for (Index k = column_start[j]; k < column_start[j + 1]; ++k)
        if (row[k] <= j)
          {
            ++start_of_row[std::max(inverse_ordering[row[k]],
                                    inverse_ordering[j]) +
                           1];
            ++n_entries;
          }
    for (Index r = 0; r < n; ++r)
      start_of_row[r + 1] += start_of_row[r];
    std::vector<Index> by_row(n_entries), column_of(n_entries);
    std::vector<Index> next = start_of_row;
    std::vector<Index> entries_in_column(n + 1, 0);
    for (Index j = 0; j < n; ++j)
      for (Index k = column_start[j]; k < column_start[j + 1]; ++k)
        if (row[k] <= j)
          {
            const Index p_i = inverse_ordering[row[k]];
            const Index p_j = inverse_ordering[j];
            const Index at  = next[std::max(p_i, p_j)]++;
            by_row[at]      = k;
            column_of[at]   = std::min(p_i, p_j);
            ++entries_in_column[column_of[at] + 1];
          }
    permuted = cholmod_allocate_sparse(n,
                                       n,
                                       n_entries,
                                       /*sorted=*/1,
                                       /*packed=*/1,
                                       /*stype=*/-1,
                                       CHOLMOD_REAL,
                                       &common);
    if (permuted == nullptr)
      return false;
    auto *const p = static_cast<Index *>(permuted->p);
    auto *const i = static_cast<Index *>(permuted->i);
    for (Index c = 0; c < n; ++c)
      entries_in_column[c + 1] += entries_in_column[c];
    std::copy(entries_in_column.begin(), entries_in_column.end(), p);
    permuted_source.resize(n_entries);
    for (Index r = 0; r < n; ++r)
      for (Index at = start_of_row[r]; at < start_of_row[r + 1]; ++at)
        {
          const Index e      = entries_in_column[column_of[at]]++;
          i[e]               = r;
          permuted_source[e] = by_row[at];
        }
    return true;
  }

  /**
   * The values of the permuted triangle built by build_permuted: A's, or
   * A's with @p changes made, found at the original row and column of each
   * entry (the ordering maps the permuted ones back).
   */
  void
  SparseCholesky::Implementation::fill_permuted(const SparseMatrix &A,
                                                const Changes      *changes)
  {
    double *const       value  = static_cast<double *>(permuted->x);
    const double *const source = A.valuePtr();
    if (changes == nullptr)
      {
        for (std::size_t e = 0; e < permuted_source.size(); ++e)
          value[e] = source[permuted_source[e]];
        return;
      }
    const auto *const original     = static_cast<const Index *>(factor->Perm);
    const auto *const column_start = static_cast<const Index *>(permuted->p);
    const auto *const row          = static_cast<const Index *>(permuted->i);
    for (std::size_t c = 0; c < permuted->ncol; ++c)
      for (Index e = column_start[c]; e < column_start[c + 1]; ++e)
        value[e] = changes->value(original[row[e]],
                                  original[c],
                                  source[permuted_source[e]]);
  }

  /**
   * The pattern of row @p position of the modified factor, from the
   * pattern of the matrix's column there: row k of L is the set of columns
   * on the paths from each j < k with a_jk != 0 up to k in the tree of L
   * (simplicial_parent). Entries L_kj stored outside those paths (supernodal
   * amalgamation, fill of another active set) are exact zeros: every term
   * that could make them nonzero has a structural zero as a factor. False
   * if a path does not lead to k (then CHOLMOD searches itself).
   */
  bool
  SparseCholesky::Implementation::row_pattern(
    const Index               position,
    const std::vector<Index> &column_rows)
  {
    row_mark.resize(modified->n, 0);
    row_pattern_positions.clear();
    bool complete = true;
    for (const Index row : column_rows)
      {
        Index j = position_of(row);
        if (j >= position) // the diagonal, or a row of column k of L
          continue;
        while (j >= 0 && j < position && !row_mark[j])
          {
            row_mark[j] = 1;
            row_pattern_positions.push_back(j);
            j = simplicial_parent(modified, j);
          }
        // A path ends at k or at a column already on the pattern.
        complete = complete && j >= 0 && (j == position || row_mark[j]);
      }
    for (const Index j : row_pattern_positions)
      row_mark[j] = 0;
    return complete;
  }

  bool
  SparseCholesky::delete_row(const Index               k,
                             const double              diagonal,
                             const std::vector<Index> &column_rows)
  {
    auto &impl = *implementation;
    if (!prepare_modification())
      return false;
    const Index position = impl.position_of(k);
    // Row k of L as an n x 1 pattern.
    cholmod_sparse  row{};
    Index           row_start[2] = {0, 0};
    cholmod_sparse *row_given    = nullptr;
    if (impl.row_pattern(position, column_rows))
      {
        row_start[1] = static_cast<Index>(impl.row_pattern_positions.size());
        row          = Implementation::column_view(impl.modified->n,
                                          row_start,
                                          impl.row_pattern_positions.data(),
                                          nullptr);
        row_given    = &row;
      }
    if (!cholmod_rowdel(position, row_given, impl.modified, &impl.common))
      {
        impl.factor_valid = false;
        return false;
      }
    impl.modification_flops += impl.common.modfl;
    // CHOLMOD leaves the row of the identity (D_kk = 1); the matrix has
    // @p diagonal there. In a simplicial LDL' factor each column starts
    // with its entry of D.
    auto *const Lp = static_cast<const Index *>(impl.modified->p);
    static_cast<double *>(impl.modified->x)[Lp[position]] = diagonal;
    return true;
  }

  bool
  SparseCholesky::add_row(const Index                k,
                          const std::vector<Index>  &rows,
                          const std::vector<double> &values)
  {
    auto &impl = *implementation;
    if (!prepare_modification())
      return false;
    const Index position = impl.position_of(k);
    // Column k of P A P^T as an n x 1 sparse matrix (need not be sorted).
    Index              column_start[2] = {0, static_cast<Index>(rows.size())};
    std::vector<Index> permuted_rows(rows.size());
    for (std::size_t entry = 0; entry < rows.size(); ++entry)
      permuted_rows[entry] = impl.position_of(rows[entry]);
    cholmod_sparse column =
      Implementation::column_view(impl.modified->n,
                                  column_start,
                                  permuted_rows.data(),
                                  const_cast<double *>(values.data()));
    if (!cholmod_rowadd(position, &column, impl.modified, &impl.common))
      {
        impl.factor_valid = false;
        return false;
      }
    impl.modification_flops += impl.common.modfl;
    return true;
  }

  bool
  SparseCholesky::has_modification_copy() const
  {
    return implementation->modified != nullptr;
  }

  double
  SparseCholesky::factorisation_flops() const
  {
    if (implementation->distributed)
      return implementation->distributed->factorisation_flops();
    return implementation->analysis_flops;
  }

  double
  SparseCholesky::modification_flops() const
  {
    return implementation->modification_flops;
  }

  double
  SparseCholesky::reciprocal_condition() const
  {
    auto &impl = *implementation;
    if (impl.distributed)
      throw std::logic_error("SparseCholesky::reciprocal_condition of a "
                             "distributed factor (MUMPS tests null pivots "
                             "while it factorises instead)");
    if (!impl.factor_valid || impl.current() == nullptr)
      return 0;
    return cholmod_rcond(impl.current(), &impl.common);
  }

  std::vector<Index>
  SparseCholesky::amd_ordering(const SparseMatrix &A, Counters &counters)
  {
    std::vector<Index> ordering(A.rows());
    if (A.rows() == 0)
      return ordering;
    Implementation impl;
    cholmod_sparse matrix = Implementation::view(A);
    Implementation::require_ordering_memory(A);
    if (!cholmod_amd(&matrix, nullptr, 0, ordering.data(), &impl.common))
      impl.throw_failure("AMD ordering", A.rows());
    ++counters.orderings;
    return ordering;
  }

  std::vector<Index>
  SparseCholesky::ordering() const
  {
    const auto &impl = *implementation;
    if (impl.factor == nullptr)
      return {};
    const Index *perm = static_cast<const Index *>(impl.factor->Perm);
    return std::vector<Index>(perm, perm + impl.factor->n);
  }

  bool
  SparseCholesky::has_factor() const
  {
    return implementation->factor_valid;
  }

  double
  SparseCholesky::factor_nonzeros() const
  {
    const auto &impl = *implementation;
    if (impl.distributed)
      return impl.distributed->factor_nonzeros();
    const cholmod_factor *factor = impl.current();
    if (factor == nullptr)
      return 0;
    if (factor->is_super)
      return static_cast<double>(factor->xsize);
    return static_cast<double>(factor->nzmax);
  }

  namespace
  {
    /**
     * The forward solve's view of a factor L: its nodes (supernodes, or the
     * single columns of a simplicial factor), their columns, and their
     * parents in the elimination tree.
     */
    class EliminationTree
    {
    public:
      explicit EliminationTree(const cholmod_factor *L)
        : L(L)
        , super(L->is_super)
        , n_nodes(super ? static_cast<Index>(L->nsuper) :
                          static_cast<Index>(L->n))
        , first_column(static_cast<const Index *>(L->super))
        , row_start(static_cast<const Index *>(L->pi))
        , rows(static_cast<const Index *>(L->s))
      {
        if (super)
          {
            node_of.resize(L->n);
            for (Index s = 0; s < n_nodes; ++s)
              for (Index j = first_column[s]; j < first_column[s + 1]; ++j)
                node_of[j] = s;
          }
      }

      /// The node of column @p j.
      Index
      node(const Index j) const
      {
        return super ? node_of[j] : j;
      }

      Index
      columns(const Index s) const
      {
        return super ? first_column[s + 1] - first_column[s] : 1;
      }

      Index
      first(const Index s) const
      {
        return super ? first_column[s] : s;
      }

      /// The node of the first row below the diagonal block, -1 at a root.
      Index
      parent(const Index s) const
      {
        if (!super)
          return simplicial_parent(L, s);
        const Index below = row_start[s] + columns(s);
        return below < row_start[s + 1] ? node(rows[below]) : -1;
      }

      const cholmod_factor *const L;
      const bool                  super;
      const Index                 n_nodes;

    private:
      const Index       *first_column, *row_start, *rows;
      std::vector<Index> node_of;
    };

    /// The columns of B that one forward solve takes together: the nodes
    /// of their paths (ascending), where each starts in the block's rows,
    /// and Y = L^-1 B on those rows (scaled by D^-1/2 for L D L').
    struct PathBlock
    {
      std::vector<Index> nodes, offsets;
      DenseMatrix        Y;
    };

    /**
     * Y_s = L_ss^-1 Y_s at each node s of @p block's paths in turn, and
     * the update of the rows below it (@p local: the row of each column of
     * L in the block). False on a nonpositive pivot of L D L'.
     */
    bool
    forward_solve(const EliminationTree    &tree,
                  const std::vector<Index> &local,
                  PathBlock                &block)
    {
      const cholmod_factor *L  = tree.L;
      const double         *Lx = static_cast<const double *>(L->x);
      for (std::size_t q = 0; q < block.nodes.size(); ++q)
        {
          const Index s = block.nodes[q];
          auto Y_s      = block.Y.middleRows(block.offsets[q], tree.columns(s));
          if (tree.super)
            {
              const Index *row_start   = static_cast<const Index *>(L->pi);
              const Index *value_start = static_cast<const Index *>(L->px);
              const Index  nscol       = tree.columns(s);
              const Index  nsrow       = row_start[s + 1] - row_start[s];
              using Stride             = Eigen::OuterStride<>;
              const Eigen::Map<const DenseMatrix, 0, Stride> L11(
                Lx + value_start[s], nscol, nscol, Stride(nsrow));
              const Eigen::Map<const DenseMatrix, 0, Stride> L21(
                Lx + value_start[s] + nscol,
                nsrow - nscol,
                nscol,
                Stride(nsrow));
              L11.triangularView<Eigen::Lower>().solveInPlace(Y_s);
              if (nsrow > nscol)
                {
                  const DenseMatrix update = L21 * Y_s;
                  const Index      *below =
                    static_cast<const Index *>(L->s) + row_start[s] + nscol;
                  for (Index r = 0; r < nsrow - nscol; ++r)
                    block.Y.row(local[below[r]]) -= update.row(r);
                }
            }
          else
            {
              // Unit L; the diagonal entry of the column holds D.
              const Index *Lp  = static_cast<const Index *>(L->p);
              const Index *Li  = static_cast<const Index *>(L->i);
              const Index *Lnz = static_cast<const Index *>(L->nz);
              const double d   = Lx[Lp[s]];
              if (!(d > 0))
                return false;
              for (Index p = Lp[s] + 1; p < Lp[s] + Lnz[s]; ++p)
                block.Y.row(local[Li[p]]) -= Lx[p] * Y_s;
              Y_s /= std::sqrt(d);
            }
        }
      return true;
    }

    /// G = Y' Y over the rows two blocks share (the nodes on both of their
    /// paths), in the blocks' column order, @p width columns per block.
    DenseMatrix
    gram_of_blocks(const EliminationTree        &tree,
                   const std::vector<PathBlock> &blocks,
                   const Index                   k,
                   const Index                   width)
    {
      DenseMatrix        G(k, k);
      std::vector<Index> rows_a, rows_b;
      for (std::size_t a = 0; a < blocks.size(); ++a)
        for (std::size_t b = a; b < blocks.size(); ++b)
          {
            const PathBlock &A_block = blocks[a], &B_block = blocks[b];
            auto             G_ab =
              G.block(a * width, b * width, A_block.Y.cols(), B_block.Y.cols());
            if (a == b)
              {
                G_ab.noalias() = A_block.Y.transpose() * A_block.Y;
                continue;
              }
            rows_a.clear();
            rows_b.clear();
            for (std::size_t p = 0, q = 0;
                 p < A_block.nodes.size() && q < B_block.nodes.size();)
              if (A_block.nodes[p] < B_block.nodes[q])
                ++p;
              else if (B_block.nodes[q] < A_block.nodes[p])
                ++q;
              else
                {
                  for (Index j = 0; j < tree.columns(A_block.nodes[p]); ++j)
                    {
                      rows_a.push_back(A_block.offsets[p] + j);
                      rows_b.push_back(B_block.offsets[q] + j);
                    }
                  ++p;
                  ++q;
                }
            const DenseMatrix Y_a = A_block.Y(rows_a, Eigen::all);
            const DenseMatrix Y_b = B_block.Y(rows_b, Eigen::all);
            G_ab.noalias()        = Y_a.transpose() * Y_b;
            G.block(b * width, a * width, B_block.Y.cols(), A_block.Y.cols()) =
              G_ab.transpose();
          }
      return G;
    }
  } // namespace

  bool
  SparseCholesky::inverse_gram(const SparseMatrix &B,
                               DenseMatrix        &G,
                               const double        max_entries) const
  {
    auto &impl = *implementation;
    // A distributed factor is not walked along its tree: full solves.
    if (!impl.factor_valid || impl.distributed)
      return false;
    const Index k = static_cast<Index>(B.cols());
    if (B.rows() == 0) // the empty factor of an empty matrix
      {
        G = DenseMatrix::Zero(k, k);
        return true;
      }
    const cholmod_factor *L = impl.current();
    const Index           n = static_cast<Index>(L->n);
    if (B.rows() != n)
      throw std::logic_error("SparseCholesky::inverse_gram: B has " +
                             std::to_string(B.rows()) + " rows, A " +
                             std::to_string(n));
    // Supernodal factors are L L', simplicial ones (the modified copy) L D L'.
    if (static_cast<bool>(L->is_super) != static_cast<bool>(L->is_ll))
      return false;
    const EliminationTree tree(L);

    // Columns ordered by where they enter the tree, so that a block's paths
    // share most of their nodes.
    std::vector<Index> order(k), entry(k, n);
    for (Index c = 0; c < k; ++c)
      {
        order[c] = c;
        for (SparseMatrix::InnerIterator it(B, c); it; ++it)
          entry[c] = std::min(entry[c], impl.position_of(it.row()));
      }
    std::stable_sort(order.begin(), order.end(), [&](Index a, Index b) {
      return entry[a] < entry[b];
    });

    // Blocks of columns, each forward-solved along the union of its paths.
    constexpr Index        width = 32;
    std::vector<PathBlock> blocks;
    std::vector<char>      marked(tree.n_nodes, 0);
    std::vector<Index>     local(n, -1);
    double                 kept = 0;
    for (Index start = 0; start < k; start += width)
      {
        const Index w     = std::min(width, k - start);
        PathBlock  &block = blocks.emplace_back();
        for (Index c = start; c < start + w; ++c)
          for (SparseMatrix::InnerIterator it(B, order[c]); it; ++it)
            for (Index s = tree.node(impl.position_of(it.row()));
                 s >= 0 && !marked[s];
                 s = tree.parent(s))
              {
                marked[s] = 1;
                block.nodes.push_back(s);
              }
        std::sort(block.nodes.begin(), block.nodes.end());
        Index size = 0;
        for (const Index s : block.nodes)
          {
            marked[s] = 0;
            block.offsets.push_back(size);
            for (Index j = 0; j < tree.columns(s); ++j)
              local[tree.first(s) + j] = size + j;
            size += tree.columns(s);
          }
        kept += static_cast<double>(size) * w;
        if (kept > max_entries)
          return false;
        block.Y = DenseMatrix::Zero(size, w);
        for (Index c = 0; c < w; ++c)
          for (SparseMatrix::InnerIterator it(B, order[start + c]); it; ++it)
            block.Y(local[impl.position_of(it.row())], c) += it.value();
        if (!forward_solve(tree, local, block))
          return false;
        for (const Index s : block.nodes)
          for (Index j = 0; j < tree.columns(s); ++j)
            local[tree.first(s) + j] = -1;
      }

    const DenseMatrix sorted_G = gram_of_blocks(tree, blocks, k, width);
    G.resize(k, k);
    for (Index r = 0; r < k; ++r)
      for (Index c = 0; c < k; ++c)
        G(order[r], order[c]) = sorted_G(r, c);
    return true;
  }

  void
  SparseCholesky::solve(const Vector &b, Vector &x) const
  {
    DenseMatrix B = b;
    DenseMatrix X;
    solve(B, X);
    x = X.col(0);
  }

  void
  SparseCholesky::solve(const DenseMatrix &B, DenseMatrix &X) const
  {
    auto &impl = *implementation;
    if (!impl.factor_valid)
      throw std::logic_error("SparseCholesky::solve without a valid factor");
    if (impl.distributed)
      {
        impl.distributed->solve(B, X);
        return;
      }
    if (B.rows() == 0)
      {
        X.resize(0, B.cols());
        return;
      }
    // One right-hand side: the substitutions on the factorisation's
    // threads.
    if (B.cols() == 1 && impl.current() == impl.factor &&
        impl.on_several_threads())
      {
        X.resize(B.rows(), 1);
        impl.subtrees.solve(*impl.factor, B.data(), X.data());
        return;
      }
    cholmod_dense rhs{};
    rhs.nrow  = B.rows();
    rhs.ncol  = B.cols();
    rhs.nzmax = B.size();
    rhs.d     = B.rows();
    rhs.x     = const_cast<double *>(B.data());
    rhs.xtype = CHOLMOD_REAL;
    rhs.dtype = CHOLMOD_DOUBLE;
    cholmod_dense *solution =
      cholmod_solve(CHOLMOD_A, impl.current(), &rhs, &impl.common);
    if (solution == nullptr)
      impl.throw_failure("solve", B.rows());
    X = Eigen::Map<DenseMatrix>(static_cast<double *>(solution->x),
                                B.rows(),
                                B.cols());
    cholmod_free_dense(&solution, &impl.common);
  }
} // namespace unilateral::lcp
