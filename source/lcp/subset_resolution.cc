#include <unilateral/lcp/principal_pivoting.h>
#include <unilateral/lcp/subset_resolution.h>

#include <algorithm>

namespace unilateral::lcp
{
  namespace
  {
    /**
     * M = A_UU - A_UF A_FF^-1 A_FU by full solves, when inverse_gram
     * declines: the response of the multipliers on U when one index j of U
     * moves off its bound by one. K(X) x = e_j's load is -A_Fj on the free
     * rows and D_jj at j; the multipliers on U are rows of A x, taken
     * column by column of the symmetric A (no product with all of A).
     * Blocks of columns keep the n x block work arrays small on a million
     * unknowns, and the same two serve every block.
     */
    DenseMatrix
    schur_by_full_solves(const Problem            &problem,
                         const ActiveSetFactor    &factor,
                         const std::vector<Index> &subset,
                         Counters                 &counters)
    {
      const Index n = problem.size();
      const Index k = static_cast<Index>(subset.size());
      const auto  load_of =
        [&](const Index j, const Index c, DenseMatrix &load, const bool set) {
          for (SparseMatrix::InnerIterator it(problem.A, j); it; ++it)
            if (!factor.fixed[it.row()])
              load(it.row(), c) = set ? -it.value() : 0.0;
          load(j, c) = set ? factor.fixed_diagonal[j] : 0.0;
        };
      constexpr Index block = 32;
      DenseMatrix     M(k, k);
      DenseMatrix     load = DenseMatrix::Zero(n, std::min(block, k)), response;
      for (Index first = 0; first < k; first += block)
        {
          const Index columns = std::min(block, k - first);
          if (columns < load.cols())
            load = DenseMatrix::Zero(n, columns);
          for (Index c = 0; c < columns; ++c)
            load_of(subset[first + c], c, load, true);
          factor.solve(load, response);
          counters.triangular_solves += static_cast<unsigned int>(columns);
          for (Index c = 0; c < columns; ++c)
            load_of(subset[first + c], c, load, false);
          for (Index r = 0; r < k; ++r)
            {
              auto row = M.block(r, first, 1, columns);
              row.setZero();
              for (SparseMatrix::InnerIterator it(problem.A, subset[r]); it;
                   ++it)
                row += it.value() * response.row(it.row());
            }
        }
      return M;
    }
  } // namespace

  SubsetResolution
  resolve_subset(const Problem            &problem,
                 ActiveSetSystem          &system,
                 const std::vector<Index> &subset,
                 std::vector<char>        &active,
                 Counters                 &counters)
  {
    const Index n = problem.size();
    const Index k = static_cast<Index>(subset.size());
    if (k == 0)
      return SubsetResolution::resolved;

    // The base: every index of U at its bound, the rest as they are. It
    // holds at least what the current active set holds, and when that left
    // a body free, U holds the open constraints its free motion moves.
    std::vector<char> fixed = active;
    for (const Index i : subset)
      fixed[i] = 1;
    if (!system.prepare_factor(fixed))
      return SubsetResolution::singular;

    const Vector lower = problem.full_lower_bound();
    Vector       base  = Vector::Zero(n);
    for (Index i = 0; i < n; ++i)
      if (fixed[i])
        base[i] = lower[i];
    if (!system.solve(fixed, problem.b, base))
      return SubsetResolution::singular;
    const Vector lambda_base = problem.A * base - problem.b;
    ++counters.matrix_vector_products;

    // M = A_UU - A_UF A_FF^-1 A_FU. The last term is B' K(X)^-1 B for the
    // sparse B = A_FU, solved forward along the elimination tree only
    // (inverse_gram): a fraction of a full solve per index, where full
    // solves pass forward and backward through all of L for each
    // (benchmarks/masonry_tables/README.md, "Design measurements").
    const std::shared_ptr<const ActiveSetFactor> factor = system.factor();
    if (factor == nullptr || factor->fixed != fixed)
      return SubsetResolution::singular; // not after prepare_factor(fixed)
    DenseMatrix M = DenseMatrix::Zero(k, k);
    {
      std::vector<Index> in_subset(n, -1);
      for (Index r = 0; r < k; ++r)
        in_subset[subset[r]] = r;
      std::vector<Eigen::Triplet<double, Index>> coupling;
      for (Index c = 0; c < k; ++c)
        for (SparseMatrix::InnerIterator it(problem.A, subset[c]); it; ++it)
          if (!fixed[it.row()])
            coupling.emplace_back(it.row(), c, it.value());
          else if (in_subset[it.row()] >= 0)
            M(in_subset[it.row()], c) = it.value();
      SparseMatrix A_FU(n, k);
      A_FU.setFromTriplets(coupling.begin(), coupling.end());
      DenseMatrix gram;
      if (factor->inverse_gram(A_FU, gram))
        {
          M -= gram;
          counters.partial_forward_solves += static_cast<unsigned int>(k);
        }
      else
        M = schur_by_full_solves(problem, *factor, subset, counters);
    }

    // The dense LCP in z = u_U - l_U: lambda_U = q + M z, as a Problem
    // (A = M, b = -q, every index bounded below by 0).
    M = 0.5 * (M + M.transpose()).eval();
    clamp_rounded_diagonal(M, problem.A, subset);
    Problem reduced;
    reduced.A = M.sparseView();
    reduced.b.resize(k);
    reduced.constrained.resize(k);
    reduced.lower_bound = Vector::Zero(k);
    for (Index r = 0; r < k; ++r)
      {
        reduced.b[r]           = -lambda_base[subset[r]];
        reduced.constrained[r] = r;
      }
    check_and_normalise(reduced);

    Solution reduced_solution;
    Report   reduced_report;
    principal_pivoting(
      reduced, 10 * k + 100, reduced_solution, reduced_report, nullptr);
    if (!reduced_report.converged())
      return SubsetResolution::no_solution;

    // Ties (z = 0 with w = 0) go to the active side, as in PDAS.
    for (Index r = 0; r < k; ++r)
      active[subset[r]] = !(reduced_solution.u[r] > 0);
    return SubsetResolution::resolved;
  }
} // namespace unilateral::lcp
