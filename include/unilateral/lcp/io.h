#pragma once

#include <unilateral/lcp/problem.h>

#include <functional>
#include <string>

/**
 * The LCP exchange format, so that other tools can be compared on exactly
 * our problems and users can bring their own:
 *  - A: Matrix Market coordinate file ("real" or "integer"; "general" or
 *       "symmetric"), 1-based indices;
 *  - b: text, one number per line (lines starting with '%' or '#' are
 *       comments; a Matrix Market "array" header is accepted);
 *  - constraints: text, one line "index lower_bound" per constrained index,
 *       1-based like Matrix Market (comments as above). "-inf" is not
 *       allowed: an index without a bound is simply not listed.
 * Every line ends with a newline: a last entry without one is refused (the
 * file may have been cut short inside that number).
 * Readers throw InputError with one line naming file, line and problem.
 */
namespace unilateral::lcp
{
  /// @p check_size, if given, is called with the rows and columns of the
  /// size line before anything of that size is allocated (and may throw).
  SparseMatrix
  read_matrix_market(
    const std::string                               &file_name,
    const std::function<void(long long, long long)> &check_size = {});

  void
  write_matrix_market(const SparseMatrix &A, const std::string &file_name);

  Vector
  read_vector(const std::string &file_name);

  void
  write_vector(const Vector &v, const std::string &file_name);

  /// Indices must be >= 1 and given once; with @p size >= 0 also <= size.
  void
  read_constraints(const std::string  &file_name,
                   std::vector<Index> &indices,
                   Vector             &lower_bounds,
                   Index               size = -1);

  void
  write_constraints(const Problem &problem, const std::string &file_name);

  /// Read all three files and check_and_normalise() the result; its errors
  /// name the matrix file.
  Problem
  read_problem(const std::string &matrix_file,
               const std::string &rhs_file,
               const std::string &constraints_file);

  /// Write lcp_A.mtx, lcp_b.txt and lcp_constraints.txt into @p directory.
  void
  write_problem(const Problem &problem, const std::string &directory);
} // namespace unilateral::lcp
