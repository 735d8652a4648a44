// The paper's three walls (m = 5) read from Gmsh files (meshes/, written by
// Debian's gmsh from meshes/make_walls.py, formats 2.2 and 4.1; blocks that
// share nodes in the file) against the built-in generator: the same n and
// n_c, the same closed contacts, and the same energy: to 1e-12 with the base
// closed (g = 0), to 1e-10 with g = H/2, where the blocks drop by g as
// bodies and the energy, a difference of terms a thousand times larger, is
// determined only to about 1e-11 of itself.
#include "masonry_test_tools.h"

#include <algorithm>
#include <cmath>

using namespace masonry_test;

namespace
{
  std::string
  prm(const std::string &geometry, const double gap)
  {
    return "subsection Masonry\n  set Geometry = " + geometry +
           "\n  set Blocks per side = 5\n  subsection Boundary conditions\n"
           "    set Relative gap = " +
           std::to_string(gap) + "\n  end\nend\n";
  }

  std::string
  from_file(const std::string &file, const double gap)
  {
    return "subsection Masonry\n  set Geometry = mesh file\n"
           "  set Mesh file = " SOURCE_DIR "/meshes/" +
           file +
           "\n  subsection Boundary conditions\n    set Relative gap = " +
           std::to_string(gap) + "\n  end\nend\n";
  }
} // namespace

int
main()
{
  for (const std::string geometry : {"stack bond", "running bond", "laminae"})
    for (const double relative_gap : {0.0, 0.5})
      {
        // H = 1/5 for the generator, H = 1 for a mesh file: the same g.
        const Run   built = run(parse(prm(geometry, relative_gap)), "built_in");
        std::string stem  = geometry;
        std::replace(stem.begin(), stem.end(), ' ', '_');
        for (const std::string version : {"2", "4"})
          {
            const std::string file = stem + "_5_v" + version + ".msh";
            const Run         read =
              run(parse(from_file(file, relative_gap / 5)), "from_file");
            const Sizes &a = built.scene->sizes(), &b = read.scene->sizes();
            const double tolerance = relative_gap == 0 ? 1e-12 : 1e-10;
            std::cout << geometry << ", g = " << relative_gap << " H, " << file
                      << ": " << b.n_blocks << " blocks, n = " << b.n_unknowns
                      << ", n_c = " << b.n_constraints << ", both converged: "
                      << yes_no(built.report.converged() &&
                                read.report.converged())
                      << "; n, n_c equal: "
                      << yes_no(a.n_unknowns == b.n_unknowns &&
                                a.n_constraints == b.n_constraints &&
                                a.n_blocks == b.n_blocks)
                      << "; contacts carrying force equal: "
                      << yes_no(carrying(built) == carrying(read))
                      << "; energy equal to " << tolerance << ": "
                      << yes_no(
                           std::abs(built.report.energy - read.report.energy) <=
                           tolerance * std::abs(built.report.energy))
                      << "\n";
          }
      }
}
