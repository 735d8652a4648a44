#include <unilateral/lcp/report.h>

namespace unilateral::lcp
{
  std::string
  to_string(const Status status)
  {
    switch (status)
      {
        case Status::converged:
          return "converged";
        case Status::iteration_limit:
          return "iteration limit";
        case Status::infeasible:
          return "infeasible";
        case Status::singular:
          return "singular";
        case Status::inaccurate:
          return "inaccurate";
      }
    return "unknown";
  }

  void
  Report::add_time(const std::string &phase, const double seconds)
  {
    for (auto &entry : phase_times)
      if (entry.first == phase)
        {
          entry.second += seconds;
          return;
        }
    phase_times.emplace_back(phase, seconds);
  }

  void
  Report::take_counts_of(const Report &other)
  {
    iterations            = other.iterations;
    projection_iterations = other.projection_iterations;
    continuation_stages   = other.continuation_stages;
    projected             = other.projected;
    regularisation        = other.regularisation;
  }

  void
  Report::set_figure(const std::string &name, const double value)
  {
    for (auto &entry : figures)
      if (entry.first == name)
        {
          entry.second = value;
          return;
        }
    figures.emplace_back(name, value);
  }

  double
  Report::total_time() const
  {
    double total = 0;
    for (const auto &entry : phase_times)
      total += entry.second;
    return total;
  }

  Counters &
  Counters::operator+=(const Counters &other)
  {
    orderings += other.orderings;
    symbolic_analyses += other.symbolic_analyses;
    numeric_factorisations += other.numeric_factorisations;
    reused_factorisations += other.reused_factorisations;
    modified_factorisations += other.modified_factorisations;
    factor_row_modifications += other.factor_row_modifications;
    resolved_subsets += other.resolved_subsets;
    resolved_indices += other.resolved_indices;
    cg_iterations += other.cg_iterations;
    triangular_solves += other.triangular_solves;
    partial_forward_solves += other.partial_forward_solves;
    centrality_correctors += other.centrality_correctors;
    matrix_vector_products += other.matrix_vector_products;
    return *this;
  }

  void
  Report::add_times(const Report &other, const std::string &prefix)
  {
    for (const auto &[phase, seconds] : other.phase_times)
      add_time(prefix + phase, seconds);
  }
} // namespace unilateral::lcp
