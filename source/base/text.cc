#include <unilateral/base/text.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>

namespace unilateral
{
  std::string
  quantity(const unsigned long long n,
           const std::string       &singular,
           const std::string       &plural)
  {
    return std::to_string(n) + " " +
           (n == 1         ? singular :
            plural.empty() ? singular + "s" :
                             plural);
  }

  namespace
  {
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
  } // namespace

  std::string
  nearest_name(const std::string &name, const std::vector<std::string> &names)
  {
    // Long names are no typing slip of anything (and would take long).
    if (name.size() > 200)
      return "";
    const std::string *best   = nullptr;
    std::size_t best_distance = std::max<std::size_t>(2, name.size() / 3) + 1;
    for (const std::string &candidate : names)
      if (const std::size_t d = distance(name, candidate); d < best_distance)
        {
          best          = &candidate;
          best_distance = d;
        }
    return best == nullptr ? "" : *best;
  }

  bool
  parse_number(const std::string &text, double &value)
  {
    if (text.empty())
      return false;
    char *end = nullptr;
    value     = std::strtod(text.c_str(), &end);
    return end == text.c_str() + text.size();
  }
} // namespace unilateral
