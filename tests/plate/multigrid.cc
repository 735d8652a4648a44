// The plate's hierarchy of Bogner-Fox-Schmit meshes and the multigrid
// method that works on it (issue 22), against independent truth:
//  - the transfer: where a mesh refines another's 2 or 3 times per side
//    (nested spaces), the Hermite interpolation P reproduces a coarse field
//    that is one bicubic polynomial exactly (value, slopes and twist at the
//    fine nodes, away from the clamped border), and where the plate is
//    fully clamped the Galerkin product P^T A_fine P is the coarse mesh's
//    own assembled stiffness and P^T b_fine its own load, to round-off. (The
//    paper's clamping leaves w_xy free on the boundary: a coarse field's normal
//    slope is then nonzero between its nodes, and the fine mesh clamps it at
//    its new ones; those spaces are not nested, the coarse problems are
//    Galerkin products all the same.)
//  - the method: the same contact set and nodal DOFs as PDAS (1e-10
//    relative) with KKT <= 1e-10, on every obstacle, material and load, on
//    meshes that are a power of two times the coarsest and meshes that are
//    not (odd counts: non-nested levels), rectangular, fully clamped;
//  - a plate that does not touch its obstacle and one without any: the
//    unconstrained solution, against PDAS and the series solution.
// (A plate lying on the obstacle at every node: tests/plate/raised_obstacle.)

#include <unilateral/fe/bogner_fox_schmit.h>
#include <unilateral/lcp/hierarchy.h>
#include <unilateral/scenes/plate/assembly.h>

#include "../test_tools.h"
#include "plate_runs.h"

#include <deal.II/dofs/dof_tools.h>

#include <cmath>
#include <iomanip>

using test_tools::verdict;

namespace
{
  using unilateral::lcp::SparseMatrix;
  using unilateral::lcp::Vector;

  double
  relative_difference(const dealii::Vector<double> &a,
                      const dealii::Vector<double> &b)
  {
    double difference = 0, scale = 0;
    for (unsigned int i = 0; i < a.size(); ++i)
      {
        difference = std::max(difference, std::abs(a[i] - b[i]));
        scale      = std::max(scale, std::abs(b[i]));
      }
    return difference / (scale > 0 ? scale : 1);
  }

  double
  max_entry(const SparseMatrix &A)
  {
    double largest = 0;
    for (int k = 0; k < A.outerSize(); ++k)
      for (SparseMatrix::InnerIterator it(A, k); it; ++it)
        largest = std::max(largest, std::abs(it.value()));
    return largest;
  }

  std::string
  plate(const std::string &material,
        const std::string &obstacle,
        const std::string &force,
        const unsigned int n_x,
        const unsigned int n_y,
        const std::string &boundary = "clamped",
        const double       length_x = 100)
  {
    std::ostringstream text;
    text << "subsection Geometry\n  set Elements x = " << n_x
         << "\n  set Elements y = " << n_y << "\n  set Length x = " << length_x
         << "\n  set Boundary condition = " << boundary << "\nend\n"
         << "subsection Material\n  set Name = " << material << "\nend\n"
         << "subsection Obstacle\n  set Function = " << obstacle << "\nend\n"
         << "subsection Load\n  set Force = " << force << "\nend\n";
    return text.str();
  }

  /// The hierarchy's rule for the next coarser count of a side (while it
  /// has at least 8 cells: by 2 if even, by 3 if a multiple of 3, else
  /// halved rounded up).
  unsigned int
  coarser(const unsigned int n)
  {
    return n < 8 ? n : n % 2 == 0 ? n / 2 : n % 3 == 0 ? n / 3 : (n + 1) / 2;
  }

  /// Per unknown of a plate run: its node and its component (w, w_x, w_y,
  /// w_xy), numbered as the scene numbers its free DOFs.
  std::vector<std::pair<dealii::Point<2>, unsigned int>>
  unknowns(const plate_runs::Run &run, const bool clamp_twist)
  {
    const dealii::DoFHandler<2> &dof_handler = run.scene->get_dof_handler();
    const auto free_dofs = unilateral::plate::number_free_dofs(
      dof_handler.n_dofs(),
      dealii::DoFTools::extract_boundary_dofs(
        dof_handler, dealii::ComponentMask({true, true, true, clamp_twist})));
    const std::vector<unsigned int> bfs_index =
      unilateral::fe::bfs_local_indices(dof_handler.get_fe());
    std::vector<std::pair<dealii::Point<2>, unsigned int>> result(
      free_dofs.size());
    std::vector<dealii::types::global_dof_index> local_dofs(bfs_index.size());
    for (const auto &cell : dof_handler.active_cell_iterators())
      {
        cell->get_dof_indices(local_dofs);
        for (unsigned int i = 0; i < local_dofs.size(); ++i)
          if (const auto k = free_dofs.index[local_dofs[i]]; k >= 0)
            result[k] = {cell->vertex(bfs_index[i] / 4), bfs_index[i] % 4};
      }
    return result;
  }

  /// The derivative of @p p that DOF component @p component holds.
  double
  component_value(const test_tools::Polynomial &p,
                  const dealii::Point<2>       &x,
                  const unsigned int            component)
  {
    const unsigned int dx[] = {0, 1, 0, 1}, dy[] = {0, 0, 1, 1};
    return p.derivative(x, dx[component], dy[component]);
  }

  /**
   * P carries the coarse field whose unknowns are those of one bicubic
   * polynomial p (scaled to be of order 1 on the plate) to p's value,
   * slopes and twist at the fine nodes, to 1e-12 of the largest: at every
   * fine node at least one coarse cell away from the clamped border (the
   * coarse field equals p on the cells that touch no clamped node).
   */
  bool
  reproduces_bicubic(const SparseMatrix    &P,
                     const plate_runs::Run &coarse,
                     const plate_runs::Run &fine,
                     const double           h_x,
                     const double           h_y,
                     const double           length_x,
                     const double           length_y,
                     const bool             clamp_twist)
  {
    test_tools::Sequence             sequence(7);
    std::vector<std::vector<double>> a(4, std::vector<double>(4));
    for (unsigned int i = 0; i < 4; ++i)
      for (unsigned int j = 0; j < 4; ++j)
        a[i][j] =
          sequence.next() / std::pow(length_x, i) / std::pow(length_y, j);
    const test_tools::Polynomial p(a);

    const auto coarse_unknowns = unknowns(coarse, clamp_twist);
    const auto fine_unknowns   = unknowns(fine, clamp_twist);
    if (static_cast<long>(coarse_unknowns.size()) != P.cols() ||
        static_cast<long>(fine_unknowns.size()) != P.rows())
      return false;
    Vector coarse_field(P.cols());
    for (long j = 0; j < P.cols(); ++j)
      coarse_field[j] =
        component_value(p, coarse_unknowns[j].first, coarse_unknowns[j].second);
    // P carries the solvers' unknowns, scaled on a mesh whose elements are
    // far from unit length (PlateScene::unknown_scale).
    const Vector fine_field =
      fine.scene->dofs_of(P * coarse.scene->unknowns_of(coarse_field));
    double       largest = 0, error = 0;
    unsigned int checked = 0;
    const double margin  = 1e-9 * length_x;
    for (long k = 0; k < P.rows(); ++k)
      {
        const dealii::Point<2> &x = fine_unknowns[k].first;
        if (x[0] < h_x - margin || x[0] > length_x - h_x + margin ||
            x[1] < h_y - margin || x[1] > length_y - h_y + margin)
          continue;
        const double truth = component_value(p, x, fine_unknowns[k].second);
        largest            = std::max(largest, std::abs(truth));
        error              = std::max(error, std::abs(fine_field[k] - truth));
        ++checked;
      }
    return checked > 0 && error <= 1e-12 * largest;
  }

  /// The hierarchy of a plate, fully clamped: each Galerkin product
  /// against the coarse mesh's own assembly, and the transfer against a
  /// bicubic field. 16 x 16: 8 x 8, 4 x 4; 20 x 12: 10 x 6, 5 x 6;
  /// 45 x 18 (factors 3 and 2): 15 x 9, 5 x 3.
  void
  check_transfer(const unsigned int n_x,
                 const unsigned int n_y,
                 const std::string &boundary,
                 const double       length_x = 100)
  {
    const std::string name = "transfer_" + std::to_string(n_x) + "_" +
                             boundary.substr(0, 5) +
                             (length_x != 100 ? "_short" : "");
    const auto fine = plate_runs::run_plate(
      name,
      plate("steel", "psi3", "f1", n_x, n_y, boundary, length_x),
      "tnnmg");
    const auto &hierarchy = *fine.scene->problem().hierarchy;
    std::cout << n_x << " x " << n_y << " " << boundary;
    if (length_x != 100)
      std::cout << ", " << length_x << " x 100 mm";
    std::cout << ": " << hierarchy.levels.size() << " levels" << std::endl;
    SparseMatrix    A_fine = fine.scene->problem().A;
    Vector          b_fine = fine.scene->problem().b;
    plate_runs::Run finer_run;
    const auto     *finer = &fine;
    unsigned int    c_x = n_x, c_y = n_y;
    for (std::size_t l = hierarchy.levels.size() - 1; l-- > 0;)
      {
        // The coarse mesh of this level, by the hierarchy's rule.
        c_x         = coarser(c_x);
        c_y         = coarser(c_y);
        auto coarse = plate_runs::run_plate(
          name + "_" + std::to_string(c_x),
          plate("steel", "psi3", "f1", c_x, c_y, boundary, length_x),
          "pdas");
        const SparseMatrix &P = hierarchy.levels[l].prolongation;
        const SparseMatrix  galerkin =
          SparseMatrix(P.transpose() * A_fine * P).pruned();
        const SparseMatrix &A          = coarse.scene->problem().A;
        const Vector       &b          = coarse.scene->problem().b;
        const Vector        restricted = P.transpose() * b_fine;
        verdict("  " + std::to_string(c_x) + " x " + std::to_string(c_y) +
                  ": P^T A P = the coarse stiffness to 1e-12",
                galerkin.rows() == A.rows() &&
                  max_entry(galerkin - A) <= 1e-12 * max_entry(A));
        verdict("  " + std::to_string(c_x) + " x " + std::to_string(c_y) +
                  ": P^T b = the coarse load to 1e-12",
                restricted.size() == b.size() &&
                  (restricted - b).lpNorm<Eigen::Infinity>() <=
                    1e-12 * b.lpNorm<Eigen::Infinity>());
        verdict("  " + std::to_string(c_x) + " x " + std::to_string(c_y) +
                  ": the level's bounds are the coarse mesh's obstacle",
                hierarchy.levels[l].constrained ==
                    coarse.scene->problem().constrained &&
                  hierarchy.levels[l].lower_bound ==
                    coarse.scene->problem().lower_bound);
        verdict("  " + std::to_string(c_x) + " x " + std::to_string(c_y) +
                  ": P reproduces a coarse bicubic field to 1e-12",
                reproduces_bicubic(P,
                                   coarse,
                                   *finer,
                                   length_x / c_x,
                                   100.0 / c_y,
                                   length_x,
                                   100,
                                   boundary == "fully clamped"));
        A_fine    = A;
        b_fine    = b;
        finer_run = std::move(coarse);
        finer     = &finer_run;
      }
    if (c_x != coarser(c_x) || c_y != coarser(c_y))
      std::cout << "  the hierarchy stops early" << std::endl;
  }

  /// TNNMG against PDAS on one plate; returns the TNNMG run.
  plate_runs::Run
  check_against_pdas(const std::string &name,
                     const std::string &text,
                     const std::string &tnnmg_settings = "")
  {
    const auto reference = plate_runs::run_plate(name + "_pdas", text, "pdas");
    auto       run       = plate_runs::run_plate(
      name + "_tnnmg", text, "tnnmg", false, tnnmg_settings);
    std::cout << name << ": cn = " << reference.results().n_contact
              << std::endl;
    verdict("  tnnmg converged, KKT <= 1e-10, same cn as pdas, nodal DOFs "
            "within 1e-10 relative",
            reference.report.converged() && run.report.converged() &&
              run.report.kkt.max() <= 1e-10 &&
              run.results().n_contact == reference.results().n_contact &&
              relative_difference(run.scene->nodal_values(),
                                  reference.scene->nodal_values()) <= 1e-10);
    return run;
  }
} // namespace

int
main()
{
  std::cout << "Transfer (nested meshes):" << std::endl;
  check_transfer(16, 16, "fully clamped");
  check_transfer(20, 12, "fully clamped");
  check_transfer(45, 18, "fully clamped");
  // Elements 0.003, 0.006 and 0.012 mm long (and 8.3, 16.7, 16.7 mm
  // across): the solvers' unknowns scaled on the two finer meshes, not on
  // the coarsest (PlateScene::unknown_scale), so that P maps scaled to
  // scaled and unscaled to scaled.
  check_transfer(20, 12, "fully clamped", 0.06);

  std::cout << "TNNMG against PDAS:" << std::endl;
  for (const std::string obstacle : {"psi1", "psi2", "psi3"})
    for (const std::string material : {"steel", "bronze", "lead"})
      for (const std::string force : {"f1", "f2"})
        check_against_pdas(material + "_" + obstacle + "_" + force + "_16",
                           plate(material, obstacle, force, 16, 16));
  check_against_pdas("steel_psi3_f1_32", plate("steel", "psi3", "f1", 32, 32));
  // The default is the W-cycle; the V-cycle (deal.II's Multigrid) too.
  check_against_pdas("steel_psi3_f1_32_v_cycle",
                     plate("steel", "psi3", "f1", 32, 32),
                     "  subsection TNNMG\n    set Cycle = V\n  end\n");
  // Without expansions the crossing step is only projected and searched;
  // with many, every crossing is held and the correction made again.
  for (const std::string expansions : {"0", "5"})
    check_against_pdas("steel_psi3_f1_32_expansions_" + expansions,
                       plate("steel", "psi3", "f1", 32, 32),
                       "  subsection TNNMG\n    set Expansions per correction "
                       "= " +
                         expansions + "\n  end\n");
  check_against_pdas("lead_psi2_f2_24", plate("lead", "psi2", "f2", 24, 24));
  // Odd counts: 19 -> 10 -> 5 (not nested), 21 x 13 -> 7 x 7 (nested in x
  // by 3, not in y), 45 -> 15 -> 5 (nested by 3).
  check_against_pdas("steel_psi3_f1_19", plate("steel", "psi3", "f1", 19, 19));
  check_against_pdas("steel_psi3_f1_45", plate("steel", "psi3", "f1", 45, 45));
  check_against_pdas("bronze_psi3_f2_21x13",
                     plate("bronze", "psi3", "f2", 21, 13, "clamped", 150));
  check_against_pdas("steel_psi3_f1_24x16",
                     plate("steel", "psi3", "f1", 24, 16, "clamped", 150));
  check_against_pdas("steel_psi3_f1_20_fully_clamped",
                     plate("steel", "psi3", "f1", 20, 20, "fully clamped"));

  std::cout << "No contact:" << std::endl;
  const auto far = check_against_pdas("steel_psi1_f1_32_far",
                                      plate("steel", "-50", "f1", 32, 32));
  verdict("  the obstacle far below: no node in contact",
          far.results().n_contact == 0);
  const auto free =
    check_against_pdas("steel_none_f1_32",
                       plate("steel", "none", "f1", 32, 32, "fully clamped"));
  // Timoshenko & Woinowsky-Krieger: w = 0.00126532 q a^4 / D at the
  // centre (tests/plate/convergence: the 32 x 32 fully clamped plate is
  // within 1e-5 of it), with the steel plate's D = E t^3 / (12 (1 - nu^2))
  // computed here (E = 21000 kg/mm^2, nu = 0.28, t = 2 mm), not the scene's.
  const double E = 21000, nu = 0.28, t = 2;
  const double rigidity = E * t * t * t / (12 * (1 - nu * nu));
  const double series   = -0.00126532 * 1e8 / rigidity;
  std::cout << "  w_centre / w_series = " << std::fixed << std::setprecision(4)
            << free.results().centre_deflection / series << std::endl;
  verdict("  no obstacle: the series solution to 1e-4",
          std::abs(free.results().centre_deflection / series - 1) < 1e-4);
}
