#pragma once

#include <chrono>
#include <ostream>
#include <streambuf>

namespace unilateral
{
  /**
   * An output stream that begins each line with the wall time elapsed since
   * it was made ("[  12.3 s] ") and writes through to another stream: the
   * progress lines of a long run say when each iteration ended, so a user
   * sees where the time goes without a profiler.
   */
  class TimestampedStream : public std::ostream
  {
  public:
    explicit TimestampedStream(std::ostream &target);

  private:
    class Buffer : public std::streambuf
    {
    public:
      explicit Buffer(std::streambuf *target);

    protected:
      int_type
      overflow(int_type c) override;

      int
      sync() override;

    private:
      std::streambuf                             *target;
      std::chrono::steady_clock::time_point const start;
      bool                                        at_line_start = true;
    };

    Buffer buffer;
  };
} // namespace unilateral
