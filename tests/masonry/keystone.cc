// A flat arch of three blocks: a wedge-shaped keystone between two
// abutments whose bases are fixed, under self-weight, its two joints
// leaning outwards by theta from the vertical (a review's structure).
// Independent truth, statics: frictionless joints carry forces normal to
// them, so the keystone's weight W = (1 + dx) / 2 hangs on two joint forces
// N with 2 N sin(theta) = W, and each abutment takes the thrust H = N
// cos(theta) = W / (2 tan(theta)) and the vertical reaction 3/4 (its own
// weight and half the keystone's), whatever theta is.
//  - theta = 1e-2, 1e-3: converged, with those reactions to 1e-8.
// Not below: at theta = 1e-4 the run ends 'converged' with the thrust
// 1.5e-7 off (1.7e-4 at 3e-6), its residuals at round-off; a known limit
// (README, masonry), not checked here so that no failed verdict stands in
// the expected output.
#include "masonry_test_tools.h"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <string>

using namespace masonry_test;

namespace
{
  /// The three blocks as a Gmsh 2.2 file: abutment, keystone, abutment
  /// (the abutments of two cells), their bases named baseL and baseR.
  void
  write_mesh(const std::string &file_name, const double theta)
  {
    const double  dx = 0.5 * std::tan(theta);
    std::ofstream mesh(file_name);
    const auto    x = [&](const double value) {
      std::ostringstream text;
      text << std::setprecision(17) << value;
      return text.str();
    };
    mesh << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
         << "$PhysicalNames\n3\n2 1 \"masonry\"\n1 2 \"baseL\"\n"
         << "1 3 \"baseR\"\n$EndPhysicalNames\n"
         << "$Nodes\n16\n"
         << "1 -1.5 0 0\n2 -1 0 0\n3 -0.5 0 0\n4 -1.5 0.5 0\n"
         << "5 " << x(-1 - dx / 2) << " 0.5 0\n"
         << "6 " << x(-0.5 - dx) << " 0.5 0\n"
         << "7 -0.5 0 0\n8 0.5 0 0\n"
         << "9 " << x(-0.5 - dx) << " 0.5 0\n"
         << "10 " << x(0.5 + dx) << " 0.5 0\n"
         << "11 0.5 0 0\n12 1 0 0\n13 1.5 0 0\n"
         << "14 " << x(0.5 + dx) << " 0.5 0\n"
         << "15 " << x(1 + dx / 2) << " 0.5 0\n"
         << "16 1.5 0.5 0\n$EndNodes\n"
         << "$Elements\n9\n"
         << "1 3 2 1 1 1 2 5 4\n2 3 2 1 1 2 3 6 5\n"
         << "3 1 2 2 2 1 2\n4 1 2 2 3 2 3\n"
         << "5 3 2 1 4 7 8 10 9\n"
         << "6 3 2 1 5 11 12 15 14\n7 3 2 1 5 12 13 16 15\n"
         << "8 1 2 3 6 11 12\n9 1 2 3 7 12 13\n$EndElements\n";
  }

  bool
  close(const double value, const double expected)
  {
    return std::abs(value - expected) <= 1e-8 * std::abs(expected);
  }
} // namespace

int
main()
{
  for (const double theta : {1e-2, 1e-3})
    {
      write_mesh("keystone.msh", theta);
      const Run run =
        masonry_test::run(parse("subsection Masonry\n"
                                "  set Geometry = mesh file\n"
                                "  set Mesh file = keystone.msh\n"
                                "  subsection Boundary conditions\n"
                                "    set Fixed = baseL, baseR\n"
                                "    set Normal displacement zero =\n"
                                "    set Signorini =\n"
                                "    set Relative gap = 0\n"
                                "    set Traction boundaries =\n"
                                "  end\n"
                                "end\n"),
                          "keystone");
      const double dx        = 0.5 * std::tan(theta);
      const double weight    = 0.5 * (1 + dx);
      const double thrust    = weight / (2 * std::tan(theta));
      const auto  &statics   = run.scene->statics();
      bool         reactions = statics.support.size() == 2;
      for (std::size_t s = 0; reactions && s < 2; ++s)
        {
          const double sign = statics.support[s] == "baseL" ? 1 : -1;
          reactions         = close(statics.reaction[s][0], sign * thrust) &&
                      close(statics.reaction[s][1], 0.75);
        }
      std::cout << "theta = " << theta << ": "
                << lcp::to_string(run.report.status)
                << ", thrust W / (2 tan theta) and vertical reactions 3/4 "
                   "(1e-8): "
                << yes_no(reactions) << "\n";
    }
}
