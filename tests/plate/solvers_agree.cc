// Every LCP method on the plate: the paper's interior point and block
// pivoting, PDAS, PDPC, PSOR, LSSNN, and Graves on the Schur complement (it
// needs every unknown constrained) must find the same plate as PDAS: nodal
// DOFs equal to 1e-8 relative and the same nodes in contact, on four small
// configurations of the paper's tables. A method that is not registered
// makes the test fail (SolverRegistry throws), never skip.

#include "plate_runs.h"

#include "../test_tools.h"

#include <cmath>

using test_tools::verdict;

namespace
{
  struct Method
  {
    std::string name;
    std::string settings; // extra lines for subsection Solver
  };

  double
  relative_difference(const dealii::Vector<double> &a,
                      const dealii::Vector<double> &b)
  {
    double difference = 0, scale = 0;
    for (unsigned int i = 0; i < a.size(); ++i)
      {
        difference = std::max(difference, std::abs(a[i] - b[i]));
        scale      = std::max(scale, std::abs(b[i]));
      }
    return difference / scale;
  }
} // namespace

int
main()
{
  const std::vector<std::vector<std::string>> configurations = {
    {"lead", "psi2", "f2", "4"},
    {"steel", "psi1", "f1", "10"},
    {"steel", "psi3", "f1", "10"},
    {"bronze", "psi3", "f1", "20"}};
  const std::vector<Method> methods = {
    {"interior_point", ""},
    {"block_pivoting", ""},
    {"pdpc", ""},
    {"psor", ""},
    {"lssnn", ""},
    {"graves", "  set Schur complement = true\n"},
    {"pdas", "  set Schur complement = true\n"}};

  bool all = true;
  for (const auto &c : configurations)
    {
      const unsigned int n    = std::stoi(c[3]);
      const std::string  plate =
        plate_runs::paper_configuration(c[0], c[1], c[2], n);
      const std::string name = c[0] + "_" + c[1] + "_" + c[2] + "_" + c[3];
      const auto reference   = plate_runs::run_plate(name + "_pdas", plate, "pdas");
      std::cout << c[0] << " " << c[1] << " " << c[2] << " " << n << "x" << n
                << ": pdas " << (reference.report.converged() ? "converged" : "FAILED")
                << ", cn = " << reference.results().n_contact << std::endl;
      all = all && reference.report.converged();
      for (const Method &method : methods)
        {
          const auto run = plate_runs::run_plate(
            name + "_" + method.name, plate, method.name, false, method.settings);
          const bool agree =
            run.report.converged() &&
            run.results().n_contact == reference.results().n_contact &&
            relative_difference(run.scene->nodal_values(),
                                reference.scene->nodal_values()) < 1e-8;
          all = all && agree;
          verdict("  " + method.name +
                    (method.settings.empty() ? "" : " (Schur complement)") +
                    ": converged, same cn, nodal DOFs within 1e-8 relative of pdas",
                  agree);
        }
    }
  verdict("all methods agree on all configurations", all);
}
