// The coarse-mesh start of the masonry scene (nested iteration over meshes
// of the same wall): where it applies, which coarsening it takes, and that
// it changes the path of PDAS but not the answer.
//  - laminae m = 40 (40 cells along each lamina, one through it): cells
//    twice as long in x; the same energy (1e-10), the same contacts closed
//    and carrying, KKT at round-off, in fewer PDAS iterations;
//  - laminae m = 20 refined once (40 x 2 cells per lamina): the same, x
//    only (two cells through a lamina are too few to coarsen);
//  - stack bond m = 2 refined 6 times (64 x 64 cells per block): square
//    blocks, which the all-active start serves better, so no start;
//  - the paper's stack and running bond (one or two cells per block side)
//    and a lamina of 20 cells: no coarser mesh with matching nodes, so no
//    start; each of these the same answer as with the option off.
#include "masonry_test_tools.h"

#include <cmath>

using namespace masonry_test;

namespace
{
  Run
  wall(const std::string &geometry,
       const unsigned int m,
       const unsigned int refinement,
       const bool         coarse_start)
  {
    std::ostringstream prm;
    prm << "subsection Masonry\n  set Geometry = " << geometry
        << "\n  set Blocks per side = " << m
        << "\n  set Refinement = " << refinement
        << "\n  set Coarse-mesh start = " << (coarse_start ? "true" : "false")
        << "\nend\n";
    return run(parse(prm.str()), "coarse_mesh_start");
  }

  void
  compare(const std::string &geometry,
          const unsigned int m,
          const unsigned int refinement)
  {
    const Run   with    = wall(geometry, m, refinement, true);
    const Run   without = wall(geometry, m, refinement, false);
    const auto &start   = with.scene->coarse_mesh_start_taken();
    std::cout << geometry << ", m = " << m << ", refinement " << refinement
              << ": ";
    if (start.n_unknowns == 0)
      std::cout << "no coarse-mesh start";
    else
      std::cout << "cells " << start.coarsening[0] << " x "
                << start.coarsening[1] << " times as long, " << start.n_unknowns
                << " of " << with.scene->sizes().n_unknowns << " unknowns";
    const double energy_difference =
      std::abs(with.report.energy - without.report.energy) /
      std::abs(without.report.energy);
    std::cout << "\n  both converged: "
              << yes_no(with.report.converged() && without.report.converged())
              << "; the same energy (1e-10): "
              << yes_no(energy_difference <= 1e-10)
              << "; the same contacts closed and carrying: "
              << yes_no(with.report.n_active == without.report.n_active &&
                        carrying(with) == carrying(without))
              << "; KKT <= 1e-10: "
              << yes_no(with.report.kkt.max() <= 1e-10 &&
                        without.report.kkt.max() <= 1e-10);
    if (start.n_unknowns > 0)
      std::cout << "; fewer PDAS iterations with the start: "
                << yes_no(with.report.iterations < without.report.iterations);
    else
      std::cout << "; the same path: "
                << yes_no(with.report.iterations == without.report.iterations &&
                          with.report.energy == without.report.energy);
    std::cout << "\n";
  }
} // namespace

int
main()
{
  compare("laminae", 40, 0);
  compare("laminae", 20, 1);
  compare("stack bond", 2, 6);
  compare("stack bond", 10, 0);
  compare("running bond", 10, 0);
  compare("laminae", 20, 0);
}
