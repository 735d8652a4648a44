// The Bogner-Fox-Schmit element on its own and on a mesh:
//  1. nodal basis: each shape function has exactly one nonzero nodal DOF;
//  2. every bicubic is reproduced exactly (value, gradient, Hessian) by its
//     nodal interpolant, and a quartic is not;
//  3. with deal.II numbering the DOFs (FE_Q(1)^4 and bfs_local_indices), a
//     field on a non-uniform mesh is C1: value and both first derivatives are
//     continuous across every interior edge (the second normal derivative is
//     not: the element is C1, not C2), and a global bicubic given through its
//     nodal DOFs is reproduced on every cell;
//  4. the same check fails for a wrong DOF map (vertices 1 and 2 exchanged),
//     so it can detect one; wrong elements and non-rectangles are rejected.

#include <unilateral/fe/bogner_fox_schmit.h>

#include "../test_tools.h"

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/vector.h>

using namespace dealii;
using test_tools::Polynomial;
using test_tools::verdict;
using unilateral::fe::BognerFoxSchmit;

namespace
{
  // Points in (and a little outside) the rectangle: the interpolant is a
  // polynomial, so reproduction must hold everywhere.
  std::vector<Point<2>>
  sample_points(const BognerFoxSchmit &element)
  {
    std::vector<Point<2>> points;
    for (const double s : {-0.2, 0.0, 0.13, 0.5, 0.77, 1.0, 1.1})
      for (const double t : {-0.1, 0.0, 0.31, 0.5, 0.9, 1.0})
        points.emplace_back(element.vertex(0)[0] + s * element.size(0),
                            element.vertex(0)[1] + t * element.size(1));
    return points;
  }

  // Largest error of value, gradient and Hessian of the interpolant of p,
  // relative to the largest magnitude of each.
  double
  interpolation_error(const BognerFoxSchmit &element, const Polynomial &p)
  {
    const auto coefficients = element.interpolate(p);
    double     error = 0, scale_v = 0, scale_g = 0, scale_h = 0;
    double     error_v = 0, error_g = 0, error_h = 0;
    for (const Point<2> &x : sample_points(element))
      {
        scale_v = std::max(scale_v, std::abs(p.value(x)));
        scale_g = std::max(scale_g, p.gradient(x).norm());
        scale_h = std::max(scale_h, p.full_hessian(x).norm());
        error_v =
          std::max(error_v,
                   std::abs(element.value(coefficients, x) - p.value(x)));
        error_g =
          std::max(error_g,
                   (element.gradient(coefficients, x) - p.gradient(x)).norm());
        error_h = std::max(
          error_h,
          (element.hessian(coefficients, x) - p.full_hessian(x)).norm());
      }
    error = std::max(error, error_v / std::max(scale_v, 1e-300));
    if (scale_g > 0)
      error = std::max(error, error_g / scale_g);
    else
      error = std::max(error, error_g);
    if (scale_h > 0)
      error = std::max(error, error_h / scale_h);
    else
      error = std::max(error, error_h);
    return error;
  }

  void
  check_nodal_basis(const BognerFoxSchmit &element)
  {
    bool ok = true;
    for (unsigned int i = 0; i < BognerFoxSchmit::dofs_per_cell; ++i)
      for (unsigned int v = 0; v < 4; ++v)
        {
          const Point<2>     x       = element.vertex(v);
          const Tensor<1, 2> g       = element.shape_gradient(i, x);
          const Tensor<2, 2> h       = element.shape_hessian(i, x);
          const double       dofs[4] = {element.shape_value(i, x),
                                        g[0],
                                        g[1],
                                        h[0][1]};
          for (unsigned int c = 0; c < 4; ++c)
            {
              const double expected =
                (i == BognerFoxSchmit::local_index(v, c)) ? 1.0 : 0.0;
              ok = ok && std::abs(dofs[c] - expected) < 1e-12;
            }
        }
    verdict("nodal basis: shape function 4v+c has DOF c = 1 at vertex v and "
            "all other nodal DOFs 0",
            ok);
  }

  void
  check_polynomial_reproduction(const BognerFoxSchmit &element)
  {
    bool all_monomials = true;
    for (unsigned int i = 0; i <= 3; ++i)
      for (unsigned int j = 0; j <= 3; ++j)
        all_monomials =
          all_monomials &&
          interpolation_error(element, Polynomial::monomial(i, j)) < 1e-12;
    verdict("all 16 monomials x^i y^j (i, j <= 3) reproduced exactly "
            "(value, gradient, Hessian; relative error < 1e-12)",
            all_monomials);

    test_tools::Sequence sequence(7);
    bool                 random_bicubics = true;
    for (unsigned int k = 0; k < 10; ++k)
      random_bicubics =
        random_bicubics &&
        interpolation_error(element, Polynomial::bicubic(sequence)) < 1e-12;
    verdict("10 random bicubics reproduced exactly", random_bicubics);

    verdict("x^4 is not reproduced (relative error > 1e-3)",
            interpolation_error(element, Polynomial::monomial(4, 0)) > 1e-3);
    verdict("x^3 y^4 is not reproduced (relative error > 1e-3)",
            interpolation_error(element, Polynomial::monomial(3, 4)) > 1e-3);
  }

  // The largest jump of value, w_x and w_y (and of the second normal
  // derivative) across the interior edges of the mesh, relative to the
  // largest magnitude seen.
  struct Jumps
  {
    double       first_order   = 0; ///< value and gradient
    double       second_normal = 0;
    unsigned int n_edges       = 0;
  };

  Jumps
  edge_jumps(const DoFHandler<2>             &dof_handler,
             const std::vector<unsigned int> &bfs_index,
             const Vector<double>            &dofs)
  {
    auto coefficients_of =
      [&](const DoFHandler<2>::active_cell_iterator &cell) {
        std::vector<types::global_dof_index> local(
          BognerFoxSchmit::dofs_per_cell);
        cell->get_dof_indices(local);
        BognerFoxSchmit::Coefficients c;
        for (unsigned int i = 0; i < local.size(); ++i)
          c[bfs_index[i]] = dofs[local[i]];
        return c;
      };
    auto element_of = [](const DoFHandler<2>::active_cell_iterator &cell) {
      return BognerFoxSchmit::from_vertices(
        {{cell->vertex(0), cell->vertex(1), cell->vertex(2), cell->vertex(3)}});
    };

    Jumps  jumps;
    double scale = 0, scale_second = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (!cell->at_boundary(f) && cell->neighbor(f)->index() > cell->index())
          {
            ++jumps.n_edges;
            const auto neighbor = cell->neighbor(f);
            const auto e1 = element_of(cell), e2 = element_of(neighbor);
            const auto c1             = coefficients_of(cell),
                       c2             = coefficients_of(neighbor);
            const unsigned int normal = f / 2; // faces 0,1: x = const
            for (const double s : {0.0, 0.1, 0.35, 0.5, 0.8, 1.0})
              {
                const Point<2> x =
                  cell->face(f)->vertex(0) +
                  s * (cell->face(f)->vertex(1) - cell->face(f)->vertex(0));
                const double       v1 = e1.value(c1, x), v2 = e2.value(c2, x);
                const Tensor<1, 2> g1 = e1.gradient(c1, x),
                                   g2 = e2.gradient(c2, x);
                const Tensor<2, 2> h1 = e1.hessian(c1, x),
                                   h2 = e2.hessian(c2, x);
                scale = std::max({scale, std::abs(v1), g1.norm()});
                scale_second =
                  std::max(scale_second, std::abs(h1[normal][normal]));
                jumps.first_order = std::max({jumps.first_order,
                                              std::abs(v1 - v2),
                                              std::abs(g1[0] - g2[0]),
                                              std::abs(g1[1] - g2[1])});
                jumps.second_normal =
                  std::max(jumps.second_normal,
                           std::abs(h1[normal][normal] - h2[normal][normal]));
              }
          }
    jumps.first_order /= scale;
    jumps.second_normal /= scale_second;
    return jumps;
  }

  void
  check_mesh()
  {
    // A non-uniform 3 x 4 mesh: every cell has a different size.
    Triangulation<2> triangulation;
    GridGenerator::subdivided_hyper_rectangle(triangulation,
                                              {{0.5, 1.3, 0.8},
                                               {0.9, 0.4, 1.1, 0.7}},
                                              Point<2>(-1.0, 0.5),
                                              Point<2>(1.6, 3.6));
    const FESystem<2> fe(FE_Q<2>(1), 4);
    DoFHandler<2>     dof_handler(triangulation);
    dof_handler.distribute_dofs(fe);
    const std::vector<unsigned int> bfs_index =
      unilateral::fe::bfs_local_indices(fe);

    verdict("FE_Q(1)^4 has 4 DOFs per vertex and 16 per cell",
            fe.n_dofs_per_vertex() == 4 && fe.n_dofs_per_cell() == 16 &&
              dof_handler.n_dofs() == 4 * triangulation.n_vertices());

    test_tools::Sequence sequence(3);
    Vector<double>       dofs(dof_handler.n_dofs());
    for (double &d : dofs)
      d = sequence.next();

    const Jumps jumps = edge_jumps(dof_handler, bfs_index, dofs);
    std::cout << "interior edges checked: " << jumps.n_edges << std::endl;
    verdict("random DOFs: value, w_x and w_y continuous across every interior "
            "edge (relative jump < 1e-12)",
            jumps.first_order < 1e-12);
    verdict("random DOFs: the second normal derivative jumps (C1, not C2)",
            jumps.second_normal > 1e-3);

    // A global bicubic through its nodal DOFs, set vertex by vertex.
    const Polynomial p = Polynomial::bicubic(sequence);
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        std::vector<types::global_dof_index> local(16);
        cell->get_dof_indices(local);
        const BognerFoxSchmit element =
          BognerFoxSchmit::from_vertices({{cell->vertex(0),
                                           cell->vertex(1),
                                           cell->vertex(2),
                                           cell->vertex(3)}});
        const auto nodal = element.interpolate(p);
        for (unsigned int i = 0; i < 16; ++i)
          dofs[local[i]] = nodal[bfs_index[i]];
      }
    double error = 0, scale = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        std::vector<types::global_dof_index> local(16);
        cell->get_dof_indices(local);
        BognerFoxSchmit::Coefficients c;
        for (unsigned int i = 0; i < 16; ++i)
          c[bfs_index[i]] = dofs[local[i]];
        const BognerFoxSchmit element =
          BognerFoxSchmit::from_vertices({{cell->vertex(0),
                                           cell->vertex(1),
                                           cell->vertex(2),
                                           cell->vertex(3)}});
        for (const double s : {0.25, 0.6})
          for (const double t : {0.4, 0.9})
            {
              const Point<2> x(element.vertex(0)[0] + s * element.size(0),
                               element.vertex(0)[1] + t * element.size(1));
              error =
                std::max({error,
                          std::abs(element.value(c, x) - p.value(x)),
                          (element.hessian(c, x) - p.full_hessian(x)).norm()});
              scale = std::max(
                {scale, std::abs(p.value(x)), p.full_hessian(x).norm()});
            }
      }
    verdict("a global bicubic set through nodal DOFs is reproduced on every "
            "cell (value and Hessian, relative error < 1e-12)",
            error < 1e-12 * scale);

    // The same C1 check with a wrong map, vertices 1 and 2 exchanged (as if
    // the vertex numbering were lexicographic by y first): it must notice.
    // (A consistent relabelling of components, like w_x <-> w_y everywhere,
    // still gives a C1 field, so it is not a useful control.)
    std::vector<unsigned int> wrong = bfs_index;
    for (unsigned int &b : wrong)
      {
        const unsigned int v = b / 4, c = b % 4;
        const unsigned int w = (v == 1) ? 2 : (v == 2) ? 1 : v;
        b                    = BognerFoxSchmit::local_index(w, c);
      }
    for (double &d : dofs)
      d = sequence.next();
    verdict("with vertices 1 and 2 exchanged in the DOF map, the C1 check "
            "fails (relative jump > 1e-3)",
            edge_jumps(dof_handler, wrong, dofs).first_order > 1e-3);

    bool rejected = false;
    try
      {
        unilateral::fe::bfs_local_indices(FESystem<2>(FE_Q<2>(2), 4));
      }
    catch (const std::invalid_argument &)
      {
        rejected = true;
      }
    verdict("bfs_local_indices rejects FE_Q(2)^4", rejected);

    bool not_rectangle = false;
    try
      {
        BognerFoxSchmit::from_vertices(
          {{Point<2>(0, 0), Point<2>(1, 0.1), Point<2>(0, 1), Point<2>(1, 1)}});
      }
    catch (const std::invalid_argument &)
      {
        not_rectangle = true;
      }
    verdict("a cell that is not an axis-aligned rectangle is rejected",
            not_rectangle);
  }
} // namespace

int
main()
{
  std::cout << "Bogner-Fox-Schmit rectangle [0.3, 1.0] x [-1.2, 0.7]"
            << std::endl;
  const BognerFoxSchmit element(Point<2>(0.3, -1.2), 0.7, 1.9);
  check_nodal_basis(element);
  check_polynomial_reproduction(element);
  std::cout << "Mesh of 3 x 4 rectangles of different sizes" << std::endl;
  check_mesh();
}
