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
//
// The same wall with both faces free (rollers on the ends and the right
// half of the base only): every block of either leaf may slide along z, in
// both directions, held by nothing but the collar joint between the leaves.
// PDAS and the interior point against PDPC: the same energy to 1e-10, KKT
// <= 1e-10, no block flown off (which displacement each returns within the
// set depends on its path, so the displacements are not compared).
//
// The 2D running bond with its right side free: each course may slide to
// the right as far as its open head joints allow, again at no change of
// energy. The answers of PDAS (which cycles and hands over to the interior
// point) and of the interior point leave A singular on their free set, so
// the projection onto A fails; they are finished by the proximal point
// method (lcp/projection.h). Against PDPC, an exact method on A: the same
// energy to 1e-10, KKT <= 1e-10.
#include "tfeti_test_tools.h"

using namespace tfeti_test;

namespace
{
  /// The verdicts of @p result against @p reference (named
  /// @p reference_name): both converged, KKT <= 1e-10, the same energy to
  /// 1e-10, and with @p check_extent no block flown off.
  template <int dim>
  void
  print_verdicts(const RunOf<dim>  &result,
                 const RunOf<dim>  &reference,
                 const std::string &reference_name,
                 const bool         check_extent)
  {
    std::cout << "converged: "
              << yes_no(result.report.converged() &&
                        reference.report.converged())
              << ", KKT <= 1e-10: " << yes_no(result.report.kkt.max() <= 1e-10)
              << ", energy as " << reference_name << "'s: "
              << yes_no(
                   std::abs(result.report.energy - reference.report.energy) <=
                   1e-10 * std::abs(reference.report.energy));
    if (check_extent)
      std::cout << ", largest displacement below 0.1: "
                << yes_no(largest_displacement(*result.scene) < 0.1);
    std::cout << "\n";
  }
} // namespace

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
  std::cout << "3D running bond m = 25, back leaf free along z: ";
  print_verdicts(result, reference, "PDAS", true);

  const std::string both_faces_free =
    "    set Normal displacement zero = left, right, base where x > s\n";
  const RunOf<3> exact_3d =
    run<3>(parse(wall + prm_text("running bond", 8, "pdpc", both_faces_free)),
           "both_free");
  for (const std::string method : {"pdas", "interior_point"})
    {
      std::cout << "3D running bond m = 8, both faces free, " << method
                << " against pdpc: ";
      print_verdicts(
        run<3>(parse(wall +
                     prm_text("running bond", 8, method, both_faces_free)),
               "both_free"),
        exact_3d,
        "PDPC",
        true);
    }

  const std::string right_free =
    "    set Normal displacement zero = left, base where x > s\n";
  const RunOf<2> exact =
    run<2>(parse(prm_text("running bond", 20, "pdpc", right_free)), "free");
  for (const std::string method : {"pdas", "interior_point"})
    {
      std::cout << "2D running bond m = 20, right side free, " << method
                << " against pdpc: ";
      print_verdicts(
        run<2>(parse(prm_text("running bond", 20, method, right_free)), "free"),
        exact,
        "PDPC",
        false);
    }
}
