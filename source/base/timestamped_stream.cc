#include <unilateral/base/timestamped_stream.h>

#include <cstdio>

namespace unilateral
{
  TimestampedStream::TimestampedStream(std::ostream &target)
    : std::ostream(nullptr)
    , buffer(target.rdbuf())
  {
    rdbuf(&buffer);
  }

  TimestampedStream::Buffer::Buffer(std::streambuf *target)
    : target(target)
    , start(std::chrono::steady_clock::now())
  {}

  TimestampedStream::Buffer::int_type
  TimestampedStream::Buffer::overflow(const int_type c)
  {
    if (traits_type::eq_int_type(c, traits_type::eof()))
      return traits_type::not_eof(c);
    // A stream without a buffer (another rank's) fails as it would.
    if (target == nullptr)
      return traits_type::eof();
    if (at_line_start)
      {
        const std::chrono::duration<double> elapsed =
          std::chrono::steady_clock::now() - start;
        char      prefix[32];
        const int length =
          std::snprintf(prefix, sizeof prefix, "[%7.1f s] ", elapsed.count());
        if (target->sputn(prefix, length) != length)
          return traits_type::eof();
        at_line_start = false;
      }
    if (traits_type::eq_int_type(target->sputc(traits_type::to_char_type(c)),
                                 traits_type::eof()))
      return traits_type::eof();
    at_line_start = traits_type::to_char_type(c) == '\n';
    return c;
  }

  int
  TimestampedStream::Buffer::sync()
  {
    return target == nullptr ? -1 : target->pubsync();
  }
} // namespace unilateral
