// TFETI (the dual over blocks) against PDAS on the paper's walls (g = H/2,
// the three geometries at m = 5, 10, 20): both converged, KKT <= 1e-10,
// the same energy (1e-10 relative), the same closed contacts (normal gap
// <= 1e-10 of the largest displacement) and the same contact forces (1e-8
// of the largest). Stack bond has degenerate contacts (closed, no force:
// their number is printed); where they alone hold a block the
// displacements may differ, the closed set and the forces may not.
// The same in 3D (m = 5, two blocks thick). Then: without load (u = 0, energy
// 0), with only a top load, with g = 0 (every joint closed), and a block that
// nothing holds: under gravity no equilibrium (found by the scene before
// solving), unloaded G G^T singular; never converged, and a message that names
// the block. TFETI's answer is approximate and the projection step (PDAS from
// the contacts whose multipliers are positive) makes it exact: in one or two
// iterations where TFETI's active set is right, so that is checked too (a
// wrong dual still ends exact, after many more).
// MPRGP's adaptive expansion step ('TFETI/Expansion step') on running bond
// and laminae, the same checks; so FETI's lumped preconditioner in MPRGP's
// faces ('TFETI/Preconditioner') on the three walls. Long blocks are cut into
// pieces glued by equalities ('Tearing/Largest aspect ratio', default 2: the
// laminae above are cut): the laminae with their blocks whole and cut give
// PDAS's answer, with the subdomains and multipliers counted; and a U-shaped
// block whose upper slice falls in two parts (the slice must be split, or a
// part would float with the rigid motions of the whole slice). A 3D wall free
// to slide along z, unloaded that way: TFETI refuses it with a message that
// says what to do. Gravity upwards (no equilibrium): infeasible, not an
// iteration limit; a tolerance out of reach (0) on a wall in equilibrium:
// not infeasible.
#include "tfeti_test_tools.h"

#include <fstream>

using namespace tfeti_test;

namespace
{
  /// A U of unit squares: the base x in [0, 3], y in [0, 1] and two posts
  /// x in [0, 1] and [2, 3] up to y = 7, one block (entity 1); boundary 1
  /// the base's lower side, 2 the left side.
  void
  write_u_block(const std::string &file)
  {
    const auto node = [](const int i, const int j) { return 4 * j + i + 1; };
    std::ostringstream elements;
    int                n = 0;
    for (int j = 0; j < 7; ++j)
      for (int i = 0; i < 3; ++i)
        if (j == 0 || i != 1)
          elements << ++n << " 3 2 1 1 " << node(i, j) << ' ' << node(i + 1, j)
                   << ' ' << node(i + 1, j + 1) << ' ' << node(i, j + 1)
                   << "\n";
    for (int i = 0; i < 3; ++i)
      elements << ++n << " 1 2 1 11 " << node(i, 0) << ' ' << node(i + 1, 0)
               << "\n";
    for (int j = 0; j < 7; ++j)
      elements << ++n << " 1 2 2 12 " << node(0, j) << ' ' << node(0, j + 1)
               << "\n";
    std::ofstream out(file);
    out << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n32\n";
    for (int j = 0; j < 8; ++j)
      for (int i = 0; i < 4; ++i)
        out << node(i, j) << ' ' << i << ' ' << j << " 0\n";
    out << "$EndNodes\n$Elements\n"
        << n << "\n"
        << elements.str() << "$EndElements\n";
  }
} // namespace

int
main()
{
  for (const std::string geometry : {"stack bond", "running bond", "laminae"})
    for (const unsigned int m : {5u, 10u, 20u})
      against_pdas(geometry + ", m = " + std::to_string(m), geometry, m);

  // 3D: the walls two blocks thick (six rigid motions per block), the front
  // face on rollers (the back leaf is held along z only by the front one).
  for (const std::string geometry : {"stack bond", "running bond", "laminae"})
    against_pdas<3>(geometry + ", m = 5, 3D, two blocks thick",
                    geometry,
                    5,
                    "    set Normal displacement zero = left, right, front, "
                    "base where x > s\n",
                    "tfeti",
                    "subsection Masonry\n  set Dimension = 3\n"
                    "  set Blocks through the thickness = 2\n"
                    "  set Thickness = 2\nend\n");

  // Without load nothing moves: u = 0 and the energy 0, whatever the gap.
  {
    const Run result =
      run(parse(prm_text("running bond", 10, "tfeti", "    set Gravity = 0\n")),
          "tfeti");
    std::cout << "running bond, m = 10, no load: converged: "
              << yes_no(result.report.converged())
              << ", u = 0: " << yes_no(largest_displacement(*result.scene) == 0)
              << ", energy 0: " << yes_no(result.report.energy == 0) << "\n";
  }
  against_pdas("laminae, m = 10, only a top load",
               "laminae",
               10,
               "    set Gravity = 0\n    set Traction = 0.3; -1\n");
  against_pdas("stack bond, m = 10, g = 0",
               "stack bond",
               10,
               "    set Relative gap = 0\n");
  against_pdas("running bond, m = 10, g = 0",
               "running bond",
               10,
               "    set Relative gap = 0\n");

  // MPRGP's adaptive expansion step: the same answers, and the adaptive
  // length taken.
  for (const std::string geometry : {"running bond", "laminae"})
    {
      const Run result =
        against_pdas(geometry + ", m = 10, 'Expansion step' = adaptive",
                     geometry,
                     10,
                     "",
                     "tfeti",
                     "subsection Solver\n  subsection TFETI\n    set "
                     "Expansion step = adaptive\n  end\nend\n");
      std::cout << "  adaptive expansions taken: "
                << yes_no(figure(result.report, "adaptive_expansions") > 0)
                << "\n";
    }

  // The lumped preconditioner in MPRGP's faces: the same answers, and the
  // preconditioner applied.
  for (const std::string geometry : {"stack bond", "running bond", "laminae"})
    {
      const Run result =
        against_pdas(geometry + ", m = 10, 'Preconditioner' = lumped",
                     geometry,
                     10,
                     "",
                     "tfeti",
                     "subsection Solver\n  subsection TFETI\n    set "
                     "Preconditioner = lumped\n  end\nend\n");
      std::cout << "  lumped preconditioner applied: "
                << yes_no(figure(result.report, "lumped_products") > 0) << "\n";
    }

  for (const std::string ratio : {"0", "2"})
    {
      const Run result =
        against_pdas("laminae, m = 10, 'Largest aspect ratio' = " + ratio,
                     "laminae",
                     10,
                     "",
                     "tfeti",
                     "subsection Masonry\n  subsection Tearing\n    set "
                     "Largest aspect ratio = " +
                       ratio + "\n  end\nend\n");
      std::cout << "  " << figure(result.report, "subdomains")
                << " subdomains, " << figure(result.report, "multipliers")
                << " multipliers\n";
    }
  {
    write_u_block("u_block.msh");
    const std::string u_block =
      "subsection Masonry\n  set Geometry = mesh file\n  set Mesh file = "
      "u_block.msh\n  subsection Boundary conditions\n    set Relative gap "
      "= 0\n    set Signorini = 1\n    set Normal displacement zero = 2\n"
      "    set Traction boundaries =\n  end\nend\n";
    const auto solver = [](const std::string &method) {
      return "subsection Solver\n  set Method = " + method + "\nend\n";
    };
    const Run reference = run(parse(solver("pdas") + u_block), "u_block");
    const Run result    = run(parse(solver("tfeti") + u_block), "u_block");
    compare("a U-shaped block on the ground", reference, result);
    std::cout << "  " << figure(result.report, "subdomains") << " subdomains, "
              << figure(result.report, "multipliers") << " multipliers\n";
  }

  // A 3D wall without the front rollers: the wall may slide along z, a
  // mechanism that the load does not drive. TFETI, which needs every rigid
  // motion held, refuses it and says what to do; the scene's failure line
  // says the wall is not held (it said the solver found no configuration
  // and the wall might have no equilibrium).
  {
    const RunOf<3> result =
      run<3>(parse("subsection Masonry\n  set Dimension = 3\n  set Blocks "
                   "through the thickness = 2\n  set Thickness = 2\nend\n" +
                   prm_text("stack bond", 2, "tfeti")),
             "sliding");
    const std::string line = result.scene->failure_description(result.report);
    std::cout << "3D stack bond free to slide along z: status "
              << to_string(result.report.status) << ": "
              << result.report.message << "\n"
              << "  the failure line names the free motion and claims no "
                 "lack of equilibrium (a review): "
              << yes_no(line.find("not held against every rigid motion") !=
                          std::string::npos &&
                        line.find("no equilibrium") == std::string::npos)
              << "\n";
  }

  // Gravity upwards: no compressive forces hold the blocks down. The
  // violation of G l = e stalled while the penalty doubled at every outer
  // iteration, and the run ended 'iteration limit' (at m = 2, 3: 'not
  // positive definite', the penalty overflowed), with an energy of -2.6e18
  // beside residuals of 1e-16; now 'infeasible', as PDAS says.
  for (const unsigned int m : {2u, 4u})
    {
      const Run result =
        run(parse("subsection Masonry\n  subsection Boundary conditions\n"
                  "    set Gravity = -1\n  end\nend\n" +
                  prm_text("stack bond", m, "tfeti")),
            "upwards");
      std::cout << "gravity upwards, m = " << m << ": status "
                << to_string(result.report.status) << ": "
                << result.report.message << "\n";
    }

  // A tolerance out of reach (0): the penalty grows as for no equilibrium,
  // but the violation goes on falling far below any force; the run was
  // called 'infeasible' (a review), and ends at its iteration limit now.
  {
    const Run result = run(parse(prm_text("stack bond", 4, "tfeti") +
                                 "subsection Solver\n  subsection TFETI\n"
                                 "    set Tolerance = 0\n  end\nend\n"),
                           "tolerance_zero");
    std::cout << "stack bond m = 4, 'TFETI/Tolerance = 0': status "
              << to_string(result.report.status) << ", not called "
              << "infeasible: "
              << yes_no(result.report.status != lcp::Status::infeasible)
              << "\n";
  }

  // Without the projection step TFETI's answer is as accurate as its own
  // tolerance; where the final checks find it short, the message said only
  // "a body held by round-off?" (a review): it now names the cause.
  {
    const Run result =
      run(parse(prm_text("running bond", 6, "tfeti") +
                "subsection Solver\n  set Projection = false\nend\n"),
          "unprojected");
    std::cout << "running bond m = 6 without the projection: status "
              << to_string(result.report.status) << ", names the cause: "
              << (result.report.message.find(
                    "only as accurate as its own tolerance") !=
                      std::string::npos ?
                    "yes" :
                    "NO")
              << "\n";
  }

  // A block in the air, above a slab on the ground: nothing holds it.
  // Under gravity the scene proves before solving that there is no
  // equilibrium; unloaded, TFETI's coarse matrix is singular.
  for (const std::string load : {"", "    set Gravity = 0\n"})
    {
      Layout layout;
      layout.name          = "floating block";
      layout.course_height = 0.25;
      layout.blocks        = {{0, 0, 1, 0.25}, {0.25, 0.75, 0.75, 1}};
      Setup      setup     = parse(prm_text("stack bond", 4, "tfeti", load));
      Run        result;
      RunContext context;
      result.scene =
        std::make_unique<MasonryScene<2>>(setup.parameters, layout);
      std::ostringstream  quiet;
      dealii::TimerOutput timer(quiet,
                                dealii::TimerOutput::never,
                                dealii::TimerOutput::wall_times);
      context.run_name         = "floating";
      context.output_directory = std::filesystem::path("results") / "floating";
      std::filesystem::create_directories(context.output_directory);
      context.write_vtu = false;
      context.solver    = setup.solver;
      context.timer     = &timer;
      result.report     = result.scene->run(context);
      std::cout << "a floating block" << (load.empty() ? "" : ", unloaded")
                << ": status " << to_string(result.report.status) << ": "
                << result.report.message << "\n";
    }
}
