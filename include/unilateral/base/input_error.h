#pragma once

#include <sstream>
#include <stdexcept>
#include <string>

namespace unilateral
{
  /**
   * An error in what the user gave us: a parameter value, a file, a matrix.
   *
   * The message is one line that names the problem and, where we can, the
   * parameter, the value and the fix. The application prints it and exits
   * with a nonzero code; it never becomes a crash or a stack trace.
   */
  class InputError : public std::runtime_error
  {
  public:
    explicit InputError(const std::string &message)
      : std::runtime_error(message)
    {}
  };

  /**
   * Throw an InputError for parameter @p name (in subsection @p section)
   * with value @p value unless @p condition holds; @p requirement says what a
   * valid value is ("must be > 0").
   */
  template <typename T>
  void
  check_parameter(const bool         condition,
                  const std::string &section,
                  const std::string &name,
                  const T           &value,
                  const std::string &requirement)
  {
    if (!condition)
      {
        std::ostringstream message;
        message << "parameter '" << (section.empty() ? "" : section + "/")
                << name << "' = " << value << ": " << requirement;
        throw InputError(message.str());
      }
  }

  /**
   * Reduce any exception to one line for the user: deal.II's exceptions
   * carry a multi-line banner, of which only the "Additional information"
   * is meant for people.
   */
  std::string
  one_line_message(const std::exception &exception);
} // namespace unilateral
