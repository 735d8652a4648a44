// No unneeded work, checked from the solver's counters (never from times):
// a factorisation is reused while its matrix does not change, the projection
// step reuses the regularised factor, one ordering/analysis serves a whole
// run, and optional phases run only when asked for.
#include <unilateral/base/blas_threads.h>
#include <unilateral/lcp/active_set_system.h>
#include <unilateral/lcp/sparse_cholesky.h>

#include "../lcp_test_tools.h"

#include <array>

using namespace test;

namespace
{
  // The 7-point Laplacian on a k x k x k grid (Dirichlet): SPD, with the
  // large separators of a 3D mesh.
  SparseMatrix
  laplacian_3d(const Index k)
  {
    std::vector<Eigen::Triplet<double>> entries;
    const auto                          index = [k](Index i, Index j, Index l) {
      return (i * k + j) * k + l;
    };
    for (Index i = 0; i < k; ++i)
      for (Index j = 0; j < k; ++j)
        for (Index l = 0; l < k; ++l)
          {
            const Index row = index(i, j, l);
            entries.emplace_back(row, row, 6.0);
            for (const auto &[di, dj, dl] :
                 {std::array<Index, 3>{1, 0, 0}, {0, 1, 0}, {0, 0, 1}})
              if (i + di < k && j + dj < k && l + dl < k)
                {
                  const Index neighbour = index(i + di, j + dj, l + dl);
                  entries.emplace_back(row, neighbour, -1.0);
                  entries.emplace_back(neighbour, row, -1.0);
                }
          }
    SparseMatrix A(k * k * k, k * k * k);
    A.setFromTriplets(entries.begin(), entries.end());
    return A;
  }

  // A chain of masses on springs: mass 0 rests on a support (u_0 >= 0), the
  // others hang freely (unconstrained) or touch a floor (every third one):
  // A is singular (the chain can translate), the solution unique.
  Problem
  chain(const Index n)
  {
    DenseMatrix A = DenseMatrix::Zero(n, n);
    for (Index i = 0; i + 1 < n; ++i)
      {
        A(i, i) += 1;
        A(i + 1, i + 1) += 1;
        A(i, i + 1) -= 1;
        A(i + 1, i) -= 1;
      }
    std::vector<Index>  S;
    std::vector<double> lower;
    for (Index i = 0; i < n; i += 3)
      {
        S.push_back(i);
        lower.push_back(-0.01 * i);
      }
    return make_problem(A, Vector::Constant(n, -1.0), S, lower);
  }

  // The 5-point Laplacian on a k x k grid (Dirichlet): SPD.
  SparseMatrix
  laplacian(const Index k)
  {
    std::vector<Eigen::Triplet<double>> entries;
    for (Index i = 0; i < k; ++i)
      for (Index j = 0; j < k; ++j)
        {
          const Index row = i * k + j;
          entries.emplace_back(row, row, 4.0);
          if (i > 0)
            entries.emplace_back(row, row - k, -1.0);
          if (i + 1 < k)
            entries.emplace_back(row, row + k, -1.0);
          if (j > 0)
            entries.emplace_back(row, row - 1, -1.0);
          if (j + 1 < k)
            entries.emplace_back(row, row + 1, -1.0);
        }
    SparseMatrix A(k * k, k * k);
    A.setFromTriplets(entries.begin(), entries.end());
    return A;
  }

  // The rows of column k of A (the pattern delete_row takes).
  std::vector<Index>
  column_pattern(const SparseMatrix &A, const Index k)
  {
    std::vector<Index> rows;
    for (SparseMatrix::InnerIterator it(A, k); it; ++it)
      rows.push_back(it.row());
    return rows;
  }

  // b_i = sin(1 + i): a load with no special structure.
  Vector
  smooth_load(const Index n)
  {
    Vector b(n);
    for (Index i = 0; i < n; ++i)
      b[i] = std::sin(1.0 + i);
    return b;
  }

  // The answer of a fresh active-set system for the fixed set @p X (fixed
  // values zero): what a reused or updated factor must reproduce.
  Vector
  fresh_answer(const SparseMatrix      &A,
               const std::vector<char> &X,
               const Vector            &b)
  {
    Counters        counters;
    ActiveSetSystem fresh(A, counters);
    Vector          x = Vector::Zero(A.rows());
    fresh.solve(X, b, x);
    return x;
  }

  // A with the rows and columns in @p fixed replaced by their diagonal.
  SparseMatrix
  with_fixed(const SparseMatrix &A, const std::vector<char> &fixed)
  {
    SparseMatrix K = A;
    for (Index j = 0; j < K.outerSize(); ++j)
      for (SparseMatrix::InnerIterator it(K, j); it; ++it)
        if ((fixed[it.row()] || fixed[j]) && it.row() != j)
          it.valueRef() = 0;
    return K;
  }

  bool
  has_phase(const Report &report, const std::string &phase)
  {
    for (const auto &entry : report.phase_times)
      if (entry.first == phase)
        return true;
    return false;
  }
} // namespace

int
main()
{
  // Row modifications of a factor (CHOLMOD's rowdel/rowadd) against a fresh
  // factorisation of the modified matrix, on a simplicial (12 x 12) and a
  // supernodal (120 x 120) factor; the last deletions follow additions, so
  // the row patterns given to rowdel come from a modified factor.
  for (const Index grid : {12, 120})
    {
      const SparseMatrix A = laplacian(grid);
      const Index        n = A.rows();
      const Vector       b = smooth_load(n);
      Counters           counters;
      SparseCholesky     updated;
      std::vector<char>  fixed(n, 0);
      updated.factorise(A, counters);
      const auto agrees_with_fresh = [&]() {
        SparseCholesky fresh;
        fresh.factorise(with_fixed(A, fixed), counters);
        Vector x_updated, x_fresh;
        updated.solve(b, x_updated);
        fresh.solve(b, x_fresh);
        return relative_difference(x_updated, x_fresh) < 1e-12;
      };
      const auto delete_rows = [&](const std::vector<Index> &rows) {
        for (const Index k : rows)
          {
            updated.delete_row(k, A.coeff(k, k), column_pattern(A, k));
            fixed[k] = 1;
          }
      };
      std::cout << "laplacian(" << grid << "):\n";
      delete_rows({5, 40, 77, 100, 143});
      std::cout << "  factor with 5 rows deleted solves as a fresh one: "
                << yes_no(agrees_with_fresh()) << "\n";
      for (const Index k : {40, 143})
        {
          fixed[k] = 0;
          std::vector<Index>  rows;
          std::vector<double> values;
          for (SparseMatrix::InnerIterator it(A, k); it; ++it)
            if (!fixed[it.row()])
              {
                rows.push_back(it.row());
                values.push_back(it.value());
              }
          updated.add_row(k, rows, values);
        }
      std::cout << "  and with 2 of them added back: "
                << yes_no(agrees_with_fresh())
                << ", modification flops counted: "
                << yes_no(updated.modification_flops() > 0 &&
                          updated.modification_flops() <
                            updated.factorisation_flops())
                << "\n";
      delete_rows({41, 40, 130});
      std::cout << "  and with 3 more deleted after that: "
                << yes_no(agrees_with_fresh()) << "\n";
    }
  // A pattern factorised many times (try_nested_dissection) is analysed a
  // second time, in METIS's nested dissection, only where AMD leaves large
  // dense fronts: the 7-point Laplacian on a 25^3 grid (AMD about 600 flops
  // per entry of L), which METIS orders with fewer flops and which then
  // solves as AMD's factor does; not the 5-point one on 120 x 120 (AMD
  // about 40 flops per entry).
  {
    const auto compare = [](const SparseMatrix &A, const std::string &name) {
      const Vector   b = smooth_load(A.rows());
      Counters       amd_counters, tried_counters;
      SparseCholesky amd, tried;
      tried.try_nested_dissection = true;
      amd.factorise(A, amd_counters);
      tried.factorise(A, tried_counters);
      Vector x_amd, x_tried;
      amd.solve(b, x_amd);
      tried.solve(b, x_tried);
      std::cout << name << " with the nested-dissection trial: "
                << "symbolic analyses " << tried_counters.symbolic_analyses
                << ", "
                << (tried.factorisation_flops() < amd.factorisation_flops() ?
                      "fewer flops than AMD" :
                    tried.factorisation_flops() == amd.factorisation_flops() ?
                      "AMD's flops" :
                      "more flops than AMD (wrong)")
                << ", solves as AMD's factor: "
                << yes_no(relative_difference(x_tried, x_amd) < 1e-12) << "\n";
    };
    compare(laplacian_3d(25), "laplacian_3d(25)");
    compare(laplacian(120), "laplacian(120)");
  }
  // A pattern factorised again is permuted once and refactorised from the
  // kept permutation (supernodal factors only): each new set of values on
  // the same pattern solves as a fresh factorisation of it does.
  {
    const SparseMatrix A = laplacian(120);
    const Vector       b = smooth_load(A.rows());
    Counters           counters;
    SparseCholesky     reused;
    bool               same = true;
    for (const double shift : {0.0, 0.5, 3.0})
      {
        SparseMatrix shifted = A;
        for (Index j = 0; j < shifted.outerSize(); ++j)
          for (SparseMatrix::InnerIterator it(shifted, j); it; ++it)
            if (it.row() == j)
              it.valueRef() += shift * (1 + j % 7);
        SparseCholesky fresh;
        Counters       fresh_counters;
        reused.factorise(shifted, counters);
        fresh.factorise(shifted, fresh_counters);
        Vector x_reused, x_fresh;
        reused.solve(b, x_reused);
        fresh.solve(b, x_fresh);
        same = same && relative_difference(x_reused, x_fresh) < 1e-14;
      }
    std::cout << "laplacian(120) refactorised twice on its kept permutation: "
              << "1 analysis, 3 factorisations: "
              << yes_no(counters.symbolic_analyses == 1 &&
                        counters.numeric_factorisations == 3)
              << ", each as a fresh factor: " << yes_no(same) << "\n";
  }
  // B' A^-1 B by forward solves along the elimination tree (inverse_gram)
  // against full solves with the same factor: supernodal (120 x 120), and
  // the simplicial L D L' copy after row deletions; 70 columns of two or
  // three entries each, so three blocks of 32 and the products between
  // them.
  {
    const SparseMatrix                  A = laplacian(120);
    const Index                         n = A.rows();
    std::vector<Eigen::Triplet<double>> entries;
    for (Index c = 0; c < 70; ++c)
      {
        const Index row = (c * 7919) % n;
        entries.emplace_back(row, c, 1.0 + c % 3);
        entries.emplace_back((row + 121) % n, c, -0.5);
        if (c % 4 == 0)
          entries.emplace_back((row * 31 + 5) % n, c, 0.25);
      }
    SparseMatrix B(n, 70);
    B.setFromTriplets(entries.begin(), entries.end());
    const DenseMatrix B_dense = DenseMatrix(B);
    const auto        agrees  = [&](const SparseCholesky &cholesky) {
      DenseMatrix G, X;
      if (!cholesky.inverse_gram(B, G))
        return false;
      cholesky.solve(B_dense, X);
      const DenseMatrix reference = B_dense.transpose() * X;
      return (G - reference).norm() <= 1e-12 * reference.norm();
    };
    Counters       counters;
    SparseCholesky cholesky;
    cholesky.factorise(A, counters);
    std::cout << "B' A^-1 B forward along the tree, supernodal factor: "
              << yes_no(agrees(cholesky));
    for (const Index k : {3000, 7260, 12001})
      cholesky.delete_row(k, A.coeff(k, k), column_pattern(A, k));
    std::cout << ", simplicial L D L' after 3 row deletions: "
              << yes_no(cholesky.has_modification_copy() && agrees(cholesky))
              << "\n";
  }
  // The cost of modifications is predicted from the analysed factor alone,
  // before any is made: about four flops per entry of L on the changed
  // rows' elimination paths. Checked against CHOLMOD's own count on a small
  // (simplicial) and a larger (supernodal) factor.
  for (const unsigned int grid : {12u, 120u})
    {
      const SparseMatrix A = laplacian(grid);
      Counters           counters;
      SparseCholesky     cholesky;
      cholesky.factorise(A, counters);
      const std::vector<Index> rows = {5, 40, 77, 100, 143};
      const double predicted = 4 * cholesky.modification_path_entries(rows);
      for (const Index k : rows)
        cholesky.delete_row(k, A.coeff(k, k), column_pattern(A, k));
      const double ratio = predicted / cholesky.modification_flops();
      std::cout << "laplacian(" << grid
                << "): predicted modification flops within 25% of CHOLMOD's "
                   "count: "
                << yes_no(ratio > 0.75 && ratio < 1.25) << "\n";
    }
  {
    // The active-set system updates its factor for a nearby fixed set and
    // gives the answer of a fresh factorisation (on a grid large enough
    // that two changes cost far less than a factorisation).
    const SparseMatrix A = laplacian(40);
    const Index        n = A.rows();
    const Vector       b = smooth_load(n);
    Counters           system_counters;
    ActiveSetSystem    system(A, system_counters);
    std::vector<char>  X(n, 0);
    for (Index i = 0; i < n; i += 7)
      X[i] = 1;
    Vector x = Vector::Zero(n);
    system.solve(X, b, x);
    X[14] = 0;
    X[15] = 1;
    x[15] = 0; // the fixed value
    system.solve(X, b, x);
    const Vector x_fresh = fresh_answer(A, X, b);
    std::cout << "active-set system, 2 changes: factorised once, updated "
                 "once (2 rows): "
              << yes_no(system_counters.numeric_factorisations == 1 &&
                        system_counters.modified_factorisations == 1 &&
                        system_counters.factor_row_modifications == 2)
              << ", same answer: "
              << yes_no(relative_difference(x, x_fresh) < 1e-12) << "\n";
  }

  {
    // A factor of a fixed set a few indices away preconditions CG only
    // where the expected 2 changes + 2 iterations cost less than a
    // factorisation (ActiveSetSystem::cg_iteration_cost): on a 3D Laplacian
    // (large fronts: many flops per entry of L) one change is solved by CG;
    // on a 2D one (few flops per entry) three changes are factorised anew.
    // The first third of the unknowns is fixed, so A_FF is factorised on
    // its own and never updated row by row. The fixed values are zero:
    // CG's test must not ask for an exact zero residual on the fixed rows,
    // which round-off grants on some BLAS thread counts and not on others,
    // so each case runs on one and on two threads.
    const auto nearby_set = [](const SparseMatrix &A,
                               const unsigned int  changes,
                               const char         *name,
                               const int           blas_threads) {
      const unilateral::blas::ScopedThreads threads(blas_threads);
      const Index                           n = A.rows();
      const Vector                          b = smooth_load(n);
      Counters                              counters;
      ActiveSetSystem                       system(A, counters);
      std::vector<char>                     X(n, 0);
      for (Index i = 0; i < n / 3; ++i)
        X[i] = 1;
      Vector x = Vector::Zero(n);
      system.solve(X, b, x);
      // Free the last fixed indices and fix the first free one.
      for (unsigned int c = 0; c + 1 < changes; ++c)
        X[n / 3 - 1 - c] = 0;
      X[n / 3] = 1;
      x        = Vector::Zero(n);
      system.solve(X, b, x);
      const Vector x_fresh = fresh_answer(A, X, b);
      std::cout << name << ", " << changes << " change(s), " << blas_threads
                << " BLAS thread(s): "
                << (counters.reused_factorisations == 1 &&
                        counters.numeric_factorisations == 1 ?
                      "CG with the nearby factor" :
                    counters.reused_factorisations == 0 &&
                        counters.numeric_factorisations == 2 &&
                        counters.cg_iterations == 0 ?
                      "factorised anew, no CG tried" :
                      "CG tried, then factorised")
                << ", same answer: "
                << yes_no(relative_difference(x, x_fresh) < 1e-12) << "\n";
    };
    for (const int blas_threads : {1, 2})
      {
        nearby_set(laplacian_3d(25), 1, "laplacian_3d(25)", blas_threads);
        nearby_set(laplacian(120), 3, "laplacian(120)", blas_threads);
      }
  }

  {
    // A third of the unknowns fixed, spread over the grid (A_FF's factor
    // about as large as the full pattern's): A_FF is factorised on its
    // own; a change of 20 indices (at most 1/500 of the unknowns: the set
    // is settling, and more than CG's 16) takes the full pattern, so that
    // the next change of 5 is an update of it row by row. Each answer as
    // a fresh system's.
    const SparseMatrix A = laplacian(120);
    const Index        n = A.rows();
    const Vector       b = smooth_load(n);
    Counters           counters;
    ActiveSetSystem    system(A, counters);
    std::vector<char>  X(n, 0);
    for (Index i = 0; i < n; i += 3)
      X[i] = 1;
    Vector x = Vector::Zero(n);
    system.solve(X, b, x);
    const bool reduced_first = counters.numeric_factorisations == 1 &&
                               !system.factor()->reduced_index.empty();
    const auto change = [&](const Index first, const Index count) {
      for (Index i = first; i < first + 3 * count; i += 3)
        X[i] = 0; // free one, fix its neighbour
      for (Index i = first + 1; i < first + 3 * count; i += 6)
        X[i] = 1;
      x = Vector::Zero(n);
      system.solve(X, b, x);
      return relative_difference(x, fresh_answer(A, X, b)) < 1e-12;
    };
    const bool same_after_20 = change(3000, 13); // 13 freed, 7 fixed
    const bool full_after_20 = counters.numeric_factorisations == 2 &&
                               counters.modified_factorisations == 0 &&
                               system.factor()->reduced_index.empty();
    const bool same_after_5    = change(9000, 3); // 3 freed, 2 fixed
    const bool updated_after_5 = counters.numeric_factorisations == 2 &&
                                 counters.modified_factorisations == 1 &&
                                 counters.factor_row_modifications == 5;
    std::cout << "a settling active set (a third fixed): A_FF first: "
              << yes_no(reduced_first)
              << ", 20 changes factorise the full pattern: "
              << yes_no(full_after_20 && same_after_20)
              << ", the next 5 update it row by row: "
              << yes_no(updated_after_5 && same_after_5) << "\n";
  }

  {
    // A later system on the same A (the projection after the regularised
    // solve) inherits the factor and, with it, the ordering of A: a fixed
    // set far from the inherited one is factorised anew without a second
    // AMD ordering.
    const SparseMatrix A = laplacian(40);
    const Index        n = A.rows();
    const Vector       b = smooth_load(n);
    Counters           counters;
    std::vector<char>  X(n, 0);
    for (Index i = 0; i < n; i += 7)
      X[i] = 1;
    Vector          x = Vector::Zero(n);
    ActiveSetSystem first(A, counters);
    first.solve(X, b, x);
    for (Index i = 0; i < n; i += 5)
      X[i] = 1;
    ActiveSetSystem later(A, counters, first.factor());
    later.solve(X, b, x);
    std::cout << "a later system on the same A: factorised again: "
              << yes_no(counters.numeric_factorisations == 2)
              << ", ordered once: " << yes_no(counters.orderings == 1) << "\n";
  }

  const Problem problem = chain(60);
  Vector        u;

  // PSOR: A_EE is factorised once, however many sweeps run.
  {
    SolverParameters no_projection;
    no_projection.projection = false;
    const Report psor =
      solve_with(problem, method("psor"), u, 1e-2, no_projection);
    // Regularised and not projected, so the answer is honestly reported
    // "inaccurate" against the original problem.
    std::cout << "psor: " << to_string(psor.status)
              << " (regularised, not projected), sweeps > 1: "
              << yes_no(psor.iterations > 1)
              << "\n  one ordering of A and one symbolic analysis of A_EE: "
              << yes_no(psor.counters.orderings == 1 &&
                        psor.counters.symbolic_analyses == 1)
              << ", factorised once: "
              << yes_no(psor.counters.numeric_factorisations == 1) << "\n";
  }

  // PDAS with regularisation: the projection's first system (same active
  // set, A instead of A + eps I) is solved with the regularised factor as a
  // preconditioner, not factorised anew.
  {
    const Report pdas = solve_with(problem, method("pdas"), u, 1e-12);
    std::cout << "pdas + projection: " << to_string(pdas.status)
              << ", projection iterations: " << pdas.projection_iterations
              << "\n  projection reused the regularised factor: "
              << yes_no(pdas.counters.reused_factorisations >= 1)
              << "\n  factorisations <= pdas iterations + 1 (the start): "
              << yes_no(pdas.counters.numeric_factorisations <=
                        pdas.iterations + 1)
              << "\n";
  }

  // 'auto' regularisation where the scene expected a definite A (an LCP
  // read from files) but A is singular, as this chain's. The paper's PDAS
  // (no safeguards) meets a singular system, then regularises with 1e-9 and
  // projects. With its safeguards PDAS closes the constraints that the free
  // motion moves (resolve_subset) and needs no regularisation.
  {
    // Two bodies of two nodes each, each held at its first node; the load
    // pulls that node off its support, so PDAS from u = 0 releases it and
    // the body floats (A_FF singular). Solution: u = (0, -2, 0, -1).
    DenseMatrix two_bodies = DenseMatrix::Zero(4, 4);
    for (const Index first : {0, 2})
      {
        two_bodies(first, first) = two_bodies(first + 1, first + 1) = 1;
        two_bodies(first, first + 1) = two_bodies(first + 1, first) = -1;
      }
    Vector load(4);
    load << 1, -2, 0, -1;
    Vector exact(4);
    exact << 0, -2, 0, -1;
    for (const unsigned int safeguard : {0u, 10u})
      {
        SolverParameters parameters;
        parameters.set("PDAS/Safeguard", std::to_string(safeguard));
        const Report report =
          solve_with(make_problem(two_bodies, load, {0, 2}, {0, 0}),
                     method("pdas"),
                     u,
                     -1,
                     parameters);
        std::cout << "pdas" << (safeguard == 0 ? " without safeguards" : "")
                  << ", eps = auto, singular A: " << to_string(report.status)
                  << ", regularised after all: "
                  << yes_no(report.regularisation > 0 && report.projected)
                  << ", resolved exactly: "
                  << yes_no(report.counters.resolved_subsets > 0)
                  << ", u exact: "
                  << yes_no(relative_difference(u, exact) < 1e-12) << "\n";
      }
  }

  // Interior point and its projection (A is singular: eps = auto, then the
  // projection on A): the projection's systems take over the interior
  // point's analysis of A's pattern and analyse nothing themselves.
  {
    Vector pdas_u;
    solve_with(problem, method("pdas"), pdas_u);
    const Report ip = solve_with(problem, method("interior_point"), u);
    std::cout << "interior point + projection: " << to_string(ip.status)
              << ", projected: " << yes_no(ip.projected)
              << "\n  one symbolic analysis in all (the projection took the "
                 "interior point's): "
              << yes_no(ip.counters.symbolic_analyses == 1)
              << ", the answer of PDAS: "
              << yes_no(relative_difference(u, pdas_u) < 1e-10) << "\n";
  }

  // Nothing touches (a membrane the load lifts off an obstacle far
  // below): every multiplier of the interior point's answer is rounding
  // noise, and the projection must start with every constraint open, not
  // with the half that the ratio of noise to slack would close.
  {
    const Index         k = 20;
    const SparseMatrix  L = laplacian(k);
    std::vector<Index>  S(k * k);
    std::vector<double> lower(k * k, -1e3);
    for (Index i = 0; i < k * k; ++i)
      S[i] = i;
    const Problem lifted =
      make_problem(DenseMatrix(L), Vector::Constant(k * k, 1.0), S, lower);
    const Report ip = solve_with(lifted, method("interior_point"), u);
    std::cout << "interior point, nothing touches: " << to_string(ip.status)
              << ", one projection iteration: "
              << yes_no(ip.projection_iterations == 1) << "\n";
  }

  // Interior point: one analysis of the pattern for all its Newton systems.
  {
    SolverParameters parameters;
    parameters.projection = false;
    const Report ip =
      solve_with(problem, method("interior_point"), u, -1, parameters);
    std::cout << "interior point: " << ip.iterations
              << " Newton systems, one symbolic analysis: "
              << yes_no(ip.counters.symbolic_analyses == 1)
              << ", one factorisation each: "
              << yes_no(ip.counters.numeric_factorisations == ip.iterations)
              << "\n";
  }

  // Predictor-corrector: Mehrotra's start costs one factorisation;
  // Gondzio's correctors are extra solves with each iteration's factor,
  // kept only where they lengthen the step. Both leave the answer, that of
  // PDAS (exact). On a membrane pressed onto a bowl (part of it touches)
  // the affine steps are short.
  {
    Problem             obstacle;
    std::vector<double> lower;
    const Index         k = 30;
    obstacle.A            = laplacian(k);
    obstacle.b            = Vector::Constant(k * k, -50.0 / (k * k));
    for (Index i = 0; i < k * k; ++i)
      {
        const double x = (i % k + 1.0) / (k + 1) - 0.5,
                     y = (i / k + 1.0) / (k + 1) - 0.5;
        obstacle.constrained.push_back(i);
        lower.push_back(x * x + y * y - 0.2);
      }
    obstacle.lower_bound = Eigen::Map<const Vector>(lower.data(), k * k);
    check_and_normalise(obstacle);

    SolverParameters parameters;
    parameters.projection = false;
    parameters.set("Interior point/Centrality correctors", "0");
    const Method predictor_corrector{
      &SolverRegistry::get("interior_point"),
      false,
      &SolverRegistry::get("interior_point").variants.front()};
    Vector exact_u, mehrotra_u, gondzio_u;
    solve_with(obstacle, method("pdas"), exact_u, 0);
    const Report mehrotra =
      solve_with(obstacle, predictor_corrector, mehrotra_u, 0, parameters);
    parameters.set("Interior point/Centrality correctors", "2");
    const Report gondzio =
      solve_with(obstacle, predictor_corrector, gondzio_u, 0, parameters);
    // Solves: two per iteration, one for the start, one per corrector
    // tried (at most one rejected per iteration).
    const int kept  = static_cast<int>(gondzio.counters.centrality_correctors);
    const int tried = static_cast<int>(gondzio.counters.triangular_solves) -
                      2 * static_cast<int>(gondzio.iterations) - 1;
    std::cout << "interior point, predictor-corrector: without correctors "
              << mehrotra.iterations
              << " iterations, one factorisation and two solves each, one "
                 "of each for the start: "
              << yes_no(mehrotra.counters.numeric_factorisations ==
                          mehrotra.iterations + 1 &&
                        mehrotra.counters.triangular_solves ==
                          2 * mehrotra.iterations + 1 &&
                        mehrotra.counters.centrality_correctors == 0)
              << "\n  with 2 correctors " << gondzio.iterations
              << " iterations, one factorisation each and one for the "
                 "start: "
              << yes_no(gondzio.counters.numeric_factorisations ==
                        gondzio.iterations + 1)
              << ", correctors kept: " << yes_no(kept > 0)
              << ", one solve per corrector tried: "
              << yes_no(tried >= kept &&
                        tried <= kept + static_cast<int>(gondzio.iterations))
              << ", the answer of PDAS: "
              << yes_no(relative_difference(gondzio_u, exact_u) < 1e-6 &&
                        relative_difference(mehrotra_u, exact_u) < 1e-6)
              << "\n";
  }

  // Optional phases run only when asked for.
  {
    const Report full = solve_with(problem, method("pdas"), u, 1e-12);
    const Report schur =
      solve_with(problem, {&SolverRegistry::get("pdas"), true}, u, 1e-12);
    std::cout << "Schur complement formed only when asked: "
              << yes_no(!has_phase(full, "schur complement") &&
                        has_phase(schur, "schur complement"))
              << "\n";
    SolverParameters no_projection;
    no_projection.projection = false;
    const Report unprojected =
      solve_with(problem, method("pdas"), u, 1e-12, no_projection);
    std::cout << "projection only when asked: "
              << yes_no(full.projected && !unprojected.projected &&
                        !has_phase(unprojected, "projection"))
              << "\n";
    const Report definite = solve_with(make_problem(DenseMatrix::Identity(3, 3),
                                                    Vector::Ones(3),
                                                    {0, 1, 2},
                                                    {0, 0, 0}),
                                       method("pdas"),
                                       u);
    std::cout << "no regularisation or projection for a definite matrix "
                 "with eps = auto: "
              << yes_no(definite.regularisation == 0 && !definite.projected)
              << "\n";
  }
}
