#include <unilateral/base/text.h>

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
} // namespace unilateral
