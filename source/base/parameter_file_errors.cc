#include <unilateral/base/input_error.h>
#include <unilateral/base/parameter_file_errors.h>
#include <unilateral/base/text.h>

#include <deal.II/base/utilities.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <boost/property_tree/xml_parser.hpp>

#include <algorithm>
#include <climits>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <vector>

namespace unilateral
{
  namespace
  {
    std::string
    trimmed(const std::string &text)
    {
      const auto first = text.find_first_not_of(" \t\r\n");
      if (first == std::string::npos)
        return "";
      return text.substr(first, text.find_last_not_of(" \t\r\n") - first + 1);
    }

    std::string
    joined(const std::vector<std::string> &path)
    {
      std::string result;
      for (const std::string &name : path)
        result += (result.empty() ? "" : "/") + name;
      return result;
    }

    /// What deal.II's parser sees in a parameter file (after
    /// ParameterHandler::parse_input and scan_line, whose rules this
    /// repeats: lines ending in '\' joined to the next, then comments cut,
    /// tabs made spaces; keywords in lower or upper case; included files
    /// read in place): the subsection each line lies in, and the values
    /// set.
    struct Walk
    {
      /// Per file (as the parser names it: an included one by its include
      /// line), the subsection path at each line (1-based, [0] unused).
      std::map<std::string, std::vector<std::string>> path_at_line;
      /// Per file, each logical line (comments cut), by the number of its
      /// first physical line, as the parser reports it.
      std::map<std::string, std::map<std::size_t, std::string>> lines;
      /// The path at the end of the file walked.
      std::string path_at_end;
      /// The last value set for each "path/name".
      std::map<std::string, std::string> values;
    };

    bool
    starts_with(const std::string &line, const std::string &keyword)
    {
      std::string upper = keyword;
      for (char &c : upper)
        c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      return line.rfind(keyword, 0) == 0 || line.rfind(upper, 0) == 0;
    }

    void
    walk(std::istream             &in,
         const std::string        &file,
         std::vector<std::string> &path,
         Walk                     &result,
         const unsigned int        depth = 0)
    {
      std::vector<std::string> &at_line = result.path_at_line[file];
      at_line.assign(1, "");
      std::string logical, line;
      std::size_t first_line = 0;
      while (std::getline(in, line))
        {
          if (at_line.size() == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0)
            line.erase(0, 3); // a byte-order mark, which the program skips
          at_line.push_back(joined(path));
          line = trimmed(line);
          if (!line.empty() && line.back() == '\\')
            {
              if (logical.empty())
                first_line = at_line.size() - 1;
              logical += line.substr(0, line.size() - 1);
              continue;
            }
          if (logical.empty())
            first_line = at_line.size() - 1;
          logical += line;
          line = logical.substr(0, logical.find('#'));
          logical.clear();
          std::replace(line.begin(), line.end(), '\t', ' ');
          line                           = trimmed(line);
          result.lines[file][first_line] = line;
          // The lines joined into this one lie where it begins.
          for (std::size_t n = at_line.size() - 1;
               n > 0 && at_line[n] != joined(path);
               --n)
            at_line[n] = joined(path);
          if (starts_with(line, "subsection "))
            {
              path.push_back(trimmed(line.substr(11)));
            }
          else if (starts_with(line, "end"))
            {
              if (!path.empty())
                path.pop_back();
            }
          else if (starts_with(line, "set "))
            {
              const std::size_t equals = line.find('=');
              const std::string name   = trimmed(line.substr(4, equals - 4));
              if (equals != std::string::npos)
                result.values[joined(path) + "/" + name] =
                  trimmed(line.substr(equals + 1));
            }
          else if (starts_with(line, "include") && depth < 16)
            {
              // Opened as the parser opens it: by the name as written.
              const std::string name = trimmed(line.substr(7));
              std::ifstream     included(name);
              if (included)
                walk(included, name, path, result, depth + 1);
            }
        }
      result.path_at_end = joined(path);
    }

    /// ": did you mean 'X'?" for a near name of @p names, else nothing.
    std::string
    nearest(const std::string &name, const std::vector<std::string> &names)
    {
      const std::string best          = nearest_name(name, names);
      const auto        single_spaced = [](const std::string &text) {
        std::istringstream words(text);
        std::string        result, word;
        while (words >> word)
          result += (result.empty() ? "" : " ") + word;
        return result;
      };
      if (!best.empty() && single_spaced(name) == best)
        return ": the words of '" + best + "' take single spaces";
      return best.empty() ? "" : ": did you mean '" + best + "'?";
    }

    /// A pattern's description in words ("[Integer range 1...2147483647
    /// (inclusive)]": "an integer >= 1").
    std::string
    in_words(const std::string &pattern)
    {
      static const std::regex integer(
        R"(\[Integer range (-?\d+)\.\.\.(-?\d+) \(inclusive\)\])");
      static const std::regex real(
        R"(\[Double (\S+)\.\.\.(\S+) \(inclusive\)\])");
      static const std::regex selection(R"(\[Selection (.*)\])");
      std::smatch             match;
      if (std::regex_match(pattern, match, integer) ||
          std::regex_match(pattern, match, real))
        {
          const bool        is_integer = pattern.find("Integer") == 1;
          const std::string lower = match[1], upper = match[2];
          const bool no_lower = is_integer ? lower == std::to_string(INT_MIN) :
                                             lower == "-MAX_DOUBLE";
          const bool no_upper = is_integer ? upper == std::to_string(INT_MAX) :
                                             upper == "MAX_DOUBLE";
          const std::string kind =
            is_integer ? "an integer" : "a finite number";
          return no_lower && no_upper ? kind :
                 no_upper             ? kind + " >= " + lower :
                 no_lower             ? kind + " <= " + upper :
                                        kind + " from " + lower + " to " + upper;
        }
      if (pattern == "[Bool]")
        return "true or false";
      static const std::regex list(
        R"(\[List of <(.*)> of length (\d+)\.\.\.(\d+) \(inclusive\)\])");
      if (std::regex_match(pattern, match, list))
        return "a list of " + match[2].str() + " to " + match[3].str() +
               " entries separated by ',', each " + in_words(match[1].str());
      if (std::regex_match(pattern, match, selection))
        {
          std::string        result;
          std::istringstream options(match[1].str());
          std::string        option;
          while (std::getline(options, option, '|'))
            result += (result.empty() ? "" : ", ") + trimmed(option);
          return "one of: " + result;
        }
      return "of the form " + pattern;
    }

    /// @p text, or its start if it is too long to repeat in one line.
    std::string
    shortened(const std::string &text)
    {
      return text.size() > 80 ? text.substr(0, 60) + "..." : text;
    }

    /// "'A/B'" or "the top level".
    std::string
    where(const std::string &path)
    {
      return path.empty() ? "the top level" : "subsection '" + path + "'";
    }

    const std::string see_listing =
      " ('unilateral --print-parameters' lists every parameter)";

    /// nearest() among the names @p by_path lists for @p path.
    std::string
    nearest_among(
      const std::string                                     &name,
      const std::map<std::string, std::vector<std::string>> &by_path,
      const std::string                                     &path)
    {
      const auto names = by_path.find(path);
      return names == by_path.end() ? "" : nearest(name, names->second);
    }

    /// ": it is a parameter of 'X'; set it inside that subsection" where
    /// @p name is declared in other subsections than @p path, else the
    /// nearest name declared in @p path.
    std::string
    hint_for_entry(
      const std::string                                     &name,
      const std::string                                     &path,
      const std::map<std::string, std::vector<std::string>> &entries)
    {
      std::vector<std::string> elsewhere;
      for (const auto &[other_path, names] : entries)
        if (other_path != path &&
            std::find(names.begin(), names.end(), name) != names.end())
          elsewhere.push_back("'" + other_path + "'");
      if (elsewhere.empty())
        return nearest_among(name, entries, path);
      std::string hint = ": it is a parameter of ";
      for (std::size_t k = 0; k < elsewhere.size(); ++k)
        hint += (k == 0                    ? "" :
                 k + 1 == elsewhere.size() ? " and " :
                                             ", ") +
                elsewhere[k];
      return hint + (elsewhere.size() == 1 ? "; set it inside that subsection" :
                                             "; set it inside the one meant");
    }

    using Tree = boost::property_tree::ptree;

    /// deal.II's mangled names ('Blocks_20per_20side', as XML needs them)
    /// read back; a '_' not followed by two lower-case hexadecimal digits
    /// (all that deal.II's mangling writes and its demangling reads)
    /// stays.
    std::string
    demangled(const std::string &name)
    {
      std::string result;
      for (std::size_t i = 0; i < name.size(); ++i)
        if (name[i] == '_' && i + 2 < name.size() &&
            std::string("0123456789abcdef").find(name[i + 1]) !=
              std::string::npos &&
            std::string("0123456789abcdef").find(name[i + 2]) !=
              std::string::npos)
          {
            result +=
              static_cast<char>(std::stoi(name.substr(i + 1, 2), nullptr, 16));
            i += 2;
          }
        else
          result += name[i];
      return result;
    }

    /// deal.II 9.4's reading of a JSON or XML parameter file node: one
    /// with a 'value' child, or with no children, sets an entry; any other
    /// node is a subsection.
    bool
    sets_entry(const Tree &node)
    {
      return node.empty() || node.get_child_optional("value");
    }

    std::string
    value_of(const Tree &node)
    {
      return node.empty() ? node.data() : node.get<std::string>("value");
    }

    /// The declared parameters, by path: entries with their patterns'
    /// descriptions, and subsections (from the parameters' JSON listing,
    /// whose names are not mangled).
    struct Declared
    {
      std::map<std::string, std::vector<std::string>> entries, subsections;
      std::map<std::string, std::string>              pattern_of;
    };

    void
    collect(const Tree &node, const std::string &path, Declared &declared)
    {
      for (const auto &[name, child] : node)
        {
          const std::string full = path.empty() ? name : path + "/" + name;
          if (child.get_child_optional("value"))
            {
              declared.entries[path].push_back(name);
              declared.pattern_of[full] =
                child.get<std::string>("pattern_description", "");
            }
          else
            {
              declared.subsections[path].push_back(name);
              collect(child, full, declared);
            }
        }
    }

    /// @p prm's parameters as its JSON listing has them, each with its
    /// 'value' and 'default_value' (names not mangled).
    Tree
    listing_of(const dealii::ParameterHandler &prm)
    {
      std::stringstream listing;
      prm.print_parameters(listing, dealii::ParameterHandler::JSON);
      Tree tree;
      boost::property_tree::read_json(listing, tree);
      return tree;
    }

    /// What @p prm declares, from its JSON listing.
    Declared
    declared_parameters(const dealii::ParameterHandler &prm)
    {
      Declared declared;
      collect(listing_of(prm), "", declared);
      return declared;
    }

    /// The first thing in @p node (at @p path of @p file) that deal.II's
    /// reader refuses, said for the user; empty if none.
    std::string
    first_refusal(const Tree        &node,
                  const std::string &path,
                  const Declared    &declared,
                  const std::string &file)
    {
      const auto declares = [](const auto        &by_path,
                               const std::string &in,
                               const std::string &name) {
        const auto names = by_path.find(in);
        return names != by_path.end() &&
               std::find(names->second.begin(), names->second.end(), name) !=
                 names->second.end();
      };
      const std::string in_file = "parameter file '" + file + "': ";
      for (const auto &[key, child] : node)
        {
          const std::string name = demangled(key);
          const std::string full = path.empty() ? name : path + "/" + name;
          // Read as parameters by deal.II's reader, which then refuses them.
          if (name.empty())
            return in_file + where(path) +
                   " holds an entry without a name (a list [...] reads so): "
                   "give each parameter as \"name\": \"value\", and a list "
                   "of values as one string (\"1, 2\")";
          if (name == "<xmlcomment>")
            return in_file + "an XML comment in " + where(path) +
                   ": deal.II's reader takes it for a parameter: remove it";
          if (name == "<xmlattr>")
            return in_file + "XML attributes of " + where(path) +
                   ": deal.II's reader takes them for parameters: remove them";
          if (!sets_entry(child))
            {
              if (declares(declared.subsections, path, name))
                {
                  const std::string refusal =
                    first_refusal(child, full, declared, file);
                  if (!refusal.empty())
                    return refusal;
                }
              else if (declares(declared.entries, path, name))
                return in_file + "parameter '" + full +
                       "' is given a list or an object: give its value as "
                       "one string";
              else
                return in_file + where(path) + " has no subsection '" +
                       shortened(name) + "'" +
                       nearest_among(name, declared.subsections, path) +
                       see_listing;
              continue;
            }
          if (declares(declared.subsections, path, name))
            return in_file + "'" + full +
                   "' is a subsection, not a parameter: give it an object of "
                   "its parameters";
          if (!declares(declared.entries, path, name))
            return in_file + "'" + shortened(name) +
                   "' is not a parameter of " + where(path) +
                   hint_for_entry(name, path, declared.entries) + see_listing;
          const std::string value       = value_of(child);
          const std::string description = declared.pattern_of.at(full);
          const auto pattern = dealii::Patterns::pattern_factory(description);
          if (pattern && !pattern->match(value))
            return "parameter '" + full + "' = " +
                   (value.empty() ?
                      "'' (empty)" :
                    trimmed(value) != value ?
                      "'" + shortened(value) + "' (with the spaces around it)" :
                      shortened(value)) +
                   ": must be " + in_words(description) + " (in '" + file +
                   "')";
        }
      return "";
    }

    /// @p file read as deal.II reads a JSON or XML parameter file: the
    /// tree below the XML's <ParameterHandler> element. Throws InputError
    /// where it does not parse.
    Tree
    structured_tree(const std::string &file, const std::string &kind)
    {
      Tree tree;
      try
        {
          if (kind == "json")
            boost::property_tree::read_json(file, tree);
          else
            boost::property_tree::read_xml(file, tree);
        }
      catch (const boost::property_tree::file_parser_error &error)
        {
          if (error.line() == 0)
            throw InputError("cannot read parameter file '" + file +
                             "': " + error.message());
          throw InputError(
            "parameter file '" + file + "' is not valid " +
            (kind == "json" ? "JSON" : "XML") + ": line " +
            std::to_string(error.line()) + ": " + error.message() +
            (kind == "json" || error.message() == "unexpected end of data" ?
               "" :
               " (in XML a '<' or '&' inside a value is written '&lt;' or "
               "'&amp;': 'base where x &lt; s')"));
        }
      if (kind == "json")
        return tree;
      const auto handler = tree.get_child_optional("ParameterHandler");
      if (!handler)
        throw InputError(
          "parameter file '" + file +
          "': its parameters must lie inside one <ParameterHandler> element "
          "(<ParameterHandler><Scene><value>masonry</value></Scene>"
          "</ParameterHandler>; names with spaces written as deal.II mangles "
          "them, 'Blocks_20per_20side')");
      return *handler;
    }

    /// value_in_file for a JSON or XML file's tree: the last value set
    /// (as deal.II's reader sets them in order).
    std::string
    value_in_tree(const Tree        &tree,
                  const std::string &path,
                  const std::string &name,
                  const std::string &otherwise)
    {
      const Tree *node = &tree;
      std::string rest = path;
      while (!rest.empty() && node)
        {
          const std::string step = rest.substr(0, rest.find('/'));
          rest.erase(0, std::min(rest.size(), step.size() + 1));
          const Tree *next = nullptr;
          for (const auto &[key, child] : *node)
            if (demangled(key) == step && !sets_entry(child))
              next = &child;
          node = next;
        }
      std::string value = otherwise;
      if (node)
        for (const auto &[key, child] : *node)
          if (demangled(key) == name && sets_entry(child))
            value = value_of(child);
      return value;
    }
  } // namespace

  std::string
  parameter_file_kind(const std::string &parameter_file)
  {
    std::string ending =
      parameter_file.substr(parameter_file.find_last_of('.') + 1);
    for (char &c : ending)
      c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ending;
  }

  void
  check_structured_parameter_file(const dealii::ParameterHandler &prm,
                                  const std::string &parameter_file)
  {
    const std::string kind = parameter_file_kind(parameter_file);
    if (kind != "json" && kind != "xml")
      return;
    const std::string refusal =
      first_refusal(structured_tree(parameter_file, kind),
                    "",
                    declared_parameters(prm),
                    parameter_file);
    if (!refusal.empty())
      throw InputError(refusal);
  }

  std::string
  explain_parse_error(const dealii::ExceptionBase    &error,
                      const dealii::ParameterHandler &prm,
                      const std::string              &parameter_file)
  {
    using Handler = dealii::ParameterHandler;
    const bool invalid_value =
      dynamic_cast<const Handler::ExcInvalidEntryForPattern *>(&error);
    const bool no_subsection =
      dynamic_cast<const Handler::ExcNoSubsection *>(&error);
    const bool unbalanced =
      dynamic_cast<const Handler::ExcUnbalancedSubsections *>(&error);
    const bool no_include =
      dynamic_cast<const Handler::ExcCannotOpenIncludeStatementFile *>(&error);
    if (!invalid_value && !no_subsection && !unbalanced && !no_include &&
        !dynamic_cast<const Handler::ExcCannotParseLine *>(&error))
      return "";
    std::ostringstream info;
    error.print_info(info);
    const std::string text = info.str();

    Walk in_file;
    {
      std::ifstream            stream(parameter_file);
      std::vector<std::string> path;
      walk(stream, parameter_file, path, in_file);
    }
    if (unbalanced)
      return "parameter file '" + parameter_file + "': " +
             (in_file.path_at_end.empty() ?
                "its 'subsection' and 'end' lines do not pair up" :
                "it ends inside subsection '" + in_file.path_at_end + "'") +
             ": close each 'subsection' with an 'end' line";

    // "Line <12> of file <bad.prm>: ...", read by hand (a regular
    // expression recursed until the stack overflowed on a name of 50,000
    // characters); ExcNoSubsection has no '>' after the file name.
    const std::string head = "Line <", of_file = "> of file <";
    const std::size_t head_start = text.find(head);
    const std::size_t number_end = text.find(of_file, head_start);
    if (head_start == std::string::npos || number_end == std::string::npos)
      return "";
    const std::size_t line = std::stoul(text.substr(head_start + head.size()));
    const std::size_t file_start = number_end + of_file.size();
    const std::string no_subsection_marker =
      ": There is no such subsection to be entered:";
    const std::size_t file_end = no_subsection ?
                                   text.rfind(no_subsection_marker) :
                                   text.find(">:", file_start);
    if (file_end == std::string::npos)
      return "";
    const std::string file = text.substr(file_start, file_end - file_start);
    const std::string at_line =
      "line " + std::to_string(line) + " of '" + file + "'";
    const auto        lines_of = in_file.path_at_line.find(file);
    const std::string path =
      lines_of != in_file.path_at_line.end() && line < lines_of->second.size() ?
        lines_of->second[line] :
        "";

    if (no_include)
      {
        const std::string given = "file to include <";
        const std::size_t start = text.find(given) + given.size();
        return at_line + ": cannot open the included file '" +
               text.substr(start, text.rfind("> cannot") - start) +
               "' (deal.II's parser takes its path from the working "
               "directory, not from the including file's folder)";
      }

    const Declared declared = declared_parameters(prm);

    if (invalid_value)
      {
        // The value, the name and the pattern, after fixed markers.
        const std::string markers[] = {"The entry value",
                                       "for the entry named",
                                       "does not match the given pattern:"};
        std::size_t       positions[3];
        for (unsigned int i = 0; i < 3; ++i)
          if ((positions[i] = text.find(markers[i])) == std::string::npos)
            return "";
        const auto between = [&](const unsigned int i) {
          const std::size_t start = positions[i] + markers[i].size();
          return trimmed(
            text.substr(start,
                        i < 2 ? positions[i + 1] - start : std::string::npos));
        };
        const std::string value = between(0);
        return "parameter '" + (path.empty() ? "" : path + "/") + between(1) +
               "' = " + (value.empty() ? "'' (empty)" : shortened(value)) +
               ": must be " + in_words(between(2)) + " (" + at_line + ")";
      }
    if (no_subsection)
      {
        // deal.II names it by a mangled path: the file's line says it.
        std::string leaf;
        if (const auto lines = in_file.lines.find(file);
            lines != in_file.lines.end() && lines->second.count(line))
          leaf = trimmed(lines->second.at(line).substr(11));
        return at_line + ": " + where(path) + " has no subsection '" + leaf +
               "'" + nearest_among(leaf, declared.subsections, path) +
               see_listing;
      }
    const std::string undeclared   = "No entry with name <",
                      declared_end = "> was declared";
    const std::size_t name_start   = text.find(undeclared);
    const std::size_t name_end     = text.rfind(declared_end);
    if (name_start != std::string::npos && name_end != std::string::npos &&
        name_end > name_start)
      {
        const std::string name =
          text.substr(name_start + undeclared.size(),
                      name_end - name_start - undeclared.size());
        return at_line + ": '" + shortened(name) + "' is not a parameter of " +
               where(path) + hint_for_entry(name, path, declared.entries) +
               see_listing;
      }
    const std::size_t reason = text.find(">: ", file_start);
    return at_line + ": " + trimmed(text.substr(reason + 3));
  }

  std::string
  value_in_file(const std::string &parameter_file,
                const std::string &path,
                const std::string &name,
                const std::string &otherwise)
  {
    const std::string kind = parameter_file_kind(parameter_file);
    if (kind == "json" || kind == "xml")
      try
        {
          const Tree tree = structured_tree(parameter_file, kind);
          return value_in_tree(tree, path, name, otherwise);
        }
      catch (const InputError &)
        {
          return otherwise;
        }
    Walk                     in_file;
    std::ifstream            stream(parameter_file);
    std::vector<std::string> top;
    walk(stream, parameter_file, top, in_file);
    const auto value = in_file.values.find(path + "/" + name);
    return value == in_file.values.end() ? otherwise : value->second;
  }

  namespace
  {
    /// Whether @p value is @p default_value: item by item (lists split at
    /// ',' and ';'), the same words or the same number ('100.0' and ' 100',
    /// as JSON and XML files keep spaces; '0,-1,0' and '0, -1, 0').
    bool
    is_default(const std::string &value, const std::string &default_value)
    {
      const auto items = [](const std::string &text) {
        return dealii::Utilities::split_string_list(
          std::regex_replace(text, std::regex(";"), ","), ',');
      };
      const std::vector<std::string> a = items(value), b = items(default_value);
      if (a.size() != b.size())
        return false;
      for (std::size_t i = 0; i < a.size(); ++i)
        {
          double x = 0, y = 0;
          if (a[i] != b[i] &&
              !(parse_number(a[i], x) && parse_number(b[i], y) && x == y))
            return false;
        }
      return true;
    }

    std::pair<std::string, std::string>
    first_changed_below(const Tree &node, const std::string &path)
    {
      for (const auto &[name, child] : node)
        {
          const std::string full = path + "/" + name;
          if (const auto value = child.get_optional<std::string>("value"))
            {
              if (!is_default(*value,
                              child.get<std::string>("default_value", *value)))
                return {full, *value};
            }
          else if (auto found = first_changed_below(child, full);
                   !found.first.empty())
            return found;
        }
      return {};
    }
  } // namespace

  std::pair<std::string, std::string>
  first_changed_entry(const dealii::ParameterHandler &prm,
                      const std::string              &section)
  {
    const Tree listing = listing_of(prm);
    const auto found   = listing.find(section);
    if (found == listing.not_found())
      return {};
    return first_changed_below(found->second, section);
  }

  std::vector<std::string>
  sections_declared_by(
    const std::function<void(dealii::ParameterHandler &)> &declare)
  {
    dealii::ParameterHandler prm;
    declare(prm);
    std::vector<std::string> sections;
    for (const auto &[name, child] : listing_of(prm))
      if (!child.get_optional<std::string>("value"))
        sections.push_back(name);
    return sections;
  }
} // namespace unilateral
