#pragma once

#include <unilateral/lcp/problem.h>

#include <deal.II/base/mpi.h>

#include <functional>
#include <string>
#include <vector>

namespace unilateral::lcp
{
  /**
   * An LCP torn into subdomains, for the dual methods (TFETI): the same
   * problem as its Problem, written in the physical displacements of
   * subdomains that each float on their own, glued and supported by
   * multipliers.
   *
   *   min 1/2 x^T K x - f^T x   subject to  B_I x <= c_I,  B_E x = c_E,
   *
   * K = diag(K_s) over the subdomains s (each K_s symmetric positive
   * semidefinite, its null space spanned by the columns of R_s: the rigid
   * motions), B the multipliers' rows: first the inequalities (no
   * penetration of a joint, a Signorini support), then the equalities
   * (supports, gluing of subdomains cut from one body). Every support is a
   * multiplier, so every subdomain floats alike ("total" FETI).
   *
   * Subdomains of one shape share K_s and R_s (the stiffness of a block does
   * not change when it is translated; its rigid motions are taken about its
   * own centre, so they are the same matrix too): they are stored once per
   * shape, and the subdomains of a shape are consecutive, so that the local
   * solves of a shape are one product of matrices.
   *
   * The map to the Problem's unknowns: u = to_problem x (the Problem's
   * variables are linear in the physical displacements, e.g. the gaps of
   * the masonry scene's change of variables). The Problem's answer, checked
   * as every answer is, is to_problem x.
   */
  struct Tearing
  {
    /// The stiffness and the rigid motions of one shape of subdomain.
    struct Shape
    {
      /// K_s (n_s x n_s), symmetric positive semidefinite.
      DenseMatrix stiffness;
      /// R_s (n_s x r_s), a basis of the null space of K_s.
      DenseMatrix rigid_motions;
    };

    /// A run of consecutive subdomains of one shape: subdomain k of it has
    /// the physical DOFs first_dof + k n_s, ..., first_dof + (k + 1) n_s - 1.
    struct Group
    {
      unsigned int shape;
      Index        first_dof;
      Index        n_subdomains;
    };

    std::vector<Shape> shapes;
    std::vector<Group> groups;
    /// f, in the physical DOFs (the groups' DOFs, in order, cover them all).
    Vector f;
    /// B: one row per multiplier, the first n_inequalities inequalities.
    SparseMatrix B;
    Vector       c;
    Index        n_inequalities = 0;
    /// u = to_problem x: the Problem's unknowns from the physical DOFs.
    SparseMatrix to_problem;
    /// For each inequality, the Problem's constrained unknown it bounds:
    /// its multiplier is that unknown's lambda (contact force), positive
    /// where the contact closes.
    std::vector<Index> inequality_unknown;

    /// Subdomain k (counted through the groups) in the scene's words, for
    /// messages ("block 7 with lower left corner (0.1, 0.2)"); unset:
    /// "subdomain k".
    std::function<std::string(Index)> describe_subdomain;

    /// The ranks that share the subdomains, each its own contiguous run of
    /// them (MPI_COMM_WORLD; with MPI not started, the one process).
    MPI_Comm communicator = MPI_COMM_WORLD;

    std::string
    describe(Index subdomain) const;

    /// The number of physical DOFs.
    Index
    n_dofs() const
    {
      return static_cast<Index>(f.size());
    }

    Index
    n_multipliers() const
    {
      return static_cast<Index>(B.rows());
    }

    Index
    n_subdomains() const;
  };

  /**
   * Check that @p tearing is consistent in itself and with @p problem
   * (sizes, the groups covering the DOFs, K_s R_s = 0 to round-off, the
   * map's shape). Throws std::logic_error naming what is wrong: a tearing is
   * built by a scene, not given by a user.
   */
  void
  check_tearing(const Tearing &tearing, const Problem &problem);
} // namespace unilateral::lcp
