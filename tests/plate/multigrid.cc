// The plate's hierarchy of Bogner-Fox-Schmit meshes and the multigrid
// method that works on it (issue 22), against independent truth:
//  - the transfer: where a mesh halves another's and the plate is fully
//    clamped (nested spaces), the Hermite interpolation P reproduces the
//    coarse bicubic fields exactly, so the Galerkin product P^T A_fine P is
//    the coarse mesh's own assembled stiffness and P^T b_fine its own load,
//    to round-off. (The paper's clamping leaves w_xy free on the boundary:
//    a coarse field's normal slope is then nonzero between its nodes, and
//    the fine mesh clamps it at its new ones; those spaces are not nested,
//    the coarse problems are Galerkin products all the same.)
//  - the method: the same contact set and nodal DOFs as PDAS (1e-10
//    relative) with KKT <= 1e-10, on every obstacle, material and load, on
//    meshes that are a power of two times the coarsest and meshes that are
//    not (odd counts: non-nested levels), rectangular, fully clamped;
//  - a plate that does not touch its obstacle and one without any: the
//    unconstrained solution, against PDAS and the series solution.
// (A plate lying on the obstacle at every node: tests/plate/raised_obstacle.)

#include <unilateral/lcp/hierarchy.h>

#include "../test_tools.h"
#include "plate_runs.h"

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

  /// The hierarchy of a 16 x 16 plate (16, 8, 4 cells per side) and of a
  /// 20 x 12 one (20 x 12, 10 x 6, 5 x 6), fully clamped: each Galerkin
  /// product against the coarse mesh's own assembly.
  void
  check_transfer(const unsigned int n_x,
                 const unsigned int n_y,
                 const std::string &boundary)
  {
    const auto fine =
      plate_runs::run_plate("transfer_" + std::to_string(n_x) + "_" +
                              boundary.substr(0, 5),
                            plate("steel", "psi3", "f1", n_x, n_y, boundary),
                            "tnnmg");
    const auto &hierarchy = *fine.scene->problem().hierarchy;
    std::cout << n_x << " x " << n_y << " " << boundary << ": "
              << hierarchy.levels.size() << " levels" << std::endl;
    SparseMatrix A_fine = fine.scene->problem().A;
    Vector       b_fine = fine.scene->problem().b;
    for (std::size_t l = hierarchy.levels.size() - 1; l-- > 0;)
      {
        // The coarse mesh of this level: the fine counts halved, rounded up.
        unsigned int c_x = n_x, c_y = n_y;
        for (std::size_t k = l + 1; k < hierarchy.levels.size(); ++k)
          {
            c_x = c_x >= 8 ? (c_x + 1) / 2 : c_x;
            c_y = c_y >= 8 ? (c_y + 1) / 2 : c_y;
          }
        const auto coarse = plate_runs::run_plate(
          "transfer_" + std::to_string(c_x) + "_" + boundary.substr(0, 5),
          plate("steel", "psi3", "f1", c_x, c_y, boundary),
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
        A_fine = A;
        b_fine = b;
      }
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
  check_against_pdas("lead_psi2_f2_24", plate("lead", "psi2", "f2", 24, 24));
  // Odd counts: 19 -> 10 -> 5 and 21 x 13 -> 11 x 7, not nested.
  check_against_pdas("steel_psi3_f1_19", plate("steel", "psi3", "f1", 19, 19));
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
  // within 1e-5 of it).
  const double series = -0.00126532 * 1e8 / free.results().rigidity;
  std::cout << "  w_centre / w_series = " << std::fixed << std::setprecision(4)
            << free.results().centre_deflection / series << std::endl;
  verdict("  no obstacle: the series solution to 1e-4",
          std::abs(free.results().centre_deflection / series - 1) < 1e-4);
}
