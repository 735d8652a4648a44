// Every failure mode is reported, never hidden: iteration limits, an LCP
// without solution (Graves proves it), singular reduced systems, and bad
// input, which must give one line naming the problem and a nonzero exit code.
#include <unilateral/application.h>

#include "../lcp_test_tools.h"

#include <fstream>
#include <sstream>

using namespace test;

namespace
{
  void
  report_solver(const std::string &what, const Report &report)
  {
    std::cout << what << ": status " << to_string(report.status)
              << ", converged " << yes_no(report.converged()) << "\n";
    if (!report.message.empty())
      std::cout << "  " << report.message << "\n";
  }

  // A membrane on a line: -u'' = -1 on 40 nodes with u >= -0.05; PDAS needs
  // several active-set changes.
  Problem
  chain()
  {
    const Index n = 40;
    DenseMatrix A = DenseMatrix::Zero(n, n);
    for (Index i = 0; i < n; ++i)
      {
        A(i, i) = 2;
        if (i > 0)
          A(i, i - 1) = A(i - 1, i) = -1;
      }
    std::vector<Index>  S(n);
    std::vector<double> lower(n, -0.05 * n * n);
    for (Index i = 0; i < n; ++i)
      S[i] = i;
    return make_problem(A, Vector::Constant(n, -1.0), S, lower);
  }

  void
  write(const std::string &file_name, const std::string &text)
  {
    std::ofstream(file_name) << text;
  }

  // Run the application as a user would and show what they would see.
  void
  run(const std::string &what, const std::vector<std::string> &arguments)
  {
    std::vector<std::string> storage = {"unilateral"};
    storage.insert(storage.end(), arguments.begin(), arguments.end());
    std::vector<char *> argv;
    for (auto &argument : storage)
      argv.push_back(argument.data());
    std::ostringstream out, err;
    const int code = unilateral::run_application(static_cast<int>(argv.size()),
                                                 argv.data(),
                                                 out,
                                                 err);
    const std::string message = err.str();
    const auto        lines = std::count(message.begin(), message.end(), '\n');
    if (code == 0)
      std::cout << what << ": exit code 0, error output empty: "
                << yes_no(message.empty()) << "\n";
    else
      std::cout << what << ": exit code " << code
                << ", one line: " << yes_no(lines == 1) << "\n  " << message;
  }

  void
  write_lcp_prm(const std::string &name,
                const std::string &matrix,
                const std::string &rhs,
                const std::string &solver_lines = "")
  {
    write(name + ".prm",
          "set Scene = lcp\n"
          "subsection Output\n  set Directory = results\n"
          "  set Print timings = false\n  set Progress = false\nend\n"
          "subsection LCP\n  set Matrix file = " +
            matrix + "\n  set Right-hand side file = " + rhs +
            "\n  set Constraints file = c.txt\nend\n"
            "subsection Solver\n" +
            solver_lines + "end\n");
  }
} // namespace

int
main()
{
  // Iteration limits.
  {
    const Problem    problem = chain();
    SolverParameters parameters;
    parameters.max_iterations = 2;
    Vector u;
    // The paper's PDAS (no safeguards: the exact resolution of the front
    // would finish this chain within the limit).
    SolverParameters plain_pdas = parameters;
    plain_pdas.set("PDAS/Safeguard", "0");
    report_solver("pdas without safeguards limited to 2 iterations",
                  solve_with(problem, method("pdas"), u, -1, plain_pdas));
    report_solver("psor limited to 2 sweeps",
                  solve_with(problem, method("psor"), u, -1, parameters));
    report_solver(
      "block_pivoting limited to 2 iterations",
      solve_with(problem, method("block_pivoting"), u, -1, parameters));
    report_solver("pdas without limit", solve_with(problem, method("pdas"), u));
  }

  // LCPs without a solution: Graves says so.
  {
    DenseMatrix A(1, 1);
    A << 0;
    Vector b(1);
    b << 1; // lambda = -1 whatever u is
    Vector u;
    report_solver("graves, A = 0, b = 1",
                  solve_with(make_problem(A, b, {0}, {0}),
                             method("graves"),
                             u));
    DenseMatrix A2(2, 2);
    A2 << 1, -1, -1, 1;
    Vector b2(2);
    b2 << 1, 1; // lambda_1 + lambda_2 = -2 < 0 always
    report_solver("graves, lambda_1 + lambda_2 = -2",
                  solve_with(make_problem(A2, b2, {0, 1}, {0, 0}),
                             method("graves"),
                             u));
  }

  // LCPs without a solution, proved by PDAS itself: the free motion of a
  // singular system along which the loads do work and no bound resists
  // (before, a review's Neumann chain of 1000 nodes took 10 s of exact
  // resolutions and Graves' dense pivoting to say so, of 4000 over 90 s).
  // Truth: the chain's A has the constant vector as its null space, so
  // b = 1/n > 0 with u >= 0 has none, b = -1/n has u = 0, and a spring at
  // one end holds it (a solution exists, however far away).
  {
    const Index n     = 2000;
    const auto  chain = [n](const double spring, const double load) {
      DenseMatrix A = DenseMatrix::Zero(n, n);
      for (Index i = 0; i + 1 < n; ++i)
        {
          A(i, i) += 1;
          A(i + 1, i + 1) += 1;
          A(i, i + 1) = A(i + 1, i) = -1;
        }
      A(0, 0) += spring;
      std::vector<Index> S(n);
      for (Index i = 0; i < n; ++i)
        S[i] = i;
      return make_problem(A,
                          Vector::Constant(n, load / n),
                          S,
                          std::vector<double>(n, 0.0));
    };
    Vector       u;
    const Report pushed = solve_with(chain(0, 1), method("pdas"), u, 0);
    report_solver("pdas, a free chain pushed off its bounds", pushed);
    std::cout << "  proved at once (no exact resolution, no verification): "
              << yes_no(pushed.status == Status::infeasible &&
                        pushed.counters.resolved_subsets == 0)
              << "\n";
    const Report pressed = solve_with(chain(0, -1), method("pdas"), u, 0);
    std::cout << "pdas, the free chain pressed onto its bounds: status "
              << to_string(pressed.status)
              << ", u = 0: " << yes_no(u.size() == n && u.isZero(0)) << "\n";
    // Held by a spring, the chain has a solution, however far: no proof.
    // Of 1e-2, PDAS finds it; of 4e-10 (a stiffness along the motion of
    // 1e-13 of A's diagonal along it, a hundred times the proof's bound) it is
    // beyond double precision, and PDAS must not claim there is none.
    const Report held = solve_with(chain(1e-2, 1), method("pdas"), u);
    std::cout << "pdas, the chain pushed off but held by a spring of 1e-2: "
                 "status "
              << to_string(held.status)
              << ", KKT <= 1e-8: " << yes_no(held.kkt.max() <= 1e-8) << "\n";
    const Report barely = solve_with(chain(4e-10, 1), method("pdas"), u);
    std::cout << "pdas, held by a spring of 4e-10: no claim of no solution: "
              << yes_no(barely.status != Status::infeasible) << "\n";
  }

  // Singular reduced systems.
  {
    DenseMatrix A(2, 2);
    A << 1, -1, -1, 1;
    Vector b(2);
    b << 1, -1; // index 0 leaves its bound: A itself must be solved
    Vector u;
    // Without net load the floating body has a family of solutions,
    // u = (t, t - 1) for t >= 0. The active set {} is singular; PDAS
    // closes the constraint that the free motion moves and certifies
    // u = (0, -1).
    const Report unregularised =
      solve_with(make_problem(A, b, {0}, {0}), method("pdas"), u, 0);
    report_solver("pdas, unregularised, floating body without net load",
                  unregularised);
    std::cout << "  a solution (KKT <= 1e-10): "
              << yes_no(unregularised.kkt.max() <= 1e-10) << "\n";
    // Pulled off its support (lambda_0 = -1 whatever u is) nothing holds
    // it: every system is singular and PDAS says so.
    Vector b_off(2);
    b_off << 1, 0;
    report_solver(
      "pdas, unregularised, floating body pulled off",
      solve_with(make_problem(A, b_off, {0}, {0}), method("pdas"), u, 0));
    // With regularisation and the projection one of the family is found,
    // and certified.
    const Report regularised =
      solve_with(make_problem(A, b, {0}, {0}), method("pdas"), u, 1e-9);
    report_solver("pdas, regularised, floating body without net load",
                  regularised);
    std::cout << "  a solution (KKT <= 1e-10): "
              << yes_no(regularised.kkt.max() <= 1e-10) << "\n";
    // A semidefinite LCP with a segment of solutions, u_1 + u_2 = 1 (the
    // energy -1/2; truth by hand): pdpc, whose Newton system turns singular
    // as its iterate approaches the segment, and block pivoting on the
    // Schur complement, regularised by round-off only, ended `singular`
    // (a review). PDPC's singular system is now checked by PDAS, and block
    // pivoting is tried again regularised, then projected.
    {
      DenseMatrix A_segment(2, 2);
      A_segment << 1, 1, 1, 1;
      const Problem segment =
        make_problem(A_segment, Vector::Constant(2, 1.0), {0, 1}, {0, 0});
      for (const Method &run :
           {method("pdpc"),
            Method{&SolverRegistry::get("block_pivoting"), true}})
        {
          const Report report = solve_with(segment, run, u);
          std::cout << run.label() << " on A = [1 1; 1 1], b = (1, 1): status "
                    << to_string(report.status) << ", on the segment: "
                    << yes_no(u.size() == 2 && u.minCoeff() >= 0 &&
                              std::abs(u.sum() - 1) <= 1e-12)
                    << "\n";
        }
    }
    // PDPC on the floating body pulled off: its Newton system turns
    // singular, PDAS proves that there is no solution, and the summary is
    // PDAS's (method, counts, iterate), with PDPC's count in the note.
    {
      const Report report =
        solve_with(make_problem(A, b_off, {0}, {0}), method("pdpc"), u);
      report_solver("pdpc, floating body pulled off", report);
      std::cout << "  reported as PDAS's proof: "
                << yes_no(report.solver == "pdas" &&
                          report.message.find("PDPC had ended") !=
                            std::string::npos)
                << ", PDAS's iterations: " << report.iterations << "\n";
    }
    // Held at a bound 1e6 away (u = (1e6, 1e6, 10), lambda = 0: solved
    // exactly): the answer's motion has no stiffness and the loads' work
    // comes from its elastic part, which the proof of no solution from an
    // answer's own motion took for a runaway (a review).
    {
      DenseMatrix A_far(3, 3);
      A_far << 1, -1, 0, -1, 1, 0, 0, 0, 1e-6;
      Vector b_far(3);
      b_far << 0, 0, 1e-5;
      SolverParameters loose;
      loose.kkt_tolerance = 1e-4;
      const Report report = solve_with(
        make_problem(A_far, b_far, {0}, {1e6}), method("pdas"), u, -1, loose);
      std::cout << "pdas, a body held 1e6 away, KKT tolerance 1e-4: status "
                << to_string(report.status) << ", u = (1e6, 1e6, 10): "
                << yes_no(u.size() == 3 && std::abs(u[0] - 1e6) <= 1e-6 &&
                          std::abs(u[1] - 1e6) <= 1e-6 &&
                          std::abs(u[2] - 10) <= 1e-9)
                << "\n";
    }
    // A definite A whose diagonal spans 1e16: the soft unknown is no free
    // motion (its stiffness is its own diagonal), though 1e-16 is below
    // round-off of the mean diagonal, which the proof of no solution
    // measured it against (a review: 'no solution', exit 2).
    {
      DenseMatrix A_soft(2, 2);
      A_soft << 1, 0, 0, 1e-16;
      const Report report =
        solve_with(make_problem(A_soft, Vector::Ones(2), {0}, {0}),
                   method("pdas"),
                   u);
      std::cout << "pdas, A = diag(1, 1e-16), b = (1, 1): status "
                << to_string(report.status) << ", u = (1, 1e16): "
                << yes_no(u.size() == 2 && std::abs(u[0] - 1) <= 1e-12 &&
                          std::abs(u[1] - 1e16) <= 1e4)
                << "\n";
    }
    // A degenerate index (zero slack and zero force at the answer u =
    // (1, 0, 0)): PDPC's predictor landed the third contact exactly on its
    // bound, and the next Newton system divided by its zero slack (NaN
    // after 45 iterations, hidden since by PDAS's verification). It must
    // converge by itself.
    {
      Vector b_degenerate(3);
      b_degenerate << 1, 0, -1;
      const Report report = solve_with(make_problem(DenseMatrix::Identity(3, 3),
                                                    b_degenerate,
                                                    {0, 1, 2},
                                                    {0, 0, 0}),
                                       method("pdpc"),
                                       u);
      std::cout << "pdpc on A = I, b = (1, 0, -1): status "
                << to_string(report.status)
                << ", by itself: " << yes_no(report.solver == "pdpc")
                << ", u = (1, 0, 0): "
                << yes_no(u.size() == 3 &&
                          (u - Vector::Unit(3, 0)).lpNorm<Eigen::Infinity>() <=
                            1e-12)
                << "\n";
    }
    DenseMatrix A2(2, 2);
    A2 << 1, 0, 0, 0;
    Vector b2(2);
    b2 << 1, 1;
    report_solver("Schur complement with A_EE = 0",
                  solve_with(make_problem(A2, b2, {0}, {0}),
                             {&SolverRegistry::get("pdas"), true},
                             u));
  }

  // Bad input through the application.
  write("A.mtx",
        "%%MatrixMarket matrix coordinate real symmetric\n2 2 3\n"
        "1 1 2\n2 1 -1\n2 2 2\n");
  write("A_unsymmetric.mtx",
        "%%MatrixMarket matrix coordinate real general\n2 2 3\n"
        "1 1 2\n2 1 -1\n2 2 2\n");
  write("A_nan.mtx",
        "%%MatrixMarket matrix coordinate real symmetric\n2 2 2\n"
        "1 1 nan\n2 2 2\n");
  write("b.txt", "1\n-2\n");
  write("b3.txt", "1\n-2\n3\n");
  write("b_nan.txt", "1\nnan\n");
  write("c.txt", "1 0\n2 0\n");

  write_lcp_prm("good", "A.mtx", "b.txt");
  run("a good LCP", {"good.prm"});
  write_lcp_prm("mismatch", "A.mtx", "b3.txt");
  run("dimension mismatch", {"mismatch.prm"});
  write_lcp_prm("unsymmetric", "A_unsymmetric.mtx", "b.txt");
  run("non-symmetric A", {"unsymmetric.prm"});
  write_lcp_prm("nan_matrix", "A_nan.mtx", "b.txt");
  run("NaN in A", {"nan_matrix.prm"});
  write_lcp_prm("nan_rhs", "A.mtx", "b_nan.txt");
  run("NaN in b", {"nan_rhs.prm"});
  write_lcp_prm("negative_eps",
                "A.mtx",
                "b.txt",
                "  set Regularisation = -1e-3\n");
  run("eps < 0", {"negative_eps.prm"});
  write_lcp_prm("unreadable", "missing.mtx", "b.txt");
  run("unreadable matrix file", {"unreadable.prm"});
  write_lcp_prm("unknown_method", "A.mtx", "b.txt", "  set Method = lemke\n");
  run("unknown method", {"unknown_method.prm"});
  write_lcp_prm("dense_too_large",
                "A.mtx",
                "b.txt",
                "  set Method = graves\n  set Maximum dense size = 1\n");
  run("graves beyond the dense limit", {"dense_too_large.prm"});
  write("typo.prm", "set Scene = lcp\nset Sceen = lcp\n");
  run("misspelt parameter", {"typo.prm"});
  run("missing parameter file", {"no_such_file.prm"});
  run("unknown option", {"--frobnicate"});
}
