// A traction restricted to a region loads exactly the part of each face
// inside the region. Before, each face Gauss point inside counted for the
// part of the face it stands for: a strip 'top where x > 0.95' of a unit
// block with one cell lay between the Gauss points and was not loaded at
// all (exit 0), and on finer cells it carried 39 % too much.
//
// Part 1: face_region_rule's area of the part of one face inside a region,
// against the exact area: straight edges (exact to rounding, also on a
// distorted 2D cell and a sheared 3D cell, tetrahedron faces); a disc and
// a triangle with a corner inside the face in 3D, whose parts narrower
// than the lines' sampling escape it (to 1e-4 and 1e-3 of their areas,
// 1e-6 and 6e-5 of the face's; the face's Gauss points were 1e-2 off and
// more).
// Part 2: the load a wall's summary reports (statics.load) against weight
// plus traction times the strip's length or area, in 2D and 3D.
#include <unilateral/scenes/masonry/face_region.h>

#include "../application_test_tools.h"

#include <deal.II/base/numbers.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <iostream>
#include <regex>

using namespace unilateral::masonry;
using namespace application_test;

namespace
{
  // The area (length in 2D) of the part of face @p face inside @p inside.
  template <int dim>
  double
  area_inside(const std::vector<dealii::Point<dim>>                 &vertices,
              const unsigned int                                     face,
              const std::function<bool(const dealii::Point<dim> &)> &inside)
  {
    // A quadrilateral or hexahedron, or a triangle or tetrahedron.
    const bool                         simplex = vertices.size() == dim + 1;
    dealii::Triangulation<dim>         triangulation;
    std::vector<dealii::CellData<dim>> cells(1);
    cells[0].vertices.resize(vertices.size());
    for (unsigned int v = 0; v < vertices.size(); ++v)
      cells[0].vertices[v] = v;
    triangulation.create_triangulation(vertices, cells, {});
    std::unique_ptr<dealii::FiniteElement<dim>> fe;
    std::unique_ptr<dealii::Mapping<dim>>       mapping;
    if (simplex)
      {
        fe      = std::make_unique<dealii::FE_SimplexP<dim>>(1);
        mapping = std::make_unique<dealii::MappingFE<dim>>(*fe);
      }
    else
      {
        fe      = std::make_unique<dealii::FE_Q<dim>>(1);
        mapping = std::make_unique<dealii::MappingQ<dim>>(1);
      }
    dealii::DoFHandler<dim> dof_handler(triangulation);
    dof_handler.distribute_dofs(*fe);
    const auto cell = dof_handler.begin_active();

    const FaceRegionRule<dim> rule = face_region_rule<dim>(cell, face, inside);
    if (rule.coverage == FaceRegionRule<dim>::Coverage::none)
      return 0;
    if (rule.coverage == FaceRegionRule<dim>::Coverage::whole)
      return cell->face(face)->measure();
    dealii::FEValues<dim> values(*mapping,
                                 *fe,
                                 dealii::Quadrature<dim>(rule.points,
                                                         rule.weights),
                                 dealii::update_jacobians);
    values.reinit(cell);
    double area = 0;
    for (unsigned int q = 0; q < values.n_quadrature_points; ++q)
      {
        const auto e_s =
          apply_transformation(values.jacobian(q), rule.tangents[0]);
        double measure = e_s.norm();
        if constexpr (dim == 3)
          measure = cross_product_3d(e_s,
                                     apply_transformation(values.jacobian(q),
                                                          rule.tangents[1]))
                      .norm();
        area += rule.weights[q] * measure;
      }
    return area;
  }

  template <int dim>
  void
  check(const std::string                                     &name,
        const std::vector<dealii::Point<dim>>                 &vertices,
        const unsigned int                                     face,
        const std::function<bool(const dealii::Point<dim> &)> &inside,
        const double                                           exact,
        const double                                           tolerance)
  {
    const double area = area_inside<dim>(vertices, face, inside);
    std::cout << name << ": " << std::setprecision(8) << area << " (exact "
              << exact << "), relative error <= " << tolerance << ": "
              << yes_no(std::abs(area - exact) <= tolerance * exact) << "\n";
  }

  /// The total load of a run, from summary.json ("load": [...]).
  double
  load_size(const std::string &summary)
  {
    std::smatch found;
    if (!std::regex_search(summary,
                           found,
                           std::regex("\"load\": *\\[([^\\]]*)\\]")))
      return std::nan("");
    std::stringstream entries(found[1].str());
    std::string       entry;
    double            sum = 0;
    while (std::getline(entries, entry, ','))
      sum += std::pow(std::stod(entry), 2);
    return std::sqrt(sum);
  }
} // namespace

int
main()
{
  using P2 = dealii::Point<2>;
  using P3 = dealii::Point<3>;
  const std::vector<P2> square{P2(0, 0), P2(1, 0), P2(0, 1), P2(1, 1)};
  // The top face (face 3) from (0.2, 1) to (1.3, 1.4).
  const std::vector<P2> distorted{P2(0, 0), P2(1, 0), P2(0.2, 1), P2(1.3, 1.4)};
  const double          top_length = std::sqrt(1.1 * 1.1 + 0.4 * 0.4);
  std::cout << "Part 1: the part of one face inside a region\n";
  check<2>(
    "2D, x > 0.3",
    square,
    3,
    [](const P2 &p) { return p[0] > 0.3; },
    0.7,
    1e-13);
  check<2>(
    "2D, x > 0.95",
    square,
    3,
    [](const P2 &p) { return p[0] > 0.95; },
    0.05,
    1e-12);
  check<2>(
    "2D, sin(10 x) > 0 (two parts)",
    square,
    3,
    [](const P2 &p) { return std::sin(10 * p[0]) > 0; },
    2 * dealii::numbers::PI / 10,
    1e-13);
  check<2>(
    "2D distorted cell, x > 0.75",
    distorted,
    3,
    [](const P2 &p) { return p[0] > 0.75; },
    top_length * 0.55 / 1.1,
    1e-13);

  std::vector<P3> cube, sheared;
  for (unsigned int v = 0; v < 8; ++v)
    {
      const P3 p(v & 1, (v >> 1) & 1, (v >> 2) & 1);
      cube.push_back(p);
      sheared.push_back(p + P3(0.3 * p[2], 0, 0));
    }
  // Face 3 is y = 1, parametrised by x and z.
  check<3>(
    "3D, x + z > 0.7",
    cube,
    3,
    [](const P3 &p) { return p[0] + p[2] > 0.7; },
    1 - 0.7 * 0.7 / 2,
    1e-13);
  check<3>(
    "3D, x > 0.3 and z < 0.45",
    cube,
    3,
    [](const P3 &p) { return p[0] > 0.3 && p[2] < 0.45; },
    0.7 * 0.45,
    1e-13);
  check<3>(
    "3D sheared cell, x > 0.8",
    sheared,
    3,
    [](const P3 &p) { return p[0] > 0.8; },
    0.35,
    1e-13);
  check<3>(
    "3D, a disc of radius sqrt(0.1) centred at (0.4, 0.5)",
    cube,
    3,
    [](const P3 &p) {
      return std::pow(p[0] - 0.4, 2) + std::pow(p[2] - 0.5, 2) < 0.1;
    },
    dealii::numbers::PI * 0.1,
    1e-4);
  check<3>(
    "3D, a triangle with its corner inside the face",
    cube,
    3,
    [](const P3 &p) {
      return p[2] > 0.5 && std::abs(p[0] - 0.51) < 0.5 * (p[2] - 0.5);
    },
    0.125,
    1e-3);

  // Tetrahedron: face 0 is z = 0, face 3 the slanted x + y + z = 1.
  const std::vector<P3> tetrahedron{P3(0, 0, 0),
                                    P3(1, 0, 0),
                                    P3(0, 1, 0),
                                    P3(0, 0, 1)};
  check<3>(
    "3D tetrahedron, face z = 0, x > 0.5",
    tetrahedron,
    0,
    [](const P3 &p) { return p[0] > 0.5; },
    0.125,
    1e-13);
  check<3>(
    "3D tetrahedron, slanted face, x > 0.5",
    tetrahedron,
    3,
    [](const P3 &p) { return p[0] > 0.5; },
    std::sqrt(3.) / 8,
    1e-13);

  std::cout << "Part 2: the load of a unit block with a strip of traction "
               "-100 on x > 0.95 of its top, weight 1 (expected 6)\n";
  for (const std::string variant : {"2D, 1 cell", "2D, 16 cells", "3D"})
    {
      const bool three_d = variant == "3D";
      write("strip.prm",
            std::string("set Scene = masonry\nsubsection Masonry\n") +
              "  set Dimension = " + (three_d ? "3" : "2") +
              "\n  set Blocks per side = 1\n  set Refinement = " +
              (variant == "2D, 16 cells" ? "2" : "0") +
              "\n  subsection Boundary conditions\n"
              "    set Relative gap = 0\n"
              "    set Normal displacement zero = left, right, base where x "
              "> s" +
              (three_d ? ", front, back" : "") +
              "\n    set Traction boundaries = top where x > 0.95\n"
              "    set Traction = 0; -100" +
              (three_d ? "; 0" : "") +
              "\n  end\nend\nsubsection Output\n  set Directory = results\n"
              "  set Write VTU = false\n  set Progress = false\n"
              "  set Print timings = false\nend\n");
      std::filesystem::remove_all("results");
      const Result result = run({"strip.prm"});
      const double load   = load_size(read("results/strip/summary.json"));
      std::cout << variant << ": exit code " << result.code << ", load "
                << std::setprecision(12) << load << ", within 1e-12 of 6: "
                << yes_no(std::abs(load - 6) <= 6e-12) << "\n";
      if (result.code != 0)
        std::cout << result.err;
    }
}
