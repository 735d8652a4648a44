/**
 * Total FETI (Dostal, Horak & Kucera, "Total FETI - an easier implementable
 * variant of the FETI method for numerical solution of elliptic PDE",
 * Commun. Numer. Meth. Engng 22 (2006) 1155-1162), with SMALBE and MPRGP
 * for contact (Dostal, "Optimal Quadratic Programming Algorithms", 2009,
 * ch. 6 and 9; PERMON's PermonQP is the public implementation it was read
 * against). It solves the problem torn into floating subdomains
 * (lcp/tearing.h),
 *     min 1/2 x^T K x - f^T x,  B_I x <= c_I,  B_E x = c_E,
 * through its dual: with K^+ a generalised inverse of K, R the rigid
 * motions, F = B K^+ B^T, G = R^T B^T, d = B K^+ f - c, e = R^T f,
 *     min 1/2 l^T F l - l^T d   subject to  l_I >= 0,  G l = e.
 * Steps:
 *  1. K_s^+ = (K_s + s R_s R_s^T)^-1 - R_s R_s^T / s per shape (R_s made
 *     orthonormal; s its mean diagonal), the coarse matrix G G^T factorised
 *     (singular: a subdomain that nothing holds, refused);
 *  2. homogenisation: l = l0 + m with l0 = G^T (G G^T)^-1 e, so G m = 0 and
 *     the bounds of m are -l0_I;
 *  3. SMALBE on G m = 0 (Q = G^T (G G^T)^-1 G, P = I - Q): minimise
 *     1/2 m^T (P F P + rho Q) m - m^T (P (d - F l0) - q) over the bounds by
 *     MPRGP (lcp/mprgp.h) to the precision min(M |Q m|, eta), then
 *     q += rho Q m; rho doubles when |Q m| does not halve;
 *  4. the rigid motions alpha = (G G^T)^-1 G (F l - d - g), g the final
 *     gradient of step 3 (the bounds' multipliers: no active set needed),
 *     and x = K^+ (f - B^T l) + R alpha, the Problem's u = to_problem x.
 * The answer is approximate (the dual's tolerance); the projection step
 * makes it exact on the Problem.
 */
#include <unilateral/base/input_error.h>
#include <unilateral/lcp/mprgp.h>
#include <unilateral/lcp/solver.h>
#include <unilateral/lcp/sparse_cholesky.h>
#include <unilateral/lcp/tearing.h>

#include <deal.II/base/parameter_handler.h>

#include <Eigen/Dense>

#include <cmath>
#include <iomanip>
#include <limits>
#include <ostream>

namespace unilateral::lcp
{
  namespace
  {
    /// Subsection "Solver/TFETI".
    class TfetiParameters : public MethodParametersBase<TfetiParameters>
    {
    public:
      /// On ||g^P|| and ||G l - e||, relative to ||d||.
      double tolerance = 1e-8;
      /// rho / ||P F P|| at the start.
      double penalty = 1;
      /// M of SMALBE's inner precision min(M ||Q m||, eta).
      double precision_factor = 1;
      /// Outer (SMALBE) iterations.
      unsigned int max_outer = 100;

      void
      add_parameters(dealii::ParameterHandler &prm) override
      {
        using namespace dealii::Patterns;
        prm.add_parameter("Tolerance",
                          tolerance,
                          "Stop when the projected gradient of the dual and "
                          "the violation of its equality G l = e are at most "
                          "this times ||d||. The projection step then makes "
                          "the answer exact.",
                          Double(0));
        prm.add_parameter("Penalty",
                          penalty,
                          "SMALBE's penalty rho at the start, relative to the "
                          "largest eigenvalue of P F P (estimated); it doubles "
                          "whenever the violation of G l = e fails to halve.",
                          Double(0));
        prm.add_parameter("Inner precision",
                          precision_factor,
                          "M of SMALBE: an inner (MPRGP) solve stops at a "
                          "projected gradient of M times the violation of "
                          "G l = e (or the final tolerance).",
                          Double(0));
        prm.add_parameter("Maximum outer iterations",
                          max_outer,
                          "SMALBE's iterations (updates of the equality "
                          "multiplier); 'Maximum iterations' bounds the "
                          "products with F.",
                          Integer(1));
      }

      void
      check(const std::string &section) const override
      {
        check_parameter(penalty > 0, section, "Penalty", penalty, "must be > 0");
        check_parameter(precision_factor > 0,
                        section,
                        "Inner precision",
                        precision_factor,
                        "must be > 0");
      }
    };

    /**
     * The operators of the dual: K^+ and R by shape, B, G = R^T B^T and the
     * factorised coarse matrix G G^T, and the projector P = I - Q.
     */
    class DualOperators
    {
    public:
      explicit DualOperators(const Tearing &tearing, Counters &counters)
        : tearing(tearing)
        , counters(counters)
      {
        pseudo_inverses();
        coarse_space();
      }

      /// False if G G^T is singular (a subdomain nothing holds).
      bool
      coarse_ok() const
      {
        return coarse_factorised;
      }

      /// y = K^+ x, one product of matrices per group.
      Vector
      apply_pseudo_inverse(const Vector &x) const
      {
        Vector y(x.size());
        for (const Tearing::Group &group : tearing.groups)
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

      /// x = R alpha.
      Vector
      apply_rigid_motions(const Vector &alpha) const
      {
        Vector x(tearing.n_dofs());
        Index  coarse = 0;
        for (const Tearing::Group &group : tearing.groups)
          {
            const DenseMatrix &R = rigid[group.shape];
            Eigen::Map<DenseMatrix> X(x.data() + group.first_dof,
                                      R.rows(),
                                      group.n_subdomains);
            const Eigen::Map<const DenseMatrix> A(alpha.data() + coarse,
                                                  R.cols(),
                                                  group.n_subdomains);
            X.noalias() = R * A;
            coarse += static_cast<Index>(R.cols()) * group.n_subdomains;
          }
        return x;
      }

      /// R^T x.
      Vector
      apply_rigid_motions_transposed(const Vector &x) const
      {
        Vector alpha(n_coarse);
        Index  coarse = 0;
        for (const Tearing::Group &group : tearing.groups)
          {
            const DenseMatrix &R = rigid[group.shape];
            const Eigen::Map<const DenseMatrix> X(x.data() + group.first_dof,
                                                  R.rows(),
                                                  group.n_subdomains);
            Eigen::Map<DenseMatrix> A(alpha.data() + coarse,
                                      R.cols(),
                                      group.n_subdomains);
            A.noalias() = R.transpose() * X;
            coarse += static_cast<Index>(R.cols()) * group.n_subdomains;
          }
        return alpha;
      }

      /// F l = B K^+ B^T l.
      Vector
      apply_F(const Vector &l) const
      {
        ++products_with_F;
        ++counters.matrix_vector_products;
        return tearing.B * apply_pseudo_inverse(tearing.B.transpose() * l);
      }

      /// (G G^T)^-1 v.
      Vector
      coarse_solve(const Vector &v) const
      {
        Vector y;
        coarse.solve(v, y);
        ++counters.triangular_solves;
        return y;
      }

      /// P l = l - G^T (G G^T)^-1 G l.
      Vector
      apply_P(const Vector &l) const
      {
        return l - G.transpose() * coarse_solve(G * l);
      }

      SparseMatrix       G;
      Index              n_coarse = 0;
      mutable unsigned int products_with_F = 0;

    private:
      // K_s^+ = (K_s + s R R^T)^-1 - R R^T / s with R orthonormal.
      void
      pseudo_inverses()
      {
        for (const Tearing::Shape &shape : tearing.shapes)
          {
            const DenseMatrix R =
              Eigen::HouseholderQR<DenseMatrix>(shape.rigid_motions)
                .householderQ() *
              DenseMatrix::Identity(shape.rigid_motions.rows(),
                                    shape.rigid_motions.cols());
            const double s   = shape.stiffness.diagonal().mean();
            const DenseMatrix RRt = R * R.transpose();
            const DenseMatrix regular = shape.stiffness + s * RRt;
            pseudo_inverse.push_back(
              regular.llt().solve(DenseMatrix::Identity(regular.rows(),
                                                        regular.cols())) -
              RRt / s);
            rigid.push_back(R);
          }
      }

      // G = R^T B^T (as (B R)^T) and G G^T, factorised.
      void
      coarse_space()
      {
        std::vector<Index> coarse_of_dof(tearing.n_dofs());
        std::vector<Index> local_of_dof(tearing.n_dofs());
        std::vector<const DenseMatrix *> rigid_of_dof(tearing.n_dofs());
        for (const Tearing::Group &group : tearing.groups)
          {
            const DenseMatrix &R = rigid[group.shape];
            const Index        n = static_cast<Index>(R.rows());
            for (Index k = 0; k < group.n_subdomains; ++k)
              {
                for (Index j = 0; j < n; ++j)
                  {
                    const Index dof     = group.first_dof + k * n + j;
                    coarse_of_dof[dof]  = n_coarse;
                    local_of_dof[dof]   = j;
                    rigid_of_dof[dof]   = &R;
                  }
                n_coarse += static_cast<Index>(R.cols());
              }
          }
        std::vector<Eigen::Triplet<double, Index>> entries;
        for (Index dof = 0; dof < tearing.B.outerSize(); ++dof)
          for (SparseMatrix::InnerIterator it(tearing.B, dof); it; ++it)
            {
              const DenseMatrix &R = *rigid_of_dof[dof];
              for (Index a = 0; a < R.cols(); ++a)
                entries.emplace_back(coarse_of_dof[dof] + a,
                                     it.row(),
                                     it.value() * R(local_of_dof[dof], a));
            }
        G.resize(n_coarse, tearing.n_multipliers());
        G.setFromTriplets(entries.begin(), entries.end());
        G.makeCompressed();
        SparseMatrix GGt = G * SparseMatrix(G.transpose());
        GGt.makeCompressed();
        coarse.minimum_rcond = 1e-14;
        coarse_factorised    = coarse.factorise(GGt, counters);
      }

      const Tearing           &tearing;
      Counters                &counters;
      std::vector<DenseMatrix> pseudo_inverse, rigid;
      SparseCholesky           coarse;
      bool                     coarse_factorised = false;
    };

    class Tfeti : public Solver
    {
    public:
      using Parameters = TfetiParameters;

      Tfeti(const SolverParameters &parameters, const Parameters &options)
        : Solver(parameters)
        , options(options)
      {}

      static SolverInfo
      properties()
      {
        SolverInfo info;
        info.name        = "tfeti";
        info.label       = "TFETI";
        info.description = "total FETI (Dostal et al.): the dual of the "
                           "problem torn into floating subdomains, by SMALBE "
                           "and MPRGP; needs a scene that tears its problem "
                           "(masonry)";
        info.subsection         = "TFETI";
        info.default_iterations = "100000 products with F";
        info.exact              = false;
        info.needs_tearing      = true;
        return info;
      }

      void
      solve(const Problem &problem,
            Solution      &solution,
            Report        &report,
            std::ostream  *progress) override;

    private:
      const Parameters options;
    };

    // The largest eigenvalue of P F P, by power iteration (an estimate from
    // below, raised by a tenth for MPRGP's step length).
    double
    largest_eigenvalue(const DualOperators &dual, const Index n)
    {
      Vector x = dual.apply_P(Vector::Ones(n));
      double estimate = 0;
      for (unsigned int k = 0; k < 30 && x.norm() > 0; ++k)
        {
          x /= x.norm();
          const Vector y = dual.apply_P(dual.apply_F(dual.apply_P(x)));
          estimate       = x.dot(y);
          x              = y;
        }
      return 1.1 * estimate;
    }

    void
    Tfeti::solve(const Problem &problem,
                 Solution      &solution,
                 Report        &report,
                 std::ostream  *progress)
    {
      const Tearing &tearing = *problem.tearing;
      check_tearing(tearing, problem);
      DualOperators dual(tearing, report.counters);
      if (!dual.coarse_ok())
        {
          report.status  = Status::singular;
          report.message = "TFETI: the coarse matrix G G^T is singular: a "
                           "subdomain is held by no support and no "
                           "neighbour, so its rigid motions are free";
          return;
        }
      const Index n = tearing.n_multipliers();
      // Step 2: homogenisation.
      const Vector e      = dual.apply_rigid_motions_transposed(tearing.f);
      const Vector l0     = dual.G.transpose() * dual.coarse_solve(e);
      const Vector Kplusf = dual.apply_pseudo_inverse(tearing.f);
      const Vector d      = tearing.B * Kplusf - tearing.c;
      Vector       lower  = Vector::Constant(
        n, -std::numeric_limits<double>::infinity());
      for (Index i = 0; i < tearing.n_inequalities; ++i)
        lower[i] = -l0[i];
      const Vector b0    = dual.apply_P(d - dual.apply_F(l0));
      const double scale = std::max(d.norm(), b0.norm()) > 0 ?
                             std::max(d.norm(), b0.norm()) :
                             1.0;

      // Step 3: SMALBE-M with MPRGP.
      const double pfp_norm = largest_eigenvalue(dual, n);
      const double rho      = options.penalty * pfp_norm;
      const auto   Q        = [&](const Vector &v) -> Vector {
        return v - dual.apply_P(v);
      };
      const auto violation_of = [&](const Vector &v) {
        return rho * Q(v).norm();
      };
      Vector       m = Vector::Zero(n);
      Vector       q = Vector::Zero(n); // the equality multiplier, G^T mu
      double       M = options.precision_factor * pfp_norm;
      double       previous_lagrangian = -std::numeric_limits<double>::infinity();
      const unsigned int limit = iteration_limit(100000);
      Vector       gradient;
      bool         converged = false;
      unsigned int outer     = 0;
      for (; outer < options.max_outer; ++outer)
        {
          const Vector r = b0 - q;
          Mprgp        inner(
            [&](const Vector &x, Vector &y) {
              const Vector Px = dual.apply_P(x);
              y = dual.apply_P(dual.apply_F(Px)) + rho * (x - Px);
            },
            r,
            lower,
            1.9 / std::max(pfp_norm, rho),
            1.0);
          // SMALBE's inner precision: the projected gradient against the
          // current violation of G l = e (m is MPRGP's iterate), and never
          // finer than the final tolerance needs.
          const auto stop = [&](const double projected_gradient) {
            return projected_gradient <=
                   std::max(options.tolerance * scale,
                            std::min(M * Q(m).norm(), 0.1 * scale));
          };
          const unsigned int budget =
            limit > dual.products_with_F ? limit - dual.products_with_F : 0;
          const Mprgp::Outcome outcome = inner.solve(m, stop, budget / 2);
          gradient = inner.gradient();
          report.counters.cg_iterations += inner.steps();
          report.iterations = outer + 1;
          if (outcome == Mprgp::Outcome::not_definite ||
              outcome == Mprgp::Outcome::diverged)
            {
              report.status  = Status::singular;
              report.message = "TFETI: the dual's inner solve broke down";
              return;
            }
          const double violation = violation_of(m);
          const double projected = inner.projected_gradient(m).norm();
          if (progress != nullptr)
            *progress << "    tfeti outer iteration " << outer + 1
                      << std::scientific << std::setprecision(2)
                      << ": projected gradient " << projected / scale
                      << ", rho |G l - e| " << violation / scale << ", "
                      << inner.steps() << " inner iterations"
                      << std::defaultfloat << std::endl;
          if (projected <= options.tolerance * scale &&
              violation <= options.tolerance * scale)
            {
              converged = true;
              break;
            }
          if (outcome == Mprgp::Outcome::iteration_limit ||
              dual.products_with_F >= limit)
            break;
          // The augmented Lagrangian at m: the inner functional
          // 1/2 m^T H m - r^T m = 1/2 m^T (g - r).
          const double lagrangian = 0.5 * m.dot(gradient - r);
          const double squared_violation = Q(m).squaredNorm();
          q += rho * Q(m);
          // SMALBE-M's safeguard: the Lagrangian (with the updated q) must
          // rise by rho/2 |Q m|^2 on the last one; when it does not, the
          // inner solves were too coarse for this rho, and M shrinks.
          const double updated_lagrangian = lagrangian + rho * squared_violation;
          if (updated_lagrangian <
              previous_lagrangian + 0.5 * rho * squared_violation)
            M /= 2;
          previous_lagrangian = updated_lagrangian;
        }

      // Step 4: the primal answer.
      const Vector l     = l0 + m;
      const Vector alpha = dual.coarse_solve(
        dual.G * (dual.apply_F(l) - d - gradient));
      const Vector x = dual.apply_pseudo_inverse(
                         tearing.f - tearing.B.transpose() * l) +
                       dual.apply_rigid_motions(alpha);
      solution.u = tearing.to_problem * x;
      if (converged)
        report.status = Status::converged;
      else
        {
          report.status  = Status::iteration_limit;
          report.message = "TFETI did not reach its tolerance in " +
                           std::to_string(report.iterations) +
                           " outer iterations and " +
                           std::to_string(dual.products_with_F) +
                           " products with F";
        }
    }
  } // namespace

  UNILATERAL_REGISTER_SOLVER(Tfeti)
} // namespace unilateral::lcp
