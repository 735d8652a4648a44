// No unneeded work, checked from the solver's counters (never from times):
// a factorisation is reused while its matrix does not change, the projection
// step reuses the regularised factor, one ordering/analysis serves a whole
// run, and optional phases run only when asked for.
#include "../lcp_test_tools.h"

using namespace test;

namespace
{
  // A chain of masses on springs: mass 0 rests on a support (u_0 >= 0), the
  // others hang freely (unconstrained) or touch a floor (every third one):
  // A is singular (the chain can translate), the solution unique.
  Problem
  chain(const Index n)
  {
    DenseMatrix A = DenseMatrix::Zero(n, n);
    for (Index i = 0; i + 1 < n; ++i)
      {
        A(i, i) += 1;
        A(i + 1, i + 1) += 1;
        A(i, i + 1) -= 1;
        A(i + 1, i) -= 1;
      }
    std::vector<Index>  S;
    std::vector<double> lower;
    for (Index i = 0; i < n; i += 3)
      {
        S.push_back(i);
        lower.push_back(-0.01 * i);
      }
    return make_problem(A, Vector::Constant(n, -1.0), S, lower);
  }

  bool
  has_phase(const Report &report, const std::string &phase)
  {
    for (const auto &entry : report.phase_times)
      if (entry.first == phase)
        return true;
    return false;
  }
} // namespace

int
main()
{
  const Problem problem = chain(60);
  Vector        u;

  // PSOR: A_EE is factorised once, however many sweeps run.
  {
    SolverParameters no_projection;
    no_projection.projection = false;
    const Report psor = solve_with(problem, {"psor"}, u, 1e-2, no_projection);
    // Regularised and not projected, so the answer is honestly reported
    // "inaccurate" against the original problem.
    std::cout << "psor: " << to_string(psor.status)
              << " (regularised, not projected), sweeps > 1: "
              << yes_no(psor.iterations > 1)
              << "\n  one ordering of A and one symbolic analysis of A_EE: "
              << yes_no(psor.counters.orderings == 1 &&
                        psor.counters.symbolic_analyses == 1)
              << ", factorised once: "
              << yes_no(psor.counters.numeric_factorisations == 1) << "\n";
  }

  // PDAS with regularisation: the projection's first system (same active
  // set, A instead of A + eps I) is solved with the regularised factor as a
  // preconditioner, not factorised anew.
  {
    const Report pdas = solve_with(problem, {"pdas"}, u, 1e-12);
    std::cout << "pdas + projection: " << to_string(pdas.status)
              << ", projection iterations: " << pdas.projection_iterations
              << "\n  projection reused the regularised factor: "
              << yes_no(pdas.counters.reused_factorisations >= 1)
              << "\n  factorisations <= pdas iterations + 1 (the start): "
              << yes_no(pdas.counters.numeric_factorisations <=
                        pdas.iterations + 1)
              << "\n";
  }

  // Interior point: one analysis of the pattern for all its Newton systems.
  {
    SolverParameters parameters;
    parameters.projection = false;
    const Report ip =
      solve_with(problem, {"interior_point"}, u, -1, parameters);
    std::cout << "interior point: " << ip.iterations
              << " Newton systems, one symbolic analysis: "
              << yes_no(ip.counters.symbolic_analyses == 1)
              << ", one factorisation each: "
              << yes_no(ip.counters.numeric_factorisations == ip.iterations)
              << "\n";
  }

  // Optional phases run only when asked for.
  {
    const Report full = solve_with(problem, {"pdas"}, u, 1e-12);
    const Report schur = solve_with(problem, {"pdas", true}, u, 1e-12);
    std::cout << "Schur complement formed only when asked: "
              << yes_no(!has_phase(full, "schur complement") &&
                        has_phase(schur, "schur complement"))
              << "\n";
    SolverParameters no_projection;
    no_projection.projection = false;
    const Report unprojected =
      solve_with(problem, {"pdas"}, u, 1e-12, no_projection);
    std::cout << "projection only when asked: "
              << yes_no(full.projected && !unprojected.projected &&
                        !has_phase(unprojected, "projection"))
              << "\n";
    const Report definite = solve_with(
      make_problem(DenseMatrix::Identity(3, 3), Vector::Ones(3), {0, 1, 2},
                   {0, 0, 0}),
      {"pdas"}, u);
    std::cout << "no regularisation or projection for a definite matrix "
                 "with eps = auto: "
              << yes_no(definite.regularisation == 0 && !definite.projected)
              << "\n";
  }
}
