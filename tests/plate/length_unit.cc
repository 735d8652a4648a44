// The same clamped plate on a constant obstacle in millimetres and in
// metres (independent truth: lengths times 1e-3 with the modulus and the
// load in kg/m^2 give the deflections and the energy times 1e-3 and the
// same contact set). With 90 x 60 elements of 1.1e-3 x 1.7e-3 m, a node's
// deflection, slopes and twist differ in stiffness by about 1e12: PDAS and
// block pivoting judged the stiffness singular and ended with 269 of the
// 293 contacts (found 2026-11-30). Now the scene hands the solvers the
// slopes and the twist times the element's size (plate_scene.h,
// unknown_scale), and every method gives the millimetre plate's answer.
#include "plate_runs.h"

#include <cmath>
#include <iostream>
#include <string>

using namespace plate_runs;

namespace
{
  std::string
  plate(const std::string &length,
        const std::string &thickness,
        const std::string &modulus,
        const std::string &obstacle,
        const std::string &force)
  {
    return "subsection Geometry\n  set Length x = " + length +
           "\n  set Length y = " + length + "\n  set Thickness = " + thickness +
           "\n  set Elements x = 90\n  set Elements y = 60\nend\n"
           "subsection Material\n  set Name = custom\n"
           "  set Young's modulus = " +
           modulus +
           "\n  set Poisson's ratio = 0.28\nend\n"
           "subsection Obstacle\n  set Function = " +
           obstacle + "\nend\nsubsection Load\n  set Force = " + force +
           "\nend\n";
  }

  bool
  close(const double value, const double expected, const double tolerance)
  {
    return std::abs(value - expected) <= tolerance * std::abs(expected);
  }
} // namespace

int
main()
{
  const Run millimetres = run_plate("millimetres",
                                    plate("100", "2", "21000", "-0.5", "-0.24"),
                                    "pdas");
  std::cout << "millimetres, pdas: "
            << (millimetres.report.converged() ? "converged" : "not converged")
            << ", some contacts and some free nodes: "
            << (millimetres.results().n_contact > 100 &&
                    millimetres.results().n_contact <
                      millimetres.results().n_bounds ?
                  "yes" :
                  "NO")
            << "\n";
  for (const std::string method :
       {"pdas", "block_pivoting", "interior_point", "tnnmg"})
    {
      const Run metres =
        run_plate("metres_" + method,
                  plate("0.1", "0.002", "2.1e10", "-0.5e-3", "-0.24e6"),
                  method);
      const auto &m = metres.results(), &mm = millimetres.results();
      std::cout
        << "metres, " << method << ": "
        << (metres.report.converged() ? "converged" : "not converged")
        << ", the same contact nodes: "
        << (m.n_contact == mm.n_contact ? "yes" : "NO")
        << ", deflections times 1e-3 (1e-8): "
        << (close(m.centre_deflection, 1e-3 * mm.centre_deflection, 1e-8) &&
                close(m.min_deflection, 1e-3 * mm.min_deflection, 1e-8) ?
              "yes" :
              "NO")
        << ", energy times 1e-3 (1e-10): "
        << (close(metres.report.energy,
                  1e-3 * millimetres.report.energy,
                  1e-10) ?
              "yes" :
              "NO")
        << "\n";
    }
}
