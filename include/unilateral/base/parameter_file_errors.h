#pragma once

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <string>
#include <utility>
#include <vector>

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

  /**
   * The kind of @p parameter_file as deal.II's ParameterHandler::parse_input
   * chooses it: its ending after the last '.', in lower case ("prm",
   * "json", "xml"; deal.II refuses any other).
   */
  std::string
  parameter_file_kind(const std::string &parameter_file);

  /**
   * For a JSON or XML @p parameter_file (by its kind; nothing for others):
   * throws InputError for the first thing deal.II's reader would refuse in
   * it, said as explain_parse_error says it for a .prm file but without a
   * line (boost's property tree keeps none): a name not declared where it
   * stands (with the nearest declared one, or the subsections that declare
   * it), a value its pattern refuses, a file that does not parse (with
   * boost's line and reason), a list or an object where a value belongs,
   * XML comments. deal.II 9.4 names only the entry or the value there, or
   * gives boost's message without the file. Reads the file as deal.II 9.4
   * does: a node with a 'value' child or with no children sets an entry,
   * names may be mangled (XML's 'Blocks_20per_20side'), any other node is a
   * subsection.
   */
  void
  check_structured_parameter_file(const dealii::ParameterHandler &prm,
                                  const std::string &parameter_file);

  /**
   * The value that @p parameter_file (and the files it includes) sets for
   * parameter @p name of subsection @p path ("" for the top level), read
   * by the parser's rules, or @p otherwise where it sets none: what must be
   * known of a file that the parser refused (the run's folder, to mark an
   * earlier run's summary there as not this run's). JSON and XML files are
   * read as check_structured_parameter_file reads them.
   */
  std::string
  value_in_file(const std::string &parameter_file,
                const std::string &path,
                const std::string &name,
                const std::string &otherwise);

  /**
   * A parameter of subsection @p section (at the top level) of @p prm
   * whose value differs from its default, as "Section/.../Name" and the
   * value; two empty strings if there is none. For settings that the run
   * would not read: those of another scene's subsection.
   */
  std::pair<std::string, std::string>
  first_changed_entry(const dealii::ParameterHandler &prm,
                      const std::string              &section);

  /// The subsections that @p declare declares at the top level.
  std::vector<std::string>
  sections_declared_by(
    const std::function<void(dealii::ParameterHandler &)> &declare);
} // namespace unilateral
