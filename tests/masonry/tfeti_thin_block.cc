// A block of 2 x 3e-5 on four cells of 0.5 x 3e-5 (a mesh file), solved by
// TFETI: the block's stiffness is too ill-conditioned for its pseudo-
// inverse (K_s + s R R^T has a condition above 1e14), which TFETI took for
// a subdomain in parts and ended in an internal error, "please report it"
// (exit 3; a review, 2026-11-30). Now it refuses the input, naming the
// method and the block, and pdas solves the same file.
#include "../application_test_tools.h"

using namespace application_test;

int
main()
{
  write("thin.msh",
        "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
        "$PhysicalNames\n3\n2 1 \"brick\"\n1 2 \"base\"\n1 3 \"left\"\n"
        "$EndPhysicalNames\n$Nodes\n10\n"
        "1 0 0 0\n2 0.5 0 0\n3 1 0 0\n4 1.5 0 0\n5 2 0 0\n"
        "6 0 3e-05 0\n7 0.5 3e-05 0\n8 1 3e-05 0\n9 1.5 3e-05 0\n"
        "10 2 3e-05 0\n$EndNodes\n$Elements\n9\n"
        "1 3 2 1 1 1 2 7 6\n2 3 2 1 1 2 3 8 7\n3 3 2 1 1 3 4 9 8\n"
        "4 3 2 1 1 4 5 10 9\n5 1 2 2 2 1 2\n6 1 2 2 2 2 3\n"
        "7 1 2 2 2 3 4\n8 1 2 2 2 4 5\n9 1 2 3 3 6 1\n$EndElements\n");
  for (const std::string method : {"tfeti", "pdas"})
    write(method + ".prm",
          "set Scene = masonry\nsubsection Masonry\n"
          "  set Geometry = mesh file\n  set Mesh file = thin.msh\n"
          "  subsection Boundary conditions\n"
          "    set Normal displacement zero = left\n"
          "    set Signorini = base\n    set Signorini gap = 0\n"
          "    set Traction boundaries =\n  end\nend\n"
          "subsection Solver\n  set Method = " +
            method +
            "\nend\nsubsection Output\n  set Directory = results\n"
            "  set Print timings = false\n  set Progress = false\n"
            "  set Write VTU = false\nend\n");
  expect_error("TFETI on the thin block",
               run({"tfeti.prm"}),
               {"'Solver/Method' = tfeti", "block 0", "pdas"});
  const Result pdas = run({"pdas.prm"});
  std::cout << "pdas on the thin block: exit code 0: " << yes_no(pdas.code == 0)
            << "\n";
}
