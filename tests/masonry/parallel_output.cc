// The masonry output written in parallel (run on 2 ranks: .mpirun=2.): the
// program as a user runs it, on a running-bond wall, leaves one VTU piece
// per rank, a PVTU record naming both pieces and declaring the cell data,
// a PVD record pointing to the PVTU, and summary.json; every block lies in
// exactly one piece and the pieces together hold every block, the exit code
// is 0 on every rank. The field values of the pieces are read too: each
// piece's displacement array (deal.II's zlib-compressed binary, decoded
// here) must equal, at every point and for the block of its cell, the
// nodal displacement of a serial in-process run of the same wall (CHOLMOD
// on each rank alone) to 1e-6 of the largest |u| (the VTU holds Float32),
// and every node of the serial run must appear in some piece. A rank that
// wrote its blocks from a wrong or stale copy of u would fail here. Then a
// run whose rank 1 cannot write its piece: exit code 1 on every rank, and
// summary.json with the error. Rank 0 checks and prints.
#include <unilateral/application.h>

#include "../mpi_test_tools.h"
#include "masonry_test_tools.h"

#include <zlib.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
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

  /// Base64 text to bytes (up to the first '=' or the end).
  std::vector<unsigned char>
  from_base64(const std::string &text)
  {
    static const std::string alphabet =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::vector<unsigned char> bytes;
    unsigned int               buffer = 0, bits = 0;
    for (const char c : text)
      {
        if (c == '=')
          break;
        const std::size_t value = alphabet.find(c);
        if (value == std::string::npos)
          continue;
        buffer = (buffer << 6) | static_cast<unsigned int>(value);
        bits += 6;
        if (bits >= 8)
          {
            bits -= 8;
            bytes.push_back(
              static_cast<unsigned char>((buffer >> bits) & 0xff));
          }
      }
    return bytes;
  }

  /// The bytes of a binary DataArray as deal.II 9.4 writes it with zlib:
  /// base64 of the header (UInt32 1 block, its size, the last block's size,
  /// its compressed size: 16 bytes, 24 characters), then base64 of the
  /// compressed block. Empty if the layout is not that.
  std::vector<unsigned char>
  decompress(const std::string &content)
  {
    std::string text;
    for (const char c : content)
      if (!std::isspace(static_cast<unsigned char>(c)))
        text += c;
    if (text.size() < 24)
      return {};
    const std::vector<unsigned char> head = from_base64(text.substr(0, 24));
    if (head.size() != 16)
      return {};
    std::uint32_t header[4];
    std::memcpy(header, head.data(), 16);
    if (header[0] != 1)
      return {};
    const std::vector<unsigned char> compressed = from_base64(text.substr(24));
    if (compressed.size() < header[3])
      return {};
    std::vector<unsigned char> bytes(header[2]);
    uLongf                     size = bytes.size();
    if (uncompress(bytes.data(), &size, compressed.data(), header[3]) != Z_OK ||
        size != bytes.size())
      return {};
    return bytes;
  }

  /// The values of the binary DataArray whose opening tag contains
  /// @p attribute (e.g. Name="displacement"), after @p from, as doubles
  /// (types Float32, Int32 and UInt8). Empty if absent or unreadable.
  std::vector<double>
  binary_array(const std::string &vtu,
               const std::string &attribute,
               const std::string &from = "")
  {
    const std::size_t start = vtu.find(from);
    if (start == std::string::npos)
      return {};
    std::size_t tag = vtu.find("<DataArray", start);
    while (tag != std::string::npos)
      {
        const std::size_t close = vtu.find('>', tag);
        const std::string head  = vtu.substr(tag, close - tag);
        if (head.find(attribute) != std::string::npos)
          {
            const std::size_t end = vtu.find("</DataArray>", close);
            const std::vector<unsigned char> bytes =
              decompress(vtu.substr(close + 1, end - close - 1));
            std::vector<double> values;
            if (head.find("type=\"Float32\"") != std::string::npos)
              for (std::size_t i = 0; i + 4 <= bytes.size(); i += 4)
                {
                  float v;
                  std::memcpy(&v, &bytes[i], 4);
                  values.push_back(v);
                }
            else if (head.find("type=\"Int32\"") != std::string::npos)
              for (std::size_t i = 0; i + 4 <= bytes.size(); i += 4)
                {
                  std::int32_t v;
                  std::memcpy(&v, &bytes[i], 4);
                  values.push_back(v);
                }
            else if (head.find("type=\"UInt8\"") != std::string::npos)
              for (const unsigned char v : bytes)
                values.push_back(v);
            return values;
          }
        tag = vtu.find("<DataArray", close);
      }
    return {};
  }

  /// One piece against the serial run: each VTK point of each cell, with
  /// the cell's block id, must be a node of that block in the serial run
  /// (position within 1e-6) with the same displacement (1e-6 of the
  /// largest |u|). Marks the serial nodes found in @p seen; returns the
  /// number of points compared, 0 if any point fails or cannot be read.
  std::size_t
  compare_piece(
    const std::string                                            &vtu,
    const std::vector<unilateral::masonry::NodalDisplacement<2>> &serial,
    std::vector<char>                                            &seen)
  {
    const std::vector<int>    block_id = cell_array(vtu, "block_id");
    const std::vector<double> points =
      binary_array(vtu, "NumberOfComponents=\"3\"", "<Points>");
    const std::vector<double> connectivity =
      binary_array(vtu, "Name=\"connectivity\"");
    const std::vector<double> offsets = binary_array(vtu, "Name=\"offsets\"");
    const std::vector<double> u = binary_array(vtu, "Name=\"displacement\"");
    if (block_id.empty() || block_id.size() != offsets.size() ||
        points.size() != u.size() || points.empty())
      return 0;
    double largest = 0;
    for (const auto &node : serial)
      largest = std::max({largest,
                          std::abs(node.displacement[0]),
                          std::abs(node.displacement[1])});
    std::size_t compared = 0, begin = 0;
    for (std::size_t c = 0; c < offsets.size(); ++c)
      {
        const std::size_t end = static_cast<std::size_t>(offsets[c]);
        if (end > connectivity.size() || end < begin)
          return 0;
        for (std::size_t k = begin; k < end; ++k)
          {
            const std::size_t p = static_cast<std::size_t>(connectivity[k]);
            if (3 * p + 2 >= points.size())
              return 0;
            // The serial node of this block at this point.
            std::size_t nearest  = serial.size();
            double      distance = 1e-6;
            for (std::size_t a = 0; a < serial.size(); ++a)
              if (static_cast<int>(serial[a].block) == block_id[c])
                {
                  const double d =
                    std::hypot(serial[a].position[0] - points[3 * p],
                               serial[a].position[1] - points[3 * p + 1]);
                  if (d <= distance)
                    {
                      distance = d;
                      nearest  = a;
                    }
                }
            if (nearest == serial.size())
              return 0;
            const auto &node = serial[nearest];
            if (!(std::abs(u[3 * p] - node.displacement[0]) <= 1e-6 * largest &&
                  std::abs(u[3 * p + 1] - node.displacement[1]) <=
                    1e-6 * largest &&
                  u[3 * p + 2] == 0))
              return 0;
            seen[nearest] = 1;
            ++compared;
          }
        begin = end;
      }
    return compared;
  }
} // namespace

int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const unsigned int                       rank    = mpi_test::rank_0_prints();
  const unsigned int                       n_ranks = mpi_test::n_ranks();

  const std::string wall = "subsection Masonry\n  set Geometry = running bond\n"
                           "  set Blocks per side = 5\nend\n";
  if (rank == 0)
    std::ofstream("wall.prm")
      << "set Scene = masonry\n"
         "subsection Output\n  set Directory = results\n"
         "  set Run name = wall\n  set Print timings = false\n"
         "  set Write VTU = true\nend\n"
      << wall;
  MPI_Barrier(MPI_COMM_WORLD);
  std::vector<std::string> arguments = {"unilateral", "wall.prm"};
  char              *arguments_c[] = {arguments[0].data(), arguments[1].data()};
  std::ostringstream out, err;
  const int code  = unilateral::run_application(2, arguments_c, out, err);
  const int worst = dealii::Utilities::MPI::max(code, MPI_COMM_WORLD);
  // The same wall in process, each rank alone (CHOLMOD, no VTU): the
  // serial answer the pieces must show. Every rank runs it (the scene's
  // summary gathers over the ranks), each into its own folder.
  const masonry_test::Run serial = masonry_test::run(
    masonry_test::parse(
      wall + "subsection Solver\n  set Factorisation = cholmod\nend\n"),
    "serial_" + std::to_string(rank));
  MPI_Barrier(MPI_COMM_WORLD);

  // Rank 1 cannot write its piece (a directory stands where it goes): the
  // run fails on every rank alike, and rank 0 still writes summary.json
  // with the error, naming rank 1 (a review: no summary.json was left, as
  // rank 0 waited for the others in a collective call until rank 1 ended
  // the run).
  if (rank == 0)
    {
      std::ofstream("blocked.prm")
        << "set Scene = masonry\n"
           "subsection Output\n  set Directory = results\n"
           "  set Run name = blocked\n  set Print timings = false\n"
           "  set Write VTU = true\nend\n"
        << wall;
      std::filesystem::create_directories("results/blocked/"
                                          "solution_000.1.vtu/occupied");
    }
  MPI_Barrier(MPI_COMM_WORLD);
  arguments                      = {"unilateral", "blocked.prm"};
  char              *blocked_c[] = {arguments[0].data(), arguments[1].data()};
  std::ostringstream blocked_out, blocked_err;
  const int          blocked_code =
    unilateral::run_application(2, blocked_c, blocked_out, blocked_err);
  const int fewest = dealii::Utilities::MPI::min(blocked_code, MPI_COMM_WORLD);
  const int most   = dealii::Utilities::MPI::max(blocked_code, MPI_COMM_WORLD);
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

  const auto nodes = serial.scene->nodal_displacements();
  std::cout << "serial run in process: converged: "
            << yes_no(serial.report.converged()) << ", nodes: " << nodes.size()
            << "\n";
  std::vector<char>  seen(nodes.size(), 0);
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
      const std::size_t compared = compare_piece(vtu, nodes, seen);
      std::cout << piece << ": named in the PVTU: "
                << yes_no(pvtu.find(piece) != std::string::npos)
                << ", blocks: " << blocks.size()
                << ", displacement as the serial run's (1e-6 max |u|) at "
                   "every point: "
                << yes_no(compared > 0) << " (" << compared
                << " cell vertices)\n";
    }
  std::cout << "every node of the serial run in a piece: "
            << yes_no(!seen.empty() &&
                      std::all_of(seen.begin(),
                                  seen.end(),
                                  [](const char s) { return s == 1; }))
            << "\n";
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
  const std::string blocked = read("results/blocked/summary.json");
  std::cout << "a piece rank 1 cannot write: exit code 1 on every rank: "
            << yes_no(fewest == 1 && most == 1)
            << ", summary.json with status error naming rank 1: "
            << yes_no(blocked.find("\"error\"") != std::string::npos &&
                      blocked.find("on rank 1: cannot write") !=
                        std::string::npos)
            << "\n";
}
