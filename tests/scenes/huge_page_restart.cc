// The executable restarts itself with glibc's huge pages only for a run
// large enough to gain from them (issue 21: every start, --help included,
// paid for the restart, half of the 1 s that --help took). run_application
// calls its before_large_run hook once the parameter file is read and the
// scene built, before anything is printed or written, and only then; here
// the hook throws, as a restart would leave, so that the large runs stop at
// once. Never for --help, --print-parameters, bad arguments or bad input;
// never for a small run.
#include "../application_test_tools.h"

#include <filesystem>
#include <stdexcept>

using namespace application_test;
namespace fs = std::filesystem;

namespace
{
  // Run @p arguments with a hook; say whether it was called, and for a
  // parameter file whether anything was written or printed before.
  void
  check(const std::string              &what,
        const std::vector<std::string> &arguments,
        const bool                      expected)
  {
    bool         called = false;
    const Result result = run(arguments, [&]() {
      called = true;
      throw std::runtime_error("restarting");
    });
    std::cout << what << ": restart "
              << (called ? "requested" : "not requested") << ": "
              << yes_no(called == expected);
    if (called)
      std::cout << ", nothing printed or written before: "
                << yes_no(result.out.empty() && !fs::exists("results"));
    std::cout << "\n";
  }

  std::string
  masonry(const unsigned int m, const unsigned int r)
  {
    const std::string file =
      "masonry_" + std::to_string(m) + "_" + std::to_string(r) + ".prm";
    write(file,
          "set Scene = masonry\nsubsection Output\n"
          "  set Directory = results\n  set Write VTU = false\n"
          "  set Print timings = false\n  set Progress = false\nend\n"
          "subsection Masonry\n  set Blocks per side = " +
            std::to_string(m) + "\n  set Refinement = " + std::to_string(r) +
            "\nend\n");
    return file;
  }

  std::string
  plate(const unsigned int n1, const unsigned int n2)
  {
    const std::string file =
      "plate_" + std::to_string(n1) + "_" + std::to_string(n2) + ".prm";
    write(file,
          "set Scene = plate\nsubsection Output\n"
          "  set Directory = results\n  set Write VTU = false\n"
          "  set Print timings = false\n  set Progress = false\nend\n"
          "subsection Plate\n  subsection Geometry\n    set Elements x = " +
            std::to_string(n1) +
            "\n    set Elements y = " + std::to_string(n2) + "\n  end\nend\n");
    return file;
  }

  std::string
  lcp(const std::string &matrix)
  {
    write(matrix + ".prm",
          "set Scene = lcp\nsubsection Output\n"
          "  set Directory = results\n  set Print timings = false\n"
          "  set Progress = false\nend\n"
          "subsection LCP\n  set Matrix file = " +
            matrix +
            "\n  set Right-hand side file = b.txt\n"
            "  set Constraints file = c.txt\nend\n");
    return matrix + ".prm";
  }
} // namespace

int
main()
{
  check("--help", {"--help"}, false);
  check("--print-parameters json", {"--print-parameters", "json"}, false);
  check("an unknown option", {"--frobnicate"}, false);
  check("a missing parameter file", {"missing.prm"}, false);
  check("m = 0 (refused by the scene)", {masonry(0, 0)}, false);

  check("masonry m = 2", {masonry(2, 0)}, false);
  fs::remove_all("results");
  check("masonry m = 100", {masonry(100, 0)}, true);
  check("masonry m = 50, r = 1", {masonry(50, 1)}, true);
  check("plate 128 x 128", {plate(128, 128)}, true);
  check("plate 8 x 8", {plate(8, 8)}, false);
  fs::remove_all("results");

  write("small.mtx",
        "%%MatrixMarket matrix coordinate real symmetric\n1 1 1\n1 1 2\n");
  write("b.txt", "1\n");
  write("c.txt", "1 0\n");
  check("an LCP from a small file", {lcp("small.mtx")}, false);
  fs::remove_all("results");
  {
    // A sparse file of 20 MB: the hook runs before the file is read.
    std::ofstream large("large.mtx");
    large.seekp(20000000);
    large << '\n';
  }
  check("an LCP from a 20 MB file", {lcp("large.mtx")}, true);
}
