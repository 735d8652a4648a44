#pragma once

#include <string>

namespace unilateral
{
  /// "1 iteration", "2 iterations": @p n and the noun in its number
  /// (@p plural if given, else @p singular + "s").
  std::string
  quantity(unsigned long long n,
           const std::string &singular,
           const std::string &plural = "");
} // namespace unilateral
