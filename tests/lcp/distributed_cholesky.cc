// The factorisation over the ranks (MUMPS through PETSc, run on 1 and on 2
// ranks: .mpirun=1. and .mpirun=2.) against CHOLMOD on the same matrices:
// the solutions of several right-hand sides agree to 1e-12; a second
// factorisation of the same pattern reuses the symbolic analysis; a singular
// matrix (a floating body: the pure Neumann Laplacian) and an indefinite one
// are refused, and a definite matrix factorises again after a refusal; and
// SparseCholesky made inside a DistributedFactorisations scope, and only
// there, factorises over the ranks, without what only CHOLMOD offers.
// Rank 0 prints; the two outputs differ only in the number of ranks.
#include <unilateral/lcp/distributed_cholesky.h>
#include <unilateral/lcp/sparse_cholesky.h>

#include "../mpi_test_tools.h"

#include <cmath>
#include <iostream>
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

  /// Relative difference of the distributed and CHOLMOD's solutions.
  double
  difference(const DistributedCholesky &distributed, const SparseMatrix &A)
  {
    const DenseMatrix B = right_hand_sides(A.rows());
    DenseMatrix       X, X_serial;
    distributed.solve(B, X);
    SparseCholesky serial;
    Counters       counters;
    serial.factorise(A, counters);
    serial.solve(B, X_serial);
    return (X - X_serial).norm() / X_serial.norm();
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  mpi_test::rank_0_prints();

  DistributedCholesky cholesky(MPI_COMM_WORLD);
  std::cout << "ranks: " << cholesky.n_ranks() << "\n";
  Counters           counters;
  const SparseMatrix A          = laplacian(30, 1.0, 0.0);
  const bool         factorised = cholesky.factorise(A, 1e-14, counters);
  std::cout << "Laplacian 30 x 30: factorised: " << yes_no(factorised)
            << ", solutions as CHOLMOD's to 1e-12: "
            << yes_no(difference(cholesky, A) <= 1e-12)
            << ", factor entries > 0: "
            << yes_no(cholesky.factor_nonzeros() > 0) << "\n";

  const SparseMatrix A2    = laplacian(30, 2.0, 0.5);
  const bool         again = cholesky.factorise(A2, 1e-14, counters);
  std::cout << "same pattern, new values: factorised: " << yes_no(again)
            << ", solutions as CHOLMOD's to 1e-12: "
            << yes_no(difference(cholesky, A2) <= 1e-12)
            << ", symbolic analyses: " << counters.symbolic_analyses
            << ", numeric factorisations: " << counters.numeric_factorisations
            << "\n";

  const bool singular =
    cholesky.factorise(laplacian(30, 1.0, 0.0, true), 1e-14, counters);
  std::cout << "Neumann Laplacian (singular): refused: " << yes_no(!singular)
            << ", no factor kept: " << yes_no(!cholesky.has_factor()) << "\n";
  const bool indefinite =
    cholesky.factorise(laplacian(30, 1.0, -3.0), 0.0, counters);
  std::cout << "Laplacian - 3 I (indefinite): refused: " << yes_no(!indefinite)
            << "\n";
  const bool after = cholesky.factorise(A, 1e-14, counters);
  std::cout << "definite after the refusals: factorised: " << yes_no(after)
            << ", solutions as CHOLMOD's to 1e-12: "
            << yes_no(difference(cholesky, A) <= 1e-12) << "\n";

  // The scope: SparseCholesky inside it distributed, outside not.
  {
    SparseCholesky outside;
    std::cout << "outside a scope: serial: " << yes_no(!outside.distributed())
              << "\n";
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
    std::cout << "inside a scope: distributed: " << yes_no(inside.distributed())
              << ", solutions as CHOLMOD's "
              << "to 1e-12: "
              << yes_no((X - X_serial).norm() <= 1e-12 * X_serial.norm())
              << ", inverse_gram declines: "
              << yes_no(!inside.inverse_gram(columns, G))
              << ", row modifications cost infinitely much: "
              << yes_no(std::isinf(inside.modification_path_entries({3})))
              << "\n";
  }
  SparseCholesky after_scope;
  std::cout << "after the scope closed: serial: "
            << yes_no(!after_scope.distributed()) << "\n";
}
