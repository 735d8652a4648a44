// A membrane pressed onto an obstacle, as in deal.II's step-41, assembled
// with deal.II and solved as an LCP by unilateral's solver layer: the way a
// deal.II user calls the installed library from their own code.
//
//   -Laplace u = f on (-1, 1)^2,  u = 0 on the boundary,  u >= psi,
//
// with f = -10 (pressing down) and the obstacle psi a bowl below the
// membrane, which about 30 % of the nodes touch. The Q1 matrix with its
// boundary rows eliminated is the LCP's A, the load its b, and the interior
// nodes carry the bounds u_i >= psi(x_i).
#include <unilateral/lcp/solve_lcp.h>

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/matrix_tools.h>
#include <deal.II/numerics/vector_tools.h>

#include <iostream>
#include <map>

using namespace dealii;

namespace
{
  double
  obstacle(const Point<2> &p)
  {
    return -1.5 + 0.5 * p.norm_square();
  }

  const char *
  yes_no(const bool condition)
  {
    return condition ? "yes" : "no";
  }
} // namespace

int
main()
{
  Triangulation<2> triangulation;
  GridGenerator::hyper_cube(triangulation, -1, 1);
  triangulation.refine_global(5);
  const FE_Q<2> fe(1);
  DoFHandler<2> dof_handler(triangulation);
  dof_handler.distribute_dofs(fe);

  DynamicSparsityPattern dsp(dof_handler.n_dofs());
  DoFTools::make_sparsity_pattern(dof_handler, dsp);
  SparsityPattern pattern;
  pattern.copy_from(dsp);
  SparseMatrix<double> matrix(pattern);
  Vector<double>       rhs(dof_handler.n_dofs());
  MatrixTools::create_laplace_matrix(dof_handler, QGauss<2>(2), matrix);
  VectorTools::create_right_hand_side(dof_handler,
                                      QGauss<2>(2),
                                      Functions::ConstantFunction<2>(-10.),
                                      rhs);
  std::map<types::global_dof_index, double> boundary_values;
  VectorTools::interpolate_boundary_values(dof_handler,
                                           0,
                                           Functions::ZeroFunction<2>(),
                                           boundary_values);
  Vector<double> solution(dof_handler.n_dofs());
  MatrixTools::apply_boundary_values(boundary_values, matrix, solution, rhs);

  // The LCP: A and b from deal.II's matrix and vector, a bound at every
  // interior node.
  unilateral::lcp::Problem                                    problem;
  std::vector<Eigen::Triplet<double, unilateral::lcp::Index>> entries;
  for (const auto &entry : matrix)
    entries.emplace_back(entry.row(), entry.column(), entry.value());
  problem.A.resize(dof_handler.n_dofs(), dof_handler.n_dofs());
  problem.A.setFromTriplets(entries.begin(), entries.end());
  problem.b = Eigen::Map<const Eigen::VectorXd>(rhs.begin(), rhs.size());
  std::map<types::global_dof_index, Point<2>> support_points;
  DoFTools::map_dofs_to_support_points(MappingQ1<2>(),
                                       dof_handler,
                                       support_points);
  std::vector<double> bounds;
  for (const auto &[dof, point] : support_points)
    if (boundary_values.count(dof) == 0)
      {
        problem.constrained.push_back(dof);
        bounds.push_back(obstacle(point));
      }
  problem.lower_bound =
    Eigen::Map<const Eigen::VectorXd>(bounds.data(), bounds.size());
  unilateral::lcp::check_and_normalise(problem);

  // The default method, with one of its options set as a file would.
  unilateral::lcp::SolverParameters parameters;
  parameters.set("PDAS/Tau", "1e-3");
  unilateral::lcp::Solution     lcp_solution;
  const unilateral::lcp::Report report =
    unilateral::lcp::solve_lcp(problem, parameters, lcp_solution);

  const double contact_fraction =
    double(report.n_active) / problem.n_constrained();
  std::cout << "obstacle problem, " << problem.size()
            << " unknowns: " << unilateral::lcp::to_string(report.status)
            << "\n"
            << "relative KKT residuals <= 1e-10: "
            << yes_no(report.kkt.max() <= 1e-10) << "\n"
            << "the membrane lies on the obstacle at 20 to 40 % of the nodes: "
            << yes_no(contact_fraction > 0.2 && contact_fraction < 0.4) << "\n"
            << "nowhere below it: "
            << yes_no(report.kkt.primal_feasibility <= 1e-12) << "\n";
  return report.converged() ? 0 : 1;
}
