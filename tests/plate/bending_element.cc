// Plate bending with the Bogner-Fox-Schmit element, against independent
// truth:
//  1. the element stiffness C^e is symmetric positive semidefinite with
//     kernel exactly span{1, x, y} (rigid modes have zero energy);
//  2. z_p^T C^e z_q equals the bending energy of the paper's eqs. (27)-(28)
//     (D matrix, curvatures (w_xx, w_yy, 2 w_xy)) integrated with 8 x 8 Gauss
//     points, for random bicubics p, q: the 4 x 4 rule is exact;
//  3. the load F^e . z_p equals int f p for a force of degree 4 in each
//     variable, and is not exact for x^5 (so the check is sharp);
//  4. patch test: on a non-uniform mesh, with all four DOFs of the boundary
//     nodes prescribed from a bicubic p and the load f = D Delta^2 p, the
//     assembled system reproduces p exactly at every free DOF; with the
//     wrong load it does not.

#include <unilateral/scenes/plate/assembly.h>
#include <unilateral/scenes/plate/bending.h>

#include "../test_tools.h"

#include <deal.II/base/index_set.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/component_mask.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>

using namespace dealii;
using test_tools::Polynomial;
using test_tools::verdict;
using unilateral::fe::BognerFoxSchmit;

namespace
{
  constexpr double youngs_modulus = 11e3, poisson_ratio = 0.31, thickness = 1.7;

  // The paper's element energy density (27)-(28), written out on its own:
  // (t^2 / 12) kappa_z^T D kappa_w with kappa = (w_xx, w_yy, 2 w_xy) and
  // D = t E / (1 - nu^2) [[1, nu, 0], [nu, 1, 0], [0, 0, (1 - nu) / 2]].
  double
  paper_energy_density(const Tensor<2, 2> &hz, const Tensor<2, 2> &hw)
  {
    const double E = youngs_modulus, nu = poisson_ratio, t = thickness;
    const double kz[3]   = {hz[0][0], hz[1][1], 2 * hz[0][1]};
    const double kw[3]   = {hw[0][0], hw[1][1], 2 * hw[0][1]};
    const double D[3][3] = {{1, nu, 0}, {nu, 1, 0}, {0, 0, (1 - nu) / 2}};
    double       result  = 0;
    for (unsigned int a = 0; a < 3; ++a)
      for (unsigned int b = 0; b < 3; ++b)
        result += kz[a] * D[a][b] * kw[b];
    return t * t / 12 * t * E / (1 - nu * nu) * result;
  }

  // int over the cell of g(x), by an 8 x 8 Gauss rule (exact to degree 15).
  template <typename Integrand>
  double
  integrate(const BognerFoxSchmit &element, const Integrand &g)
  {
    const QGauss<2> quadrature(8);
    double          result = 0;
    for (unsigned int q = 0; q < quadrature.size(); ++q)
      {
        const Point<2> x(element.vertex(0)[0] +
                           quadrature.point(q)[0] * element.size(0),
                         element.vertex(0)[1] +
                           quadrature.point(q)[1] * element.size(1));
        result +=
          g(x) * quadrature.weight(q) * element.size(0) * element.size(1);
      }
    return result;
  }

  Eigen::VectorXd
  to_vector(const BognerFoxSchmit::Coefficients &c)
  {
    return Eigen::Map<const Eigen::VectorXd>(c.data(), c.size());
  }

  void
  check_element()
  {
    const double rigidity = unilateral::plate::flexural_rigidity(youngs_modulus,
                                                                 poisson_ratio,
                                                                 thickness);
    const BognerFoxSchmit element(Point<2>(0.4, -0.3), 0.7, 1.9);
    const unilateral::plate::CellIntegrals integrals(0.7,
                                                     1.9,
                                                     rigidity,
                                                     poisson_ratio);
    Eigen::MatrixXd                        K(16, 16);
    for (unsigned int i = 0; i < 16; ++i)
      for (unsigned int j = 0; j < 16; ++j)
        K(i, j) = integrals.stiffness(i, j);

    verdict("C^e is exactly symmetric", K == K.transpose());
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(K);
    const Eigen::VectorXd lambda  = eigen.eigenvalues(); // ascending
    const double          largest = lambda[15];
    unsigned int          n_zero = 0, n_negative = 0;
    for (unsigned int k = 0; k < 16; ++k)
      {
        n_zero += std::abs(lambda[k]) <= 1e-12 * largest;
        n_negative += lambda[k] < -1e-12 * largest;
      }
    verdict("C^e has no negative eigenvalue", n_negative == 0);
    verdict("C^e has exactly 3 zero eigenvalues (|lambda| <= 1e-12 max)",
            n_zero == 3);
    verdict("the other 13 eigenvalues are > 1e-6 max",
            lambda[3] > 1e-6 * largest);

    bool rigid_modes = true;
    for (const Polynomial &p : {Polynomial::monomial(0, 0),
                                Polynomial::monomial(1, 0),
                                Polynomial::monomial(0, 1)})
      {
        const Eigen::VectorXd z = to_vector(element.interpolate(p));
        rigid_modes =
          rigid_modes && (K * z).norm() <= 1e-12 * largest * z.norm();
      }
    verdict("1, x and y have zero energy (C^e z = 0)", rigid_modes);
    verdict("x^2, xy and y^2 do not",
            (K * to_vector(element.interpolate(Polynomial::monomial(2, 0))))
                  .norm() > 1e-3 * largest &&
              (K * to_vector(element.interpolate(Polynomial::monomial(1, 1))))
                  .norm() > 1e-3 * largest &&
              (K * to_vector(element.interpolate(Polynomial::monomial(0, 2))))
                  .norm() > 1e-3 * largest);

    test_tools::Sequence sequence(11);
    double               energy_error = 0, energy_scale = 0;
    for (unsigned int k = 0; k < 8; ++k)
      {
        const Polynomial p    = Polynomial::bicubic(sequence);
        const Polynomial q    = Polynomial::bicubic(sequence);
        const double     ours = to_vector(element.interpolate(p))
                              .dot(K * to_vector(element.interpolate(q)));
        const double exact = integrate(element, [&](const Point<2> &x) {
          return paper_energy_density(p.full_hessian(x), q.full_hessian(x));
        });
        energy_error       = std::max(energy_error, std::abs(ours - exact));
        energy_scale       = std::max(energy_scale, std::abs(exact));
      }
    verdict("z_p^T C^e z_q equals the paper's energy (27)-(28) for 8 pairs of "
            "random bicubics (relative error < 1e-12)",
            energy_error < 1e-12 * energy_scale);

    // Loads: degree 4 in each variable is exact with 4 x 4 Gauss, x^5 is not.
    const Polynomial quartic({{1.0, 0.3, 0.0, 0.0, 0.7},
                              {0.0, 0.2},
                              {0.0, -1.1},
                              {0.0},
                              {-0.5, 0.0, 0.0, 0.0, 0.9}});
    const Polynomial quintic = Polynomial::monomial(5, 0);
    for (const auto &[name, force, exact_expected] :
         {std::tuple{"a force of degree 4 in x and in y", &quartic, true},
          std::tuple{"the force x^5", &quintic, false}})
      {
        double error = 0, scale = 0;
        for (unsigned int k = 0; k < 4; ++k)
          {
            const Polynomial p = Polynomial::bicubic(sequence);
            const auto       load =
              integrals.load(element.vertex(0), [&](const Point<2> &x) {
                return force->value(x);
              });
            const double ours =
              Eigen::Map<const Eigen::VectorXd>(load.data(), 16)
                .dot(to_vector(element.interpolate(p)));
            const double exact = integrate(element, [&](const Point<2> &x) {
              return force->value(x) * p.value(x);
            });
            error              = std::max(error, std::abs(ours - exact));
            scale              = std::max(scale, std::abs(exact));
          }
        verdict(std::string("load F^e . z_p equals int f p for ") + name +
                  (exact_expected ? " (relative error < 1e-12)" :
                                    ": no (relative error > 1e-8)"),
                exact_expected ? error < 1e-12 * scale : error > 1e-8 * scale);
      }
  }

  // f = D Delta^2 p.
  class BiharmonicLoad : public Function<2>
  {
  public:
    BiharmonicLoad(const Polynomial &p, const double rigidity)
      : p(p)
      , rigidity(rigidity)
    {}

    double
    value(const Point<2> &x, const unsigned int = 0) const override
    {
      return rigidity * (p.derivative(x, 4, 0) + 2 * p.derivative(x, 2, 2) +
                         p.derivative(x, 0, 4));
    }

  private:
    const Polynomial &p;
    double            rigidity;
  };

  // Solve the assembled system with the boundary DOFs of p prescribed;
  // return the largest error at the free DOFs relative to the largest DOF.
  double
  patch_test_error(const DoFHandler<2> &dof_handler,
                   const Polynomial    &p,
                   const Function<2>   &force,
                   const double         rigidity)
  {
    const IndexSet fixed =
      DoFTools::extract_boundary_dofs(dof_handler, ComponentMask(4, true));
    const unilateral::plate::FreeDofs free_dofs =
      unilateral::plate::number_free_dofs(dof_handler.n_dofs(), fixed);

    // Nodal values of p: all DOFs (the fixed ones are the boundary data).
    const std::vector<unsigned int> bfs_index =
      unilateral::fe::bfs_local_indices(dof_handler.get_fe());
    Vector<double> nodal(dof_handler.n_dofs());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        std::vector<types::global_dof_index> local(16);
        cell->get_dof_indices(local);
        const auto c = unilateral::plate::cell_element(cell).interpolate(p);
        for (unsigned int i = 0; i < 16; ++i)
          nodal[local[i]] = c[bfs_index[i]];
      }

    unilateral::lcp::SparseMatrix A;
    unilateral::lcp::Vector       b;
    unilateral::plate::assemble_plate_system(dof_handler,
                                             free_dofs,
                                             &nodal,
                                             rigidity,
                                             poisson_ratio,
                                             force,
                                             "force",
                                             A,
                                             b);
    const Eigen::SimplicialLDLT<unilateral::lcp::SparseMatrix> ldlt(A);
    if (ldlt.info() != Eigen::Success || (ldlt.vectorD().array() <= 0).any())
      return std::numeric_limits<double>::infinity();
    const Eigen::VectorXd u     = ldlt.solve(b);
    double                error = 0, scale = 0;
    for (unilateral::lcp::Index k = 0; k < free_dofs.size(); ++k)
      {
        error = std::max(error, std::abs(u[k] - nodal[free_dofs.dof[k]]));
        scale = std::max(scale, std::abs(nodal[free_dofs.dof[k]]));
      }
    return error / scale;
  }

  void
  check_patch_test()
  {
    const double rigidity = unilateral::plate::flexural_rigidity(youngs_modulus,
                                                                 poisson_ratio,
                                                                 thickness);
    Triangulation<2> triangulation;
    GridGenerator::subdivided_hyper_rectangle(triangulation,
                                              {{0.5, 1.3, 0.8, 0.6},
                                               {0.9, 0.4, 1.1, 0.7, 0.3}},
                                              Point<2>(-1.0, 0.5),
                                              Point<2>(2.2, 3.9));
    const FESystem<2> fe(FE_Q<2>(1), 4);
    DoFHandler<2>     dof_handler(triangulation);
    dof_handler.distribute_dofs(fe);

    test_tools::Sequence sequence(5);
    const Polynomial     p = Polynomial::bicubic(sequence);
    const BiharmonicLoad load(p, rigidity);
    std::cout << "patch test on a non-uniform 4 x 5 mesh, "
              << dof_handler.n_dofs() << " DOFs" << std::endl;
    verdict("the assembled system reproduces a bicubic with f = D Delta^2 p "
            "exactly (relative error < 1e-10)",
            patch_test_error(dof_handler, p, load, rigidity) < 1e-10);

    const Polynomial     q = Polynomial::monomial(2, 2).scaled(0.1);
    const BiharmonicLoad load_q(q, rigidity);
    verdict("the same for x^2 y^2 (Delta^2 = 8, a constant load)",
            patch_test_error(dof_handler, q, load_q, rigidity) < 1e-10);

    const Functions::ZeroFunction<2> no_load;
    verdict("with f = 0 instead, x^2 y^2 is not reproduced (error > 1e-3)",
            patch_test_error(dof_handler, q, no_load, rigidity) > 1e-3);
  }
} // namespace

int
main()
{
  std::cout << "Element stiffness and load on a 0.7 x 1.9 rectangle"
            << std::endl;
  check_element();
  check_patch_test();
}
