// Every LCP method on the plate: the paper's interior point and block
// pivoting, PDAS, PDPC, PSOR, LSSNN, TNNMG (on the plate's hierarchy of
// meshes), and Graves on the Schur complement (it needs every unknown
// constrained) must find the same plate as PDAS: nodal
// DOFs equal to 1e-8 relative and the same nodes in contact, on four small
// configurations of the paper's tables. A method that is not registered
// makes the test fail (SolverRegistry throws), never skip.

#include "../registered_methods.h"
#include "../test_tools.h"
#include "plate_runs.h"

#include <cmath>

using test_tools::verdict;

namespace
{
  using Method = registered_methods::MethodRun;

  // Every registered method and variant (a dense one on the Schur
  // complement only: the plate has unconstrained slopes; one on a hierarchy
  // of meshes on the full LCP only), but the
  // reference: the default method on the full LCP.
  std::vector<Method>
  all_methods()
  {
    std::vector<Method> methods;
    for (const Method &method :
         registered_methods::all(true, registered_methods::a_hierarchy))
      if (method.schur_complement || !method.info->is_default)
        methods.push_back(method);
    return methods;
  }

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
  const std::string reference_method = unilateral::lcp::default_method().name;
  const std::vector<Method> methods  = all_methods();

  bool all = true;
  for (const auto &c : configurations)
    {
      const unsigned int n = std::stoi(c[3]);
      const std::string  plate =
        plate_runs::paper_configuration(c[0], c[1], c[2], n);
      const std::string name = c[0] + "_" + c[1] + "_" + c[2] + "_" + c[3];
      const auto        reference =
        plate_runs::run_plate(name + "_reference", plate, reference_method);
      std::cout << c[0] << " " << c[1] << " " << c[2] << " " << n << "x" << n
                << ": " << reference_method << " "
                << (reference.report.converged() ? "converged" : "FAILED")
                << ", cn = " << reference.results().n_contact << std::endl;
      all = all && reference.report.converged();
      for (const Method &method : methods)
        {
          const auto run =
            plate_runs::run_plate(name + "_" +
                                    std::to_string(&method - &methods[0]),
                                  plate,
                                  method.name(),
                                  false,
                                  method.prm_settings());
          const bool agree =
            run.report.converged() &&
            run.results().n_contact == reference.results().n_contact &&
            relative_difference(run.scene->nodal_values(),
                                reference.scene->nodal_values()) < 1e-8;
          all = all && agree;
          verdict(
            "  " + method.label() +
              ": converged, same cn, nodal DOFs within 1e-8 relative of " +
              reference_method,
            agree);
        }
    }
  verdict("all methods agree on all configurations", all);

  // The coarse-mesh start (nested iteration) changes where PDAS starts, not
  // where it ends: the same plate as PDAS from zero, with the coarse meshes
  // it went through.
  for (const unsigned int n : {20u, 32u})
    {
      const std::string plate =
        plate_runs::paper_configuration("steel", "psi3", "f1", n);
      const auto from_zero =
        plate_runs::run_plate("coarse_start_off_" + std::to_string(n),
                              plate + "set Coarse-mesh start = false\n",
                              "pdas");
      const auto nested =
        plate_runs::run_plate("coarse_start_on_" + std::to_string(n),
                              plate + "set Coarse-mesh start = true\n",
                              "pdas");
      std::cout << "steel psi3 f1 " << n << "x" << n << ": pdas started from";
      bool levels_converged = true;
      for (const auto &level : nested.scene->coarse_mesh_levels())
        {
          std::cout << " " << level.n_x << "x" << level.n_y;
          levels_converged = levels_converged &&
                             level.status == unilateral::lcp::Status::converged;
        }
      std::cout << std::endl;
      verdict("  from zero: no coarse mesh; nested: converged on every mesh",
              from_zero.scene->coarse_mesh_levels().empty() &&
                from_zero.report.converged() && nested.report.converged() &&
                !nested.scene->coarse_mesh_levels().empty() &&
                levels_converged);
      verdict("  same cn, nodal DOFs within 1e-10 relative",
              nested.results().n_contact == from_zero.results().n_contact &&
                relative_difference(nested.scene->nodal_values(),
                                    from_zero.scene->nodal_values()) < 1e-10);
    }
}
