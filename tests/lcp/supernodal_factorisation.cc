// SupernodalFactorisation (subtrees of the elimination tree on threads)
// against CHOLMOD's own numeric factorisation of the same analysis: the
// factor's entries agree to rounding on a connected grid, on a forest of
// three unconnected grids (several roots) and on a grid of 2 x 2 blocks
// (elasticity-like supernodes); a matrix with one negative pivot fails at
// the same column; a factorisation too small for a thread is not split.
#include <unilateral/lcp/supernodal_factorisation.h>

#include "../test_tools.h"

#include <cholmod.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using namespace unilateral::lcp;
using test_tools::verdict;

namespace
{
  /// The upper triangle (stype 1) of a 5-point grid operator on @p grids
  /// unconnected n x n grids, @p block unknowns per node coupled among
  /// themselves, shifted by @p shift, with pseudo-random weights
  /// (diagonally dominant: positive definite).
  cholmod_sparse *
  grid_matrix(const int       n,
              const int       grids,
              const int       block,
              const double    shift,
              cholmod_common &common)
  {
    test_tools::Sequence random(7);
    const int            nodes = n * n;
    const int            size  = grids * nodes * block;
    std::vector<std::vector<std::pair<int, double>>> columns(size);
    const auto add = [&](const int i, const int j, const double v) {
      columns[std::max(i, j)].emplace_back(std::min(i, j), v);
    };
    for (int g = 0; g < grids; ++g)
      for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x)
          {
            const int node = g * nodes + y * n + x;
            for (int a = 0; a < block; ++a)
              {
                const int i = node * block + a;
                add(i, i, 5.0 * block + shift + 0.5 * random.next());
                for (int b = 0; b < a; ++b)
                  add(i, node * block + b, 0.3 * random.next());
                for (const int neighbour :
                     {x + 1 < n ? node + 1 : -1, y + 1 < n ? node + n : -1})
                  if (neighbour >= 0)
                    for (int b = 0; b < block; ++b)
                      add(i,
                          neighbour * block + b,
                          (a == b ? -1.0 : 0.2) + 0.1 * random.next());
              }
          }
    std::size_t entries = 0;
    for (auto &c : columns)
      {
        std::sort(c.begin(), c.end());
        entries += c.size();
      }
    cholmod_sparse *A = cholmod_allocate_sparse(
      size, size, entries, 1, 1, 1, CHOLMOD_REAL, &common);
    auto *p = static_cast<int *>(A->p);
    auto *i = static_cast<int *>(A->i);
    auto *x = static_cast<double *>(A->x);
    p[0]    = 0;
    for (int j = 0; j < size; ++j)
      {
        int at = p[j];
        for (const auto &[row, value] : columns[j])
          {
            i[at]   = row;
            x[at++] = value;
          }
        p[j + 1] = at;
      }
    return A;
  }

  /// Factorise @p A both ways; print what agrees.
  void
  compare(const std::string &what,
          cholmod_sparse    *A,
          const unsigned int n_threads,
          cholmod_common    &common)
  {
    const std::string name =
      what + ", " + std::to_string(n_threads) + " threads";
    cholmod_factor         *theirs = cholmod_analyze(A, &common);
    cholmod_factor         *ours   = cholmod_copy_factor(theirs, &common);
    SupernodalFactorisation split;
    split.plan(*ours, 0, n_threads);
    verdict(name + ": supernodal, split between threads",
            ours->is_super && split.splits());
    // tril(P A P'), the matrix cholmod_super_numeric is given.
    cholmod_sparse *permuted = cholmod_ptranspose(
      A, 1, static_cast<int *>(ours->Perm), nullptr, 0, &common);
    cholmod_factorize(A, theirs, &common);
    const int their_status = common.status;
    split.numeric(*permuted, *ours, common);
    const int our_status = common.status;
    verdict(name + ": the same outcome", our_status == their_status);
    if (their_status == CHOLMOD_OK)
      {
        const auto *a       = static_cast<const double *>(theirs->x);
        const auto *b       = static_cast<const double *>(ours->x);
        double      largest = 0, difference = 0;
        for (std::size_t k = 0; k < theirs->xsize; ++k)
          {
            largest    = std::max(largest, std::abs(a[k]));
            difference = std::max(difference, std::abs(a[k] - b[k]));
          }
        verdict(name + ": the entries of L agree to 1e-13",
                difference <= 1e-13 * largest);
        // A solve both ways with our factor.
        const std::size_t    n = A->nrow;
        test_tools::Sequence random(3);
        cholmod_dense       *rhs = cholmod_zeros(n, 1, CHOLMOD_REAL, &common);
        for (std::size_t k = 0; k < n; ++k)
          static_cast<double *>(rhs->x)[k] = random.next();
        cholmod_dense *their_x = cholmod_solve(CHOLMOD_A, ours, rhs, &common);
        std::vector<double> our_x(n);
        split.solve(*ours, static_cast<const double *>(rhs->x), our_x.data());
        double size = 0, solve_difference = 0;
        for (std::size_t k = 0; k < n; ++k)
          {
            const double t = static_cast<const double *>(their_x->x)[k];
            size           = std::max(size, std::abs(t));
            solve_difference =
              std::max(solve_difference, std::abs(t - our_x[k]));
          }
        verdict(name + ": the solves agree to 1e-12",
                solve_difference <= 1e-12 * size);
        cholmod_free_dense(&their_x, &common);
        cholmod_free_dense(&rhs, &common);
      }
    else // one column fails: the first either way
      verdict(name + ": fails at the same column",
              ours->minor == theirs->minor && ours->minor < ours->n);
    cholmod_free_sparse(&permuted, &common);
    cholmod_free_factor(&ours, &common);
    cholmod_free_factor(&theirs, &common);
  }
} // namespace

int
main()
{
  cholmod_common common;
  cholmod_start(&common);
  common.print                      = 0;
  common.error_handler              = nullptr;
  common.quick_return_if_not_posdef = 1;
  common.supernodal                 = CHOLMOD_SUPERNODAL;

  // More threads than this machine's cores test the shares' bookkeeping,
  // not speed.
  cholmod_sparse *grid = grid_matrix(60, 1, 1, 0.01, common);
  compare("grid 60 x 60", grid, 2, common);
  compare("grid 60 x 60", grid, 4, common);

  cholmod_sparse *forest = grid_matrix(30, 3, 1, 0.01, common);
  compare("three unconnected grids", forest, 2, common);
  compare("three unconnected grids", forest, 3, common);

  cholmod_sparse *blocks = grid_matrix(40, 1, 2, 0.0, common);
  compare("grid of 2 x 2 blocks", blocks, 2, common);

  // One unknown's diagonal made negative: not positive definite.
  auto *x        = static_cast<double *>(grid->x);
  auto *p        = static_cast<int *>(grid->p);
  x[p[1801] - 1] = -100; // the diagonal of unknown 1800 (the last entry)
  compare("grid with a negative diagonal entry", grid, 2, common);
  compare("grid with a negative diagonal entry", grid, 4, common);

  cholmod_factor         *small = cholmod_analyze(forest, &common);
  SupernodalFactorisation split;
  split.plan(*small, 1e12, 2);
  verdict("a factorisation below the threshold is not split", !split.splits());
  split.plan(*small, 0, 1);
  verdict("nor one for one thread", !split.splits());
  cholmod_free_factor(&small, &common);

  cholmod_free_sparse(&grid, &common);
  cholmod_free_sparse(&forest, &common);
  cholmod_free_sparse(&blocks, &common);
  cholmod_finish(&common);
}
