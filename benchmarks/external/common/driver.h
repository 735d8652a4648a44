#pragma once

/**
 * What every external-solver driver shares: the command line, reading the
 * LCP with unilateral's own reader, timing, and judging the result with
 * unilateral's own kkt_residuals(), so that every number in the benchmark
 * table is measured with one yardstick.
 *
 * Command line of every driver:
 *   DRIVER METHOD LCP_DIRECTORY OUTPUT_DIRECTORY [key=value ...]
 * It reads LCP_DIRECTORY/{lcp_A.mtx, lcp_b.txt, lcp_constraints.txt},
 * solves, and writes OUTPUT_DIRECTORY/u.txt and OUTPUT_DIRECTORY/result.json
 * (also printed on stdout as one line). Exit code 0 when the package's solver
 * says it converged, 2 when it ran but did not, 1 on a usage or input error.
 */

#include <unilateral/base/input_error.h>
#include <unilateral/lcp/problem.h>

#include <chrono>
#include <map>
#include <string>

namespace external
{
  using unilateral::lcp::Index;
  using unilateral::lcp::Problem;
  using unilateral::lcp::Vector;

  /// key=value options of the command line, with typed getters that record
  /// which options (and defaults) a run used.
  class Options
  {
  public:
    Options(int argc, char **argv, int first);

    double
    number(const std::string &key, double default_value);

    int
    integer(const std::string &key, int default_value);

    std::string
    string(const std::string &key, const std::string &default_value);

    /// Every option as "key=value key=value", defaults included.
    std::string
    summary() const;

    /// Throws if an option was given that no getter asked for (a typo).
    void
    check_all_used() const;

  private:
    std::map<std::string, std::string> given;
    std::map<std::string, std::string> used;
  };

  /// Wall-clock seconds since construction.
  class Stopwatch
  {
  public:
    Stopwatch()
      : start(std::chrono::steady_clock::now())
    {}

    double
    seconds() const
    {
      return std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                           start)
        .count();
    }

  private:
    std::chrono::steady_clock::time_point start;
  };

  /// What a driver's solve returns.
  struct Outcome
  {
    /// "converged", or the package's own word for what happened.
    std::string status     = "converged";
    bool        converged  = true;
    long        iterations = 0;
    /// Free text: the package's reason code, factorisation used, ...
    std::string message;
    Vector      u;
    /// Seconds spent building the package's data structures from Problem.
    double setup_time = 0;
    /// Seconds inside the package's solve call(s) only.
    double solve_time = 0;
  };

  /**
   * The driver's entry point: parses the command line, reads the problem,
   * calls @p solve(method, problem, options, outcome), checks the result
   * with kkt_residuals() and writes u.txt and result.json.
   */
  int
  run(int         argc,
      char      **argv,
      const char *package,
      void (*solve)(const std::string &method,
                    const Problem     &problem,
                    Options           &options,
                    Outcome           &outcome));

  /// Infinity-norm of b (1 if zero): the force scale the tolerances use.
  double
  force_scale(const Problem &problem);
} // namespace external
