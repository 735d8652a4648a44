#include <unilateral/base/prefixed_lines.h>

#include <chrono>
#include <cstdio>
#include <utility>

namespace unilateral
{
  PrefixedLines::PrefixedLines(std::ostream                &target,
                               std::function<std::string()> prefix,
                               const bool                   after_indentation)
    : std::ostream(nullptr)
    , buffer(target, std::move(prefix), after_indentation)
  {
    rdbuf(&buffer);
  }

  std::function<std::string()>
  PrefixedLines::elapsed_seconds()
  {
    const auto start = std::chrono::steady_clock::now();
    return [start]() {
      const std::chrono::duration<double> elapsed =
        std::chrono::steady_clock::now() - start;
      char text[32];
      std::snprintf(text, sizeof text, "[%7.1f s] ", elapsed.count());
      return std::string(text);
    };
  }

  PrefixedLines::Buffer::Buffer(std::ostream                &target,
                                std::function<std::string()> prefix,
                                const bool                   after_indentation)
    : target(target)
    , prefix(std::move(prefix))
    , after_indentation(after_indentation)
  {}

  PrefixedLines::Buffer::int_type
  PrefixedLines::Buffer::overflow(const int_type c)
  {
    if (traits_type::eq_int_type(c, traits_type::eof()))
      return traits_type::not_eof(c);
    const char character = traits_type::to_char_type(c);
    if (at_line_start && !(after_indentation && character == ' '))
      {
        target << prefix();
        at_line_start = false;
      }
    target.put(character);
    if (character == '\n')
      at_line_start = true;
    // A target that cannot be written (another rank's) fails this stream.
    return target ? c : traits_type::eof();
  }

  int
  PrefixedLines::Buffer::sync()
  {
    target.flush();
    return target ? 0 : -1;
  }
} // namespace unilateral
