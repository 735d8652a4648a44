// A review's semidefinite LCP of rank 3 (7 unknowns, 4 constrained) whose
// solutions all have the energy -4.9847 (enumeration of its active sets),
// through the lcp scene as a user runs it. A_EE holds all of A's rank, so
// the Schur complement on the constrained unknowns and its right-hand side
// are zero up to round-off: PDAS proved from them that the reduced LCP has
// no solution, and every method on the Schur complement ended 'infeasible'
// (exit 2), although u recovered from its iterate solved the full LCP. A
// failure of the reduced problem is now judged on the full one. The
// review's rank-3 LCP of 8 unknowns (5 constrained, energy -13.197944709380
// by enumeration): PDPC on its Schur complement meets a singular Newton
// system and PDAS, which verifies that claim, solves the reduced problem;
// the check of each contact against its own row refused PDAS's answer
// there (the reduced entries are round-off) until it left Schur
// complements to the full problem's judgement. And a free pair pulled
// apart beside a heavily loaded part, which has no solution.
#include "../application_test_tools.h"

using namespace application_test;

namespace
{
  /// Every method that takes it, on the full LCP and on its Schur
  /// complement: exit code and whether the energy is @p energy to 1e-10.
  void
  run_methods(const std::string &name, const double energy)
  {
    for (const std::string method : {"pdas", "graves", "lssnn", "pdpc"})
      for (const bool schur : {false, true})
        {
          if (!schur && method == "graves")
            continue; // Graves needs the Schur complement
          const std::string case_name =
            name + "_" + method + (schur ? "_sc" : "");
          write(case_name + ".prm",
                "set Scene = lcp\nsubsection Output\n"
                "  set Directory = results\n  set Print timings = false\n"
                "  set Progress = false\nend\nsubsection LCP\n"
                "  set Matrix file = " +
                  name +
                  "_A.mtx\n"
                  "  set Right-hand side file = " +
                  name +
                  "_b.txt\n"
                  "  set Constraints file = " +
                  name +
                  "_c.txt\nend\n"
                  "subsection Solver\n  set Method = " +
                  method + "\n  set Schur complement = " +
                  (schur ? "true" : "false") + "\nend\n");
          const Result      result = run({case_name + ".prm"});
          const std::string summary =
            read("results/" + case_name + "/summary.json");
          std::cout << case_name << ": exit code " << result.code << ", energy "
                    << energy << " to 1e-10: "
                    << yes_no(std::abs(number(summary, "energy") - energy) <=
                              1e-10 * std::abs(energy))
                    << "\n";
        }
  }
} // namespace

int
main()
{
  write("r3_A.mtx",
        "%%MatrixMarket matrix coordinate real general\n7 7 37\n"
        "1 1 3\n1 4 -3\n1 5 -3\n1 6 4\n1 7 1\n2 2 6\n2 5 -3\n2 6 2\n"
        "2 7 -1\n3 3 2\n3 4 -2\n3 5 1\n3 7 1\n4 1 -3\n4 3 -2\n4 4 5\n"
        "4 5 2\n4 6 -4\n4 7 -2\n5 1 -3\n5 2 -3\n5 3 1\n5 4 2\n5 5 5\n"
        "5 6 -5\n6 1 4\n6 2 2\n6 4 -4\n6 5 -5\n6 6 6\n6 7 1\n7 1 1\n"
        "7 2 -1\n7 3 1\n7 4 -2\n7 6 1\n7 7 1\n");
  write("r3_b.txt",
        "5.3199999999999994\n1.46\n-0.59999999999999964\n"
        "-4.7200000000000006\n-6.3499999999999996\n7.5800000000000001\n"
        "1.23\n");
  write("r3_c.txt",
        "3 -0.94999999999999996\n5 -0.57999999999999996\n6 0\n"
        "7 -2.3199999999999998\n");
  run_methods("r3", -4.9847);
  write("r8_A.mtx",
        "%%MatrixMarket matrix coordinate real general\n"
        "8 8 64\n"
        "1 1 6.4046504044443244\n"
        "1 2 -0.61889819699159609\n"
        "1 3 0.83147632796476556\n"
        "1 4 0.42007056245795071\n"
        "1 5 0.46835569647582992\n"
        "1 6 -0.34388860063069104\n"
        "1 7 -0.34022516920591839\n"
        "1 8 2.1253617882137696\n"
        "2 1 -0.61889819699159609\n"
        "2 2 4.6539622289099345\n"
        "2 3 1.894603676718335\n"
        "2 4 1.5110139645625371\n"
        "2 5 -0.87280355409451482\n"
        "2 6 0.24536629065461793\n"
        "2 7 -0.70424759090610001\n"
        "2 8 1.3935392244982818\n"
        "3 1 0.83147632796476556\n"
        "3 2 1.894603676718335\n"
        "3 3 0.98457580861593907\n"
        "3 4 0.85122650538524391\n"
        "3 5 -0.4300911666383096\n"
        "3 6 0.18096074315689833\n"
        "3 7 -0.55795672869951374\n"
        "3 8 0.93101668946904648\n"
        "4 1 0.42007056245795071\n"
        "4 2 1.5110139645625371\n"
        "4 3 0.85122650538524391\n"
        "4 4 1.1602086500538329\n"
        "4 5 -0.88304840139257113\n"
        "4 6 0.67991796454030207\n"
        "4 7 -1.1954109496963605\n"
        "4 8 0.52803200749318691\n"
        "5 1 0.46835569647582992\n"
        "5 2 -0.87280355409451482\n"
        "5 3 -0.4300911666383096\n"
        "5 4 -0.88304840139257113\n"
        "5 5 0.84432358207735503\n"
        "5 6 -0.72077379573613121\n"
        "5 7 1.0709905549571395\n"
        "5 8 0.025166491745604442\n"
        "6 1 -0.34388860063069104\n"
        "6 2 0.24536629065461793\n"
        "6 3 0.18096074315689833\n"
        "6 4 0.67991796454030207\n"
        "6 5 -0.72077379573613121\n"
        "6 6 0.68209955850768367\n"
        "6 7 -0.97362437854783501\n"
        "6 8 -0.19718766349298669\n"
        "7 1 -0.34022516920591839\n"
        "7 2 -0.70424759090610001\n"
        "7 3 -0.55795672869951374\n"
        "7 4 -1.1954109496963605\n"
        "7 5 1.0709905549571395\n"
        "7 6 -0.97362437854783501\n"
        "7 7 1.539573462240267\n"
        "7 8 -0.13959314074192467\n"
        "8 1 2.1253617882137696\n"
        "8 2 1.3935392244982818\n"
        "8 3 0.93101668946904648\n"
        "8 4 0.52803200749318691\n"
        "8 5 0.025166491745604442\n"
        "8 6 -0.19718766349298669\n"
        "8 7 -0.13959314074192467\n"
        "8 8 1.2994213780997208\n");
  write("r8_b.txt",
        "14.714479400096454\n"
        "0.39238469624171046\n"
        "2.8093215327693413\n"
        "2.1368138363750062\n"
        "0.16669888650762021\n"
        "-0.12693923434125143\n"
        "-1.9214990367075346\n"
        "2.9753546832732849\n");
  write("r8_c.txt",
        "1 0.71999999999999997\n"
        "3 0.28000000000000003\n"
        "4 0.87\n"
        "7 -0.41999999999999998\n"
        "8 1.8\n");
  run_methods("r8", -13.197944709380);

  // No solution: a free pair pulled apart by 1e-3 beside a part loaded
  // 1e10 (a review). The reduced load, 1e-3, is not the rounding of its
  // terms (about 2), however small beside the largest load: the Schur
  // complement's 'infeasible' stands (it was rescued as 'converged', the
  // pair 4.5e12 away, while the rescue compared q with the largest load).
  write("pair_A.mtx",
        "%%MatrixMarket matrix coordinate real general\n3 3 5\n"
        "1 1 1\n1 2 -1\n2 1 -1\n2 2 1\n3 3 1\n");
  write("pair_b.txt", "-1\n1.001\n1e10\n");
  write("pair_c.txt", "1 0\n");
  for (const std::string method : {"pdas", "graves", "lssnn", "pdpc"})
    {
      write("pair_" + method + ".prm",
            "set Scene = lcp\nsubsection Output\n"
            "  set Directory = results\n  set Print timings = false\n"
            "  set Progress = false\nend\nsubsection LCP\n"
            "  set Matrix file = pair_A.mtx\n"
            "  set Right-hand side file = pair_b.txt\n"
            "  set Constraints file = pair_c.txt\nend\n"
            "subsection Solver\n  set Method = " +
              method + "\n  set Schur complement = true\nend\n");
      const Result result = run({"pair_" + method + ".prm"});
      std::cout << "no solution, " << method
                << " on the Schur complement: exit code " << result.code
                << ", said infeasible: "
                << yes_no(read("results/pair_" + method + "/summary.json")
                            .find("\"status\": \"infeasible\"") !=
                          std::string::npos)
                << "\n";
    }
}
