// What the TFETI tests share: a wall's parameter text, and TFETI's run
// against PDAS's on the same wall in verdicts (converged, KKT <= 1e-10, the
// same energy to 1e-10 relative, the same closed contacts (normal gap <=
// 1e-10 of the largest displacement), the same contact forces (1e-8 of the
// largest), the projection done in 1 or 2 iterations). Run on several
// ranks (the .mpirun=N. tests), each verdict holds only if it holds on
// every rank (mpi_test::all_ranks), each rank's run judged against the
// reference it computed itself.
#pragma once

#include "../mpi_test_tools.h"
#include "masonry_test_tools.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace tfeti_test
{
  using namespace masonry_test;

  /// The report's figure @p name, or -1 if it has none.
  inline double
  figure(const lcp::Report &report, const std::string &name)
  {
    for (const auto &[key, value] : report.figures)
      if (key == name)
        return value;
    return -1;
  }

  inline std::string
  prm_text(const std::string &geometry,
           const unsigned int m,
           const std::string &method,
           const std::string &boundary = "")
  {
    return "subsection Masonry\n  set Geometry = " + geometry +
           "\n  set Blocks per side = " + std::to_string(m) +
           "\n  subsection Boundary conditions\n" + boundary +
           "  end\nend\nsubsection Solver\n  set Method = " + method +
           "\nend\n";
  }

  /// The nodal displacements, node by node, as one vector.
  template <int dim>
  std::vector<double>
  displacements(const MasonryScene<dim> &scene)
  {
    std::vector<double> result;
    for (const auto &node : scene.nodal_displacements())
      result.insert(result.end(),
                    node.displacement.begin(),
                    node.displacement.end());
    return result;
  }

  template <int dim>
  double
  largest_displacement(const MasonryScene<dim> &scene)
  {
    double largest = 0;
    for (const auto &node : scene.nodal_displacements())
      for (unsigned int d = 0; d < dim; ++d)
        largest = std::max(largest, std::abs(node.displacement[d]));
    return largest;
  }

  // The verdicts of a run (TFETI's) against PDAS's; @p check_projection:
  // whether the run ends with the projection step (TFETI does, an exact
  // method does not).
  template <int dim>
  void
  compare(const std::string &what,
          const RunOf<dim>  &reference,
          const RunOf<dim>  &result,
          const bool         check_projection = true)
  {
    const auto  &ref_contacts = reference.scene->constraint_results();
    const auto  &contacts     = result.scene->constraint_results();
    const double gap_scale =
      std::max(largest_displacement(*reference.scene), 1e-300);
    double force_scale = 0;
    for (const auto &c : ref_contacts)
      force_scale = std::max(force_scale, std::abs(c.contact_force));
    unsigned int n_degenerate = 0, n_closed = 0, different_closed = 0;
    double       force_difference = 0;
    for (std::size_t k = 0; k < std::min(contacts.size(), ref_contacts.size());
         ++k)
      {
        const bool closed_ref = ref_contacts[k].normal_gap <= 1e-10 * gap_scale;
        const bool closed     = contacts[k].normal_gap <= 1e-10 * gap_scale;
        n_closed += closed_ref;
        different_closed += closed != closed_ref;
        n_degenerate += closed_ref && std::abs(ref_contacts[k].contact_force) <=
                                        1e-10 * force_scale;
        const double d =
          std::abs(contacts[k].contact_force - ref_contacts[k].contact_force);
        force_difference = std::isnan(d) ?
                             std::numeric_limits<double>::infinity() :
                             std::max(force_difference, d);
      }
    const double energy_difference =
      std::abs(result.report.energy - reference.report.energy);
    using mpi_test::all_ranks;
    const bool converged =
      all_ranks(result.report.converged() && reference.report.converged());
    const bool kkt = all_ranks(result.report.kkt.max() <= 1e-10);
    const bool energy =
      all_ranks(energy_difference <= 1e-10 * std::abs(reference.report.energy));
    const bool closed = all_ranks(different_closed == 0 &&
                                  contacts.size() == ref_contacts.size());
    const bool forces = all_ranks(force_difference <= 1e-8 * force_scale);
    const bool projection =
      all_ranks(result.report.projection_iterations >= 1 &&
                result.report.projection_iterations <= 2);
    std::cout << what << " (" << n_closed << " of " << contacts.size()
              << " contacts closed, " << n_degenerate
              << " degenerate): converged: " << yes_no(converged)
              << ", KKT <= 1e-10: " << yes_no(kkt)
              << ", energy: " << yes_no(energy)
              << ", closed contacts: " << yes_no(closed)
              << ", forces: " << yes_no(forces);
    if (check_projection)
      std::cout << ", projection in 1 or 2 iterations: " << yes_no(projection);
    std::cout << "\n";
  }

  /// TFETI's run, after its verdicts against PDAS's (@p name names the
  /// runs' folder, @p masonry adds lines to the Masonry section's start,
  /// e.g. the dimension).
  template <int dim = 2>
  RunOf<dim>
  against_pdas(const std::string &what,
               const std::string &geometry,
               const unsigned int m,
               const std::string &boundary = "",
               const std::string &name     = "tfeti",
               const std::string &masonry  = "")
  {
    const RunOf<dim> reference =
      run<dim>(parse(masonry + prm_text(geometry, m, "pdas", boundary)), name);
    RunOf<dim> result =
      run<dim>(parse(masonry + prm_text(geometry, m, "tfeti", boundary)), name);
    compare(what, reference, result);
    return result;
  }
} // namespace tfeti_test
