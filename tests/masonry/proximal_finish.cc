// Three 2 x 1 blocks stacked, each shifted right by 7/12 of the one below
// (meshes/offset_blocks.msh, 24 x 6 Q2 cells each), on a Signorini base,
// only the lowest held sideways: the upper two may slide on their bed
// joints, so the displacements form a family and the projection after the
// interior point and PDPC ends with the proximal point finish. That finish
// stopped once its KKT residual passed the tolerance (2.8e-11): the
// reactions were 1e-7 off the loads and the contact forces 3e-6 off PDAS's
// (a review, 2026-11-30), a residual of one sign over each block summed
// by its resultant. Independent truth: statics (the reactions balance the
// weight) and PDAS, whose projection is exact here. Now the finish
// polishes to 1e-4 of the tolerance: statics to 1e-8 of the weight, and
// the contact forces to 1e-6 of PDAS's largest.
#include "../application_test_tools.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

using namespace application_test;

namespace
{
  struct Answer
  {
    int                 code   = -1;
    double              energy = 0, force_imbalance = 1, moment_imbalance = 1;
    std::vector<double> contact_forces;
  };

  Answer
  solve(const std::string &method)
  {
    write(method + ".prm",
          "set Scene = masonry\nsubsection Masonry\n"
          "  set Geometry = mesh file\n"
          "  set Mesh file = " SOURCE_DIR "/meshes/offset_blocks.msh\n"
          "  subsection Boundary conditions\n"
          "    set Normal displacement zero = left\n"
          "    set Signorini = base\n    set Signorini gap = 0\n"
          "    set Traction boundaries =\n  end\n"
          "  subsection Materials\n    set Poisson's ratio = 0.2\n  end\n"
          "end\nsubsection Solver\n  set Method = " +
            method +
            "\nend\nsubsection Output\n  set Directory = results\n"
            "  set Run name = " +
            method +
            "\n  set Print timings = false\n  set Progress = false\n"
            "  set Write VTU = false\n  set Write solution = true\n"
            "  set Export LCP = true\nend\n");
    const Result result = run({method + ".prm"});
    Answer       answer;
    answer.code              = result.code;
    const std::string folder = "results/" + method + "/";
    const std::string json   = read(folder + "summary.json");
    answer.energy            = number(json, "energy");
    answer.force_imbalance   = number(json, "force_imbalance");
    answer.moment_imbalance  = number(json, "moment_imbalance");
    // lambda.txt: one multiplier per LCP unknown; lcp_constraints.txt: the
    // constrained unknowns (1-based) first on each line.
    std::vector<double> lambda;
    std::ifstream       lambda_file(folder + "lambda.txt");
    for (std::string line; std::getline(lambda_file, line);)
      if (!line.empty() && line[0] != '#')
        lambda.push_back(std::stod(line));
    std::ifstream constraints(folder + "lcp_constraints.txt");
    for (std::string line; std::getline(constraints, line);)
      if (!line.empty() && line[0] != '#')
        answer.contact_forces.push_back(
          lambda.at(std::stoul(line.substr(0, line.find_first_of(" \t"))) - 1));
    return answer;
  }
} // namespace

int
main()
{
  const Answer pdas = solve("pdas");
  const double largest =
    *std::max_element(pdas.contact_forces.begin(), pdas.contact_forces.end());
  std::cout << "pdas: exit code " << pdas.code << ", statics to 1e-8: "
            << yes_no(pdas.force_imbalance <= 1e-8 &&
                      pdas.moment_imbalance <= 1e-8)
            << ", " << pdas.contact_forces.size() << " contacts\n";
  for (const std::string method : {"interior_point", "pdpc"})
    {
      const Answer answer = solve(method);
      double       off =
        answer.contact_forces.size() == pdas.contact_forces.size() ? 0 : 1;
      for (std::size_t k = 0; k < std::min(answer.contact_forces.size(),
                                           pdas.contact_forces.size());
           ++k)
        off =
          std::max(off,
                   std::abs(answer.contact_forces[k] - pdas.contact_forces[k]) /
                     largest);
      std::cout << method << ": exit code " << answer.code
                << ", statics to 1e-8: "
                << yes_no(answer.force_imbalance <= 1e-8 &&
                          answer.moment_imbalance <= 1e-8)
                << ", PDAS's energy to 1e-10: "
                << yes_no(std::abs(answer.energy - pdas.energy) <=
                          1e-10 * std::abs(pdas.energy))
                << ", PDAS's contact forces to 1e-6: " << yes_no(off <= 1e-6)
                << "\n";
    }
}
