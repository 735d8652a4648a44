// The masonry output written in parallel (run on 2 ranks: .mpirun=2.): the
// program as a user runs it, on a running-bond wall, leaves one VTU piece
// per rank, a PVTU record naming both pieces and declaring the cell data,
// a PVD record pointing to the PVTU, and summary.json; every block lies in
// exactly one piece and the pieces together hold every block, the exit code
// is 0 on every rank. Rank 0 checks and prints.
#include <unilateral/application.h>

#include "../mpi_test_tools.h"

#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace
{
  const char *
  yes_no(const bool condition)
  {
    return condition ? "yes" : "NO";
  }

  std::string
  read(const std::filesystem::path &file)
  {
    std::ifstream      in(file);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }

  /// The values of the ASCII cell-data array @p name in a VTU text.
  std::vector<int>
  cell_array(const std::string &vtu, const std::string &name)
  {
    const std::string tag   = "Name=\"" + name + "\" format=\"ascii\">";
    const std::size_t start = vtu.find(tag);
    if (start == std::string::npos)
      return {};
    const std::size_t  end = vtu.find("</DataArray>", start);
    std::istringstream values(
      vtu.substr(start + tag.size(), end - start - tag.size()));
    std::vector<int> result;
    for (int value; values >> value;)
      result.push_back(value);
    return result;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int                       rank    = mpi_test::rank_0_prints();
  const unsigned int                       n_ranks = mpi_test::n_ranks();

  if (rank == 0)
    std::ofstream("wall.prm")
      << "set Scene = masonry\n"
         "subsection Output\n  set Directory = results\n"
         "  set Run name = wall\n  set Print timings = false\n"
         "  set Write VTU = true\nend\n"
         "subsection Masonry\n  set Geometry = running bond\n"
         "  set Blocks per side = 5\nend\n";
  MPI_Barrier(MPI_COMM_WORLD);
  std::vector<std::string> arguments = {"unilateral", "wall.prm"};
  char              *arguments_c[] = {arguments[0].data(), arguments[1].data()};
  std::ostringstream out, err;
  const int code  = unilateral::run_application(2, arguments_c, out, err);
  const int worst = dealii::Utilities::MPI::max(code, MPI_COMM_WORLD);
  MPI_Barrier(MPI_COMM_WORLD);
  if (rank != 0)
    return 0;

  const std::filesystem::path folder = "results/wall";
  std::cout << "ranks: " << n_ranks
            << ", exit code 0 on every rank: " << yes_no(worst == 0) << "\n";
  const std::string pvtu = read(folder / "solution_000.pvtu");
  const std::string pvd  = read(folder / "solution.pvd");
  std::cout << "PVD names the PVTU: "
            << yes_no(pvd.find("solution_000.pvtu") != std::string::npos)
            << ", PVTU declares the cell data: "
            << yes_no(pvtu.find("<PCellData") != std::string::npos &&
                      pvtu.find("Name=\"block_id\"") != std::string::npos)
            << ", summary.json: "
            << yes_no(std::filesystem::exists(folder / "summary.json"))
            << ", no serial VTU: "
            << yes_no(!std::filesystem::exists(folder / "solution_000.vtu"))
            << "\n";

  std::multiset<int> blocks_in_pieces;
  unsigned int       vtk_cells = 0;
  for (unsigned int r = 0; r < n_ranks; ++r)
    {
      const std::string piece = "solution_000." + std::to_string(r) + ".vtu";
      const std::string vtu   = read(folder / piece);
      const std::vector<int> block_id = cell_array(vtu, "block_id");
      const std::set<int>    blocks(block_id.begin(), block_id.end());
      blocks_in_pieces.insert(blocks.begin(), blocks.end());
      vtk_cells += block_id.size();
      std::cout << piece << ": named in the PVTU: "
                << yes_no(pvtu.find(piece) != std::string::npos)
                << ", blocks: " << blocks.size() << "\n";
    }
  const std::set<int> distinct(blocks_in_pieces.begin(),
                               blocks_in_pieces.end());
  std::cout << "VTK cells in all pieces: " << vtk_cells
            << ", blocks: " << distinct.size() << ", each block in one piece: "
            << yes_no(distinct.size() == blocks_in_pieces.size())
            << ", block ids 0 to " << distinct.size() - 1 << ": "
            << yes_no(!distinct.empty() && *distinct.begin() == 0 &&
                      *distinct.rbegin() ==
                        static_cast<int>(distinct.size()) - 1)
            << "\n";
}
