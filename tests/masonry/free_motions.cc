// Rigid motions that no support resists (masonry/free_motions.h): a wall
// without its side rollers converged (exit 0) with the horizontal position
// of the whole wall left to round-off, saying only that some contacts were
// degenerate; pushed sideways it ended "no equilibrium, or a block can
// move freely" without saying which block or how. Now the note names the
// group of blocks and its free motions, computed from the supports alone,
// and where the loads do work along one, the scene proves before solving
// that there is no equilibrium (exit 2), naming the motion:
//  - stack bond without rollers: the whole wall translates along x, and
//    gravity does no work along it: converged, with the note, and with
//    the note of the answer's family (masonry/mechanism.h): its blocks
//    also slide along x on their bed joints, which open head joints leave
//    free (so in 3D along z);
//  - held at one base node only (a roller): translation along x and a
//    rotation about a point on the vertical through that node (x = 0);
//    gravity turns the wall about the roller: no equilibrium;
//  - the 3D wall without its front roller: translation along z; pushed
//    along z: no equilibrium;
//  - the shipped walls with all their supports: no note;
//  - pushed sideways: no equilibrium, the translation named;
//  - one block on a frictionless slope (a mesh rotated by theta, gravity
//    vertical) slides: no equilibrium at every slope from 30 down to 1e-7
//    degrees and at every KKT tolerance. Before, PDAS proved it only at 30
//    degrees; at 5, 1 and 1e-5 the factorisation met a pivot above
//    round-off and moved the block by 1e9 or so ('inaccurate'), and at the
//    KKT tolerance of 0.05 that the message allowed, 1 degree ended
//    'converged' (exit 0) with that motion (a review). At 1e-11 degrees the
//    loads' work along the slide, 1.7e-13 of |f| |u|, is below what the
//    scene calls a proof (2.2e-10): the solver decides there, and ends
//    'converged', its residual within the KKT tolerance, with the note that
//    the answer holds only to it (the slide's regularisation force is at
//    the rounding of its rows' forces);
//  - a block in a frictionless corner (Signorini base and side) turned so
//    that it slides away from the side: no equilibrium before solving, at
//    every KKT tolerance and far from the origin, where before PDAS moved
//    it by 1e9 and ended 'inaccurate' (at a KKT tolerance of 0.2:
//    'converged'), the status depending on the turn and the position (a
//    review); turned the other way, the reactions of rigid-body statics;
//  - a block in a V-groove of 5e-6 pushed by 1e-6 of its weight is in
//    equilibrium at the origin and far from it (a review found it called
//    'no equilibrium' at 1e5: the test of a free motion once allowed more
//    than the rounding of the positions there);
//  - courses of a wall on a fixed base slide on each other under tilted
//    gravity (free_slides), in 2D and 3D: no equilibrium, the course named.
//  - a long block on a Signorini base of 16,000 faces, far from the
//    origin, under gravity tilted along its base: no equilibrium before
//    solving (the rounding of the supports' normals grows with the
//    distance over the faces' length).
#include "../application_test_tools.h"

#include <array>
#include <cmath>
#include <regex>
#include <sstream>
#include <tuple>
#include <vector>

using namespace application_test;

namespace
{
  std::string
  wall(const std::string &supports,
       const std::string &traction  = "0; 0",
       const std::string &extra     = "",
       const std::string &signorini = "base where x < s")
  {
    return "set Scene = masonry\n"
           "subsection Output\n  set Directory = results\n"
           "  set Print timings = false\n  set Progress = false\n"
           "  set Write VTU = false\nend\n"
           "subsection Masonry\n  set Geometry = stack bond\n"
           "  set Blocks per side = 3\n" +
           extra +
           "  subsection Boundary conditions\n"
           "    set Normal displacement zero = " +
           supports + "\n    set Signorini = " + signorini +
           "\n"
           "    set Traction boundaries = top\n"
           "    set Traction = " +
           traction + "\n  end\nend\n";
  }

  void
  report(const std::string &what, const Result &result)
  {
    std::cout << what << ": exit code " << result.code << "\n";
    std::size_t at = 0;
    while ((at = result.out.find("note: the", at)) != std::string::npos)
      {
        const std::size_t end = result.out.find('\n', at);
        std::cout << "  " << result.out.substr(at, end - at) << "\n";
        at = end;
      }
    // Up to the solver's own words, which follow in brackets.
    const std::size_t named = result.err.find("; the whole structure");
    const std::size_t end   = result.err.find(") (", named);
    if (named != std::string::npos && end != std::string::npos)
      std::cout << "  error names it: "
                << result.err.substr(named + 2, end + 1 - named - 2) << "\n";
    // Or the scene's own proof.
    const std::size_t proof = result.err.find("no equilibrium: the loads");
    if (proof != std::string::npos)
      std::cout << "  the error says so (no equilibrium)\n";
  }
  /// The 9 nodes of a unit square of 2 x 2 cells turned by @p theta
  /// degrees about its corner, moved by (shift, shift).
  std::string
  turned_square_nodes(const double theta, const double shift = 0)
  {
    const double pi = 3.14159265358979323846;
    const double c = std::cos(theta * pi / 180), s = std::sin(theta * pi / 180);
    std::ostringstream nodes;
    nodes.precision(17);
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i)
        nodes << 3 * j + i + 1 << " " << shift + c * 0.5 * i - s * 0.5 * j
              << " " << shift + s * 0.5 * i + c * 0.5 * j << " 0\n";
    return nodes.str();
  }

  // One unit block of 2 x 2 cells on its base, rotated by theta degrees.
  std::string
  block_on_slope(const double theta, const std::string &tolerance)
  {
    const std::string nodes = turned_square_nodes(theta);
    write("slope.msh",
          "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n1\n"
          "1 101 \"base\"\n$EndPhysicalNames\n$Nodes\n9\n" +
            nodes +
            "$EndNodes\n$Elements\n6\n1 1 2 101 101 1 2\n"
            "2 1 2 101 101 2 3\n3 3 2 1 1 1 2 5 4\n4 3 2 1 1 2 3 6 5\n"
            "5 3 2 1 1 4 5 8 7\n6 3 2 1 1 5 6 9 8\n$EndElements\n");
    write("slope.prm",
          "set Scene = masonry\nsubsection Output\n  set Directory = results\n"
          "  set Print timings = false\n  set Progress = false\n"
          "  set Write VTU = false\nend\nsubsection Masonry\n"
          "  set Geometry = mesh file\n  set Mesh file = slope.msh\n"
          "  subsection Boundary conditions\n"
          "    set Normal displacement zero =\n    set Signorini = base\n"
          "    set Signorini gap = 0\n    set Traction boundaries =\n"
          "    set Gravity = 1\n  end\nend\n"
          "subsection Solver\n  set KKT tolerance = " +
            tolerance + "\nend\n");
    return "slope.prm";
  }
  /**
   * A unit block of 2 x 2 cells in a frictionless V-groove whose sides
   * slope by 5e-6, its corner at (shift, shift), E = 1e9, pushed sideways
   * by 1e-6 of its weight: the groove holds a push below 5e-6 of the
   * weight, so this is in equilibrium (the reactions balance the loads; a
   * review). Its rotation about the far point where the sides' normals
   * meet is nearly free (the Gram matrix's eigenvalue 2.5e-11 of the
   * largest): the scene once noted it as free, and far from the origin
   * proved 'no equilibrium' along it.
   */
  std::string
  block_in_groove(const double shift)
  {
    std::ostringstream nodes;
    nodes.precision(17);
    const double eps = 5e-6;
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i)
        nodes << 3 * j + i + 1 << " " << shift + 0.5 * i << " "
              << shift + 0.5 * j + (1 - 0.5 * j) * eps * std::abs(0.5 * i - 0.5)
              << " 0\n";
    write("groove.msh",
          "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n2\n"
          "1 101 \"base\"\n1 102 \"left\"\n$EndPhysicalNames\n$Nodes\n9\n" +
            nodes.str() +
            "$EndNodes\n$Elements\n8\n1 1 2 101 101 1 2\n"
            "2 1 2 101 101 2 3\n3 1 2 102 102 4 1\n4 1 2 102 102 7 4\n"
            "5 3 2 1 1 1 2 5 4\n6 3 2 1 1 2 3 6 5\n7 3 2 1 1 4 5 8 7\n"
            "8 3 2 1 1 5 6 9 8\n$EndElements\n");
    write("groove.prm",
          "set Scene = masonry\nsubsection Output\n  set Directory = results\n"
          "  set Print timings = false\n  set Progress = false\n"
          "  set Write VTU = false\nend\nsubsection Masonry\n"
          "  set Geometry = mesh file\n  set Mesh file = groove.msh\n"
          "  subsection Boundary conditions\n"
          "    set Normal displacement zero =\n    set Signorini = base\n"
          "    set Signorini gap = 0\n    set Traction boundaries = left\n"
          "    set Traction = 1e-6; 0\n    set Gravity = 1\n  end\n"
          "  subsection Materials\n    set Young's modulus = 1e9\n  end\n"
          "end\n");
    return "groove.prm";
  }

  /**
   * One block 1600 x 0.2 of 16,000 cells along its base (its only
   * support, Signorini), rotated by 0.3 rad, at (1e5, 1e5), under gravity
   * tilted by 1e-3 along the base: it slides. The supports' normals, from
   * rounded positions of faces of 0.1 at 1e5, carry 3e-10 (a review: the
   * free motion was missed when its threshold ignored the faces' length).
   */
  std::string
  long_block_far_away()
  {
    const int          n = 16000;
    const double       a = 0.3, c = std::cos(a), s = std::sin(a);
    std::ostringstream mesh;
    mesh.precision(17);
    mesh << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n1\n"
            "1 101 \"base\"\n$EndPhysicalNames\n$Nodes\n"
         << 2 * (n + 1) << "\n";
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i <= n; ++i)
        {
          const double x = 0.1 * i - 0.05 * n, y = 0.2 * j;
          mesh << j * (n + 1) + i + 1 << " " << 1e5 + c * x - s * y << " "
               << 1e5 + s * x + c * y << " 0\n";
        }
    mesh << "$EndNodes\n$Elements\n" << 2 * n << "\n";
    for (int i = 1; i <= n; ++i)
      mesh << i << " 1 2 101 101 " << i << " " << i + 1 << "\n";
    for (int i = 1; i <= n; ++i)
      mesh << n + i << " 3 2 1 1 " << i << " " << i + 1 << " " << n + i + 2
           << " " << n + i + 1 << "\n";
    mesh << "$EndElements\n";
    write("long.msh", mesh.str());
    const double gx = c * 1e-3 + s, gy = s * 1e-3 - c;
    write("long.prm",
          "set Scene = masonry\nsubsection Output\n  set Directory = results\n"
          "  set Print timings = false\n  set Progress = false\n"
          "  set Write VTU = false\nend\nsubsection Masonry\n"
          "  set Geometry = mesh file\n  set Mesh file = long.msh\n"
          "  subsection Boundary conditions\n"
          "    set Normal displacement zero =\n    set Signorini = base\n"
          "    set Signorini gap = 0\n    set Traction boundaries =\n"
          "    set Gravity direction = " +
            std::to_string(gx) + ", " + std::to_string(gy) +
            ", 0\n  end\nend\n");
    return "long.prm";
  }

  /**
   * One elastic block 4 x 1 of 8 x 2 cells on two knife edges, Signorini
   * at (0, 0) and (3, 0), under its weight 4: free to slide along x, which
   * no load drives. The reactions are 4/3 and 8/3. PSOR and MPRGP, whose
   * regularisation (1e-2 of the mean diagonal) holds back the block's
   * deflection, ended 'singular' (exit 2) with an answer that was right: their
   * projection's proximal finish moved from it by more than its size and took
   * that for a runaway (a review).
   */
  std::string
  beam_on_two_edges(const std::string &method)
  {
    std::ostringstream mesh;
    mesh << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n2\n"
            "1 101 \"edge_0\"\n1 102 \"edge_3\"\n$EndPhysicalNames\n"
            "$Nodes\n27\n";
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 9; ++i)
        mesh << 9 * j + i + 1 << " " << 0.5 * i << " " << 0.5 * j << " 0\n";
    mesh << "$EndNodes\n$Elements\n18\n1 1 2 101 101 1 2\n"
            "2 1 2 102 102 6 7\n";
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 8; ++i)
        {
          const int corner = 9 * j + i + 1;
          mesh << 8 * j + i + 3 << " 3 2 1 1 " << corner << " " << corner + 1
               << " " << corner + 10 << " " << corner + 9 << "\n";
        }
    mesh << "$EndElements\n";
    write("beam.msh", mesh.str());
    write("beam_" + method + ".prm",
          "set Scene = masonry\nsubsection Output\n  set Directory = results\n"
          "  set Print timings = false\n  set Progress = false\n"
          "  set Write VTU = false\nend\nsubsection Masonry\n"
          "  set Geometry = mesh file\n  set Mesh file = beam.msh\n"
          "  subsection Boundary conditions\n"
          "    set Normal displacement zero =\n"
          "    set Signorini = edge_0 where x < 0.1, edge_3 where x > 2.9\n"
          "    set Signorini gap = 0\n    set Traction boundaries =\n"
          "    set Gravity = 1\n  end\nend\n"
          "subsection Solver\n  set Method = " +
            method + "\nend\n");
    return "beam_" + method + ".prm";
  }

  /**
   * A unit block of 2 x 2 cells (weight 1) in a frictionless corner: its
   * base and its left side on Signorini supports, the block turned by phi
   * degrees and moved by (shift, shift), gravity vertical. For 0 < phi <
   * 90 the base pushes with cos(phi) and the side with sin(phi); for phi <
   * 0 the block slides down its base, away from the side: no equilibrium,
   * which only the supports' sign shows (both together hold every rigid
   * motion). Before, PDAS moved it by 1e9 along the slide and ended
   * 'inaccurate', advising other units or a larger KKT tolerance, and
   * with that tolerance (0.2) 'converged' (a review).
   */
  std::string
  block_in_corner(const double       phi,
                  const double       shift,
                  const std::string &tolerance)
  {
    write("corner.msh",
          "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n2\n"
          "1 101 \"base\"\n1 102 \"side\"\n$EndPhysicalNames\n$Nodes\n9\n" +
            turned_square_nodes(phi, shift) +
            "$EndNodes\n$Elements\n8\n1 1 2 101 101 1 2\n"
            "2 1 2 101 101 2 3\n3 1 2 102 102 4 1\n4 1 2 102 102 7 4\n"
            "5 3 2 1 1 1 2 5 4\n6 3 2 1 1 2 3 6 5\n7 3 2 1 1 4 5 8 7\n"
            "8 3 2 1 1 5 6 9 8\n$EndElements\n");
    write("corner.prm",
          "set Scene = masonry\nsubsection Output\n  set Directory = results\n"
          "  set Print timings = false\n  set Progress = false\n"
          "  set Write VTU = false\nend\nsubsection Masonry\n"
          "  set Geometry = mesh file\n  set Mesh file = corner.msh\n"
          "  subsection Boundary conditions\n"
          "    set Normal displacement zero =\n    set Signorini = base, side\n"
          "    set Signorini gap = 0\n    set Traction boundaries =\n"
          "    set Gravity = 1\n  end\nend\n"
          "subsection Solver\n  set KKT tolerance = " +
            tolerance + "\nend\n");
    return "corner.prm";
  }

  /**
   * block_in_corner in 3D: the unit cube of 2 x 2 x 2 cells, its base and
   * its side on Signorini supports, free along z (no support there, and
   * gravity does no work along it).
   */
  std::string
  cube_in_corner(const double phi)
  {
    const double pi = 3.14159265358979323846;
    const double c = std::cos(phi * pi / 180), s = std::sin(phi * pi / 180);
    const auto node = [](int i, int j, int k) { return 9 * k + 3 * j + i + 1; };
    std::ostringstream nodes, elements;
    nodes.precision(17);
    for (int k = 0; k < 3; ++k)
      for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i)
          nodes << node(i, j, k) << " " << c * 0.5 * i - s * 0.5 * j << " "
                << s * 0.5 * i + c * 0.5 * j << " " << 0.5 * k << "\n";
    int element = 0;
    for (int a = 0; a < 2; ++a)
      for (int k = 0; k < 2; ++k)
        {
          elements << ++element << " 3 2 101 101 " << node(a, 0, k) << " "
                   << node(a + 1, 0, k) << " " << node(a + 1, 0, k + 1) << " "
                   << node(a, 0, k + 1) << "\n";
          elements << ++element << " 3 2 102 102 " << node(0, a, k) << " "
                   << node(0, a + 1, k) << " " << node(0, a + 1, k + 1) << " "
                   << node(0, a, k + 1) << "\n";
        }
    for (int k = 0; k < 2; ++k)
      for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i)
          {
            elements << ++element << " 5 2 1 1";
            for (const int z : {k, k + 1})
              elements << " " << node(i, j, z) << " " << node(i + 1, j, z)
                       << " " << node(i + 1, j + 1, z) << " "
                       << node(i, j + 1, z);
            elements << "\n";
          }
    write("cube.msh",
          "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n2\n"
          "2 101 \"base\"\n2 102 \"side\"\n$EndPhysicalNames\n$Nodes\n27\n" +
            nodes.str() + "$EndNodes\n$Elements\n" + std::to_string(element) +
            "\n" + elements.str() + "$EndElements\n");
    write("cube.prm",
          "set Scene = masonry\nsubsection Output\n  set Directory = results\n"
          "  set Print timings = false\n  set Progress = false\n"
          "  set Write VTU = false\nend\nsubsection Masonry\n"
          "  set Dimension = 3\n"
          "  set Geometry = mesh file\n  set Mesh file = cube.msh\n"
          "  subsection Boundary conditions\n"
          "    set Normal displacement zero =\n    set Signorini = base, side\n"
          "    set Signorini gap = 0\n    set Traction boundaries =\n"
          "    set Gravity = 1\n  end\nend\n");
    return "cube.prm";
  }

  /// The reaction force on @p boundary in summary.json (2D or 3D, z = 0
  /// in 2D; NaN if it has none).
  std::array<double, 3>
  reaction_force(const std::string &json, const std::string &boundary)
  {
    std::smatch found;
    if (!std::regex_search(json,
                           found,
                           std::regex("\"" + boundary +
                                      "\": *\\{\\s*\"force\": *\\[\\s*"
                                      "([-+0-9.eE]+),\\s*([-+0-9.eE]+)"
                                      "(?:,\\s*([-+0-9.eE]+))?")))
      return {{std::nan(""), std::nan(""), std::nan("")}};
    return {{std::stod(found[1]),
             std::stod(found[2]),
             found[3].matched ? std::stod(found[3]) : 0.0}};
  }

  double
  reaction_size(const std::string &json, const std::string &boundary)
  {
    const auto f = reaction_force(json, boundary);
    return std::hypot(f[0], f[1], f[2]);
  }

  /**
   * What a block or cube in a corner turned by @p phi degrees ended with:
   * where it converged, whether its reactions are rigid-body statics' (the
   * base cos(phi), the side sin(phi) of its weight 1); else whether the
   * scene proved before solving that it slides.
   */
  std::string
  corner_verdict(const Result      &result,
                 const std::string &summary_file,
                 const double       phi)
  {
    const double pi = 3.14159265358979323846;
    if (result.code != 0)
      return std::string(", no equilibrium before solving: ") +
             yes_no(result.err.find("could resist only by pulling") !=
                    std::string::npos);
    const std::string summary = read(summary_file);
    return std::string(", reactions cos(phi) and sin(phi): ") +
           yes_no(std::abs(reaction_size(summary, "base") -
                           std::cos(phi * pi / 180)) < 1e-8 &&
                  std::abs(reaction_size(summary, "side") -
                           std::sin(phi * pi / 180)) < 1e-8);
  }

  /// The vertical force of the reaction on @p boundary in summary.json.
  double
  reaction(const std::string &json, const std::string &boundary)
  {
    return reaction_force(json, boundary)[1];
  }
} // namespace

int
main()
{
  write("slide.prm", wall("base where x > s"));
  report("stack bond m = 3 without side rollers", run({"slide.prm"}));
  const std::string summary = read("results/slide/summary.json");
  const std::size_t key     = summary.find("\"free_rigid_motions\"");
  const std::size_t line =
    summary.find("\"the whole structure (9 blocks) can move freely by "
                 "translation along (1, 0)\"");
  std::cout << "  summary.json lists it: "
            << yes_no(key != std::string::npos && line != std::string::npos &&
                      key < line)
            << "\n";

  write("pivot.prm", wall("base where x < 0.1", "0; 0", "", ""));
  report("held by one roller at (0, 0)", run({"pivot.prm"}));

  write("push.prm", wall("base where x > s", "0.001; 0"));
  const Result push = run({"push.prm"});
  report("without side rollers, pushed along x", push);
  // Refused before solving: the summary says that no method ran, and has
  // the stages every summary has (a review: no 'solve' in 'time', and
  // 'none (pdas not run)' for the solver; the screen gave an energy and
  // residuals of the zero start).
  const std::string pushed = read("results/push/summary.json");
  std::cout << "  summary.json: solved false: "
            << yes_no(pushed.find("\"solved\": false") != std::string::npos)
            << ", solver pdas: "
            << yes_no(pushed.find("\"solver\": \"pdas\"") != std::string::npos)
            << ", a 'solve' stage: "
            << yes_no(!std::isnan(number(pushed, "solve")))
            << "; the screen shows no energy: "
            << yes_no(push.out.find("energy") == std::string::npos) << "\n";

  write("held.prm", wall("left, right, base where x > s"));
  report("with its rollers", run({"held.prm"}));

  // The 3D wall of prm/masonry_wall_3d.prm, without and with its front
  // roller.
  const std::string three_d = "  set Dimension = 3\n"
                              "  set Blocks through the thickness = 2\n"
                              "  set Thickness = 2\n";
  write("no_front.prm",
        wall("left, right, base where x > s", "0; 0; 0", three_d));
  report("3D wall without its front roller", run({"no_front.prm"}));
  write("no_front_pushed.prm",
        wall("left, right, base where x > s", "0; 0; 0.001", three_d));
  report("3D wall without its front roller, pushed along z",
         run({"no_front_pushed.prm"}));
  write("front.prm",
        wall("left, right, front, base where x > s", "0; 0; 0", three_d));
  report("3D wall with it", run({"front.prm"}));

  // Twelve unit squares apart from each other, nothing holding any: ten
  // are named, then one line counts the rest (thousands of loose blocks
  // would otherwise print thousands of lines).
  std::string nodes, elements;
  for (int k = 0; k < 12; ++k)
    {
      const auto node = [&](const int corner, const int x, const int y) {
        nodes += std::to_string(4 * k + corner) + " " + std::to_string(x) +
                 " " + std::to_string(y) + " 0\n";
      };
      node(1, 2 * k, 0);
      node(2, 2 * k + 1, 0);
      node(3, 2 * k + 1, 1);
      node(4, 2 * k, 1);
      elements += std::to_string(k + 1) + " 3 2 1 " + std::to_string(k + 1);
      for (int corner = 1; corner <= 4; ++corner)
        elements += " " + std::to_string(4 * k + corner);
      elements += "\n";
    }
  write("loose.msh",
        "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n48\n" + nodes +
          "$EndNodes\n$Elements\n12\n" + elements + "$EndElements\n");
  write("loose.prm",
        "set Scene = masonry\nsubsection Output\n  set Directory = results\n"
        "  set Print timings = false\n  set Progress = false\n"
        "  set Write VTU = false\nend\nsubsection Masonry\n"
        "  set Geometry = mesh file\n  set Mesh file = loose.msh\n"
        "  subsection Boundary conditions\n"
        "    set Normal displacement zero =\n    set Signorini =\n"
        "    set Traction boundaries =\n  end\nend\n");
  const Result loose = run({"loose.prm"});
  std::size_t  named = 0;
  for (std::size_t at = 0;
       (at = loose.err.find("is held by no support", at)) != std::string::npos;
       ++at)
    ++named;
  for (const auto &[theta, tolerance] :
       std::vector<std::pair<double, std::string>>{{30, "1e-8"},
                                                   {5, "1e-8"},
                                                   {1, "1e-8"},
                                                   {1, "0.05"},
                                                   {1e-3, "1e-3"},
                                                   {1e-5, "1e-8"},
                                                   {1e-7, "1e-8"},
                                                   {1e-11, "1e-8"}})
    {
      const Result slide = run({block_on_slope(theta, tolerance)});
      std::cout << "a block on a slope of " << theta
                << " degrees, KKT tolerance " << tolerance << ": exit code "
                << slide.code << ", no equilibrium: "
                << yes_no(slide.err.find("has no equilibrium: the loads do "
                                         "work along") != std::string::npos)
                << ", names the slide: "
                << yes_no(slide.err.find("the translation along") !=
                          std::string::npos)
                << "\n";
    }
  for (const double shift : {0.0, 1e5, 1e6})
    {
      const Result groove = run({block_in_groove(shift)});
      std::cout << "a block in a V-groove of 5e-6, pushed by 1e-6, at " << shift
                << ": exit code " << groove.code << ", noted as free: "
                << yes_no(groove.out.find("can move freely") !=
                          std::string::npos)
                << "\n";
    }

  for (const auto &[phi, shift, tolerance] :
       std::vector<std::tuple<double, double, std::string>>{{10, 0, "1e-8"},
                                                            {1e-3, 0, "1e-8"},
                                                            {10, 1e6, "1e-8"},
                                                            {-1, 0, "1e-8"},
                                                            {-1, 0, "0.2"},
                                                            {-1, 1e6, "1e-8"},
                                                            {-1e-3, 0, "1e-8"},
                                                            {91, 0, "1e-8"}})
    {
      const Result corner = run({block_in_corner(phi, shift, tolerance)});
      std::cout << "a block in a corner turned by " << phi << " degrees, at "
                << shift << ", KKT tolerance " << tolerance << ": exit code "
                << corner.code
                << corner_verdict(corner, "results/corner/summary.json", phi)
                << "\n";
    }

  // The same in 3D, free along z: the escape is found among the motions
  // the supports leave besides that free one. At 1e-3 degrees, the least
  // squares' few pushing nodes once let the loads' rounding turn the
  // escape about the line they leave free.
  for (const double phi : {10.0, -1.0, -1e-3})
    {
      const Result cube = run({cube_in_corner(phi)});
      std::cout << "a cube in a corner turned by " << phi
                << " degrees, free along z: exit code " << cube.code
                << corner_verdict(cube, "results/cube/summary.json", phi)
                << "\n";
    }

  // Courses that slide on each other (free_slides): a wall on a fixed base
  // without side rollers, gravity tilted by gx: every course above the
  // base slides along its horizontal joints, so there is no equilibrium,
  // although no support leaves the wall as a whole free. The first course
  // named is the second (blocks 3 to 5 of stack bond m = 3). At gx = 1e-11
  // the loads' work is below what the scene calls a proof (2.2e-10), and
  // the solver's answer balances the loads to within the KKT tolerance,
  // its slides along the joints, driven by 1e-11 of the weight against
  // the regularisation, below the tolerance of the displacements.
  for (const std::string &gx : {"1e-2", "1e-6", "1e-11"})
    {
      write("tilted.prm",
            wall("", "0; 0", "", "") +
              "subsection Masonry\n  subsection Boundary conditions\n"
              "    set Fixed = base\n    set Traction boundaries =\n"
              "    set Gravity direction = " +
              gx + ", -1, 0\n  end\nend\n");
      const Result tilted = run({"tilted.prm"});
      std::cout << "stack bond m = 3 on a fixed base, gravity tilted by " << gx
                << ": exit code " << tilted.code << ", a course slides: "
                << yes_no(tilted.err.find(
                            "the translation along (1, 0) of block 3 (a node "
                            "at (0, 0.33333333)) and the 2 blocks that "
                            "slide with it") != std::string::npos)
                << "\n";
    }
  // The same in 3D: the wall two blocks thick on a fixed base, gravity
  // tilted along z; the courses' rows slide along z.
  write("tilted_3d.prm",
        wall("", "0; 0; 0", three_d, "") +
          "subsection Masonry\n  subsection Boundary conditions\n"
          "    set Fixed = base\n    set Traction boundaries =\n"
          "    set Gravity direction = 0, -1, 1e-3\n  end\nend\n");
  const Result tilted_3d = run({"tilted_3d.prm"});
  std::cout << "3D wall on a fixed base, gravity tilted along z: exit code "
            << tilted_3d.code << ", a set of blocks slides along z: "
            << yes_no(tilted_3d.err.find("the translation along (0, 0, 1) of "
                                         "block") != std::string::npos)
            << "\n";

  const Result long_block = run({long_block_far_away()});
  std::cout << "a block of 16,000 cells on a slope of 1e-3 at 1e5: exit code "
            << long_block.code << ", no equilibrium before solving: "
            << yes_no(long_block.err.find("found from the supports") !=
                      std::string::npos)
            << "\n";

  for (const std::string method : {"pdas", "psor", "mprgp"})
    {
      const Result      beam = run({beam_on_two_edges(method)});
      const std::string summary =
        read("results/beam_" + method + "/summary.json");
      std::cout << "a block on two knife edges, free to slide, " << method
                << ": exit code " << beam.code << ", reactions 4/3 and 8/3: "
                << yes_no(std::abs(reaction(summary, "edge_0") - 4. / 3) <
                            1e-8 &&
                          std::abs(reaction(summary, "edge_3") - 8. / 3) < 1e-8)
                << "\n";
    }

  std::cout << "twelve loose squares: exit code " << loose.code << ", " << named
            << " named, the rest counted: "
            << yes_no(loose.err.find("and 2 more groups of blocks") !=
                      std::string::npos)
            << "\n";
}
