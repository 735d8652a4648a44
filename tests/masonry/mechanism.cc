// Answers whose displacements are one member of a family (masonry/
// mechanism.h): blocks that can move against each other along closed
// joints while the loads do no work. Independent truth: a second exact
// method (the interior point, whose path ends elsewhere in the family)
// gives the same energy to 1e-10 but other displacements.
//  - the arch of prm/ with the right end's displacement prescribed (a
//    review: two mirror-image spandrel blocks slide past each other on
//    their radial joints; PDAS said nothing, and the same structure moved
//    by (1e5, 1e5) gave a max displacement 14 % larger);
//  - the barrel vault of prm/ as shipped (its crown blocks likewise);
//  - a block on rollers in a slot with a clearance of 1e-4 on either
//    side: it may rest anywhere between the walls; an answer that closes
//    a side contact (without force) says so by its degenerate contacts,
//    which every contact force being round-off once hid (a review);
//  - the arch as shipped and a stack bond wall: no such note (every block
//    held), and both methods give one displacement.
#include "../application_test_tools.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

using namespace application_test;

namespace
{
  const std::string prm_folder = SOURCE_DIR "/../../prm";

  std::vector<double>
  numbers(const std::string &file_name)
  {
    std::istringstream  in(read(file_name));
    std::vector<double> result;
    for (std::string line; std::getline(in, line);)
      if (!line.empty() && line[0] != '#')
        result.push_back(std::stod(line));
    return result;
  }

  struct Answer
  {
    int                 code       = -1;
    bool                noted      = false;
    bool                degenerate = false;
    double              energy     = 0;
    std::vector<double> u;
  };

  Result
  run_prm(const std::string &run)
  {
    return application_test::run({run + ".prm"});
  }

  /// @p parameters with @p method, writing u.txt into results/@p name.
  Answer
  solve(const std::string &name,
        const std::string &parameters,
        const std::string &method)
  {
    const std::string run = name + "_" + method;
    write(run + ".prm",
          parameters + "\nsubsection Solver\n  set Method = " + method +
            "\nend\nsubsection Output\n  set Directory = results\n"
            "  set Run name = " +
            run +
            "\n  set Print timings = false\n  set Progress = false\n"
            "  set Write VTU = false\n  set Write solution = true\nend\n");
    const Result result = run_prm(run);
    Answer       answer;
    answer.code = result.code;
    answer.noted =
      result.out.find("one answer of a family") != std::string::npos;
    const std::string json = read("results/" + run + "/summary.json");
    answer.energy          = number(json, "energy");
    answer.degenerate      = number(json, "n_degenerate_contacts") > 0;
    answer.u               = numbers("results/" + run + "/u.txt");
    return answer;
  }

  void
  compare(const std::string &what,
          const std::string &name,
          const std::string &parameters)
  {
    const Answer pdas    = solve(name, parameters, "pdas");
    const Answer ip      = solve(name, parameters, "interior_point");
    double       largest = 0, difference = 0;
    for (std::size_t i = 0; i < std::min(pdas.u.size(), ip.u.size()); ++i)
      {
        largest    = std::max(largest, std::abs(pdas.u[i]));
        difference = std::max(difference, std::abs(pdas.u[i] - ip.u[i]));
      }
    std::cout << what << ": exit codes " << pdas.code << " and " << ip.code
              << "; PDAS notes a family: " << yes_no(pdas.noted)
              << "; the interior point's answer notes one or degenerate "
                 "contacts: "
              << yes_no(ip.noted || ip.degenerate)
              << "; the interior point's energy (1e-10): "
              << yes_no(std::abs(pdas.energy - ip.energy) <=
                        1e-10 * std::abs(ip.energy))
              << "; its displacements differ by more than 1e-6 of the "
                 "largest: "
              << yes_no(!pdas.u.empty() && pdas.u.size() == ip.u.size() &&
                        difference > 1e-6 * largest)
              << "\n";
  }

  std::string
  shipped(const std::string &file)
  {
    return std::regex_replace(read(prm_folder + "/" + file),
                              std::regex("meshes/"),
                              prm_folder + "/meshes/");
  }
} // namespace

int
main()
{
  compare("the arch with the right end's displacement prescribed",
          "arch_prescribed",
          shipped("masonry_arch.prm") +
            "\nsubsection Masonry\n  subsection Boundary conditions\n"
            "    set Prescribed displacement boundaries = right\n"
            "    set Prescribed displacement = 0.003 * y; -0.001 * (1 + y)\n"
            "    set Normal displacement zero = left, base where x < 0\n"
            "  end\nend\n");
  compare("the barrel vault as shipped",
          "barrel_vault",
          shipped("masonry_barrel_vault.prm"));
  write("slot.msh",
        "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n3\n"
        "1 101 \"base\"\n1 102 \"left\"\n1 103 \"right\"\n"
        "$EndPhysicalNames\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 1 1 0\n"
        "4 0 1 0\n$EndNodes\n$Elements\n4\n1 1 2 101 101 1 2\n"
        "2 1 2 102 102 4 1\n3 1 2 103 103 2 3\n4 3 2 1 1 1 2 3 4\n"
        "$EndElements\n");
  compare("a block on rollers in a slot",
          "slot",
          "set Scene = masonry\nsubsection Masonry\n"
          "  set Geometry = mesh file\n  set Mesh file = slot.msh\n"
          "  subsection Boundary conditions\n"
          "    set Normal displacement zero = base\n"
          "    set Signorini = left, right\n    set Signorini gap = 1e-4\n"
          "    set Traction boundaries =\n  end\n"
          "  subsection Materials\n    set Poisson's ratio = 0\n  end\n"
          "end\n");
  compare("the arch as shipped", "arch", shipped("masonry_arch.prm"));
  compare("stack bond m = 6",
          "stack_bond",
          "set Scene = masonry\nsubsection Masonry\n"
          "  set Blocks per side = 6\nend\n");
}
