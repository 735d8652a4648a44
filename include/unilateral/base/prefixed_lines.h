#pragma once

#include <functional>
#include <ostream>
#include <streambuf>
#include <string>

namespace unilateral
{
  /**
   * An output stream that writes through to another and begins each line
   * with a prefix, computed when the line starts: the elapsed time on the
   * progress lines of a run, a label on the projection step's lines (which
   * would otherwise repeat the solve's word for word). A label may go after
   * the line's leading spaces, so that it keeps the indentation.
   */
  class PrefixedLines : public std::ostream
  {
  public:
    PrefixedLines(std::ostream                &target,
                  std::function<std::string()> prefix,
                  bool                         after_indentation = false);

    /// The wall time since this call, "[   12.3 s] ", as a prefix.
    static std::function<std::string()>
    elapsed_seconds();

  private:
    class Buffer : public std::streambuf
    {
    public:
      Buffer(std::ostream                &target,
             std::function<std::string()> prefix,
             bool                         after_indentation);

    protected:
      int_type
      overflow(int_type c) override;

      int
      sync() override;

    private:
      std::ostream                      &target;
      const std::function<std::string()> prefix;
      const bool                         after_indentation;
      bool                               at_line_start = true;
    };

    Buffer buffer;
  };
} // namespace unilateral
