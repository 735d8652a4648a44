#include <unilateral/base/parameter_file_errors.h>

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
      const auto first = text.find_first_not_of(" \t\r");
      if (first == std::string::npos)
        return "";
      return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
    }

    std::string
    joined(const std::vector<std::string> &path)
    {
      std::string result;
      for (const std::string &name : path)
        result += (result.empty() ? "" : "/") + name;
      return result;
    }

    /// A parameter file's lines as the parser sees them: comments cut,
    /// and the subsection each line lies in.
    struct Walk
    {
      /// The subsection path at each line (1-based; [0] unused), and at
      /// the end of the file.
      std::vector<std::string> path_at_line;
      std::string              path_at_end;
      /// Each line without its comment and outer blanks.
      std::vector<std::string> lines;
      /// Per subsection path: the entries and the subsections declared in
      /// it.
      std::map<std::string, std::vector<std::string>> entries, subsections;
    };

    Walk
    walk(std::istream &in)
    {
      Walk                     result;
      std::vector<std::string> path;
      std::string              line;
      result.path_at_line.emplace_back();
      result.lines.emplace_back();
      while (std::getline(in, line))
        {
          result.path_at_line.push_back(joined(path));
          if (result.path_at_line.size() == 2 &&
              line.rfind("\xEF\xBB\xBF", 0) == 0) // a byte-order mark
            line.erase(0, 3);
          line = trimmed(line.substr(0, line.find('#')));
          result.lines.push_back(line);
          if (line.rfind("subsection ", 0) == 0)
            {
              const std::string name = trimmed(line.substr(11));
              result.subsections[joined(path)].push_back(name);
              path.push_back(name);
            }
          else if (line == "end" && !path.empty())
            path.pop_back();
          else if (line.rfind("set ", 0) == 0)
            result.entries[joined(path)].push_back(
              trimmed(line.substr(4, line.find('=') - 4)));
        }
      result.path_at_end = joined(path);
      return result;
    }

    /// The edit distance of @p a and @p b, ignoring case.
    std::size_t
    distance(const std::string &a, const std::string &b)
    {
      std::vector<std::size_t> row(b.size() + 1);
      for (std::size_t j = 0; j <= b.size(); ++j)
        row[j] = j;
      for (std::size_t i = 1; i <= a.size(); ++i)
        {
          std::size_t diagonal = row[0];
          row[0]               = i;
          for (std::size_t j = 1; j <= b.size(); ++j)
            {
              const std::size_t above = row[j];
              const bool        same =
                std::tolower(static_cast<unsigned char>(a[i - 1])) ==
                std::tolower(static_cast<unsigned char>(b[j - 1]));
              row[j] = std::min(
                {row[j] + 1, row[j - 1] + 1, diagonal + (same ? 0 : 1)});
              diagonal = above;
            }
        }
      return row[b.size()];
    }

    /// ": did you mean 'X'?" for the nearest of @p names to @p name, if
    /// it is near (a typing slip); else nothing.
    std::string
    nearest(const std::string &name, const std::vector<std::string> &names)
    {
      const std::string *best   = nullptr;
      std::size_t best_distance = std::max<std::size_t>(2, name.size() / 3) + 1;
      for (const std::string &candidate : names)
        if (const std::size_t d = distance(name, candidate); d < best_distance)
          {
            best          = &candidate;
            best_distance = d;
          }
      return best == nullptr ? "" : ": did you mean '" + *best + "'?";
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

    /// "'A/B'" or "the top level".
    std::string
    where(const std::string &path)
    {
      return path.empty() ? "the top level" : "subsection '" + path + "'";
    }
  } // namespace

  std::string
  explain_parse_error(const dealii::ExceptionBase    &error,
                      const dealii::ParameterHandler &prm)
  {
    using Handler = dealii::ParameterHandler;
    const bool invalid_value =
      dynamic_cast<const Handler::ExcInvalidEntryForPattern *>(&error);
    const bool no_subsection =
      dynamic_cast<const Handler::ExcNoSubsection *>(&error);
    std::ostringstream info;
    error.print_info(info);
    const std::string text = info.str();
    std::smatch       match;

    if (dynamic_cast<const Handler::ExcUnbalancedSubsections *>(&error))
      {
        static const std::regex named(R"(parameter file <([^\n]*)>)");
        if (!std::regex_search(text, match, named))
          return "";
        std::ifstream     file_stream(match[1].str());
        const std::string open = walk(file_stream).path_at_end;
        return "parameter file '" + match[1].str() + "': " +
               (open.empty() ? "an 'end' without its 'subsection': remove it" :
                               "it ends inside subsection '" + open +
                                 "': close each 'subsection' with an 'end' "
                                 "line");
      }
    if (!invalid_value && !no_subsection &&
        !dynamic_cast<const Handler::ExcCannotParseLine *>(&error))
      return "";

    // "Line <12> of file <bad.prm>: ..." (ExcNoSubsection has no '>'
    // after the file name).
    const std::regex located(R"(Line <(\d+)> of file <([^\n]*?)>?:\s)");
    if (!std::regex_search(text, match, located))
      return "";
    const unsigned int line   = std::stoul(match[1]);
    const std::string  file   = match[2];
    const std::string  reason = trimmed(match.suffix());
    const std::string  at_line =
      "line " + std::to_string(line) + " of '" + file + "'";

    std::ifstream     file_stream(file);
    const Walk        in_file = walk(file_stream);
    const std::string path =
      line < in_file.path_at_line.size() ? in_file.path_at_line[line] : "";
    std::stringstream listing;
    prm.print_parameters(listing, Handler::ShortPRM);
    const Walk        declared = walk(listing);
    const std::string see =
      " ('unilateral --print-parameters' lists every parameter)";

    if (invalid_value)
      {
        // The value, the name and the pattern, each on a line of its own.
        std::vector<std::string> lines;
        std::istringstream       text_lines(text);
        for (std::string each; std::getline(text_lines, each);)
          lines.push_back(trimmed(each));
        if (lines.size() < 7)
          return "";
        const std::string &value = lines[2], &name = lines[4];
        return "parameter '" + (path.empty() ? "" : path + "/") + name +
               "' = " + value + ": must be " + in_words(lines[6]) + " (" +
               at_line + ")";
      }
    if (no_subsection)
      {
        // deal.II names it by its mangled path: the file's line says it.
        const std::string leaf =
          line < in_file.lines.size() &&
              in_file.lines[line].rfind("subsection ", 0) == 0 ?
            trimmed(in_file.lines[line].substr(11)) :
            trimmed(text.substr(text.find("to be entered:") + 14));
        const auto names = declared.subsections.find(path);
        return at_line + ": " + where(path) + " has no subsection '" + leaf +
               "'" +
               (names == declared.subsections.end() ?
                  "" :
                  nearest(leaf, names->second)) +
               see;
      }
    static const std::regex undeclared(R"(No entry with name <(.*)> was)");
    if (std::regex_search(reason, match, undeclared))
      {
        const std::string        name = match[1];
        std::vector<std::string> elsewhere;
        for (const auto &[other_path, names] : declared.entries)
          if (other_path != path &&
              std::find(names.begin(), names.end(), name) != names.end())
            elsewhere.push_back("'" + other_path + "'");
        std::string hint;
        if (!elsewhere.empty())
          {
            hint = ": it is a parameter of ";
            for (std::size_t k = 0; k < elsewhere.size(); ++k)
              hint += (k == 0                    ? "" :
                       k + 1 == elsewhere.size() ? " and " :
                                                   ", ") +
                      elsewhere[k];
            hint += elsewhere.size() == 1 ? "; set it inside that subsection" :
                                            "; set it inside the one meant";
          }
        else
          {
            const auto names = declared.entries.find(path);
            hint             = names == declared.entries.end() ?
                                 "" :
                                 nearest(name, names->second);
          }
        return at_line + ": '" + name + "' is not a parameter of " +
               where(path) + hint + see;
      }
    return at_line + ": " + reason;
  }
} // namespace unilateral
