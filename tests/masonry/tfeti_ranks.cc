// TFETI with its subdomains distributed over the ranks (run with 1 and with
// 2 ranks, .mpirun=1. and .mpirun=2.): on every wall the same answer as
// serial PDAS, which every rank computes alone (energy to 1e-10, the same
// closed contacts, KKT <= 1e-10; the verdicts of tfeti_test_tools.h), so
// that the answers on 1 and 2 ranks are the same. The number of ranks that
// shared the subdomains is printed: the two outputs differ only there.
// Every rank judges its own TFETI run against the PDAS run it made alone,
// a verdict holding only if it holds on every rank, and every rank's
// nodal displacements must equal rank 0's (broadcast) to 1e-12 of the
// largest: TFETI gathers the whole u on every rank, which writes its own
// blocks' output from it. Rank 0 prints; every rank writes its runs into
// its own folder.
#include "../mpi_test_tools.h"
#include "tfeti_test_tools.h"

using namespace tfeti_test;

namespace
{
  void
  same_on_every_rank(const Run &tfeti)
  {
    std::cout << "  displacements as rank 0's on every rank (1e-12): "
              << yes_no(
                   mpi_test::same_as_rank_0(displacements(*tfeti.scene), 1e-12))
              << "\n";
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int                       rank = mpi_test::rank_0_prints();
  const std::string name = "tfeti_rank_" + std::to_string(rank);

  for (const std::string geometry : {"stack bond", "running bond", "laminae"})
    for (const unsigned int m : {5u, 10u})
      {
        const Run tfeti = against_pdas(
          geometry + ", m = " + std::to_string(m), geometry, m, "", name);
        for (const auto &[figure, value] : tfeti.report.figures)
          if (figure == "ranks")
            std::cout << "  subdomains shared by " << value << " ranks\n";
        same_on_every_rank(tfeti);
      }
  same_on_every_rank(against_pdas("stack bond, m = 10, g = 0",
                                  "stack bond",
                                  10,
                                  "    set Relative gap = 0\n",
                                  name));
}
