// What ParaView will see: run the application on a paper configuration
// (Table 4, steel, psi3, f2, 10 x 10), read plate.vtu, nodes.vtu and their
// PVD records back with VTK's own XML reader (read_plate_vtu.py, Debian's
// python3-vtk9 under /usr/bin/python3) and check the fields against
// summary.json. Also: without an obstacle no obstacle/gap fields are
// written, and Write VTU = false writes no VTU or PVD at all.

#include <unilateral/application.h>

#include "../test_tools.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

using test_tools::verdict;

namespace
{
  int
  run(const std::string &name, const std::string &plate, const bool write_vtu)
  {
    const std::string prm = name + ".prm";
    std::filesystem::remove_all("results/" + name);
    std::ofstream(prm) << "set Scene = plate\n"
                       << "subsection Output\n"
                       << "  set Directory = results\n"
                       << "  set Print timings = false\n"
                       << "  set Progress = false\n"
                       << "  set Write VTU = " << (write_vtu ? "true" : "false")
                       << "\nend\n"
                       << "subsection Solver\n  set Method = pdas\nend\n"
                       << "subsection Plate\n"
                       << plate << "end\n";
    std::ostringstream out, err;
    std::string        program = "unilateral", file = prm;
    char              *argv[] = {program.data(), file.data()};
    const int          code   = unilateral::run_application(2, argv, out, err);
    std::cout << name << ": exit code " << code << err.str() << std::endl;
    return code;
  }

  // Run the reader, print its verdicts, return whether all were "yes".
  bool
  read_back(const std::string &directory)
  {
    const std::string command = "/usr/bin/python3 " SOURCE_DIR
                                "/read_plate_vtu.py " +
                                directory + " 2>&1";
    FILE *pipe = popen(command.c_str(), "r");
    if (pipe == nullptr)
      return false;
    std::string text;
    char        buffer[4096];
    while (fgets(buffer, sizeof buffer, pipe) != nullptr)
      text += buffer;
    const int status = pclose(pipe);
    std::cout << text;
    return status == 0 && text.find(": no") == std::string::npos &&
           !text.empty();
  }
} // namespace

int
main()
{
  const std::string paper =
    "subsection Geometry\n  set Elements x = 10\n  set Elements y = 10\nend\n"
    "subsection Material\n  set Name = steel\nend\n"
    "subsection Obstacle\n  set Function = psi3\nend\n"
    "subsection Load\n  set Force = f2\nend\n"
    "subsection Output\n  set Subdivisions = 4\nend\n";
  run("table4_steel_psi3_f2_10", paper, true);
  verdict("every check of read_plate_vtu.py passed",
          read_back("results/table4_steel_psi3_f2_10"));

  run("no_obstacle", "subsection Obstacle\n  set Function = none\nend\n", true);
  {
    std::ifstream     file("results/no_obstacle/plate.vtu");
    std::stringstream text;
    text << file.rdbuf();
    const std::string vtu = text.str();
    verdict("without an obstacle plate.vtu has deflection and moments but no "
            "obstacle or gap",
            vtu.find("Name=\"deflection\"") != std::string::npos &&
              vtu.find("Name=\"bending_moment_xx\"") != std::string::npos &&
              vtu.find("Name=\"obstacle\"") == std::string::npos &&
              vtu.find("Name=\"gap\"") == std::string::npos);
  }

  run("no_vtu", paper, false);
  bool none_written = std::filesystem::exists("results/no_vtu/summary.json");
  for (const auto &entry :
       std::filesystem::directory_iterator("results/no_vtu"))
    none_written = none_written && entry.path().extension() != ".vtu" &&
                   entry.path().extension() != ".pvd";
  verdict("Write VTU = false writes summary.json but no VTU or PVD file",
          none_written);
}
