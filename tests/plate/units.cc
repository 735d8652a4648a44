// Plate/Units: the paper's steel plate on psi3 under f1 (Table 4's
// configuration, 20 x 20 elements) in the study's mm and kg, in mm and N and
// in m and N. Independent truth: a kilogram-force is 9.80665 N and a mm
// 1e-3 m, so the contact set stays, deflections scale with the length unit
// and the energy with force times length; and the named quantities
// converted by the program must give what the same plate written out by
// hand in SI units gives. The summary must label its numbers with the
// chosen units, and with units of the user's own name none.
#include "plate_runs.h"

#include <cmath>
#include <iostream>
#include <string>

using namespace plate_runs;

namespace
{
  std::string
  plate(const std::string &units, const std::string &length)
  {
    return "set Units = " + units +
           "\nsubsection Geometry\n  set Length x = " + length +
           "\n  set Length y = " + length +
           "\n  set Thickness = " + (length == "100" ? "2" : "0.002") +
           "\nend\n" + paper_configuration("steel", "psi3", "f1", 20);
  }

  bool
  close(const double value, const double expected, const double tolerance)
  {
    return std::abs(value - expected) <= tolerance * std::abs(expected);
  }

  bool
  prints(const Run &run, const std::string &text)
  {
    return run.printed.find(text) != std::string::npos;
  }

  void
  compare(const std::string &name,
          const Run         &run,
          const Run         &paper,
          const double       mm,
          const double       kg)
  {
    const auto &r = run.results(), &p = paper.results();
    std::cout << name << ": "
              << (run.report.converged() ? "converged" : "not converged")
              << ", the same contact nodes: "
              << (r.n_contact == p.n_contact ? "yes" : "NO")
              << ", deflections times the mm (1e-10): "
              << (close(r.centre_deflection, mm * p.centre_deflection, 1e-10) &&
                      close(r.min_deflection, mm * p.min_deflection, 1e-10) ?
                    "yes" :
                    "NO")
              << ", energy times kg mm (1e-10): "
              << (close(run.report.energy,
                        kg * mm * paper.report.energy,
                        1e-10) ?
                    "yes" :
                    "NO")
              << "\n";
  }
} // namespace

int
main()
{
  const Run paper = run_plate("mm_kg", plate("mm and kg", "100"), "pdas");
  std::cout << "mm and kg: "
            << (paper.report.converged() ? "converged" : "not converged")
            << ", contacts and free nodes: "
            << (paper.results().n_contact > 10 &&
                    paper.results().n_contact < paper.results().n_bounds ?
                  "yes" :
                  "NO")
            << ", labels: "
            << (prints(paper, "plate 100 x 100 mm, t = 2 mm") &&
                    prints(paper, "E = 21000 kg/mm^2") &&
                    prints(paper, " kg mm\n") &&
                    prints(paper, "centre deflection -") ?
                  "yes" :
                  "NO")
            << "\n";

  const Run newton = run_plate("mm_N", plate("mm and N", "100"), "pdas");
  compare("mm and N", newton, paper, 1, 9.80665);
  std::cout << "  labels: "
            << (prints(newton, "E = 205940 N/mm^2") &&
                    prints(newton, " N mm\n") ?
                  "yes" :
                  "NO")
            << "\n";

  const Run si = run_plate("m_N", plate("m and N", "0.1"), "pdas");
  compare("m and N", si, paper, 1e-3, 9.80665);
  std::cout << "  labels: "
            << (prints(si, "plate 0.1 x 0.1 m, t = 0.002 m") &&
                    prints(si, "E = 2.0594e+11 Pa") && prints(si, " N m\n") &&
                    si.printed.find(" mm") == std::string::npos ?
                  "yes" :
                  "NO")
            << "\n";

  // The same SI plate with E, psi3 and f1 converted by hand.
  const Run by_hand = run_plate(
    "by_hand",
    "set Units = m and N\n"
    "subsection Geometry\n  set Length x = 0.1\n  set Length y = 0.1\n"
    "  set Thickness = 0.002\n  set Elements x = 20\n  set Elements y = 20\n"
    "end\nsubsection Material\n  set Name = custom\n"
    "  set Young's modulus = 205939650000\n  set Poisson's ratio = 0.28\nend\n"
    "subsection Obstacle\n  set Function = -0.5e-3*(x/0.05 - 1)^2 - "
    "0.02e-3*(x/0.05 - 1) - 0.5e-3/(1 + 30*(x/0.05 - 1)^2)\nend\n"
    "subsection Load\n  set Force = -9806650\nend\n",
    "pdas");
  compare("m and N by hand", by_hand, paper, 1e-3, 9.80665);
  std::cout << "  the same as the named quantities converted (1e-12): "
            << (by_hand.results().n_contact == si.results().n_contact &&
                    close(by_hand.results().centre_deflection,
                          si.results().centre_deflection,
                          1e-12) &&
                    close(by_hand.report.energy, si.report.energy, 1e-12) ?
                  "yes" :
                  "NO")
            << "\n";

  // psi2 depends on x and y: a rectangular bronze plate under f2.
  const auto rectangle = [](const std::string &units,
                            const std::string &x,
                            const std::string &y,
                            const std::string &t) {
    return "set Units = " + units +
           "\nsubsection Geometry\n  set Length x = " + x +
           "\n  set Length y = " + y + "\n  set Thickness = " + t + "\nend\n" +
           paper_configuration("bronze", "psi2", "f2", 24);
  };
  const Run rectangle_mm =
    run_plate("psi2_mm", rectangle("mm and kg", "100", "60", "2"), "pdas");
  const Run rectangle_m =
    run_plate("psi2_m", rectangle("m and N", "0.1", "0.06", "0.002"), "pdas");
  compare("psi2, 100 x 60 mm against 0.1 x 0.06 m",
          rectangle_m,
          rectangle_mm,
          1e-3,
          9.80665);

  // Units of the user's own: the millimetre plate in custom numbers, no
  // labels.
  const Run own =
    run_plate("own",
              "set Units = any consistent\nsubsection Material\n"
              "  set Name = custom\nend\nsubsection Obstacle\n"
              "  set Function = -0.5*(x/50 - 1)^2 - 0.02*(x/50 - 1) - "
              "0.5/(1 + 30*(x/50 - 1)^2)\nend\n"
              "subsection Load\n  set Force = -1\nend\n"
              "subsection Geometry\n  set Elements x = 20\n"
              "  set Elements y = 20\nend\n",
              "pdas");
  compare("any consistent", own, paper, 1, 1);
  std::cout << "  no labels: "
            << (prints(own, "plate 100 x 100, t = 2, ") &&
                    prints(own, "E = 21000, nu") &&
                    own.printed.find(" mm") == std::string::npos &&
                    own.printed.find("kg") == std::string::npos ?
                  "yes" :
                  "NO")
            << "\n";
}
