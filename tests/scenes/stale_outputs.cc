// A run starts by removing what an earlier run wrote into its directory,
// and nothing else, not even the user's own VTU files beside them (issue
// 21: two runs into the same directory mixed their
// files, and a masonry solution_000.vtu survived beside a plate
// summary.json). Three scenes run in turn into one directory; after each the
// directory holds that run's files, the user's own files and folders, and
// nothing of the earlier runs. A parameter file read from the run directory
// itself (a rerun from its copy, parameters.prm) is kept.
#include "../application_test_tools.h"

#include <filesystem>
#include <set>

using namespace application_test;
namespace fs = std::filesystem;

namespace
{
  const std::string output_block =
    "subsection Output\n  set Directory = results\n  set Run name = shared\n"
    "  set Print timings = false\n  set Progress = false\n";

  void
  list(const std::string &what, const Result &result)
  {
    std::set<std::string> names;
    for (const auto &entry : fs::directory_iterator("results/shared"))
      names.insert(entry.path().filename().string() +
                   (entry.is_directory() ? "/" : ""));
    std::cout << what << ": exit code " << result.code
              << ", error output empty: " << yes_no(result.err.empty())
              << "\n  results/shared holds:";
    for (const std::string &name : names)
      std::cout << " " << name;
    std::cout << "\n";
  }
} // namespace

int
main()
{
  fs::remove_all("results");
  fs::create_directories("results/shared/pictures");
  write("results/shared/notes.md", "the user's own notes\n");
  write("results/shared/my_model.vtu", "the user's own VTU, kept\n");
  write("results/shared/pictures/solution_000.vtu", "a copy, kept\n");

  write("A.mtx",
        "%%MatrixMarket matrix coordinate real symmetric\n2 2 3\n"
        "1 1 2\n2 1 -1\n2 2 2\n");
  write("b.txt", "1\n-2\n");
  write("c.txt", "1 0\n2 0\n");
  write("lcp.prm",
        "set Scene = lcp\n" + output_block +
          "end\nsubsection LCP\n  set Matrix file = A.mtx\n"
          "  set Right-hand side file = b.txt\n"
          "  set Constraints file = c.txt\nend\n");
  list("the lcp scene", run({"lcp.prm"}));

  write("masonry.prm",
        "set Scene = masonry\n" + output_block +
          "  set Export LCP = true\n  set Write solution = true\nend\n"
          "subsection Masonry\n  set Blocks per side = 2\nend\n");
  list("then the masonry scene with VTU, the LCP and its solution",
       run({"masonry.prm"}));

  write("plate.prm",
        "set Scene = plate\n" + output_block +
          "end\nsubsection Plate\n  subsection Geometry\n"
          "    set Elements x = 8\n    set Elements y = 8\n  end\nend\n");
  list("then the plate scene", run({"plate.prm"}));

  // Rerun from the copy the run made of its parameter file: the directory
  // is given absolutely, so that the copy names the same run directory.
  write("rerun.prm",
        "set Scene = masonry\nsubsection Output\n  set Directory = " +
          fs::absolute("results").string() +
          "\n  set Run name = shared\n  set Write VTU = false\n"
          "  set Print timings = false\n  set Progress = false\nend\n"
          "subsection Masonry\n  set Blocks per side = 2\nend\n");
  list("then masonry from rerun.prm", run({"rerun.prm"}));
  list("then masonry from its copy results/shared/parameters.prm",
       run({"results/shared/parameters.prm"}));
}
