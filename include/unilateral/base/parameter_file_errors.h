#pragma once

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <string>

namespace unilateral
{
  /**
   * What deal.II's parameter parser refused, said as the program's own
   * checks say it (input_error.h): the parameter's whole path
   * ('Solver/PSOR/Tolerance', where deal.II names only 'Tolerance', a name
   * six subsections declare), the value, what the parameter takes in words
   * and the line of the file; for a name that is not declared there, the
   * nearest declared one, or the subsections that declare it.
   *
   * deal.II's exceptions carry the line and the file but not the
   * subsection, so the path is read back from @p parameter_file (and the
   * files it includes) by the parser's own rules, and the declared names
   * from @p prm's own listing of them.
   *
   * Returns an empty string for an exception that is not one of the
   * parser's refusals.
   */
  std::string
  explain_parse_error(const dealii::ExceptionBase    &error,
                      const dealii::ParameterHandler &prm,
                      const std::string              &parameter_file);
} // namespace unilateral
