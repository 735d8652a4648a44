#include "driver.h"

#include <unilateral/base/input_error.h>
#include <unilateral/lcp/io.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace external
{
  Options::Options(int argc, char **argv, int first)
  {
    for (int i = first; i < argc; ++i)
      {
        const std::string argument = argv[i];
        const auto        equals   = argument.find('=');
        if (equals == std::string::npos || equals == 0)
          throw unilateral::InputError("option '" + argument +
                                       "' is not of the form key=value");
        given[argument.substr(0, equals)] = argument.substr(equals + 1);
      }
  }

  std::string
  Options::string(const std::string &key, const std::string &default_value)
  {
    const auto        found = given.find(key);
    const std::string value =
      found == given.end() ? default_value : found->second;
    used[key] = value;
    return value;
  }

  double
  Options::number(const std::string &key, const double default_value)
  {
    std::ostringstream text;
    text << std::setprecision(17) << default_value;
    const std::string value = string(key, text.str());
    try
      {
        std::size_t  end    = 0;
        const double result = std::stod(value, &end);
        if (end == value.size())
          return result;
      }
    catch (const std::exception &)
      {}
    throw unilateral::InputError("option " + key + "=" + value +
                                 " is not a number");
  }

  int
  Options::integer(const std::string &key, const int default_value)
  {
    const std::string value = string(key, std::to_string(default_value));
    try
      {
        std::size_t end    = 0;
        const int   result = std::stoi(value, &end);
        if (end == value.size())
          return result;
      }
    catch (const std::exception &)
      {}
    throw unilateral::InputError("option " + key + "=" + value +
                                 " is not an integer");
  }

  std::string
  Options::summary() const
  {
    std::string result;
    for (const auto &[key, value] : used)
      result += (result.empty() ? "" : " ") + key + "=" + value;
    return result;
  }

  void
  Options::check_all_used() const
  {
    for (const auto &entry : given)
      if (used.count(entry.first) == 0)
        throw unilateral::InputError("unknown option '" + entry.first +
                                     "' for this driver and method");
  }

  double
  force_scale(const Problem &problem)
  {
    const double scale =
      problem.size() > 0 ? problem.b.lpNorm<Eigen::Infinity>() : 0.0;
    return scale > 0 ? scale : 1.0;
  }

  namespace
  {
    std::string
    json_string(const std::string &text)
    {
      std::ostringstream out;
      out << '"';
      for (const char c : text)
        switch (c)
          {
            case '"':
              out << "\\\"";
              break;
            case '\\':
              out << "\\\\";
              break;
            case '\n':
              out << "\\n";
              break;
            case '\t':
              out << "\\t";
              break;
            default:
              if (static_cast<unsigned char>(c) < 0x20)
                out << ' ';
              else
                out << c;
          }
      out << '"';
      return out.str();
    }

    std::string
    json_number(const double value)
    {
      if (!std::isfinite(value))
        return "null";
      std::ostringstream out;
      out << std::setprecision(6) << std::scientific << value;
      return out.str();
    }

    const char *usage =
      "usage: DRIVER METHOD LCP_DIRECTORY OUTPUT_DIRECTORY [key=value ...]\n"
      "  reads LCP_DIRECTORY/{lcp_A.mtx,lcp_b.txt,lcp_constraints.txt},\n"
      "  writes OUTPUT_DIRECTORY/{u.txt,result.json}\n";
  } // namespace

  int
  run(int         argc,
      char      **argv,
      const char *package,
      void (*solve)(const std::string &, const Problem &, Options &, Outcome &))
  {
    if (argc < 4)
      {
        std::cerr << usage;
        return 1;
      }
    const std::string           method = argv[1];
    const std::filesystem::path input(argv[2]);
    const std::filesystem::path output(argv[3]);

    Problem         problem;
    Outcome         outcome;
    std::string     options_text;
    double          read_time = 0, total_time = 0;
    bool            solved = false;
    const Stopwatch total;
    try
      {
        Options options(argc, argv, 4);
        problem = unilateral::lcp::read_problem(
          (input / "lcp_A.mtx").string(),
          (input / "lcp_b.txt").string(),
          (input / "lcp_constraints.txt").string());
        read_time = total.seconds();
        solve(method, problem, options, outcome);
        total_time = total.seconds();
        options.check_all_used();
        options_text = options.summary();
        solved       = outcome.u.size() == problem.size();
        if (!solved && outcome.converged)
          {
            outcome.converged = false;
            outcome.status    = "failed";
            outcome.message   = "the driver returned no solution vector";
          }
      }
    catch (const unilateral::InputError &error)
      {
        std::cerr << package << " driver: " << error.what() << "\n" << usage;
        return 1;
      }
    catch (const std::exception &error)
      {
        outcome.converged = false;
        outcome.status    = "failed";
        outcome.message   = error.what();
        total_time        = total.seconds();
      }

    std::filesystem::create_directories(output);
    unilateral::lcp::KktResiduals kkt;
    if (solved)
      {
        unilateral::lcp::write_vector(outcome.u, (output / "u.txt").string());
        kkt = unilateral::lcp::kkt_residuals(problem, outcome.u);
      }
    const double nan = std::nan("");

    std::ostringstream json;
    json << "{\"package\": " << json_string(package)
         << ", \"method\": " << json_string(method)
         << ", \"n_unknowns\": " << problem.size()
         << ", \"n_constraints\": " << problem.n_constrained()
         << ", \"status\": " << json_string(outcome.status)
         << ", \"converged\": " << (outcome.converged ? "true" : "false")
         << ", \"iterations\": " << outcome.iterations
         << ", \"message\": " << json_string(outcome.message)
         << ", \"options\": " << json_string(options_text)
         << ", \"time\": {\"read\": " << json_number(read_time)
         << ", \"setup\": " << json_number(outcome.setup_time)
         << ", \"solve\": " << json_number(outcome.solve_time)
         << ", \"total\": " << json_number(total_time) << "}"
         << ", \"kkt\": {\"stationarity\": "
         << json_number(solved ? kkt.stationarity : nan)
         << ", \"primal_feasibility\": "
         << json_number(solved ? kkt.primal_feasibility : nan)
         << ", \"dual_feasibility\": "
         << json_number(solved ? kkt.dual_feasibility : nan)
         << ", \"complementarity\": "
         << json_number(solved ? kkt.complementarity : nan)
         << ", \"max\": " << json_number(solved ? kkt.max() : nan) << "}}";
    std::ofstream((output / "result.json").string()) << json.str() << "\n";
    std::cout << json.str() << std::endl;
    return outcome.converged ? 0 : 2;
  }
} // namespace external
