// Issue 21, fault 1: an obstacle above the plate's rest position (a plate
// pushed up by a die) is an ordinary problem. The 8 x 8 steel plate over
// psi = 0.1 lies on it at every interior node; every registered method must
// say so and agree (the number of methods run is printed: 18, the 9 on the
// full LCP and the 9 on its Schur complement). Before the fix of the work
// check's sign (b^T u + lambda_S^T l_S, not minus) every exact answer here
// was 'inaccurate'.
#include "../registered_methods.h"
#include "../test_tools.h"
#include "plate_runs.h"

#include <cmath>

using test_tools::verdict;

int
main()
{
  const std::string plate = "subsection Geometry\n  set Elements x = 8\n"
                            "  set Elements y = 8\nend\n"
                            "subsection Obstacle\n  set Function = 0.1\nend\n";
  const auto        reference =
    plate_runs::run_plate("raised_reference",
                          plate,
                          unilateral::lcp::default_method().name);
  std::cout << "reference: "
            << unilateral::lcp::to_string(reference.report.status)
            << ", cn = " << reference.results().n_contact
            << " of |J1| = " << reference.results().n_bounds << std::endl;
  verdict("the reference lies on the obstacle at every interior node",
          reference.report.converged() &&
            reference.results().n_contact == reference.results().n_bounds);
  bool       all = true;
  const auto methods =
    registered_methods::all(true, registered_methods::a_hierarchy);
  for (std::size_t m = 0; m < methods.size(); ++m)
    {
      const registered_methods::MethodRun &method = methods[m];
      const auto run = plate_runs::run_plate("raised_" + std::to_string(m),
                                             plate,
                                             method.name(),
                                             false,
                                             method.prm_settings());
      double     difference = 0, scale = 0;
      for (unsigned int i = 0; i < run.scene->nodal_values().size(); ++i)
        {
          difference = std::max(difference,
                                std::abs(run.scene->nodal_values()[i] -
                                         reference.scene->nodal_values()[i]));
          scale = std::max(scale, std::abs(reference.scene->nodal_values()[i]));
        }
      const bool agree =
        run.report.converged() &&
        run.results().n_contact == reference.results().n_contact &&
        difference <= 1e-8 * scale;
      if (!agree)
        std::cout << "  " << method.label() << ": "
                  << unilateral::lcp::to_string(run.report.status) << ", "
                  << run.report.message << std::endl;
      all = all && agree;
    }
  // The count: with no method the verdict below would hold vacuously.
  std::cout << "methods run: " << methods.size() << std::endl;
  verdict("every method converged to the same plate on the obstacle",
          all && !methods.empty());
}
