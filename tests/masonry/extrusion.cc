// 3D against 2D: the paper's walls (m = 4, Q2) extruded into 3D through a
// thickness T = H, one block or two behind each other, with zero normal
// displacement on the front and back faces (and, with two, on the collar
// faces between them, whose joints then drop out: both sides are held)
// reproduce the 2D plane-strain solution: energy per unit thickness to
// 1e-10 and the same contacts carrying force, once per layer of nodes in z
// (3 per block: Q2 has nodes at the front, the middle and the back).
// Also four leaves through a thickness of 0.02 H, each 200 times thinner
// than high: the faces of every other leaf, 0.005 H apart, were refused as
// faces that "nearly coincide" while nearness was judged against h rather
// than the smallest cell (the leaf's depth). Without a gap only: with
// g = H/2 the rigid settlement is 3e8 times what these stiff leaves deform:
// stack and running bond end 'inaccurate', saying that double precision
// cannot check that to the KKT tolerance, and the laminae converge with the
// energy per unit thickness 1.6e-10 from the 2D one.
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
    for (const auto &[blocks, relative_thickness] :
         {std::pair{1u, 1.0}, std::pair{2u, 1.0}, std::pair{4u, 0.02}})
      {
        if (relative_thickness != 1.0 && gap != 0.0)
          continue;
        const RunOf<3> solid =
          run<3>(parse("subsection Masonry\n  set Dimension = 3\n"
                       "  set Blocks through the thickness = " +
                       std::to_string(blocks) + "\n  set Thickness = " +
                       std::to_string(relative_thickness) + "\n" + common +
                       "    set Normal displacement zero = left, right, front, "
                       "back, collar, base where x > s\n  end\nend\n"),
                 "solid");
        const double thickness = 0.25 * relative_thickness; // H = 0.25
        const double energy    = solid.report.energy / thickness;
        std::cout << geometry << ", g = " << gap << " H, " << blocks
                  << " block(s) through the thickness"
                  << (relative_thickness != 1.0 ?
                        " of " + std::to_string(relative_thickness) + " H" :
                        std::string())
                  << ": converged: " << yes_no(solid.report.converged())
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
