// A wall whose solutions form an unbounded set: the 3D running bond two
// blocks thick with rollers on its front face only, so that every block of
// the back leaf may move away from the front one along z, which no load
// drives (the energy does not change). An interior iterate follows the
// centre of such a set off to infinity: the interior point on A alone
// diverged at m = 25 (a block 2.8e3 away, then a singular Newton matrix),
// and so did PDAS's hand-over to it at m = 40. On floating bodies the
// interior point works on A + eps d I, which has one solution, and the
// projection step makes it exact: the interior point against PDAS on the
// same wall, the same energy to 1e-10, KKT <= 1e-10, the largest
// displacement that of the wall (no block flown off).
#include "tfeti_test_tools.h"

using namespace tfeti_test;

int
main()
{
  const std::string wall =
    "subsection Masonry\n  set Dimension = 3\n  set Blocks through the "
    "thickness = 2\n  set Thickness = 2\nend\n";
  const std::string front_rollers =
    "    set Normal displacement zero = left, right, front, base where x > "
    "s\n";
  const RunOf<3> reference =
    run<3>(parse(wall + prm_text("running bond", 25, "pdas", front_rollers)),
           "unbounded");
  const RunOf<3> result =
    run<3>(parse(wall +
                 prm_text("running bond", 25, "interior_point", front_rollers)),
           "unbounded");
  const double energy_difference =
    std::abs(result.report.energy - reference.report.energy);
  std::cout << "3D running bond m = 25, back leaf free along z: converged: "
            << yes_no(result.report.converged() && reference.report.converged())
            << ", KKT <= 1e-10: " << yes_no(result.report.kkt.max() <= 1e-10)
            << ", energy as PDAS's: "
            << yes_no(energy_difference <=
                      1e-10 * std::abs(reference.report.energy))
            << ", largest displacement below 0.1: "
            << yes_no(largest_displacement(*result.scene) < 0.1) << "\n";
}
