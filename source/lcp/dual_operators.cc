#include <unilateral/base/blas_threads.h>
#include <unilateral/base/ranks.h>
#include <unilateral/lcp/dual_operators.h>

#include <deal.II/base/mpi.h>

#include <Eigen/Dense>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

namespace unilateral::lcp
{
  namespace
  {
    /// Adds the wall time of its lifetime to a number of seconds.
    class Stopwatch
    {
    public:
      explicit Stopwatch(double &seconds)
        : seconds(seconds)
        , start(std::chrono::steady_clock::now())
      {}

      ~Stopwatch()
      {
        const std::chrono::duration<double> elapsed =
          std::chrono::steady_clock::now() - start;
        seconds += elapsed.count();
      }

    private:
      double                               &seconds;
      std::chrono::steady_clock::time_point start;
    };
  } // namespace

  DualOperators::DualOperators(const Tearing &tearing)
    : torn(tearing)
  {
    Stopwatch watch(setup_seconds);
    pseudo_inverses();
    if (!pseudo_inverse_failure.empty())
      return; // factorised stays false; coarse_failure() says why
    coarse_space();
    own_subdomains();
  }

  // Rank r takes the subdomains whose midpoint of work (n_s^2 per subdomain,
  // its dense local solve) lies in the r-th of n equal parts of the total.
  void
  DualOperators::own_subdomains()
  {
    n_ranks                  = ranks::n_ranks(torn.communicator);
    const unsigned int rank  = ranks::this_rank(torn.communicator);
    double             total = 0;
    for (const Tearing::Group &group : torn.groups)
      total +=
        std::pow(static_cast<double>(torn.shapes[group.shape].stiffness.rows()),
                 2) *
        static_cast<double>(group.n_subdomains);
    double done = 0;
    for (const Tearing::Group &group : torn.groups)
      {
        const Index  n    = torn.shapes[group.shape].stiffness.rows();
        const double work = static_cast<double>(n) * static_cast<double>(n);
        for (Index k = 0; k < group.n_subdomains; ++k, done += work)
          {
            const auto owner = static_cast<unsigned int>(
              std::min<double>(n_ranks - 1,
                               n_ranks * (done + 0.5 * work) / total));
            if (owner != rank)
              continue;
            const Index dof = group.first_dof + k * n;
            if (!own.empty() && own.back().shape == group.shape &&
                own.back().first_dof + own.back().n_subdomains * n == dof)
              ++own.back().n_subdomains;
            else
              own.push_back({group.shape, dof, 1});
            ++n_own;
          }
      }
  }

  // K_s^+ = (K_s + s R R^T)^-1 - R R^T / s with R orthonormal: K_s + s R R^T
  // is K_s on its range and s on its null space.
  void
  DualOperators::pseudo_inverses()
  {
    for (const Tearing::Shape &shape : torn.shapes)
      {
        const Index       n = static_cast<Index>(shape.stiffness.rows());
        const DenseMatrix R =
          Eigen::HouseholderQR<DenseMatrix>(shape.rigid_motions)
            .householderQ() *
          DenseMatrix::Identity(n, shape.rigid_motions.cols());
        const double            s       = shape.stiffness.diagonal().mean();
        const DenseMatrix       RRt     = R * R.transpose();
        const DenseMatrix       regular = shape.stiffness + s * RRt;
        Eigen::LLT<DenseMatrix> llt(regular);
        // K_s with more null space than R (a subdomain in two parts, or a
        // hinge) leaves K_s + s R R^T singular and K_s^+ meaningless; the
        // answer would still be made exact by the projection step, so
        // nothing else would show it. The scene splits such parts, so what
        // is left here is a stiffness too ill-conditioned to tell: a block
        // of 2 x 3e-5 on 4 cells ended in an internal error (a review).
        const Vector pivots = llt.matrixLLT().diagonal();
        if (llt.info() != Eigen::Success ||
            std::pow(pivots.minCoeff() / pivots.maxCoeff(), 2) < 1e-14)
          {
            Index subdomain = 0;
            for (const Tearing::Group &group : torn.groups)
              {
                if (&torn.shapes[group.shape] == &shape)
                  break;
                subdomain += group.n_subdomains;
              }
            pseudo_inverse_failure =
              "the stiffness of " + torn.describe(subdomain) +
              " is singular beyond its " + std::to_string(R.cols()) +
              " rigid motions, or too ill-conditioned to tell (K_s + s R "
              "R^T has a condition above 1e14: cells far from square, as "
              "in a very thin block); choose 'Solver/Method' = pdas, which "
              "does not tear the problem";
            return;
          }
        pseudo_inverse.push_back(llt.solve(DenseMatrix::Identity(n, n)) -
                                 RRt / s);
        rigid.push_back(R);
      }
  }

  // G = R^T B^T (as (B R)^T) and G G^T, factorised.
  void
  DualOperators::coarse_space()
  {
    std::vector<Index>               coarse_of_dof(torn.n_dofs());
    std::vector<Index>               local_of_dof(torn.n_dofs());
    std::vector<const DenseMatrix *> rigid_of_dof(torn.n_dofs());
    for (const Tearing::Group &group : torn.groups)
      {
        const DenseMatrix &R = rigid[group.shape];
        const Index        n = static_cast<Index>(R.rows());
        for (Index k = 0; k < group.n_subdomains; ++k)
          {
            for (Index j = 0; j < n; ++j)
              {
                const Index dof    = group.first_dof + k * n + j;
                coarse_of_dof[dof] = coarse_size;
                local_of_dof[dof]  = j;
                rigid_of_dof[dof]  = &R;
              }
            coarse_size += static_cast<Index>(R.cols());
          }
      }
    std::vector<Eigen::Triplet<double, Index>> entries;
    for (Index dof = 0; dof < torn.B.outerSize(); ++dof)
      for (SparseMatrix::InnerIterator it(torn.B, dof); it; ++it)
        {
          const DenseMatrix &R = *rigid_of_dof[dof];
          for (Index a = 0; a < R.cols(); ++a)
            entries.emplace_back(coarse_of_dof[dof] + a,
                                 it.row(),
                                 it.value() * R(local_of_dof[dof], a));
        }
    coarse_matrix.resize(coarse_size, torn.n_multipliers());
    coarse_matrix.setFromTriplets(entries.begin(), entries.end());
    coarse_matrix.makeCompressed();
    SparseMatrix GGt = coarse_matrix * SparseMatrix(coarse_matrix.transpose());
    GGt.makeCompressed();
    // Its condition grows like the square of the number of subdomains
    // across the body; below this estimate the rigid motions are not all
    // held.
    coarse.minimum_rcond = 1e-14;
    // Solved with twice per product with F: the ordering with the fewer
    // flops (METIS's on these grids of subdomains) pays at once.
    coarse.try_nested_dissection    = true;
    coarse.nested_dissection_fronts = 0;
    Stopwatch watch(factorisation_seconds);
    factorised = coarse.factorise(GGt, setup_counters);
  }

  std::string
  DualOperators::coarse_failure() const
  {
    if (!pseudo_inverse_failure.empty())
      return pseudo_inverse_failure;
    // A subdomain that no multiplier touches, or whose multipliers leave a
    // rigid motion free: its own block of G G^T is singular.
    Index first = 0, subdomain = 0;
    for (const Tearing::Group &group : torn.groups)
      {
        const Index r = static_cast<Index>(rigid[group.shape].cols());
        for (Index k = 0; k < group.n_subdomains; ++k, ++subdomain)
          {
            const DenseMatrix own =
              DenseMatrix(coarse_matrix.middleRows(first, r)) *
              DenseMatrix(coarse_matrix.middleRows(first, r)).transpose();
            first += r;
            Eigen::SelfAdjointEigenSolver<DenseMatrix> eigen(own);
            if (!(eigen.eigenvalues().minCoeff() >
                  1e-12 * eigen.eigenvalues().cwiseAbs().maxCoeff()))
              return "the coarse matrix G G^T is singular: " +
                     torn.describe(subdomain) +
                     " is held by no support and no neighbour in some "
                     "direction, so a rigid motion of it is free and the "
                     "problem has no unique solution; TFETI needs every "
                     "rigid motion held: where the load drives it, the "
                     "structure has no equilibrium; where it does not (a "
                     "block that may slide unloaded on frictionless "
                     "joints), the problem has solutions; solve it with "
                     "pdas, which does not tear the problem";
          }
      }
    // Also where the load does not drive that motion (a 3D wall whose
    // blocks may slide along z unloaded): the problem then has solutions,
    // which a method on the whole problem finds.
    return "the coarse matrix G G^T is singular: the subdomains together "
           "have a free rigid motion (a mechanism: some are held only by "
           "others that are free themselves); TFETI needs every rigid "
           "motion held, also one that the load does not drive: hold it by "
           "a support, or choose a method that does not tear the problem";
  }

  Vector
  DualOperators::apply_pseudo_inverse(const Vector &x) const
  {
    Vector y(x.size());
    for (const Tearing::Group &group : torn.groups)
      {
        const DenseMatrix &Kplus = pseudo_inverse[group.shape];
        const Index        n     = static_cast<Index>(Kplus.rows());
        const Eigen::Map<const DenseMatrix> X(x.data() + group.first_dof,
                                              n,
                                              group.n_subdomains);
        Eigen::Map<DenseMatrix>             Y(y.data() + group.first_dof,
                                  n,
                                  group.n_subdomains);
        Y.noalias() = Kplus * X;
      }
    return y;
  }

  Vector
  DualOperators::apply_rigid_motions(const Vector &alpha) const
  {
    Vector x(torn.n_dofs());
    Index  first = 0;
    for (const Tearing::Group &group : torn.groups)
      {
        const DenseMatrix                  &R = rigid[group.shape];
        Eigen::Map<DenseMatrix>             X(x.data() + group.first_dof,
                                  R.rows(),
                                  group.n_subdomains);
        const Eigen::Map<const DenseMatrix> A(alpha.data() + first,
                                              R.cols(),
                                              group.n_subdomains);
        X.noalias() = R * A;
        first += static_cast<Index>(R.cols()) * group.n_subdomains;
      }
    return x;
  }

  Vector
  DualOperators::apply_rigid_motions_transposed(const Vector &x) const
  {
    Vector alpha(coarse_size);
    Index  first = 0;
    for (const Tearing::Group &group : torn.groups)
      {
        const DenseMatrix                  &R = rigid[group.shape];
        const Eigen::Map<const DenseMatrix> X(x.data() + group.first_dof,
                                              R.rows(),
                                              group.n_subdomains);
        Eigen::Map<DenseMatrix>             A(alpha.data() + first,
                                  R.cols(),
                                  group.n_subdomains);
        A.noalias() = R.transpose() * X;
        first += static_cast<Index>(R.cols()) * group.n_subdomains;
      }
    return alpha;
  }

  Vector
  DualOperators::apply_F(const Vector &l) const
  {
    Stopwatch watch(product_seconds);
    ++n_products;
    return apply_blockwise(Local::pseudo_inverse, l);
  }

  Vector
  DualOperators::apply_lumped(const Vector &l) const
  {
    Stopwatch watch(lumped_seconds);
    ++n_lumped;
    return apply_blockwise(Local::stiffness, l);
  }

  Vector
  DualOperators::apply_blockwise(const Local local, const Vector &l) const
  {
    Vector y = Vector::Zero(n_multipliers());
    for (const Tearing::Group &piece : own)
      {
        const DenseMatrix &M = local == Local::pseudo_inverse ?
                                 pseudo_inverse[piece.shape] :
                                 torn.shapes[piece.shape].stiffness;
        const Index        n = static_cast<Index>(M.rows());
        const auto         B =
          torn.B.middleCols(piece.first_dof, n * piece.n_subdomains);
        const Vector      x = B.transpose() * l;
        const DenseMatrix Z =
          M * Eigen::Map<const DenseMatrix>(x.data(), n, piece.n_subdomains);
        y += B * Eigen::Map<const Vector>(Z.data(), Z.size());
      }
    // Reduced on rank 0 and broadcast rather than all-reduced: every rank
    // must get the same sum to the last bit, or their iterations drift
    // apart.
    if (n_ranks > 1)
      {
        const unsigned int rank = ranks::this_rank(torn.communicator);
        const int          size = static_cast<int>(y.size());
        MPI_Reduce(rank == 0 ? MPI_IN_PLACE : y.data(),
                   y.data(),
                   size,
                   MPI_DOUBLE,
                   MPI_SUM,
                   0,
                   torn.communicator);
        MPI_Bcast(y.data(), size, MPI_DOUBLE, 0, torn.communicator);
      }
    return y;
  }

  Vector
  DualOperators::coarse_solve(const Vector &v) const
  {
    Stopwatch watch(coarse_seconds);
    ++n_coarse_solves;
    Vector y;
    coarse.solve(v, y);
    return y;
  }

  Vector
  DualOperators::apply_Q(const Vector &l) const
  {
    return coarse_matrix.transpose() * coarse_solve(coarse_matrix * l);
  }

  Vector
  DualOperators::apply_P(const Vector &l) const
  {
    return l - apply_Q(l);
  }

  Vector
  DualOperators::apply_penalised(const Vector &x,
                                 const double  rho,
                                 CoarseParts  &parts) const
  {
    parts.Gx        = coarse_matrix * x;
    parts.c         = coarse_solve(parts.Gx);
    const Vector Qx = coarse_matrix.transpose() * parts.c;
    return apply_P(apply_F(x - Qx)) + rho * Qx;
  }

  void
  DualOperators::add_setup(Report &report) const
  {
    report.counters += setup_counters;
    report.set_figure("setup_seconds", setup_seconds);
    report.set_figure("coarse_factorisation_seconds", factorisation_seconds);
    report.set_figure("subdomains", torn.n_subdomains());
    report.set_figure("multipliers", torn.n_multipliers());
    report.set_figure("coarse_size", coarse_size);
    report.set_figure("coarse_factor_nonzeros", coarse.factor_nonzeros());
    report.set_figure("ranks", n_ranks);
    report.set_figure("most_subdomains_on_a_rank",
                      dealii::Utilities::MPI::max(static_cast<double>(n_own),
                                                  torn.communicator));
  }

  void
  DualOperators::add_work(Report &report) const
  {
    report.counters.matrix_vector_products += n_products;
    report.counters.triangular_solves += n_coarse_solves;
    report.set_figure("products_with_F_seconds", product_seconds);
    report.set_figure("coarse_solve_seconds", coarse_seconds);
    report.set_figure("products_with_F", n_products);
    report.set_figure("coarse_solves", n_coarse_solves);
    if (n_lumped > 0)
      {
        report.set_figure("lumped_products", n_lumped);
        report.set_figure("lumped_products_seconds", lumped_seconds);
      }
  }
} // namespace unilateral::lcp
