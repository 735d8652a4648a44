// The factorisation over the ranks (MUMPS through PETSc, run on 1 and on 2
// ranks: .mpirun=1. and .mpirun=2.) against CHOLMOD on the same matrices:
// the solutions of several right-hand sides agree to 1e-12; a second
// factorisation of the same pattern reuses the symbolic analysis; a singular
// matrix (a floating body: the pure Neumann Laplacian) and an indefinite one
// are refused, and a definite matrix factorises again after a refusal; and
// SparseCholesky made inside a DistributedFactorisations scope, and only
// there, factorises over the ranks, without what only CHOLMOD offers.
// Every rank checks: a verdict holds only if it holds on every rank (each
// rank's solutions against its own CHOLMOD solve), and every rank's
// solutions must equal rank 0's (broadcast) to 1e-12 of the largest entry.
// Rank 0 prints; the two outputs differ only in the number of ranks.
#include <unilateral/lcp/distributed_cholesky.h>
#include <unilateral/lcp/sparse_cholesky.h>

#include "../mpi_test_tools.h"

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

using namespace unilateral::lcp;

namespace
{
  const char *
  yes_no(const bool condition)
  {
    return condition ? "yes" : "NO";
  }

  /// The 5-point Laplacian on a side x side grid, times @p scale on the
  /// diagonal, plus @p shift on it; with @p neumann no Dirichlet boundary
  /// (rows sum to zero: singular).
  SparseMatrix
  laplacian(const int    side,
            const double scale,
            const double shift,
            const bool   neumann = false)
  {
    const int                                  n = side * side;
    std::vector<Eigen::Triplet<double, Index>> entries;
    for (int x = 0; x < side; ++x)
      for (int y = 0; y < side; ++y)
        {
          const int i          = x * side + y;
          int       neighbours = 0;
          for (const auto [dx, dy] :
               {std::pair{1, 0}, std::pair{-1, 0}, {0, 1}, {0, -1}})
            {
              const int nx = x + dx, ny = y + dy;
              if (nx < 0 || ny < 0 || nx >= side || ny >= side)
                continue;
              entries.emplace_back(i, nx * side + ny, -1.0);
              ++neighbours;
            }
          entries.emplace_back(i,
                               i,
                               scale * (neumann ? neighbours : 4.0) + shift);
        }
    SparseMatrix A(n, n);
    A.setFromTriplets(entries.begin(), entries.end());
    A.makeCompressed();
    return A;
  }

  DenseMatrix
  right_hand_sides(const Index n)
  {
    DenseMatrix B(n, 3);
    for (Index i = 0; i < n; ++i)
      {
        B(i, 0) = 1.0;
        B(i, 1) = std::sin(0.1 * i);
        B(i, 2) = (i % 7) - 3.0;
      }
    return B;
  }

  /// Verdicts on the distributed solutions of several right-hand sides,
  /// over every rank: "as CHOLMOD's to 1e-12" (relative to CHOLMOD's on the
  /// same rank) and "as rank 0's" (1e-12 of the largest entry).
  std::string
  solutions(const DistributedCholesky &distributed, const SparseMatrix &A)
  {
    const DenseMatrix B = right_hand_sides(A.rows());
    DenseMatrix       X, X_serial;
    distributed.solve(B, X);
    SparseCholesky serial;
    Counters       counters;
    serial.factorise(A, counters);
    serial.solve(B, X_serial);
    const bool as_cholmod = mpi_test::max_over_ranks((X - X_serial).norm() /
                                                     X_serial.norm()) <= 1e-12;
    const bool as_rank_0  = mpi_test::same_as_rank_0(
      std::vector<double>(X.data(), X.data() + X.size()), 1e-12);
    return std::string("solutions as CHOLMOD's to 1e-12: ") +
           yes_no(as_cholmod) + ", as rank 0's: " + yes_no(as_rank_0);
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_test::rank_0_prints();

  using mpi_test::all_ranks;
  DistributedCholesky cholesky(MPI_COMM_WORLD);
  std::cout << "ranks: " << cholesky.n_ranks() << "\n";
  Counters           counters;
  const SparseMatrix A    = laplacian(30, 1.0, 0.0);
  const bool factorised   = all_ranks(cholesky.factorise(A, 1e-14, counters));
  const std::string first = solutions(cholesky, A);
  std::cout << "Laplacian 30 x 30: factorised: " << yes_no(factorised) << ", "
            << first << ", factor entries > 0: "
            << yes_no(all_ranks(cholesky.factor_nonzeros() > 0)) << "\n";

  const SparseMatrix A2    = laplacian(30, 2.0, 0.5);
  const bool         again = all_ranks(cholesky.factorise(A2, 1e-14, counters));
  const std::string  second = solutions(cholesky, A2);
  std::cout << "same pattern, new values: factorised: " << yes_no(again) << ", "
            << second << ", symbolic analyses: " << counters.symbolic_analyses
            << ", numeric factorisations: " << counters.numeric_factorisations
            << " (on every rank: "
            << yes_no(all_ranks(counters.symbolic_analyses == 1 &&
                                counters.numeric_factorisations == 2))
            << ")\n";

  const bool singular =
    cholesky.factorise(laplacian(30, 1.0, 0.0, true), 1e-14, counters);
  const bool refused_singular = all_ranks(!singular);
  const bool no_factor        = all_ranks(!cholesky.has_factor());
  std::cout << "Neumann Laplacian (singular): refused: "
            << yes_no(refused_singular)
            << ", no factor kept: " << yes_no(no_factor) << "\n";
  const bool indefinite =
    cholesky.factorise(laplacian(30, 1.0, -3.0), 0.0, counters);
  std::cout << "Laplacian - 3 I (indefinite): refused: "
            << yes_no(all_ranks(!indefinite)) << "\n";
  const bool        after = all_ranks(cholesky.factorise(A, 1e-14, counters));
  const std::string third = solutions(cholesky, A);
  std::cout << "definite after the refusals: factorised: " << yes_no(after)
            << ", " << third << "\n";

  // The scope: SparseCholesky inside it distributed, outside not.
  {
    SparseCholesky outside;
    std::cout << "outside a scope: serial: "
              << yes_no(all_ranks(!outside.distributed())) << "\n";
    DistributedFactorisations scope(MPI_COMM_WORLD);
    SparseCholesky            inside;
    Counters                  inside_counters;
    inside.factorise(A, inside_counters);
    const DenseMatrix B = right_hand_sides(A.rows());
    DenseMatrix       X, X_serial, G;
    inside.solve(B, X);
    outside.factorise(A, inside_counters);
    outside.solve(B, X_serial);
    SparseMatrix columns(A.rows(), 2);
    columns.insert(3, 0)  = 1.0;
    columns.insert(40, 1) = 1.0;
    columns.makeCompressed();
    const bool distributed = all_ranks(inside.distributed());
    const bool as_cholmod =
      all_ranks((X - X_serial).norm() <= 1e-12 * X_serial.norm());
    const bool as_rank_0 = mpi_test::same_as_rank_0(
      std::vector<double>(X.data(), X.data() + X.size()), 1e-12);
    const bool declines = all_ranks(!inside.inverse_gram(columns, G));
    const bool infinite =
      all_ranks(std::isinf(inside.modification_path_entries({3})));
    std::cout << "inside a scope: distributed: " << yes_no(distributed)
              << ", solutions as CHOLMOD's to 1e-12: " << yes_no(as_cholmod)
              << ", as rank 0's: " << yes_no(as_rank_0)
              << ", inverse_gram declines: " << yes_no(declines)
              << ", row modifications cost infinitely much: "
              << yes_no(infinite) << "\n";
  }
  SparseCholesky after_scope;
  std::cout << "after the scope closed: serial: "
            << yes_no(all_ranks(!after_scope.distributed())) << "\n";
}
