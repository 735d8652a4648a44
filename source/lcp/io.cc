#include <unilateral/base/input_error.h>
#include <unilateral/base/output_file.h>
#include <unilateral/base/text.h>
#include <unilateral/lcp/io.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>
#include <unordered_map>

namespace unilateral::lcp
{
  namespace
  {
    std::ifstream
    open_for_reading(const std::string &file_name, const std::string &what)
    {
      // A directory opens, and reads as an empty file.
      if (std::filesystem::is_directory(file_name))
        throw InputError("cannot read " + what + " file '" + file_name +
                         "': a directory, not a file");
      std::ifstream in(file_name);
      if (!in)
        throw InputError("cannot read " + what + " file '" + file_name +
                         "': no such file, or not readable");
      // Some editors start a text file with a UTF-8 byte-order mark (0xEF
      // 0xBB 0xBF), which would read as part of the first word. Its first
      // byte starts no valid file: peeked at, so that a pipe, which cannot
      // seek back, reads as a file.
      if (in.peek() == 0xEF)
        throw InputError(what + " file '" + file_name +
                         "' starts with a byte-order mark (or another "
                         "non-ASCII byte); save it without one (plain UTF-8 "
                         "or ASCII)");
      return in;
    }

    [[noreturn]] void
    fail(const std::string &file_name,
         const unsigned int line,
         const std::string &problem)
    {
      throw InputError(file_name + ":" + std::to_string(line) + ": " + problem);
    }

    bool
    is_comment_or_blank(const std::string &line)
    {
      const auto first = line.find_first_not_of(" \t\r");
      return first == std::string::npos || line[first] == '%' ||
             line[first] == '#';
    }

    /**
     * A data line with no newline after it, at the end of the file: a file
     * cut short (a copy or a download that stopped) ends so, often inside
     * its last number, which still reads as a number: a wrong entry that no
     * other check can see. Every line of a complete file ends with a
     * newline (so do ours), so the file is refused, with the fix.
     */
    void
    refuse_unterminated(const std::istream &in,
                        const std::string  &file_name,
                        const unsigned int  line_number)
    {
      if (in.eof())
        fail(file_name,
             line_number,
             "the file ends inside this line, with no newline after it: it "
             "may have been cut short (inside its last number); if the file "
             "is complete, end its last line with a newline");
    }

    /// A line quoted in a message, cut after 60 characters.
    std::string
    clipped(const std::string &line)
    {
      return line.size() <= 60 ? line : line.substr(0, 60) + " ...";
    }

    bool
    parse_index(const std::string &token, long long &value)
    {
      if (token.empty())
        return false;
      char *end = nullptr;
      value     = std::strtoll(token.c_str(), &end, 10);
      return end == token.c_str() + token.size();
    }
    /**
     * An entry listed twice would be summed (Eigen's triplets): in a
     * symmetric file that has both triangles, every off-diagonal entry
     * would count double. @p positions: row, column (a symmetric file's
     * (i, j) and (j, i) as one) and line of each entry.
     */
    void
    refuse_repeated_entries(const std::string                        &file_name,
                            std::vector<std::array<unsigned int, 3>> &positions,
                            const bool                                symmetric)
    {
      std::sort(positions.begin(), positions.end());
      for (std::size_t k = 1; k < positions.size(); ++k)
        if (positions[k][0] == positions[k - 1][0] &&
            positions[k][1] == positions[k - 1][1])
          fail(file_name,
               positions[k][2],
               "the entry in row " + std::to_string(positions[k][0]) +
                 ", column " + std::to_string(positions[k][1]) +
                 " is listed twice (also on line " +
                 std::to_string(positions[k - 1][2]) + ")" +
                 (symmetric ? ", or with its mirror: a symmetric file lists "
                              "one triangle only" :
                              ""));
    }

    /// A size line of exactly N whole numbers >= 0 and nothing else ("3 3
    /// 5.9" would otherwise read as 5 entries); false if it is not one.
    template <std::size_t N>
    bool
    parse_size_line(const std::string &line, std::array<long long, N> &size)
    {
      std::istringstream tokens(line);
      std::string        token;
      for (long long &number : size)
        if (!(tokens >> token) || !parse_index(token, number) || number < 0)
          return false;
      return !(tokens >> token);
    }

    /// The size line 'rows columns entries' after the header's comments.
    std::array<long long, 3>
    read_size_line(std::istream      &in,
                   const std::string &file_name,
                   unsigned int      &line_number)
    {
      std::string line;
      while (std::getline(in, line))
        {
          ++line_number;
          if (is_comment_or_blank(line))
            continue;
          std::array<long long, 3> size{};
          if (!parse_size_line(line, size))
            fail(file_name,
                 line_number,
                 "expected the size line 'rows columns entries' (three "
                 "whole numbers), found '" +
                   clipped(line) + "'");
          refuse_unterminated(in, file_name, line_number);
          return size;
        }
      fail(file_name, line_number, "missing the size line");
    }
  } // namespace

  SparseMatrix
  read_matrix_market(
    const std::string                               &file_name,
    const std::function<void(long long, long long)> &check_size)
  {
    std::ifstream in = open_for_reading(file_name, "matrix");
    std::string   line;
    unsigned int  line_number = 0;

    if (!std::getline(in, line))
      fail(file_name, 1, "empty file, expected a Matrix Market header");
    ++line_number;
    std::istringstream header(line);
    std::string        banner, object, format, field, symmetry;
    header >> banner >> object >> format >> field >> symmetry;
    std::transform(object.begin(), object.end(), object.begin(), ::tolower);
    std::transform(format.begin(), format.end(), format.begin(), ::tolower);
    std::transform(field.begin(), field.end(), field.begin(), ::tolower);
    std::transform(symmetry.begin(),
                   symmetry.end(),
                   symmetry.begin(),
                   ::tolower);
    if (banner != "%%MatrixMarket" || object != "matrix" ||
        format != "coordinate")
      fail(file_name,
           1,
           "expected '%%MatrixMarket matrix coordinate real "
           "symmetric|general'");
    if (field != "real" && field != "integer" && field != "double")
      fail(file_name, 1, "field '" + field + "' not supported (real only)");
    if (symmetry != "general" && symmetry != "symmetric")
      fail(file_name,
           1,
           "symmetry '" + symmetry + "' not supported (general or symmetric)");
    const bool symmetric = (symmetry == "symmetric");

    const auto [rows, cols, entries] =
      read_size_line(in, file_name, line_number);
    if (rows > std::numeric_limits<Index>::max() ||
        cols > std::numeric_limits<Index>::max() ||
        entries > std::numeric_limits<Index>::max())
      fail(file_name, line_number, "matrix too large for 32-bit indices");
    if (check_size)
      check_size(rows, cols);

    // Reserved for the entries the file can hold (a line holds at least
    // "i j v"), not for what its size line claims.
    std::error_code size_error;
    const auto      bytes = std::filesystem::file_size(file_name, size_error);
    const long long room  = size_error ? 0 : static_cast<long long>(bytes / 6);
    const long long expected_entries = std::min(entries, room);
    std::vector<Eigen::Triplet<double, Index>> triplets;
    triplets.reserve(symmetric ? 2 * expected_entries : expected_entries);
    std::vector<std::array<unsigned int, 3>> positions;
    positions.reserve(expected_entries);
    long long read = 0;
    while (read < entries && std::getline(in, line))
      {
        ++line_number;
        if (is_comment_or_blank(line))
          continue;
        // Exactly three tokens: a fourth (a complex part, two entries run
        // together) would otherwise be dropped without a word.
        std::istringstream entry(line);
        std::string        si, sj, sv, extra;
        long long          i = 0, j = 0;
        double             value = 0;
        if (!(entry >> si >> sj >> sv) || (entry >> extra) ||
            !parse_index(si, i) || !parse_index(sj, j) ||
            !parse_number(sv, value))
          fail(file_name,
               line_number,
               "expected 'row column value', found '" + clipped(line) + "'");
        if (i < 1 || i > rows || j < 1 || j > cols)
          fail(file_name,
               line_number,
               "index (" + si + ", " + sj + ") outside the " +
                 std::to_string(rows) + " x " + std::to_string(cols) +
                 " matrix (indices are 1-based)");
        if (!std::isfinite(value))
          fail(file_name, line_number, "entry is not a finite number");
        refuse_unterminated(in, file_name, line_number);
        triplets.emplace_back(i - 1, j - 1, value);
        if (symmetric && i != j)
          triplets.emplace_back(j - 1, i - 1, value);
        // Where it stands, for refuse_repeated_entries.
        positions.push_back(std::array<unsigned int, 3>{
          {static_cast<unsigned int>(symmetric ? std::max(i, j) : i),
           static_cast<unsigned int>(symmetric ? std::min(i, j) : j),
           line_number}});
        ++read;
      }
    refuse_repeated_entries(file_name, positions, symmetric);
    if (read < entries)
      fail(file_name,
           line_number,
           "file ends after " + std::to_string(read) + " of " +
             std::to_string(entries) + " entries");
    // An entry beyond the announced count would be dropped silently, and
    // the matrix would differ from the file.
    while (std::getline(in, line))
      {
        ++line_number;
        if (!is_comment_or_blank(line))
          fail(file_name,
               line_number,
               "more entries than the " + std::to_string(entries) +
                 " the size line announces; correct the count or remove "
                 "the extra entries");
      }

    SparseMatrix A(static_cast<Index>(rows), static_cast<Index>(cols));
    A.setFromTriplets(triplets.begin(), triplets.end());
    A.makeCompressed();
    return A;
  }

  void
  write_matrix_market(const SparseMatrix &A, const std::string &file_name)
  {
    std::ofstream out = open_for_writing(file_name);
    out << std::setprecision(17);
    // Symmetric storage: the lower triangle only.
    long long lower = 0;
    for (Index j = 0; j < A.outerSize(); ++j)
      for (SparseMatrix::InnerIterator it(A, j); it; ++it)
        lower += (it.row() >= j);
    out << "%%MatrixMarket matrix coordinate real symmetric\n"
        << "% written by unilateral\n"
        << A.rows() << " " << A.cols() << " " << lower << "\n";
    for (Index j = 0; j < A.outerSize(); ++j)
      for (SparseMatrix::InnerIterator it(A, j); it; ++it)
        if (it.row() >= j)
          out << it.row() + 1 << " " << j + 1 << " " << it.value() << "\n";
    finish_writing(out, file_name);
  }

  Vector
  read_vector(const std::string &file_name)
  {
    std::ifstream       in = open_for_reading(file_name, "vector");
    std::string         line;
    unsigned int        line_number = 0;
    std::vector<double> values;
    bool                array_header = false, size_line_seen = false;
    // The size line of an array header, "rows 1": the values it announces.
    long long    announced        = -1;
    unsigned int size_line_number = 0;
    while (std::getline(in, line))
      {
        ++line_number;
        if (line_number == 1 && line.rfind("%%MatrixMarket", 0) == 0)
          {
            array_header = true;
            continue;
          }
        if (is_comment_or_blank(line))
          continue;
        if (array_header && !size_line_seen)
          {
            size_line_seen   = true;
            size_line_number = line_number;
            std::array<long long, 2> size{};
            if (!parse_size_line(line, size))
              fail(file_name,
                   line_number,
                   "expected the size line 'rows 1' of a Matrix Market "
                   "array, found '" +
                     clipped(line) + "'");
            if (size[1] != 1)
              fail(file_name,
                   line_number,
                   "the size line announces " + std::to_string(size[1]) +
                     " columns; a vector is one column ('rows 1')");
            refuse_unterminated(in, file_name, line_number);
            announced = size[0];
            continue;
          }
        std::istringstream tokens(line);
        std::string        token, extra;
        double             value = 0;
        tokens >> token;
        if (!parse_number(token, value) || (tokens >> extra))
          fail(file_name, line_number, "expected one number per line");
        if (!std::isfinite(value))
          fail(file_name, line_number, "value is not a finite number");
        refuse_unterminated(in, file_name, line_number);
        values.push_back(value);
      }
    if (announced >= 0 && static_cast<long long>(values.size()) != announced)
      fail(file_name,
           size_line_number,
           "the size line announces " + std::to_string(announced) +
             " values, the file holds " + std::to_string(values.size()));
    return Eigen::Map<Vector>(values.data(), values.size());
  }

  void
  write_vector(const Vector &v, const std::string &file_name)
  {
    std::ofstream out = open_for_writing(file_name);
    out << std::setprecision(17);
    for (Index i = 0; i < v.size(); ++i)
      out << v[i] << "\n";
    finish_writing(out, file_name);
  }

  void
  read_constraints(const std::string  &file_name,
                   std::vector<Index> &indices,
                   Vector             &lower_bounds,
                   const Index         size)
  {
    std::ifstream       in = open_for_reading(file_name, "constraints");
    std::string         line;
    unsigned int        line_number = 0;
    std::vector<double> bounds;
    // The line on which each index was first given (duplicates are named
    // with both lines).
    std::unordered_map<long long, unsigned int> first_line;
    indices.clear();
    while (std::getline(in, line))
      {
        ++line_number;
        if (is_comment_or_blank(line))
          continue;
        std::istringstream tokens(line);
        std::string        si, sb, extra;
        long long          i     = 0;
        double             bound = 0;
        if (!(tokens >> si >> sb) || (tokens >> extra) || !parse_index(si, i) ||
            !parse_number(sb, bound))
          fail(file_name,
               line_number,
               "expected 'index lower_bound' (1-based index)");
        if (i < 1 || i > std::numeric_limits<Index>::max())
          fail(file_name,
               line_number,
               "index " + si +
                 (i < 1 ? " must be >= 1 (indices are 1-based)" :
                          " is beyond 32-bit indices"));
        if (size >= 0 && i > size)
          fail(file_name,
               line_number,
               "index " + si + " is outside 1.." + std::to_string(size) +
                 ", the rows of A (indices are 1-based)");
        if (const auto [first, inserted] = first_line.emplace(i, line_number);
            !inserted)
          fail(file_name,
               line_number,
               "index " + si + " appears twice (first on line " +
                 std::to_string(first->second) + ")");
        if (!std::isfinite(bound))
          fail(file_name,
               line_number,
               "lower bound must be a finite number (an index without a "
               "bound is not listed)");
        refuse_unterminated(in, file_name, line_number);
        indices.push_back(static_cast<Index>(i - 1));
        bounds.push_back(bound);
      }
    lower_bounds = Eigen::Map<Vector>(bounds.data(), bounds.size());
  }

  void
  write_constraints(const Problem &problem, const std::string &file_name)
  {
    std::ofstream out = open_for_writing(file_name);
    out << std::setprecision(17);
    out << "# index (1-based) lower_bound\n";
    for (Index k = 0; k < problem.n_constrained(); ++k)
      out << problem.constrained[k] + 1 << " " << problem.lower_bound[k]
          << "\n";
    finish_writing(out, file_name);
  }

  Problem
  read_problem(const std::string &matrix_file,
               const std::string &rhs_file,
               const std::string &constraints_file)
  {
    Problem problem;
    problem.b = read_vector(rhs_file);
    // Checked at A's size line, before a matrix of that size is allocated
    // (a size line can claim billions of rows in a file of three lines).
    problem.A = read_matrix_market(
      matrix_file, [&](const long long rows, const long long cols) {
        if (rows == cols && rows != problem.b.size())
          throw InputError("dimension mismatch: A in '" + matrix_file +
                           "' is " + std::to_string(rows) + " x " +
                           std::to_string(cols) + " but b in '" + rhs_file +
                           "' has " + std::to_string(problem.b.size()) +
                           " entries");
      });
    read_constraints(constraints_file,
                     problem.constrained,
                     problem.lower_bound,
                     static_cast<Index>(problem.A.rows()));
    // What is left to find is in A: name its file.
    try
      {
        check_and_normalise(problem);
      }
    catch (const InputError &error)
      {
        throw InputError("'" + matrix_file + "': " + error.what());
      }
    return problem;
  }

  void
  write_problem(const Problem &problem, const std::string &directory)
  {
    write_matrix_market(problem.A, directory + "/lcp_A.mtx");
    write_vector(problem.b, directory + "/lcp_b.txt");
    write_constraints(problem, directory + "/lcp_constraints.txt");
  }
} // namespace unilateral::lcp
