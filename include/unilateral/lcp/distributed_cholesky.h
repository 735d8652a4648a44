#pragma once

#include <unilateral/lcp/problem.h>
#include <unilateral/lcp/report.h>

#include <deal.II/base/mpi.h>

#include <memory>

namespace unilateral::lcp
{
  /**
   * The LDL' factorisation of a symmetric matrix spread over the ranks of a
   * communicator: MUMPS through PETSc (route 1 of issue 24). Every rank holds
   * the whole matrix (the scenes build the same problem on every rank); each
   * gives MUMPS its own contiguous run of rows, MUMPS distributes the factor
   * and the work over all ranks, and every solve returns the whole solution
   * on every rank, so that the methods above run unchanged and take the same
   * decisions on every rank.
   *
   * As SparseCholesky: the symbolic analysis runs once per sparsity pattern
   * (the pattern agreed over the ranks), every numeric factorisation of the
   * same pattern reuses it, and a factor that is not positive definite is
   * refused. Positive definite is checked, not assumed: MUMPS factorises in
   * its general symmetric mode and counts negative pivots (INFOG(12)), and
   * with a @p minimum_rcond it also counts null pivots (ICNTL(24), CNTL(3)),
   * the counterpart of CHOLMOD's reciprocal condition estimate. What MUMPS
   * reports is global, so every rank decides alike.
   *
   * Why PETSc's MUMPS interface and not deal.II's (PETScWrappers::
   * SparseDirectMUMPS): that one factorises afresh for every solve and
   * solves one right-hand side at a time; the active-set methods refactorise
   * one pattern many times and solve many columns at once.
   */
  class DistributedCholesky
  {
  public:
    explicit DistributedCholesky(const MPI_Comm &communicator);
    ~DistributedCholesky();
    DistributedCholesky(const DistributedCholesky &) = delete;
    DistributedCholesky &
    operator=(const DistributedCholesky &) = delete;

    /// Throws InputError unless MPI runs (the program was started by an MPI
    /// launcher) and PETSc offers MUMPS.
    static void
    require_available();

    /**
     * Numeric factorisation of @p A (both triangles stored), after the
     * symbolic analysis if its pattern differs from the one analysed last.
     * False (no factor kept) if A is not positive definite, or if a pivot is
     * below @p minimum_rcond times the largest entry (0: not checked).
     */
    bool
    factorise(const SparseMatrix &A, double minimum_rcond, Counters &counters);

    /// Solve A X = B for every column of B at once; B and X whole on every
    /// rank.
    void
    solve(const DenseMatrix &B, DenseMatrix &X) const;

    bool
    has_factor() const;

    /// Entries of the factor over all ranks (MUMPS's INFOG(29)).
    double
    factor_nonzeros() const;

    /// Floating-point operations of the elimination (MUMPS's RINFOG(3)).
    double
    factorisation_flops() const;

    unsigned int
    n_ranks() const;

  private:
    struct Implementation;
    std::unique_ptr<Implementation> implementation;
  };

  /**
   * While an object of this class lives, every SparseCholesky made on this
   * thread factorises through a DistributedCholesky over @p communicator
   * (the driver opens one around a method's run when 'Solver/
   * Factorisation' asks for it). A scope rather than a parameter handed down
   * to every system: the methods build their factorisations deep inside
   * (active-set systems, the interior point's Newton matrix, the projection
   * step) and need not know where the factor lives.
   */
  class DistributedFactorisations
  {
  public:
    explicit DistributedFactorisations(const MPI_Comm &communicator);
    ~DistributedFactorisations();
    DistributedFactorisations(const DistributedFactorisations &) = delete;
    DistributedFactorisations &
    operator=(const DistributedFactorisations &) = delete;

    /// The communicator of the innermost open scope on this thread, or
    /// nullptr if none is open.
    static const MPI_Comm *
    current();

  private:
    MPI_Comm                         communicator;
    const DistributedFactorisations *enclosing;
  };
} // namespace unilateral::lcp
