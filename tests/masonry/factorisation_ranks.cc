// The direct methods with their factorisations spread over the ranks
// ('Solver/Factorisation = mumps', run with 1 and with 2 ranks: .mpirun=1.
// and .mpirun=2.): on every wall PDAS and the interior point give the same
// answer as serial PDAS with CHOLMOD, which every rank computes alone
// (energy to 1e-10, the same closed contacts and forces, KKT <= 1e-10: the
// verdicts of tfeti_test_tools.h), and PDAS takes the same iterations. The
// walls: the paper's three at m = 5 and 10, one without gap (degenerate
// contacts), and a 3D wall two blocks thick. That the factorisations did
// run over the ranks is read from each MUMPS run's report: its
// 'factorisation_ranks' figure (set only where the distributed scope was
// opened) is printed, 1 or 2, and the CHOLMOD reference must have none (a
// silent fall-back to CHOLMOD would otherwise compare a computation with
// itself). Every rank judges its own runs, a verdict holding only if it
// holds on every rank, and every rank's nodal displacements must equal
// rank 0's (broadcast) to 1e-12 of the largest: every rank gets the whole
// MUMPS solution and writes its own blocks' output from it. Rank 0
// prints; the two outputs differ only in the number of ranks.
#include "../mpi_test_tools.h"
#include "tfeti_test_tools.h"

using namespace tfeti_test;

namespace
{
  std::string
  factorisation(const std::string &choice)
  {
    return "subsection Solver\n  set Factorisation = " + choice + "\nend\n";
  }

  template <int dim = 2>
  void
  over_ranks(const std::string &what,
             const std::string &geometry,
             const unsigned int m,
             const std::string &boundary,
             const std::string &masonry,
             const std::string &name)
  {
    using mpi_test::all_ranks;
    const RunOf<dim> reference =
      run<dim>(parse(masonry + prm_text(geometry, m, "pdas", boundary) +
                     factorisation("cholmod")),
               name);
    std::cout << what << ", cholmod reference: no factorisation_ranks figure: "
              << yes_no(all_ranks(
                   figure(reference.report, "factorisation_ranks") < 0))
              << "\n";
    for (const std::string method : {"pdas", "interior_point"})
      {
        const RunOf<dim> result =
          run<dim>(parse(masonry + prm_text(geometry, m, method, boundary) +
                         factorisation("mumps")),
                   name);
        compare(what + ", " + method, reference, result, false);
        const double ranks      = figure(result.report, "factorisation_ranks");
        const bool   same_ranks = all_ranks(ranks == mpi_test::n_ranks());
        const bool   same_u =
          mpi_test::same_as_rank_0(displacements(*result.scene), 1e-12);
        std::cout << "  factorisation_ranks = " << ranks
                  << " (the number of ranks, on every rank: "
                  << yes_no(same_ranks)
                  << "), displacements as rank 0's on every rank (1e-12): "
                  << yes_no(same_u) << "\n";
        if (method == "pdas")
          std::cout << "  pdas iterations as serial: "
                    << yes_no(all_ranks(result.report.iterations ==
                                        reference.report.iterations))
                    << "\n";
      }
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int                       rank = mpi_test::rank_0_prints();
  std::cout << "ranks: " << mpi_test::n_ranks() << "\n";
  const std::string name = "factorisation_rank_" + std::to_string(rank);

  for (const std::string geometry : {"stack bond", "running bond", "laminae"})
    for (const unsigned int m : {5u, 10u})
      over_ranks(
        geometry + ", m = " + std::to_string(m), geometry, m, "", "", name);
  over_ranks("running bond, m = 10, g = 0",
             "running bond",
             10,
             "    set Relative gap = 0\n",
             "",
             name);
  over_ranks<3>("running bond, m = 5, 3D, two blocks thick",
                "running bond",
                5,
                "    set Normal displacement zero = left, right, front, "
                "base where x > s\n",
                "subsection Masonry\n  set Dimension = 3\n"
                "  set Blocks through the thickness = 2\n"
                "  set Thickness = 2\nend\n",
                name);
}
