#pragma once

// Run the application as a user would and judge what they would see: the
// exit code, and for bad input exactly one line on the error stream that
// names what it should. Tests print verdicts, and the message where it does
// not depend on the machine.

#include <unilateral/application.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace application_test
{
  struct Result
  {
    int         code = -1;
    std::string out;
    std::string err;
  };

  inline const char *
  yes_no(const bool condition)
  {
    return condition ? "yes" : "no";
  }

  /// The number after "key": in a summary.json's text (NaN if absent).
  inline double
  number(const std::string &json, const std::string &key)
  {
    std::smatch found;
    if (std::regex_search(json,
                          found,
                          std::regex("\"" + key + "\": *([-+0-9.eE]+)")))
      return std::stod(found[1]);
    return std::nan("");
  }

  inline void
  write(const std::string &file_name, const std::string &text)
  {
    std::ofstream(file_name) << text;
  }

  /// The whole text of a file ("" if it cannot be read).
  inline std::string
  read(const std::string &file_name)
  {
    std::ifstream      in(file_name);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }

  /// `unilateral arguments...` through run_application.
  inline Result
  run(const std::vector<std::string> &arguments)
  {
    std::vector<std::string> storage = {"unilateral"};
    storage.insert(storage.end(), arguments.begin(), arguments.end());
    std::vector<char *> argv;
    for (auto &argument : storage)
      argv.push_back(argument.data());
    std::ostringstream out, err;
    Result             result;
    result.code = unilateral::run_application(static_cast<int>(argv.size()),
                                              argv.data(),
                                              out,
                                              err);
    result.out  = out.str();
    result.err  = err.str();
    return result;
  }

  inline bool
  one_line(const std::string &text)
  {
    return !text.empty() && text.back() == '\n' &&
           std::count(text.begin(), text.end(), '\n') == 1;
  }

  /**
   * Verdicts for bad input: exit code 1, one line on the error stream, and
   * each of @p fragments in it; then the line itself unless
   * @p print_message is false (messages that quote the machine's memory).
   */
  inline void
  expect_error(const std::string              &what,
               const Result                   &result,
               const std::vector<std::string> &fragments,
               const bool                      print_message = true)
  {
    std::cout << what << ":\n  exit code 1: " << yes_no(result.code == 1)
              << "\n  one line on stderr: " << yes_no(one_line(result.err))
              << "\n";
    for (const std::string &fragment : fragments)
      std::cout << "  names '" << fragment << "': "
                << yes_no(result.err.find(fragment) != std::string::npos)
                << "\n";
    if (!print_message)
      return;
    std::cout << "  " << result.err;
    if (result.err.empty() || result.err.back() != '\n')
      std::cout << "\n";
  }
} // namespace application_test
