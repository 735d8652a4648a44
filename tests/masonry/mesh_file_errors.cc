// Bad masonry input around mesh files and supports, run as a user runs it:
// each gives exit code 1 and one line on stderr that names the file or the
// parameter and says what to do (printed here: the code and the line);
// controls, a mesh 1e4 from the origin and a 3D box 1e5 from it, are read
// and solved (the box as at the origin), and so are
// two blocks 0.02 apart, with a note that names the gap (no joint there).
#include "../application_test_tools.h"

#include <array>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <regex>
#include <sstream>
#include <string>

using namespace application_test;

namespace
{
  const std::string unit_square_nodes =
    "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n$EndNodes\n";
  const std::string header = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n";

  /// Two unit squares side by side (x in [0, 1] and [shift, shift + 1]),
  /// each its own entity; the base lines named 'base' (physical 7).
  std::string
  two_squares(const double shift, const int second_tag = 1)
  {
    const std::string s0 = std::to_string(shift);
    const std::string s1 = std::to_string(shift + 1);
    return header + "$PhysicalNames\n1\n1 7 \"base\"\n$EndPhysicalNames\n" +
           "$Nodes\n8\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n5 " + s0 +
           " 0 0\n6 " + s1 + " 0 0\n7 " + s1 + " 1 0\n8 " + s0 +
           " 1 0\n$EndNodes\n$Elements\n4\n1 3 2 1 1 1 2 3 4\n2 3 2 " +
           std::to_string(second_tag) +
           " 2 5 6 7 8\n3 1 2 7 11 1 2\n4 1 2 7 12 5 6\n$EndElements\n";
  }

  /// One unit square with its corners at x = @p x0 and @p x1 (given as
  /// text, so that they are exact far from the origin), its base 'base'.
  std::string
  square_at(const std::string &x0, const std::string &x1)
  {
    return header + "$PhysicalNames\n1\n1 7 \"base\"\n$EndPhysicalNames\n" +
           "$Nodes\n4\n1 " + x0 + " 0 0\n2 " + x1 + " 0 0\n3 " + x1 +
           " 1 0\n4 " + x0 +
           " 1 0\n$EndNodes\n$Elements\n2\n1 3 2 1 1 1 2 3 4\n"
           "2 1 2 7 11 1 2\n$EndElements\n";
  }

  /// The program on @p mesh (none: the file @p name.msh stays as it is),
  /// its 'base' fixed and no other support or load but self-weight.
  Result
  run_mesh(const std::string &name,
           const std::string &mesh,
           const std::string &masonry_lines = "")
  {
    if (!mesh.empty())
      write(name + ".msh", mesh);
    write(name + ".prm",
          "set Scene = masonry\nsubsection Output\n  set Directory = results\n"
          "  set Write VTU = false\n  set Progress = false\nend\n"
          "subsection Masonry\n  set Geometry = mesh file\n"
          "  set Mesh file = " +
            name +
            ".msh\n  subsection Boundary conditions\n"
            "    set Normal displacement zero =\n    set Signorini =\n"
            "    set Traction boundaries =\n    set Fixed = base\n  end\n" +
            masonry_lines + "end\n");
    return run({name + ".prm"});
  }

  void
  bad(const std::string &what,
      const std::string &mesh,
      const std::string &masonry_lines = "")
  {
    const Result result = run_mesh("bad", mesh, masonry_lines);
    std::cout << what << ": exit code " << result.code << ", "
              << (one_line(result.err) ? "" : "(not one line) ") << result.err;
  }
} // namespace

int
main()
{
  std::filesystem::remove("bad.msh");
  bad("no such file", "");
  std::filesystem::create_directory("bad.msh");
  bad("a directory", "");
  std::filesystem::remove("bad.msh");
  bad("not a mesh", "hello\n");
  bad("binary", "$MeshFormat\n2.2 1 8\n$EndMeshFormat\n");
  bad("format 3", "$MeshFormat\n3.0 0 8\n$EndMeshFormat\n");
  bad("second-order cells",
      header + unit_square_nodes +
        "$Elements\n1\n1 10 2 1 1 1 2 3 4 1 2 3 4 1\n$EndElements\n");
  bad("a 3D mesh read in 2D",
      header + unit_square_nodes +
        "$Elements\n1\n1 4 2 1 1 1 2 3 4\n$EndElements\n");
  bad("an element with an undefined node",
      header + unit_square_nodes +
        "$Elements\n1\n1 3 2 1 1 1 2 3 9\n$EndElements\n");
  bad("a tangled cell",
      header + unit_square_nodes +
        "$Elements\n2\n1 3 2 1 1 1 2 4 3\n2 1 2 7 11 1 2\n$EndElements\n");
  bad("a degenerate cell",
      header + unit_square_nodes +
        "$Elements\n2\n1 3 2 1 1 1 2 2 4\n2 1 2 7 11 1 2\n$EndElements\n");
  bad("overlapping blocks", two_squares(0.5));
  bad("a gap between nearly coincident faces", two_squares(1.001));
  bad("blocks that overlap slightly", two_squares(0.999));
  // Just beyond the refusal band (1e-2 of the cell) no joint is made and
  // the run goes on, but says so (a review: blocks drawn 0.01 apart fell
  // apart with no word of the face across the gap).
  {
    const Result result = run_mesh("near", two_squares(1.02));
    std::cout << "blocks 0.02 apart: exit code " << result.code
              << ", the gap noted: "
              << yes_no(result.out.find("face each other across a gap of "
                                        "0.02") != std::string::npos)
              << "\n";
  }
  bad("a block tag with no material",
      two_squares(1, 2),
      "  subsection Materials\n    set Assignment = physical tag\n"
      "    set Tags = 1\n  end\n");
  // Named groups: the message gives the number too, which 'Tags' may
  // use (a review could not tell which number to write); a tag named
  // twice in 'Tags' is refused as such (before: only the missing one).
  {
    const std::string named =
      header +
      "$PhysicalNames\n3\n1 7 \"base\"\n2 1 \"stone\"\n2 4 \"lintel\"\n"
      "$EndPhysicalNames\n$Nodes\n8\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n"
      "5 1 0 0\n6 2 0 0\n7 2 1 0\n8 1 1 0\n$EndNodes\n$Elements\n4\n"
      "1 3 2 1 1 1 2 3 4\n2 3 2 4 2 5 6 7 8\n3 1 2 7 11 1 2\n"
      "4 1 2 7 12 5 6\n$EndElements\n";
    bad("a named block tag with no material",
        named,
        "  subsection Materials\n    set Assignment = physical tag\n"
        "    set Young's modulus = 4e3, 4e3\n    set Poisson's ratio = 0.3, "
        "0.3\n    set Density = 1, 1\n    set Tags = stone, 2\n  end\n");
    bad("a tag named twice",
        named,
        "  subsection Materials\n    set Assignment = physical tag\n"
        "    set Young's modulus = 4e3, 4e3\n    set Poisson's ratio = 0.3, "
        "0.3\n    set Density = 1, 1\n    set Tags = stone, stone\n  end\n");
  }
  // Two squares of one entity and group that meet only at the corner
  // (1, 1): taken for one block until 2026-11-30, hung from that node.
  bad("cells of one group meeting only at a corner",
      header + "$PhysicalNames\n1\n1 7 \"base\"\n$EndPhysicalNames\n"
               "$Nodes\n7\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n5 2 1 0\n"
               "6 2 2 0\n7 1 2 0\n$EndNodes\n$Elements\n3\n1 3 2 1 1 1 2 3 4\n"
               "2 3 2 1 1 3 5 6 7\n3 1 2 7 11 1 2\n$EndElements\n");
  bad("a support that is not a boundary",
      two_squares(1),
      "  subsection Boundary conditions\n    set Fixed = springing\n  end\n");
  bad("a region that does not parse",
      two_squares(1),
      "  subsection Boundary conditions\n    set Fixed = base where x <\n"
      "  end\n");
  // The comma of max(x, 1) splits the list: once 'Missing parenthesis'.
  bad("a region with a comma",
      two_squares(1),
      "  subsection Boundary conditions\n"
      "    set Fixed = base where max(x, 1) < 2\n  end\n");
  bad("a prescribed displacement with three components in 2D",
      two_squares(1),
      "  subsection Boundary conditions\n"
      "    set Prescribed displacement boundaries = base\n"
      "    set Prescribed displacement = 0; 1; 2\n  end\n");
  // Non-matching: the second square (two cells high) meets the first (one
  // cell) along x = 1; its middle node (1, 0.5) has no partner.
  bad("non-matching nodes",
      header +
        "$PhysicalNames\n1\n1 7 \"base\"\n$EndPhysicalNames\n"
        "$Nodes\n10\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n5 1 0 0\n6 2 0 0\n"
        "7 2 0.5 0\n8 1 0.5 0\n9 2 1 0\n10 1 1 0\n$EndNodes\n"
        "$Elements\n5\n1 3 2 1 1 1 2 3 4\n2 3 2 1 2 5 6 7 8\n"
        "3 3 2 1 2 8 7 9 10\n4 1 2 7 11 1 2\n5 1 2 7 12 5 6\n$EndElements\n");
  // One block of 2 x 2 cells whose first cell uses node 10, a copy of the
  // centre node 5: accepted before 7103d09, the copy cut a traction-free
  // slit into the block (energy -8.54e-5 instead of -7.57e-5).
  bad("two nodes of one block at one position",
      header +
        "$PhysicalNames\n1\n1 7 \"base\"\n$EndPhysicalNames\n"
        "$Nodes\n10\n1 0 0 0\n2 0.5 0 0\n3 1 0 0\n4 0 0.5 0\n5 0.5 0.5 0\n"
        "6 1 0.5 0\n7 0 1 0\n8 0.5 1 0\n9 1 1 0\n10 0.5 0.5 0\n$EndNodes\n"
        "$Elements\n6\n1 3 2 1 1 1 2 10 4\n2 3 2 1 1 2 3 6 5\n"
        "3 3 2 1 1 4 5 8 7\n4 3 2 1 1 5 6 9 8\n5 1 2 7 11 1 2\n"
        "6 1 2 7 11 2 3\n$EndElements\n");
  // Two boundary groups named 'base' (7 under the first square, 8 under the
  // second): before f915a3c 'Fixed = base' took the last one silently.
  {
    std::string mesh = two_squares(1);
    mesh.replace(mesh.find("1\n1 7 \"base\""),
                 12,
                 "2\n1 7 \"base\"\n1 8 \"base\"");
    mesh.replace(mesh.find("4 1 2 7 12"), 10, "4 1 2 8 12");
    bad("two boundary groups of one name", mesh);
  }
  // 1e14 from the origin double precision keeps the unit square's geometry
  // only to 2e-2 (exact coordinates: integers below 2^53); before ff1e49a
  // such a wall solved with its energy 4e-3 off. 1e4 away it is kept to
  // 2e-12: the mesh is read and the square (its base fixed) solved.
  bad("a mesh far from the origin",
      square_at("100000000000000", "100000000000001"));
  // A box of 2 x 2 x 2 hexahedra of edge 0.5 (cells of the orientation
  // GridIn turns), 1e5 from the origin: deal.II's own checks of the cells'
  // volumes, cubic in the coordinates, failed there (at 3e4 they passed),
  // and the box was refused although double precision keeps its geometry
  // to 4e-11 (a review); turned, it was called tangled. Now read around a
  // point near it, and solved as at the origin (fixed base, self-weight),
  // straight and turned.
  for (const bool turned : {false, true})
    {
      // Turned by 0.5 about z, then 0.4 about x.
      const auto place =
        [turned](const double x, const double y, const double z) {
          if (!turned)
            return std::array<double, 3>{{x, y, z}};
          const double c = std::cos(0.5), s = std::sin(0.5), a = std::cos(0.4),
                       b  = std::sin(0.4);
          const double x1 = c * x - s * y, y1 = s * x + c * y;
          return std::array<double, 3>{{x1, a * y1 - b * z, b * y1 + a * z}};
        };
      // Turned, written three nodes to a line (a hand-written layout, which
      // the reading around a point near the mesh must follow: a review).
      const auto box_at = [&place, turned](const double corner) {
        std::ostringstream box;
        box.precision(17);
        box << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n1\n"
               "2 101 \"base\"\n$EndPhysicalNames\n$Nodes\n27\n";
        for (int k = 0; k < 3; ++k)
          for (int j = 0; j < 3; ++j)
            for (int i = 0; i < 3; ++i)
              {
                const auto p = place(0.5 * i, 0.5 * j, 0.5 * k);
                box << 9 * k + 3 * j + i + 1 << " " << corner + p[0] << " "
                    << corner + p[1] << " " << corner + p[2]
                    << (turned && i < 2 ? "  " : "\n");
              }
        box << "$EndNodes\n$Elements\n9\n1 3 2 101 101 1 10 11 2\n";
        int element = 2;
        for (int k = 0; k < 2; ++k)
          for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 2; ++i)
              {
                const int n = 9 * k + 3 * j + i + 1;
                box << element++ << " 5 2 1 1 " << n << " " << n + 1 << " "
                    << n + 4 << " " << n + 3 << " " << n + 9 << " " << n + 10
                    << " " << n + 13 << " " << n + 12 << "\n";
              }
        box << "$EndElements\n";
        return box.str();
      };
      const Result near   = run_mesh("box", box_at(0), "  set Dimension = 3\n");
      const double energy = number(read("results/box/summary.json"), "energy");
      const Result far = run_mesh("box", box_at(1e5), "  set Dimension = 3\n");
      const double far_energy =
        number(read("results/box/summary.json"), "energy");
      std::cout << "a box of hexahedra" << (turned ? ", turned," : "")
                << " 1e5 from the origin: exit codes " << near.code
                << " at the origin, " << far.code
                << " there; the same energy to 1e-9: "
                << yes_no(std::abs(far_energy - energy) <=
                          1e-9 * std::abs(energy))
                << "\n";
    }
  {
    const Result result = run_mesh("far", square_at("10000", "10001"));
    std::cout << "the same square 1e4 from the origin: exit code "
              << result.code
              << ", stderr empty: " << (result.err.empty() ? "yes" : "no")
              << "\n";
  }
  // A hexahedron with a quadrilateral on its face y = 0 read with the
  // default Dimension = 2: the quadrilateral's nodes leave the plane z = 0;
  // before 4d50023 the message did not say to set the dimension.
  bad("a 3D mesh with quadrilateral faces read in 2D",
      header +
        "$PhysicalNames\n1\n2 7 \"base\"\n$EndPhysicalNames\n"
        "$Nodes\n8\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n5 0 0 1\n6 1 0 1\n"
        "7 1 1 1\n8 0 1 1\n$EndNodes\n"
        "$Elements\n2\n1 5 2 1 1 1 2 3 4 5 6 7 8\n2 3 2 7 11 1 2 6 5\n"
        "$EndElements\n");
  // Found by a review (2026-11-27): the first cell of two squares listed
  // a second time counted its weight and stiffness twice (exit 0, energy
  // 25 % off on a 3 x 3 wall); listed with its vertices reversed, GridIn
  // never returned. gmsh's format 2.2 writes a surface's cells once for
  // each physical group it belongs to.
  {
    const std::string mesh  = two_squares(1);
    std::string       twice = mesh;
    twice.replace(twice.find("$Elements\n4\n"), 12, "$Elements\n5\n");
    twice.replace(twice.find("$EndElements"),
                  12,
                  "5 3 2 3 1 1 2 3 4\n$EndElements");
    bad("a cell listed twice", twice);
    twice.replace(twice.find("5 3 2 3 1 1 2 3 4"), 17, "5 3 2 3 1 4 3 2 1");
    bad("a cell listed twice, its vertices reversed", twice);
  }
  // Two unit squares of one cell each, the second pushed 0.1 into the
  // first along their course: every point the check above tries lies on
  // the first square's edges, and before the review the pair was solved
  // as two blocks without a joint.
  bad("blocks pushed into each other along a course", two_squares(0.9));
  // A physical line on the joint of two squares that share their nodes
  // (or a file without physical groups, where gmsh saves every curve):
  // deal.II's message named its own vertex indices, with a stack trace.
  bad("a boundary line between two cells that share its nodes",
      header +
        "$PhysicalNames\n1\n1 7 \"base\"\n$EndPhysicalNames\n"
        "$Nodes\n6\n1 0 0 0\n2 1 0 0\n3 2 0 0\n4 2 1 0\n5 1 1 0\n6 0 1 0\n"
        "$EndNodes\n$Elements\n5\n1 3 2 1 1 1 2 5 6\n2 3 2 2 2 2 3 4 5\n"
        "3 1 2 7 11 1 2\n4 1 2 7 12 2 3\n5 1 2 8 13 2 5\n$EndElements\n");
  // A square held by nothing, 0.5 above a square on its fixed base: the
  // message names it (a face that nearly touches another at an angle, found
  // by the review, makes no joint either and ended with the same words).
  {
    write("loose.msh",
          header + "$PhysicalNames\n1\n1 7 \"base\"\n$EndPhysicalNames\n"
                   "$Nodes\n8\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n5 0 1.5 0\n"
                   "6 1 1.5 0\n7 1 2.5 0\n8 0 2.5 0\n$EndNodes\n$Elements\n3\n"
                   "1 3 2 1 1 1 2 3 4\n2 3 2 1 2 5 6 7 8\n3 1 2 7 11 1 2\n"
                   "$EndElements\n");
    write("loose.prm",
          "set Scene = masonry\nsubsection Output\n"
          "  set Directory = results\n  set Write VTU = false\n"
          "  set Progress = false\nend\nsubsection Masonry\n"
          "  set Geometry = mesh file\n  set Mesh file = loose.msh\n"
          "  subsection Boundary conditions\n"
          "    set Normal displacement zero =\n    set Signorini =\n"
          "    set Traction boundaries =\n    set Fixed = base\n  end\nend\n");
    const Result result = run({"loose.prm"});
    std::cout << "a block with no joint and no support: exit code "
              << result.code << ", named: "
              << (result.err.find("block 1 (a node at") != std::string::npos ?
                    "yes" :
                    "no")
              << "\n";
  }
  // A square inside a flat trapezoid, 5.3 from the origin: the trapezoid's
  // bounding box (10 wide) is wider than its diagonals (5.4), and the grid
  // the overlap checks search by never compared the two (a review: solved,
  // exit 0).
  bad("a block inside a flat trapezoid",
      header + "$PhysicalNames\n1\n1 7 \"base\"\n$EndPhysicalNames\n"
               "$Nodes\n8\n1 5.3 0 0\n2 15.3 0 0\n3 10.7 0.3 0\n4 9.9 0.3 0\n"
               "5 9.3 0 0\n6 10.3 0 0\n7 10.3 0.2 0\n8 9.3 0.2 0\n$EndNodes\n"
               "$Elements\n4\n1 3 2 1 1 1 2 3 4\n2 3 2 1 2 5 6 7 8\n"
               "3 1 2 7 11 1 2\n4 1 2 7 12 5 6\n$EndElements\n");
  // Found by a review (2026-11-27): a node tag listed twice, the last
  // position taken silently (a block's corner moved, exit 0).
  bad("a node defined twice",
      header + "$Nodes\n5\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n4 0 2 0\n"
               "$EndNodes\n$Elements\n1\n1 3 2 1 1 1 2 3 4\n$EndElements\n");
  // Found by the same review: the second square's left side tilted by
  // 1e-7 (its top corner at x = 1 + 1e-7) made no joint with the first
  // square's right side, and said nothing: joints were sought only between
  // faces whose normals agree to 1e-9, so the squares stood side by side
  // unjoined (exit 0; with the joint they press on each other, bulging
  // under their weight). Refused now; with 'Coincidence tolerance' raised
  // as the message says, the joint is made and the energy is the untilted
  // squares' (the tilt moves the joint by at most 1e-7).
  {
    std::string tilted = two_squares(1);
    tilted.replace(tilted.find("8 1.000000 1 0"), 14, "8 1.0000001 1 0");
    bad("a joint's faces tilted by 1e-7", tilted);
    const auto energy = [](const std::string &mesh, const std::string &lines) {
      write("joint.msh", mesh);
      write("joint.prm",
            "set Scene = masonry\nsubsection Output\n"
            "  set Directory = results\n  set Write VTU = false\n"
            "  set Progress = false\nend\nsubsection Masonry\n"
            "  set Geometry = mesh file\n  set Mesh file = joint.msh\n" +
              lines +
              "  subsection Boundary conditions\n"
              "    set Normal displacement zero =\n    set Signorini =\n"
              "    set Traction boundaries =\n    set Fixed = base\n"
              "  end\nend\n");
      const Result      result = run({"joint.prm"});
      const std::size_t at     = result.out.find("  energy ");
      return std::pair<int, double>(result.code,
                                    at == std::string::npos ?
                                      0.0 :
                                      std::stod(result.out.substr(at + 9)));
    };
    const auto straight = energy(two_squares(1), "");
    const auto joined =
      energy(tilted, "  set Coincidence tolerance = 1.5e-7\n");
    const auto apart = energy(two_squares(1.5), "");
    std::cout << "the same with 'Coincidence tolerance' = 1.5e-7: exit code "
              << joined.first << ", energy the untilted squares' to 1e-6: "
              << yes_no(std::abs(joined.second - straight.second) <=
                        1e-6 * std::abs(straight.second))
              << ", and not that of squares apart: "
              << yes_no(std::abs(apart.second - straight.second) >
                        1e-3 * std::abs(straight.second))
              << "\n";
  }
  // Found by a review (2026-11-30): a 2 x 1 block on four cells per row,
  // tilted by 1e-7 about the left end of its bed, on a block of the same
  // mesh. The message suggested the tolerance its first face needed
  // (1.5e-7), which then refused the far end's nodes as not matching; the
  // tolerance it suggests must let the run through. (A first fix made
  // none at a tilt of 1e-4, a review.)
  for (const double tilt : {1e-7, 1e-4})
    {
      std::ostringstream mesh;
      mesh << std::setprecision(17) << header
           << "$PhysicalNames\n1\n1 7 \"base\"\n$EndPhysicalNames\n"
           << "$Nodes\n30\n";
      for (int block = 0; block < 2; ++block)
        for (int row = 0; row < 3; ++row)
          for (int column = 0; column < 5; ++column)
            mesh << 15 * block + 5 * row + column + 1 << " " << 0.5 * column
                 << " " << block + 0.5 * row + block * tilt * 0.5 * column
                 << " 0\n";
      mesh << "$EndNodes\n$Elements\n20\n";
      int element = 0;
      for (int block = 0; block < 2; ++block)
        for (int row = 0; row < 2; ++row)
          for (int column = 0; column < 4; ++column)
            {
              const int first = 15 * block + 5 * row + column + 1;
              mesh << ++element << " 3 2 1 " << block + 1 << " " << first << " "
                   << first + 1 << " " << first + 6 << " " << first + 5 << "\n";
            }
      for (int column = 0; column < 4; ++column)
        mesh << ++element << " 1 2 7 11 " << column + 1 << " " << column + 2
             << "\n";
      mesh << "$EndElements\n";
      const Result refused = run_mesh("tilted_end", mesh.str());
      std::smatch  suggested;
      std::regex_search(refused.err,
                        suggested,
                        std::regex("Coincidence tolerance' to ([-+.e0-9]+)"));
      const std::string tolerance = suggested.empty() ? "" : suggested[1].str();
      const Result      accepted =
        run_mesh("tilted_end",
                 "",
                 "  set Coincidence tolerance = " + tolerance + "\n");
      std::cout << "a block tilted by " << tilt << " about one end: exit code "
                << refused.code
                << ", suggests a tolerance: " << yes_no(!tolerance.empty())
                << "; with it the run goes through (exit code 0): "
                << yes_no(accepted.code == 0) << "\n";
    }
  // Found by a review of that fix: direction classes do not chain. Four
  // unit squares, two alone with tops tilted by 0 and 6e-8 (two classes),
  // and a joint whose faces are tilted by 2.8e-8 and 3.2e-8: each face
  // fell into its nearest class, a different one, and the joint was not
  // made (a first fix then refused the wall as tilted, with exit 3). The
  // -d faces of neighbouring classes are now compared too.
  {
    write("classes.msh",
          header +
            "$PhysicalNames\n1\n1 7 \"base\"\n$EndPhysicalNames\n"
            "$Nodes\n16\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n5 3 0 0\n"
            "6 4 0 0\n7 4 0.99999994000000003 0\n8 3 1 0\n9 6 0 0\n"
            "10 7 0 0\n11 7 0.99999997200000001 0\n12 6 1 0\n13 6 1 0\n"
            "14 7 0.99999996800000002 0\n15 7 2 0\n16 6 2 0\n$EndNodes\n"
            "$Elements\n7\n1 1 2 7 101 1 2\n2 1 2 7 102 5 6\n"
            "3 1 2 7 103 9 10\n4 3 2 1 1 1 2 3 4\n5 3 2 1 2 5 6 7 8\n"
            "6 3 2 1 3 9 10 11 12\n7 3 2 1 4 13 14 15 16\n$EndElements\n");
    write("classes.prm",
          "set Scene = masonry\nsubsection Output\n"
          "  set Directory = results\n  set Write VTU = false\n"
          "  set Progress = false\nend\nsubsection Masonry\n"
          "  set Geometry = mesh file\n  set Mesh file = classes.msh\n"
          "  subsection Boundary conditions\n"
          "    set Normal displacement zero =\n    set Signorini =\n"
          "    set Traction boundaries =\n    set Fixed = base\n  end\nend\n");
    const Result result = run({"classes.prm"});
    std::cout << "a joint whose faces lie in neighbouring direction classes: "
                 "exit code "
              << result.code << ", its three node pairs joined: "
              << yes_no(result.out.find("joints: 3 horizontal") !=
                        std::string::npos)
              << "\n";
  }
  // Found by the same review: the boundary 'base' also on the lower side
  // of the upper of two stacked squares (nodes of their own): a Signorini
  // support there set the upper square on a rigid support inside the lower
  // one (exit 0).
  const std::string stacked_squares =
    header + "$PhysicalNames\n1\n1 7 \"base\"\n$EndPhysicalNames\n"
             "$Nodes\n8\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n5 0 1 0\n"
             "6 1 1 0\n7 1 2 0\n8 0 2 0\n$EndNodes\n$Elements\n4\n"
             "1 3 2 1 1 1 2 3 4\n2 3 2 1 2 5 6 7 8\n3 1 2 7 11 1 2\n"
             "4 1 2 7 12 5 6\n$EndElements\n";
  bad("a Signorini support on a joint",
      stacked_squares,
      "  subsection Boundary conditions\n    set Fixed = base where y < 0.5\n"
      "    set Signorini = base where y > 0.5\n  end\n");
  // So a traction there (a review: 'Traction boundaries = collar' on a 3D
  // wall loaded both faces of every collar joint, twice the load, exit 0);
  // but not one kept to the free part of a face partly a joint (a review:
  // a block [1, 3] x [1, 2] on the middle of one [0, 4] x [0, 1] of two
  // cells, a traction (0, -1) on its top where x < 0.5 or x <= 1): the
  // load is the weight 6 and the traction's 0.5 or 1.
  const std::string resting_block =
    header + "$PhysicalNames\n2\n1 101 \"base\"\n1 102 \"top\"\n"
             "$EndPhysicalNames\n$Nodes\n10\n1 0 0 0\n2 2 0 0\n"
             "3 4 0 0\n4 0 1 0\n5 2 1 0\n6 4 1 0\n7 1 1 0\n8 3 1 0\n"
             "9 1 2 0\n10 3 2 0\n$EndNodes\n$Elements\n8\n"
             "1 3 2 1 1 1 2 5 4\n2 3 2 1 1 2 3 6 5\n3 3 2 1 2 7 8 10 9\n"
             "4 1 2 101 101 1 2\n5 1 2 101 101 2 3\n6 1 2 102 102 4 5\n"
             "7 1 2 102 102 5 6\n8 1 2 102 102 9 10\n$EndElements\n";
  for (const std::string region : {"x < 0.5", "x <= 1"})
    {
      const Result result = run_mesh(
        "partial",
        resting_block,
        "  subsection Boundary conditions\n    set Traction boundaries = top "
        "where " +
          region + "\n    set Traction = 0; -1\n  end\n");
      const std::string summary = read("results/partial/summary.json");
      const std::size_t at      = summary.find("\"load\": [");
      const double      load_y =
        at == std::string::npos ?
               std::nan("") :
               std::strtod(summary.c_str() + summary.find(',', at) + 1, nullptr);
      std::cout << "a traction on the free part of a face partly a joint ("
                << region << "): exit code " << result.code
                << ", the vertical load "
                << (region == "x < 0.5" ? "-6.5" : "-7") << ": "
                << yes_no(std::abs(load_y - (region == "x < 0.5" ? -6.5 : -7)) <
                          1e-12)
                << "\n";
    }
  // A Signorini support constrains nodes: on the free part it is meant,
  // at the joint's end node (x <= 1) refused, as inside the joint.
  {
    const Result result = run_mesh("partial",
                                   resting_block,
                                   "  subsection Boundary conditions\n"
                                   "    set Signorini = top where x < 0.5\n"
                                   "  end\n");
    std::cout << "a Signorini support on the free part of a face partly a "
                 "joint: exit code "
              << result.code << "\n";
  }
  bad("a Signorini support at a joint's end node",
      resting_block,
      "  subsection Boundary conditions\n"
      "    set Signorini = top where x <= 1\n  end\n");
  bad("a traction on a joint",
      stacked_squares,
      "  subsection Boundary conditions\n    set Fixed = base where y < 0.5\n"
      "    set Traction boundaries = base where y > 0.5\n"
      "    set Traction = 0; -1\n  end\n");
  // Found by the same review: a Signorini gap that is zero on the support,
  // evaluated at rounded node positions, came out -7e-19 and was refused
  // as "-0.000000 < 0". Below zero by less than the coincidence tolerance
  // it is zero; a real one is printed in full.
  {
    const std::string lines =
      "  subsection Boundary conditions\n    set Fixed = base where x < 0.25\n"
      "    set Signorini = base where x > 0.25\n";
    write("bad.msh", square_at("0", "1"));
    bad("a negative Signorini gap",
        "",
        lines + "    set Signorini gap = -0.001\n  end\n");
    write("bad.msh", square_at("0", "1"));
    write("gap.prm",
          "set Scene = masonry\nsubsection Output\n"
          "  set Directory = results\n  set Write VTU = false\n"
          "  set Progress = false\nend\nsubsection Masonry\n"
          "  set Geometry = mesh file\n  set Mesh file = bad.msh\n" +
            lines +
            "    set Normal displacement zero =\n"
            "    set Traction boundaries =\n"
            "    set Signorini gap = -1e-20\n  end\nend\n");
    const Result result = run({"gap.prm"});
    std::cout << "a Signorini gap of -1e-20 (zero rounded): exit code "
              << result.code << ", stderr empty: " << yes_no(result.err.empty())
              << "\n";
  }
  // A hexahedron whose top is twisted (y = 0.5 + 0.1 (2x - 1)(2z - 1), its
  // corners 0.025 out of one plane), optionally with a second one on it
  // (its own entity: a block of its own). Node-to-node contact needs flat
  // faces, but before, every face had to be flat, a traction-free one too
  // (a review: the intrados of a vault). Now refused only where touched:
  // the control stands on its base, its weight the volume 0.5 exactly.
  {
    const auto twisted = [&](const bool second) {
      return header +
             "$PhysicalNames\n5\n2 101 \"left\"\n2 102 \"base\"\n"
             "2 103 \"front\"\n2 105 \"top\"\n3 1 \"b\"\n"
             "$EndPhysicalNames\n$Nodes\n" +
             (second ? "12" : "8") +
             "\n1 0 0 0\n2 1 0 0\n3 1 0.4 0\n4 0 0.6 0\n5 0 0 1\n6 1 0 1\n"
             "7 1 0.6 1\n8 0 0.4 1\n" +
             (second ? "9 0 1.6 0\n10 1 1.4 0\n11 1 1.6 1\n12 0 1.4 1\n" : "") +
             "$EndNodes\n$Elements\n5" +
             "\n1 3 2 102 102 1 2 6 5\n2 3 2 101 101 1 4 8 5\n"
             "3 3 2 103 103 1 2 3 4\n" +
             (second ? "" : "4 3 2 105 105 4 3 7 8\n") +
             "5 5 2 1 1 1 2 3 4 5 6 7 8\n" +
             (second ? "6 5 2 1 2 4 3 10 9 8 7 11 12\n" : "") +
             "$EndElements\n";
    };
    const std::string supports =
      "  set Dimension = 3\n  subsection Boundary conditions\n"
      "    set Fixed =\n    set Normal displacement zero = left, front\n"
      "    set Gravity = 1\n    set Signorini = base";
    write("bad.msh", twisted(false));
    write("twisted.prm",
          "set Scene = masonry\nsubsection Output\n"
          "  set Directory = results\n  set Write VTU = false\n"
          "  set Progress = false\nend\nsubsection Masonry\n"
          "  set Geometry = mesh file\n  set Mesh file = bad.msh\n" +
            supports + "\n  end\nend\n");
    const Result result = run({"twisted.prm"});
    // summary.json: "base": {"force": [x, y, z], ...}.
    const std::string summary = read("results/twisted/summary.json");
    const std::size_t base    = summary.find("\"base\"");
    const std::size_t force =
      base == std::string::npos ? base : summary.find('[', base);
    double y = 0;
    if (force != std::string::npos)
      y = std::stod(summary.substr(summary.find(',', force) + 1));
    std::cout << "a block with a twisted traction-free top: exit code "
              << result.code << ", base reaction = weight 0.5 to 1e-9: "
              << yes_no(std::abs(y - 0.5) <= 1e-9) << "\n";
    bad("a twisted face with a Signorini support",
        twisted(false),
        supports + ", top\n  end\n");
    bad("a twisted face between two blocks",
        twisted(true),
        supports + "\n  end\n");
    // A block of a thin layer (so that 'near', 1e-2 of the smallest cell,
    // is below the twist of 0.002) and a cell with a twisted top, under a
    // block meshed 2 x 2 on that top (its faces lie on it: the top is
    // bilinear). Neither the joints' sweep (no face of one direction
    // class) nor the check for tilted faces (no plane) saw them: no joint,
    // and the upper block passed through (a review; held by no support
    // here).
    {
      const auto top = [](const double x, const double z) {
        return 0.5 + 0.002 * (2 * x - 1) * (2 * z - 1);
      };
      std::ostringstream nodes, cells;
      nodes.precision(17);
      const double corner[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
      for (int c = 0; c < 4; ++c)
        {
          const double x = corner[c][0], z = corner[c][1];
          nodes << 1 + c << " " << x << " 0 " << z << "\n"
                << 5 + c << " " << x << " 0.01 " << z << "\n"
                << 9 + c << " " << x << " " << top(x, z) << " " << z << "\n";
        }
      for (int level = 0; level < 2; ++level)
        for (int k = 0; k < 3; ++k)
          for (int i = 0; i < 3; ++i)
            nodes << 13 + 9 * level + 3 * k + i << " " << 0.5 * i << " "
                  << (level == 0 ? top(0.5 * i, 0.5 * k) : 1.5) << " "
                  << 0.5 * k << "\n";
      // gmsh's hexahedron: (x, z) corners 0 1 2 3 at the lower layer, then
      // at the upper (y up).
      for (int layer = 0; layer < 2; ++layer)
        {
          const int lo = 1 + 4 * layer, hi = lo + 4;
          cells << 2 + layer << " 5 2 1 1 " << lo << " " << lo + 1 << " "
                << hi + 1 << " " << hi << " " << lo + 3 << " " << lo + 2 << " "
                << hi + 2 << " " << hi + 3 << "\n";
        }
      for (int k = 0; k < 2; ++k)
        for (int i = 0; i < 2; ++i)
          {
            const int n = 13 + 3 * k + i;
            cells << 4 + 2 * k + i << " 5 2 1 2 " << n << " " << n + 1 << " "
                  << n + 10 << " " << n + 9 << " " << n + 3 << " " << n + 4
                  << " " << n + 13 << " " << n + 12 << "\n";
          }
      bad("a twisted face under a block meshed 2 x 2",
          header +
            "$PhysicalNames\n2\n2 102 \"base\"\n3 1 \"b\"\n"
            "$EndPhysicalNames\n$Nodes\n30\n" +
            nodes.str() + "$EndNodes\n$Elements\n7\n1 3 2 102 102 1 2 3 4\n" +
            cells.str() + "$EndElements\n",
          "  set Dimension = 3\n");
    }
  }
  // Two hexahedra whose faces cross like a '+' (a block on a strip): the
  // faces overlap, but no node of either lies on the other, so no joint
  // was made and the block passed through the strip (a review).
  bad("faces crossing like a '+'",
      header + "$PhysicalNames\n1\n2 7 \"base\"\n$EndPhysicalNames\n"
               "$Nodes\n16\n1 -1 0 -1\n2 1 0 -1\n3 1 1 -1\n4 -1 1 -1\n"
               "5 -1 0 1\n6 1 0 1\n7 1 1 1\n8 -1 1 1\n"
               "9 0.3 -1 -1.5\n10 0.7 -1 -1.5\n11 0.7 0 -1.5\n12 0.3 0 -1.5\n"
               "13 0.3 -1 4\n14 0.7 -1 4\n15 0.7 0 4\n16 0.3 0 4\n$EndNodes\n"
               "$Elements\n3\n1 3 2 7 7 9 10 14 13\n2 5 2 1 1 1 2 3 4 5 6 7 8\n"
               "3 5 2 1 2 9 10 11 12 13 14 15 16\n$EndElements\n",
      "  set Dimension = 3\n");
  bad("a cell with no area",
      header + "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 2 0 0\n4 3 0 0\n$EndNodes\n"
               "$Elements\n1\n1 3 2 1 1 1 2 3 4\n$EndElements\n");
}
