// 3D against 2D: the paper's walls (m = 4, Q2) extruded into 3D through a
// thickness T = H, one block or two behind each other, with zero normal
// displacement on the front and back faces (and, with two, on the collar
// faces between them, whose joints then drop out: both sides are held)
// reproduce the 2D plane-strain solution: energy per unit thickness to
// 1e-10 and the same contacts carrying force, once per layer of nodes in z
// (3 per block: Q2 has nodes at the front, the middle and the back).
#include "masonry_test_tools.h"

#include <algorithm>
#include <cmath>

using namespace masonry_test;

namespace
{
  void
  compare(const std::string &geometry, const double gap)
  {
    const std::string common = "  set Geometry = " + geometry +
                               "\n  set Blocks per side = 4\n"
                               "  subsection Boundary conditions\n"
                               "    set Relative gap = " +
                               std::to_string(gap) + "\n";
    const Run plane =
      run(parse("subsection Masonry\n" + common + "  end\nend\n"), "plane");
    for (const unsigned int blocks : {1u, 2u})
      {
        const RunOf<3> solid =
          run<3>(parse("subsection Masonry\n  set Dimension = 3\n"
                       "  set Blocks through the thickness = " +
                       std::to_string(blocks) + "\n" + common +
                       "    set Normal displacement zero = left, right, front, "
                       "back, collar, base where x > s\n  end\nend\n"),
                 "solid");
        const double thickness = 0.25; // T = H
        const double energy    = solid.report.energy / thickness;
        std::cout << geometry << ", g = " << gap << " H, " << blocks
                  << " block(s) through the thickness: converged: "
                  << yes_no(solid.report.converged())
                  << "; energy / T = 2D energy to 1e-10: "
                  << yes_no(std::abs(energy - plane.report.energy) <=
                            1e-10 * std::abs(plane.report.energy))
                  << "; contacts carrying force = " << 3 * blocks << " x 2D: "
                  << yes_no(carrying(solid) == 3 * blocks * carrying(plane))
                  << "\n";
      }
  }
} // namespace

int
main()
{
  for (const std::string geometry : {"stack bond", "running bond", "laminae"})
    for (const double gap : {0.0, 0.5})
      compare(geometry, gap);
}
