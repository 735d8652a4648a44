// Plates whose numbers lie far from 1, against the same plate in ordinary
// numbers (independent truth: the clamped plate's deflection under a
// uniform load scales with the length to the 4th power and with the load):
//  1. a steel plate 1e-3 mm wide (elements of 5e-5 mm, whose deflections,
//     slopes and twists differ in stiffness by about 1e17): converged only
//     with the deflection of the 100 mm plate times 1e-20. Found by a
//     review (2026-11-27): tnnmg ended 'converged' 3.7e-4 off, its KKT
//     residuals relative to the largest force hiding the others' errors;
//     then every method ended 'singular' (saying why), and since the
//     scene scales the unknowns by the element size (2026-11-30,
//     tests/plate/length_unit) every method converges, to that deflection.
//  2. a load of -1e-150: the deflection of the load -1 times 1e-150 (tnnmg
//     ended with NaN, blaming its iteration limit);
//  3. an obstacle at 1e150 or 1e-150 above the plate, under a load far
//     too weak to matter: tnnmg as pdas (scaled by the load alone in a
//     first fix, tnnmg broke down).
//  4. elements 5e4 times longer than wide (100000 x 2 on the 100 mm
//     plate): PDAS's factorisation judges the stiffness singular, and the
//     failure line must name the elements' shape (found by a review,
//     2026-11-27: it blamed lengths far from 1 in the plate's units);
//  5. a sheet 1e-4 mm thick on the obstacle psi3 under the load times
//     (1e-4 / 2)^3: the 2 mm plate's deflections and contact set, every
//     method (a review: PDAS, block pivoting and the interior point ended
//     'inaccurate' before the plate scene got its force unit).
// A failure line speaks of no "body" (a review, 2026-11-27: the solver
// layer's causes for blocks, "some body is held by no active constraint",
// "a body held by round-off", ended the plate's lines): a clamped plate's
// stiffness is definite. 6. TNNMG stopped early by weak settings (its own
// tolerance 1e-3) without the projection step: its line says it stopped
// short.
//  7. elements 2000 times longer than wide (4000 x 2): TNNMG's corrections
//     stall at 9e-8 of |u| (round-off), where it ended 'converged' with
//     KKT residuals of 2e-16, its energy 3.6e-4 above the minimum and a
//     contact force 18 % off (a review); now it hands over to PDAS, and
//     the answer is the interior point's (energy and centre deflection to
//     1e-10).
//  8. an obstacle with a pole between the nodes of a 25 x 25 mesh, at a
//     node of the 13 x 13 coarse mesh: refused, naming that node, by
//     tnnmg's hierarchy and pdas's coarse-mesh start (a review); now solved
//     as by the interior point, which builds no coarse mesh.
//  9. one element: every node lies on the clamped edge, so the obstacle
//     acts nowhere; the summary says so (a review: the plate went 23 mm
//     through it without a word).
// 10. elements 1000 times longer than wide (2000 x 2): TNNMG's steps fell
//     by 0.6 per iteration at 1e-8 of |u| and it stopped there as at a
//     rounding floor, 'converged' 6e-8 off PDAS (a review); now only steps
//     that stop falling end it, and it hands over to PDAS: the interior
//     point's answer, as in 7.
// 11. an obstacle above the clamped edge (w = 0 and dw/dn = 0 there: no
//     solution in the continuum, the answer grows as the mesh is refined;
//     a review): the summary says so, also for one that rises from 0 at
//     the edge with a slope, or is above it only between two vertices;
//     at the edge's height or below it (psi3), or above it on the edge
//     line alone (the obstacle acts inside), not.
// 12. Young's modulus 1e300 and 1e-250 with no obstacle: the energy of
//     E = 1e20 times 1e20 / E. The energy reported was 0 at 1e300 (the
//     scaled energy, 1e-590, underflowed before the scene multiplied it
//     back), and the run at 1e-250 failed its work check with W = NaN (b_i
//     u_i beyond double's range).
// 13. elements 2000 times longer than wide across psi3's crest line (2 x
//     4000; psi3 varies along x only): the interior point and TNNMG
//     (handing over to PDAS) ended 'inaccurate' with a contact pulling at
//     3e-4 of the largest force, kept active by PDAS's rounding tolerance
//     (Round-off tolerance times |A| |u|, A_ii up to 5e13 against loads of
//     1); PDAS alone happened to converge. Now all three give its answer.
//     Likewise PDAS on 2000 x 2 elements over psi2 (1321 contacts, one
//     pulling at 6e-5 of the largest force; the answer has 1319).
#include "plate_runs.h"

#include <cmath>
#include <iostream>
#include <string>
#include <utility>

using namespace plate_runs;

namespace
{
  std::string
  free_plate(const std::string &length,
             const std::string &force,
             const std::string &obstacle = "none")
  {
    return "subsection Geometry\n  set Length x = " + length +
           "\n  set Length y = " + length +
           "\n  set Elements x = 20\n  set Elements y = 20\nend\n"
           "subsection Material\n  set Name = steel\nend\n"
           "subsection Obstacle\n  set Function = " +
           obstacle +
           "\nend\n"
           "subsection Load\n  set Force = " +
           force + "\nend\n";
  }

  bool
  close(const double value, const double expected)
  {
    return std::abs(value - expected) <= 1e-8 * std::abs(expected);
  }

  /// The reference converged, and the run's energy is its to 1e-10.
  const char *
  same_energy(const Run &run, const Run &reference)
  {
    return reference.report.converged() &&
               std::abs(run.report.energy - reference.report.energy) <=
                 1e-10 * std::abs(reference.report.energy) ?
             "yes" :
             "NO";
  }

  /// Both converged, with the same centre deflection and contact set.
  bool
  same_answer(const Run &run, const Run &reference)
  {
    return run.report.converged() && reference.report.converged() &&
           close(run.results().centre_deflection,
                 reference.results().centre_deflection) &&
           run.results().n_contact == reference.results().n_contact;
  }
} // namespace

int
main()
{
  const double reference =
    run_plate("reference", free_plate("100", "-1"), "pdas")
      .results()
      .min_deflection;
  for (const std::string method : {"tnnmg", "pdas", "interior_point"})
    {
      const Run tiny =
        run_plate("tiny_" + method, free_plate("0.001", "-1"), method);
      std::cout << "1e-3 mm plate, " << method << ": "
                << (tiny.report.converged() ? "converged" : "not converged")
                << ", right if converged: "
                << (!tiny.report.converged() ||
                        close(tiny.results().min_deflection,
                              1e-20 * reference) ?
                      "yes" :
                      "NO")
                << ", its failure line speaks of no body: "
                << (tiny.scene->failure_description(tiny.report).find("body") ==
                        std::string::npos ?
                      "yes" :
                      "NO")
                << "\n";
    }
  for (const std::string method : {"tnnmg", "pdas"})
    {
      const Run faint =
        run_plate("faint_" + method, free_plate("100", "-1e-150"), method);
      std::cout << "load -1e-150, " << method << ": "
                << (faint.report.converged() ? "converged" : "not converged")
                << ", deflection right: "
                << (faint.report.converged() &&
                        close(faint.results().min_deflection,
                              1e-150 * reference) ?
                      "yes" :
                      "NO")
                << "\n";
    }
  for (const auto &[obstacle, force] :
       {std::pair<std::string, std::string>{"1e150", "-1e-20"},
        {"1e-150", "0"}})
    {
      const Run lifted = run_plate("lifted_" + obstacle,
                                   free_plate("100", force, obstacle),
                                   "tnnmg");
      const Run direct = run_plate("lifted_pdas_" + obstacle,
                                   free_plate("100", force, obstacle),
                                   "pdas");
      std::cout << "obstacle " << obstacle << " above, load " << force
                << ", tnnmg: "
                << (lifted.report.converged() ? "converged" : "not converged")
                << ", as pdas: " << (same_answer(lifted, direct) ? "yes" : "NO")
                << "\n";
    }
  {
    const auto sheet = [](const std::string &thickness,
                          const std::string &force) {
      return "subsection Geometry\n  set Thickness = " + thickness +
             "\n  set Elements x = 20\n  set Elements y = 20\nend\n"
             "subsection Material\n  set Name = steel\nend\n"
             "subsection Obstacle\n  set Function = psi3\nend\n"
             "subsection Load\n  set Force = " +
             force + "\nend\n";
    };
    const Run plate = run_plate("plate_2mm", sheet("2", "-1"), "pdas");
    for (const std::string method :
         {"pdas", "block_pivoting", "interior_point", "tnnmg"})
      {
        const Run thin =
          run_plate("sheet_" + method, sheet("1e-4", "-1.25e-13"), method);
        std::cout << "1e-4 mm sheet on psi3, " << method << ": "
                  << (thin.report.converged() ? "converged" : "not converged")
                  << ", the 2 mm plate's centre deflection and contact set: "
                  << (same_answer(thin, plate) ? "yes" : "NO") << "\n";
      }
  }
  // TNNMG's iterate went NaN on them (after 30 s, every finer level
  // carried on with NaN, and the minimum deflection showed 0): now it stops
  // on the level where it happens and the failure names the elements.
  for (const std::string method : {"pdas", "tnnmg"})
    {
      const Run elongated =
        run_plate("elongated_" + method,
                  "subsection Geometry\n  set Elements x = 100000\n"
                  "  set Elements y = 2\nend\n",
                  method);
      std::cout
        << "elements 5e4 times longer than wide, " << method << ": "
        << (elongated.report.converged() ? "converged" : "not converged")
        << ", the failure line names their shape: "
        << (!elongated.report.converged() &&
                elongated.scene->failure_description(elongated.report)
                    .find("times longer than wide") != std::string::npos ?
              "yes" :
              "NO")
        << (method == "tnnmg" ?
              std::string(", min deflection NaN (not 0): ") +
                (std::isnan(elongated.results().min_deflection) ? "yes" :
                                                                  "NO") :
              std::string())
        << "\n";
    }
  // 7 and 10: TNNMG on elements 2000 and 1000 times longer than wide
  // hands over to PDAS, and its answer is then the direct methods'.
  for (const unsigned int n_x : {4000u, 2000u})
    {
      const std::string plate =
        "subsection Geometry\n  set Elements x = " + std::to_string(n_x) +
        "\n  set Elements y = 2\nend\n"
        "subsection Obstacle\n  set Function = psi3\nend\n";
      const std::string name = std::to_string(n_x);
      const Run tnnmg = run_plate("elongated_tnnmg_" + name, plate, "tnnmg");
      const Run ip = run_plate("elongated_ip_" + name, plate, "interior_point");
      const double w = ip.results().centre_deflection;
      std::cout << "elements " << n_x / 2 << " times longer than wide, tnnmg: "
                << unilateral::lcp::to_string(tnnmg.report.status)
                << ", handed over to pdas: "
                << (tnnmg.report.message.find("handed over to PDAS") !=
                        std::string::npos ?
                      "yes" :
                      "NO")
                << ", the interior point's energy (1e-10): "
                << same_energy(tnnmg, ip) << ", centre deflection (1e-10): "
                << (std::abs(tnnmg.results().centre_deflection - w) <=
                        1e-10 * std::abs(w) ?
                      "yes" :
                      "NO")
                << "\n";
    }
  // 13: the same elements across the obstacle's crest line, and along
  // psi2: every method converges to one answer.
  {
    const std::string plate =
      "subsection Geometry\n  set Elements x = 2000\n  set Elements y = 2\n"
      "end\nsubsection Obstacle\n  set Function = psi2\nend\n";
    const Run pdas = run_plate("psi2_pdas", plate, "pdas");
    const Run ip   = run_plate("psi2_ip", plate, "interior_point");
    std::cout << "elements 1000 times longer than wide over psi2, pdas: "
              << unilateral::lcp::to_string(pdas.report.status)
              << ", the interior point's energy (1e-10): "
              << same_energy(pdas, ip) << ", centre deflection and contact "
              << "nodes: " << (same_answer(pdas, ip) ? "yes" : "NO") << "\n";
  }
  {
    const std::string plate =
      "subsection Geometry\n  set Elements x = 2\n  set Elements y = 4000\n"
      "end\nsubsection Obstacle\n  set Function = psi3\nend\n";
    const Run pdas = run_plate("crest_pdas", plate, "pdas");
    std::cout << "elements 2000 times longer than wide along the crest, pdas: "
              << unilateral::lcp::to_string(pdas.report.status) << "\n";
    for (const std::string method : {"tnnmg", "interior_point"})
      {
        const Run run = run_plate("crest_" + method, plate, method);
        std::cout << "  " << method << ": "
                  << unilateral::lcp::to_string(run.report.status)
                  << ", pdas's energy (1e-10): " << same_energy(run, pdas)
                  << ", centre deflection and contact nodes: "
                  << (same_answer(run, pdas) ? "yes" : "NO") << "\n";
      }
  }
  for (const std::string height : {"1",
                                   "0",
                                   "psi3",
                                   "1e-7*x*(100-x)*y*(100-y)",
                                   "1 - (x-2.5)^2",
                                   "if(x < 1e-9, 1, -2)"})
    {
      const Run raised =
        run_plate("edge_obstacle",
                  "subsection Geometry\n  set Elements x = 20\n"
                  "  set Elements y = 20\nend\n"
                  "subsection Obstacle\n  set Function = " +
                    height + "\nend\n",
                  "tnnmg");
      std::cout << "obstacle " << height << ": "
                << unilateral::lcp::to_string(raised.report.status)
                << ", says it rises above the clamped edge: "
                << (raised.printed.find("rises above the clamped edge") !=
                        std::string::npos ?
                      "yes" :
                      "no")
                << "\n";
    }
  {
    const std::string plate =
      "subsection Geometry\n  set Elements x = 25\n"
      "  set Elements y = 25\nend\n"
      "subsection Obstacle\n  set Function = -1 + 1/(x - 100/13)\nend\n";
    const Run ip = run_plate("pole_ip", plate, "interior_point");
    for (const std::string method : {"tnnmg", "pdas"})
      {
        const Run pole = run_plate("pole_" + method, plate, method);
        std::cout << "an obstacle with a pole at a coarse mesh's node, "
                  << method << ": "
                  << unilateral::lcp::to_string(pole.report.status)
                  << ", the interior point's energy (1e-10): "
                  << same_energy(pole, ip) << "\n";
      }
  }
  for (const std::string boundary : {"clamped", "fully clamped"})
    {
      const Run one =
        run_plate("one_element",
                  paper_configuration("steel", "psi3", "f1", 1, boundary),
                  "pdas");
      std::cout << "one element, " << boundary << ": "
                << unilateral::lcp::to_string(one.report.status)
                << ", says the obstacle acts "
                << "nowhere: "
                << (one.printed.find("so it acts nowhere") !=
                        std::string::npos ?
                      "yes" :
                      "NO")
                << "\n";
    }
  {
    const auto modulus = [](const std::string &youngs_modulus) {
      return run_plate("modulus_" + youngs_modulus,
                       "subsection Geometry\n  set Elements x = 12\n"
                       "  set Elements y = 8\nend\n"
                       "subsection Material\n  set Name = custom\n"
                       "  set Young's modulus = " +
                         youngs_modulus +
                         "\n  set Poisson's ratio = 0.3\nend\n"
                         "subsection Obstacle\n  set Function = none\nend\n",
                       "pdas");
    };
    const Run ordinary = modulus("1e20");
    for (const std::string youngs_modulus : {"1e300", "1e-250"})
      {
        const Run    extreme = modulus(youngs_modulus);
        const double ratio   = 1e20 / std::stod(youngs_modulus);
        std::cout << "Young's modulus " << youngs_modulus << ": "
                  << unilateral::lcp::to_string(extreme.report.status)
                  << ", the energy of E = 1e20 times 1e20 / E (1e-10): "
                  << (extreme.report.converged() &&
                          ordinary.report.converged() &&
                          std::abs(extreme.report.energy -
                                   ratio * ordinary.report.energy) <=
                            1e-10 * std::abs(ratio * ordinary.report.energy) ?
                        "yes" :
                        "NO")
                  << "\n";
      }
  }
  {
    const Run stopped =
      run_plate("stopped_short",
                "subsection Geometry\n  set Elements x = 4\n"
                "  set Elements y = 400\nend\n"
                "subsection Obstacle\n  set Function = psi3\nend\n"
                "subsection Load\n  set Force = f3\nend\n",
                "tnnmg",
                false,
                "set Projection = false\nsubsection TNNMG\n"
                "  set Tolerance = 1e-3\n  set Correction reduction = 0.9\n"
                "  set Cycles per correction = 1\n  set Cycle = V\nend\n");
    const std::string line = stopped.scene->failure_description(stopped.report);
    std::cout << "weak tnnmg without projection: "
              << (stopped.report.converged() ? "converged" : "not converged")
              << ", its failure line says it stopped short and speaks of no "
                 "body: "
              << (!stopped.report.converged() &&
                      line.find("stopped short") != std::string::npos &&
                      line.find("body") == std::string::npos ?
                    "yes" :
                    "NO")
              << "\n";
  }
}
