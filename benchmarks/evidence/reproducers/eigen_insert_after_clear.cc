// Why PDAS factorisations are slow on large walls (see
// pdas_slow_restricted_factorisation.prm). ActiveSetSystem::factorise builds
// A_FF in a member matrix that already held a larger matrix:
//     reduced.resize(n_free, n_free); reduced.data().clear();
//     reduced.reserve(column_sizes); ... reduced.insert(i, j) = value;
// resize() and data().clear() keep the old allocation. reserve() then leaves
// m_data.size() < m_data.allocatedSize(), and Eigen 3.4's insert() takes its
// slow path on every call: reserveInnerVectors(Constant(outerSize, 2)), an
// O(n) pass per inserted entry, so the assembly is O(n nnz). A matrix with no
// old allocation (swap with a fresh one, or setFromTriplets) is instant.
//   g++ -O2 -I/usr/include/eigen3 eigen_insert_after_clear.cc && ./a.out
// On this machine: 8-15 s against 0.007 s for n = 20000.
#include <Eigen/Sparse>

#include <chrono>
#include <iostream>
#include <vector>

using SparseMatrix = Eigen::SparseMatrix<double>;

int
main()
{
  const int                           n = 20000, half_bandwidth = 15;
  std::vector<Eigen::Triplet<double>> entries;
  for (int j = 0; j < n; ++j)
    for (int i = std::max(0, j - half_bandwidth);
         i <= std::min(n - 1, j + half_bandwidth);
         ++i)
      entries.emplace_back(i, j, 1.0);
  SparseMatrix A(n, n);
  A.setFromTriplets(entries.begin(), entries.end());
  std::vector<char> fixed(n, 0);
  for (int i = 0; i < n; i += 3)
    fixed[i] = 1;

  for (const bool fresh : {false, true})
    {
      SparseMatrix     reduced = A; // what the member held before
      const auto       start   = std::chrono::steady_clock::now();
      std::vector<int> index(n, -1);
      int              n_free = 0;
      for (int i = 0; i < n; ++i)
        if (!fixed[i])
          index[i] = n_free++;
      if (fresh)
        {
          SparseMatrix empty(n_free, n_free);
          reduced.swap(empty);
        }
      else
        {
          reduced.resize(n_free, n_free);
          reduced.data().clear();
        }
      std::vector<int> column_sizes(n_free, 0);
      for (int j = 0; j < n; ++j)
        if (!fixed[j])
          for (SparseMatrix::InnerIterator it(A, j); it; ++it)
            column_sizes[index[j]] += !fixed[it.row()];
      reduced.reserve(column_sizes);
      for (int j = 0; j < n; ++j)
        if (!fixed[j])
          for (SparseMatrix::InnerIterator it(A, j); it; ++it)
            if (!fixed[it.row()])
              reduced.insert(index[it.row()], index[j]) = it.value();
      reduced.makeCompressed();
      std::cout << (fresh ? "fresh matrix:          " :
                            "resize + data().clear: ")
                << std::chrono::duration<double>(
                     std::chrono::steady_clock::now() - start)
                     .count()
                << " s, nnz " << reduced.nonZeros() << '\n';
    }
}
