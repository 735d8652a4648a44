#pragma once

#include <unilateral/base/blas_threads.h>
#include <unilateral/lcp/problem.h>
#include <unilateral/lcp/report.h>
#include <unilateral/lcp/sparse_cholesky.h>
#include <unilateral/lcp/tearing.h>

#include <string>
#include <vector>

namespace unilateral::lcp
{
  /**
   * The operators of the dual of a torn problem (TFETI, Dostal, Horak &
   * Kucera 2006): K^+ and R by shape, B, G = R^T B^T = (B R)^T and the
   * coarse matrix G G^T, factorised once, and with them
   *   F = B K^+ B^T,  P = I - Q,  Q = G^T (G G^T)^-1 G.
   *
   * K_s^+ = (K_s + s R_s R_s^T)^-1 - R_s R_s^T / s, R_s made orthonormal and
   * s the mean diagonal of K_s: the Moore-Penrose inverse, dense, once per
   * shape, so that K^+ x is one product of matrices per group of
   * subdomains of that shape (BLAS 3). G G^T is singular where a subdomain's
   * rigid motions are held by no multiplier (no support, no neighbour):
   * coarse_factorised() is then false and coarse_failure() says which.
   * Likewise a subdomain whose stiffness has more null space than its
   * rigid motions, or too little conditioning for K_s + s R R^T to tell
   * (blocks of cells far from square): pseudo_inverses_formed() is false
   * and coarse_failure() names it; nothing else is set up then.
   *
   * The subdomains are distributed over the ranks of the tearing's
   * communicator, each rank its own contiguous run of them (balanced by
   * the work of their local solves): a product with F sums the ranks'
   * parts, the one communication of an iteration. Everything else, the
   * coarse problem included, is replicated: every rank computes the same
   * multipliers.
   *
   * While it lives, OpenBLAS runs on one thread: a coarse solve is a
   * sequence of small triangular BLAS calls per supernode, which threads
   * slow down many times over (benchmarks/tfeti/README.md).
   *
   * Every product with F and every coarse solve is counted and timed
   * (add_work), for the report: products with F are TFETI's measure of
   * work, the coarse problem its one global coupling.
   */
  class DualOperators
  {
  public:
    explicit DualOperators(const Tearing &tearing);

    DualOperators(const DualOperators &) = delete;
    DualOperators &
    operator=(const DualOperators &) = delete;

    const Tearing &
    tearing() const
    {
      return torn;
    }

    Index
    n_multipliers() const
    {
      return torn.n_multipliers();
    }

    /// The size of the coarse problem: the rigid motions of all subdomains.
    Index
    n_coarse() const
    {
      return coarse_size;
    }

    const SparseMatrix &
    G() const
    {
      return coarse_matrix;
    }

    bool
    pseudo_inverses_formed() const
    {
      return pseudo_inverse_failure.empty();
    }

    bool
    coarse_factorised() const
    {
      return factorised;
    }

    /// Why G G^T is singular (which subdomain floats), for a message.
    std::string
    coarse_failure() const;

    /// K^+ x.
    Vector
    apply_pseudo_inverse(const Vector &x) const;

    /// R alpha.
    Vector
    apply_rigid_motions(const Vector &alpha) const;

    /// R^T x.
    Vector
    apply_rigid_motions_transposed(const Vector &x) const;

    /// F l = B K^+ B^T l (counted; the sum over the ranks' subdomains).
    Vector
    apply_F(const Vector &l) const;

    /// B K B^T l, the lumped preconditioner of FETI (Farhat & Roux): an
    /// approximate inverse of F at the cost of a product with F.
    Vector
    apply_lumped(const Vector &l) const;

    /// (G G^T)^-1 v (counted).
    Vector
    coarse_solve(const Vector &v) const;

    /// P l = l - Q l.
    Vector
    apply_P(const Vector &l) const;

    /// Q l = G^T (G G^T)^-1 G l.
    Vector
    apply_Q(const Vector &l) const;

    /// What a product with P F P + rho Q computes of its input x on the
    /// way: G x and (G G^T)^-1 G x, so that ||Q x||^2 = (G x)^T c and
    /// Q x = G^T c.
    struct CoarseParts
    {
      Vector Gx, c;
    };

    /// (P F P + rho Q) x, with two coarse solves and one product with F;
    /// the coarse parts of x into @p parts.
    Vector
    apply_penalised(const Vector &x, double rho, CoarseParts &parts) const;

    unsigned int
    products_with_F() const
    {
      return n_products;
    }

    /// The coarse problem's size and factorisation, into @p report's
    /// figures and counters.
    void
    add_setup(Report &report) const;

    /// Products with F, coarse solves and their times, into @p report.
    void
    add_work(Report &report) const;

  private:
    void
    pseudo_inverses();

    void
    coarse_space();

    void
    own_subdomains();

    /// Which matrix of each shape apply_blockwise takes.
    enum class Local
    {
      pseudo_inverse,
      stiffness
    };

    /// The sum over the subdomains of B_s M_s B_s^T l (M_s = K_s^+ or K_s),
    /// each rank its own, summed over the ranks.
    Vector
    apply_blockwise(Local local, const Vector &l) const;

    /// OpenBLAS on one thread while this lives (see the class comment).
    blas::ScopedThreads      one_blas_thread{1};
    const Tearing           &torn;
    std::vector<DenseMatrix> pseudo_inverse, rigid;
    /// Why a subdomain's K_s^+ could not be formed ("" if every one was).
    std::string pseudo_inverse_failure;
    /// This rank's subdomains, as runs of one shape.
    std::vector<Tearing::Group> own;
    Index                       n_own   = 0;
    unsigned int                n_ranks = 1;
    SparseMatrix                coarse_matrix;
    Index                       coarse_size = 0;
    SparseCholesky              coarse;
    bool                        factorised = false;
    Counters                    setup_counters;
    double                      setup_seconds = 0, factorisation_seconds = 0;
    mutable unsigned int        n_products = 0, n_coarse_solves = 0;
    mutable unsigned int        n_lumped        = 0;
    mutable double              product_seconds = 0, coarse_seconds = 0;
    mutable double              lumped_seconds = 0;
  };
} // namespace unilateral::lcp
