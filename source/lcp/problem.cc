#include <unilateral/base/input_error.h>
#include <unilateral/lcp/problem.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace unilateral::lcp
{
  Problem::Problem(Problem &&other) noexcept
  {
    *this = std::move(other);
  }

  Problem &
  Problem::operator=(Problem &&other) noexcept
  {
    A.swap(other.A);
    SparseMatrix().swap(other.A); // our former A goes with the temporary
    b                  = std::move(other.b);
    constrained        = std::move(other.constrained);
    lower_bound        = std::move(other.lower_bound);
    floating_bodies    = other.floating_bodies;
    mostly_active      = other.mostly_active;
    known_semidefinite = other.known_semidefinite;
    definite           = other.definite;
    eliminated         = other.eliminated;
    energy_unit        = other.energy_unit;
    tearing            = std::move(other.tearing);
    hierarchy          = std::move(other.hierarchy);
    return *this;
  }

  std::vector<char>
  Problem::constrained_mask() const
  {
    std::vector<char> mask(size(), 0);
    for (const Index i : constrained)
      mask[i] = 1;
    return mask;
  }

  Vector
  Problem::full_lower_bound() const
  {
    Vector bound =
      Vector::Constant(size(), -std::numeric_limits<double>::infinity());
    for (Index k = 0; k < n_constrained(); ++k)
      bound[constrained[k]] = lower_bound[k];
    return bound;
  }

  namespace
  {
    [[noreturn]] void
    fail(const std::string &what)
    {
      throw InputError(what);
    }

    // A square, b and the bounds of the sizes A and S give.
    void
    check_dimensions(const Problem &problem)
    {
      const Index n = problem.size();
      if (problem.A.rows() != problem.A.cols())
        fail("LCP matrix A is not square: " + std::to_string(problem.A.rows()) +
             " x " + std::to_string(problem.A.cols()));
      if (problem.A.rows() != n)
        fail("dimension mismatch: A is " + std::to_string(problem.A.rows()) +
             " x " + std::to_string(problem.A.cols()) + " but b has " +
             std::to_string(n) + " entries");
      if (static_cast<Index>(problem.lower_bound.size()) !=
          problem.n_constrained())
        fail("dimension mismatch: " + std::to_string(problem.n_constrained()) +
             " constrained indices but " +
             std::to_string(problem.lower_bound.size()) + " lower bounds");
    }

    // b finite, S within 1..n, bounds finite.
    void
    check_b_and_bounds(const Problem &problem)
    {
      const Index n = problem.size();
      for (Index i = 0; i < n; ++i)
        if (!std::isfinite(problem.b[i]))
          fail("entry " + std::to_string(i + 1) +
               " of b (counted from 1) is not a finite number");
      for (Index k = 0; k < problem.n_constrained(); ++k)
        {
          const Index i = problem.constrained[k];
          if (i < 0 || i >= n)
            fail("constrained index " + std::to_string(i + 1) +
                 " is outside 1.." + std::to_string(n) + " (counted from 1)");
          // -infinity too: the answer checks scale by |l| (an index
          // without a bound belongs outside S).
          if (!std::isfinite(problem.lower_bound[k]))
            fail("lower bound of index " + std::to_string(i + 1) +
                 " (counted from 1) is not a finite number (an unbounded "
                 "index belongs outside S)");
        }
    }

    // S sorted (the bounds carried along), no index twice.
    void
    sort_constrained(Problem &problem)
    {
      std::vector<Index> order(problem.n_constrained());
      std::iota(order.begin(), order.end(), 0);
      std::sort(order.begin(), order.end(), [&](Index a, Index b) {
        return problem.constrained[a] < problem.constrained[b];
      });
      std::vector<Index> sorted(order.size());
      Vector             bounds(order.size());
      for (std::size_t k = 0; k < order.size(); ++k)
        {
          sorted[k] = problem.constrained[order[k]];
          bounds[k] = problem.lower_bound[order[k]];
          if (k > 0 && sorted[k] == sorted[k - 1])
            fail("constrained index " + std::to_string(sorted[k] + 1) +
                 " (counted from 1) appears twice in S");
        }
      problem.constrained = std::move(sorted);
      problem.lower_bound = std::move(bounds);
    }

    // Every entry of A finite; returns the largest magnitude.
    double
    check_finite_entries(const Problem &problem)
    {
      const Index n         = problem.size();
      double      max_entry = 0;
      for (Index j = 0; j < n; ++j)
        for (SparseMatrix::InnerIterator it(problem.A, j); it; ++it)
          {
            if (!std::isfinite(it.value()))
              fail("the entry of A in row " + std::to_string(it.row() + 1) +
                   ", column " + std::to_string(j + 1) +
                   " (counted from 1) is not a finite number");
            max_entry = std::max(max_entry, std::abs(it.value()));
          }
      return max_entry;
    }

    // Symmetry, relative to each entry's scale: every entry against its
    // mirror, without a transposed copy (building A - A^T costs far more
    // than the comparison on large matrices; benchmarks/masonry_tables/
    // README.md, "Design measurements"). The columns are walked in order,
    // so the mirrors of column j's entries below the diagonal, (j, i) in
    // column i, are met in increasing j: one cursor per column finds each
    // in a single pass, and an entry above the diagonal that the cursor
    // passes over has no mirror.
    void
    check_symmetry(Problem &problem, const double max_entry)
    {
      const Index n      = problem.size();
      bool        sorted = true;
      for (Index j = 0; j < n && sorted; ++j)
        sorted = std::is_sorted(problem.A.innerIndexPtr() +
                                  problem.A.outerIndexPtr()[j],
                                problem.A.innerIndexPtr() +
                                  problem.A.outerIndexPtr()[j + 1]);
      if (!sorted) // a transposition sorts every column
        problem.A =
          SparseMatrix(SparseMatrix(problem.A.transpose()).transpose());
      const auto *const column_start = problem.A.outerIndexPtr();
      const auto *const row_index    = problem.A.innerIndexPtr();
      const double     *value        = problem.A.valuePtr();
      const Vector      diagonal     = problem.A.diagonal();
      const auto        compare      = [&](const Index  row,
                               const Index  column,
                               const double entry,
                               const double mirror) {
        // Relative to the entries' own scale (for a semidefinite A, |a_ij|
        // <= sqrt(a_ii a_jj)): an asymmetry of order one beside an entry of
        // 1e12 elsewhere is one. Plus 1e-14 of the largest entry: the
        // rounding of a product T^T K T, where a diagonal entry that came
        // out of cancellation is no scale.
        const double scale =
          std::max({std::sqrt(std::abs(diagonal[row] * diagonal[column])),
                    std::abs(entry),
                    std::abs(mirror)});
        if (std::abs(entry - mirror) <= 1e-12 * scale + 1e-14 * max_entry)
          return;
        std::ostringstream message;
        // The difference too: entries equal to six digits would read alike.
        message << "A is not symmetric: its entry in row " << row + 1
                << ", column " << column + 1 << " is " << entry
                << ", the one in row " << column + 1 << ", column " << row + 1
                << " is " << mirror << " (counted from 1; they differ by "
                << std::setprecision(3) << std::abs(entry - mirror)
                << "); the LCP needs a symmetric positive semidefinite A";
        fail(message.str());
      };
      // cursor[i]: the first entry of column i not yet matched.
      std::vector<Index> cursor(column_start, column_start + n);
      // Column i's entries above row j whose mirrors were never asked for.
      const auto unmatched_up_to = [&](const Index i, const Index j) {
        for (; cursor[i] < column_start[i + 1] && row_index[cursor[i]] < j;
             ++cursor[i])
          compare(row_index[cursor[i]], i, value[cursor[i]], 0.0);
      };
      for (Index j = 0; j < n; ++j)
        for (auto k = column_start[j]; k < column_start[j + 1]; ++k)
          {
            const Index i = row_index[k];
            if (i <= j)
              continue;
            unmatched_up_to(i, j);
            double mirror = 0;
            if (cursor[i] < column_start[i + 1] && row_index[cursor[i]] == j)
              mirror = value[cursor[i]++];
            compare(i, j, value[k], mirror);
          }
      for (Index i = 0; i < n; ++i)
        unmatched_up_to(i, i);
    }

    // Every diagonal entry must be in the pattern (the factorisations modify
    // it in place) and nonnegative (a necessary condition for A >= 0).
    void
    check_and_complete_diagonal(Problem &problem)
    {
      const Index n                 = problem.size();
      bool        diagonal_complete = true;
      for (Index j = 0; j < n; ++j)
        {
          bool found = false;
          for (SparseMatrix::InnerIterator it(problem.A, j); it; ++it)
            if (it.row() == j)
              {
                found = true;
                if (it.value() < 0)
                  {
                    std::ostringstream message;
                    message << "the diagonal entry of A in row " << j + 1
                            << " (counted from 1) is " << it.value()
                            << " < 0: A is not positive semidefinite";
                    fail(message.str());
                  }
              }
          diagonal_complete = diagonal_complete && found;
        }
      if (!diagonal_complete)
        {
          std::vector<Eigen::Triplet<double, Index>> entries;
          entries.reserve(problem.A.nonZeros() + n);
          for (Index j = 0; j < n; ++j)
            {
              entries.emplace_back(j, j, 0.0);
              for (SparseMatrix::InnerIterator it(problem.A, j); it; ++it)
                entries.emplace_back(it.row(), j, it.value());
            }
          problem.A.setFromTriplets(entries.begin(), entries.end());
          problem.A.makeCompressed();
        }
    }
  } // namespace

  void
  check_and_normalise(Problem &problem)
  {
    check_dimensions(problem);
    check_b_and_bounds(problem);
    sort_constrained(problem);
    problem.A.makeCompressed();
    const double max_entry = check_finite_entries(problem);
    check_symmetry(problem, max_entry);
    check_and_complete_diagonal(problem);
  }

  void
  clamp_rounded_diagonal(DenseMatrix              &schur,
                         const SparseMatrix       &A,
                         const std::vector<Index> &indices)
  {
    for (Index j = 0; j < schur.rows(); ++j)
      if (schur(j, j) < 0 &&
          schur(j, j) >= -1e-10 * std::abs(A.coeff(indices[j], indices[j])))
        schur(j, j) = 0;
  }

  std::vector<Index>
  diagonal_positions(const SparseMatrix &A)
  {
    std::vector<Index> position(A.outerSize(), -1);
    if (A.isCompressed())
      for (Index j = 0; j < A.outerSize(); ++j)
        for (Index k = A.outerIndexPtr()[j]; k < A.outerIndexPtr()[j + 1]; ++k)
          if (A.innerIndexPtr()[k] == j)
            position[j] = k;
    for (const Index k : position)
      if (k < 0)
        throw std::logic_error("diagonal missing from the pattern of a "
                               "compressed A (call check_and_normalise "
                               "first)");
    return position;
  }

  double
  diagonal_scale(const SparseMatrix &A)
  {
    const double mean = A.rows() > 0 ? A.diagonal().mean() : 1.0;
    return mean > 0 ? mean : 1.0;
  }

  Vector
  absolute_product(const SparseMatrix &A, const Vector &u)
  {
    Vector product = Vector::Zero(A.rows());
    for (Index j = 0; j < A.outerSize(); ++j)
      for (SparseMatrix::InnerIterator it(A, j); it; ++it)
        product[it.row()] += std::abs(it.value() * u[j]);
    return product;
  }

  std::string
  singular_cause(const Problem &problem)
  {
    if (problem.definite)
      return "A is positive definite, so this is round-off: are its "
             "unknowns of very different sizes in the units given?";
    return "some body is held by no active constraint";
  }

  // Summed in long double: on an ill-conditioned A the terms A_ij u_i u_j
  // cancel to a billionth of their size, and in double the energy of a
  // plate of elements 1000 times longer than wide came out 1e-7 off that of
  // its own u, more than two solvers' answers differed (a review).
  double
  energy(const Problem &problem, const Vector &u)
  {
    long double twice_strain = 0, work = 0;
    for (Index j = 0; j < problem.A.outerSize(); ++j)
      {
        long double column = 0;
        for (SparseMatrix::InnerIterator it(problem.A, j); it; ++it)
          column += static_cast<long double>(it.value()) * u[it.row()];
        twice_strain += column * u[j];
        work += static_cast<long double>(problem.b[j]) * u[j];
      }
    return static_cast<double>(static_cast<long double>(problem.energy_unit) *
                               (0.5L * twice_strain - work));
  }

  Vector
  multiplier(const Problem &problem, const Vector &u)
  {
    const Vector residual = problem.A * u - problem.b;
    Vector       lambda   = Vector::Zero(problem.size());
    for (const Index i : problem.constrained)
      lambda[i] = residual[i];
    return lambda;
  }

  double
  KktResiduals::max() const
  {
    // NaN-aware: std::max would drop a NaN that is not its first argument.
    double largest = 0;
    for (const double residual :
         {stationarity, primal_feasibility, dual_feasibility, complementarity})
      if (std::isnan(residual))
        return residual;
      else
        largest = std::max(largest, residual);
    return largest;
  }

  KktResiduals
  kkt_residuals(const Problem &problem, const Vector &u)
  {
    const Index  n      = problem.size();
    const Vector lambda = problem.A * u - problem.b;
    // A non-finite answer has no residual: infinity in each, so that every
    // test "residual <= tolerance" fails (a NaN would pass the std::max
    // below unseen).
    if (!u.allFinite() || !lambda.allFinite())
      {
        const double infinite = std::numeric_limits<double>::infinity();
        return {infinite, infinite, infinite, infinite};
      }

    // Measured in the unknowns scaled to A's unit diagonal (u_i sqrt(A_ii),
    // forces / sqrt(A_ii)), so that no choice of units hides an error: where
    // unknowns of different kinds differ in stiffness by many orders (the
    // plate's deflections and slopes on elements of 1e-4 mm), a residual
    // relative to the largest force let the others be wrong.
    const double mean_diagonal = diagonal_scale(problem.A);
    const Vector diagonal      = problem.A.diagonal();
    Vector       root_stiffness(n);
    for (Index i = 0; i < n; ++i)
      root_stiffness[i] =
        std::sqrt(diagonal[i] > 0 ? diagonal[i] : mean_diagonal);

    const Vector abs_product = absolute_product(problem.A, u);

    double force_scale =
      n > 0 ?
        problem.b.cwiseQuotient(root_stiffness).lpNorm<Eigen::Infinity>() +
          abs_product.cwiseQuotient(root_stiffness).lpNorm<Eigen::Infinity>() :
        0.0;
    // A bound's penetration relative to |u|, not to |u| + |l|: one far
    // bound (an obstacle that nothing reaches) would hide any penetration
    // of the others. |l| only where u = 0.
    double displacement_scale =
      n > 0 ? u.cwiseProduct(root_stiffness).lpNorm<Eigen::Infinity>() : 0.0;
    if (displacement_scale == 0)
      for (Index k = 0; k < problem.n_constrained(); ++k)
        displacement_scale = std::max(displacement_scale,
                                      std::abs(problem.lower_bound[k]) *
                                        root_stiffness[problem.constrained[k]]);
    if (force_scale == 0)
      force_scale = 1;
    if (displacement_scale == 0)
      displacement_scale = 1;

    KktResiduals            result;
    const std::vector<char> mask = problem.constrained_mask();
    for (Index i = 0; i < n; ++i)
      if (!mask[i])
        result.stationarity = std::max(result.stationarity,
                                       std::abs(lambda[i]) / root_stiffness[i]);
    for (Index k = 0; k < problem.n_constrained(); ++k)
      {
        const Index  i = problem.constrained[k];
        const double slack =
          (u[i] - problem.lower_bound[k]) * root_stiffness[i];
        const double force        = lambda[i] / root_stiffness[i];
        result.primal_feasibility = std::max(result.primal_feasibility, -slack);
        result.dual_feasibility   = std::max(result.dual_feasibility, -force);
        result.complementarity =
          std::max(result.complementarity,
                   std::min(std::abs(slack), std::abs(force)));
      }
    result.stationarity /= force_scale;
    result.primal_feasibility /= displacement_scale;
    result.dual_feasibility /= force_scale;
    result.complementarity /= force_scale;
    return result;
  }
} // namespace unilateral::lcp
