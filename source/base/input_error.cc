#include <unilateral/base/input_error.h>

#include <deal.II/base/exceptions.h>

#include <sstream>

namespace unilateral
{
  std::string
  one_line_message(const std::exception &exception)
  {
    std::string text = exception.what();
    if (dynamic_cast<const dealii::ExceptionBase *>(&exception) != nullptr)
      {
        // Keep what deal.II meant for people: "Additional information", or
        // failing that the violated condition.
        for (const std::string marker :
             {"Additional information:", "The violated condition was:"})
          {
            const auto start = text.find(marker);
            if (start != std::string::npos)
              {
                text = text.substr(start + marker.size());
                for (const std::string stop : {"-----", "Stacktrace:"})
                  {
                    const auto end = text.find(stop);
                    if (end != std::string::npos)
                      text = text.substr(0, end);
                  }
                break;
              }
          }
      }
    // Collapse all whitespace (newlines included) to single spaces.
    std::string        result;
    std::istringstream words(text);
    std::string        word;
    while (words >> word)
      result += (result.empty() ? "" : " ") + word;
    return result;
  }
} // namespace unilateral
