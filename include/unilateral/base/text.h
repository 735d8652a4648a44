#pragma once

#include <string>
#include <vector>

namespace unilateral
{
  /// "1 iteration", "2 iterations": @p n and the noun in its number
  /// (@p plural if given, else @p singular + "s").
  std::string
  quantity(unsigned long long n,
           const std::string &singular,
           const std::string &plural = "");

  /// The one of @p names nearest to @p name (fewest letters to change,
  /// ignoring case), if it is near enough to be a slip in typing it; else
  /// empty.
  std::string
  nearest_name(const std::string &name, const std::vector<std::string> &names);

  /// Reads @p text as one number, accepting what strtod accepts and
  /// nothing more (no space, no trailing characters); false if it is not.
  bool
  parse_number(const std::string &text, double &value);
} // namespace unilateral
