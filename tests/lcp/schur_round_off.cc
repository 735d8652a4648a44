// A review's semidefinite LCP of rank 3 (7 unknowns, 4 constrained) whose
// solutions all have the energy -4.9847 (enumeration of its active sets),
// through the lcp scene as a user runs it. A_EE holds all of A's rank, so
// the Schur complement on the constrained unknowns and its right-hand side
// are zero up to round-off: PDAS proved from them that the reduced LCP has
// no solution, and every method on the Schur complement ended 'infeasible'
// (exit 2), although u recovered from its iterate solved the full LCP. A
// failure of the reduced problem is now judged on the full one.
#include "../application_test_tools.h"

using namespace application_test;

int
main()
{
  write("A.mtx",
        "%%MatrixMarket matrix coordinate real general\n7 7 37\n"
        "1 1 3\n1 4 -3\n1 5 -3\n1 6 4\n1 7 1\n2 2 6\n2 5 -3\n2 6 2\n"
        "2 7 -1\n3 3 2\n3 4 -2\n3 5 1\n3 7 1\n4 1 -3\n4 3 -2\n4 4 5\n"
        "4 5 2\n4 6 -4\n4 7 -2\n5 1 -3\n5 2 -3\n5 3 1\n5 4 2\n5 5 5\n"
        "5 6 -5\n6 1 4\n6 2 2\n6 4 -4\n6 5 -5\n6 6 6\n6 7 1\n7 1 1\n"
        "7 2 -1\n7 3 1\n7 4 -2\n7 6 1\n7 7 1\n");
  write("b.txt",
        "5.3199999999999994\n1.46\n-0.59999999999999964\n"
        "-4.7200000000000006\n-6.3499999999999996\n7.5800000000000001\n"
        "1.23\n");
  write("c.txt",
        "3 -0.94999999999999996\n5 -0.57999999999999996\n6 0\n"
        "7 -2.3199999999999998\n");
  for (const std::string method : {"pdas", "graves", "lssnn", "pdpc"})
    for (const bool schur : {false, true})
      {
        if (!schur && method == "graves")
          continue; // Graves needs the Schur complement
        const std::string name = method + (schur ? "_sc" : "");
        write(name + ".prm",
              "set Scene = lcp\nsubsection Output\n"
              "  set Directory = results\n  set Print timings = false\n"
              "  set Progress = false\nend\nsubsection LCP\n"
              "  set Matrix file = A.mtx\n  set Right-hand side file = b.txt\n"
              "  set Constraints file = c.txt\nend\nsubsection Solver\n"
              "  set Method = " +
                method + "\n  set Schur complement = " +
                (schur ? "true" : "false") + "\nend\n");
        const Result      result  = run({name + ".prm"});
        const std::string summary = read("results/" + name + "/summary.json");
        std::cout << name << ": exit code " << result.code
                  << ", energy -4.9847 to 1e-10: "
                  << yes_no(std::abs(number(summary, "energy") + 4.9847) <=
                            1e-10 * 4.9847)
                  << "\n";
      }
}
