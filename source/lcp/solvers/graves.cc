/**
 * Graves' principal pivoting simplex method, as given by Ainsworth & Mihai
 * (Section 4, "Graves"; Graves 1967, Murty ch. 4), for an LCP in which every
 * index is constrained, in practice the reduced Schur-complement LCP
 * (3.17)-(3.18) ('Solver/Schur complement = true').
 *
 * Tableau form: with z = u - l >= 0 and w = lambda >= 0,
 *     w = M z + q,   M = A (after diagonal scaling),  q = A l - b.
 * The tableau (M, q, B) starts with B = I (rows lexico-positive) and every
 * w basic. Each iteration:
 *   Step 2: if q >= 0 the basic variables equal q: stop.
 *   Step 3: t = the row with q_t < 0 whose B_t / q_t is lexicographically
 *           largest.
 *   Step 4, Case 1 (M_tt != 0): principal pivot on t, exchanging w_t, z_t.
 *   Case 2 (M_tt = 0): if M_it >= 0 for all i the LCP has no solution (stop);
 *           else s = the row with M_st < 0 maximising lexicographically
 *           (B_s - q_s B_t / q_t) / M_st, and a double principal pivot on
 *           {s, t}.
 * The pivots are the 1x1 and 2x2 principal pivot transforms written in block
 * form (the paper spells out their entries; its Case 1 update of B has a
 * typo, B_ij - A_it B_ij / A_tt for B_ij - A_it B_tj / A_tt, not repeated
 * here). Theorem 4.5: the lexicographic rule makes the method finite.
 */
#include <unilateral/base/input_error.h>
#include <unilateral/lcp/solver.h>

#include <Eigen/Dense>

#include <cmath>
#include <ostream>

namespace unilateral::lcp
{
  namespace
  {
    /**
     * Lexicographic comparison of the rows (B_a - c_a B_t) / d_a and
     * (B_b - c_b B_t) / d_b, without forming them: returns true if the
     * first is larger. Rows of B are never equal (B stays nonsingular).
     */
    bool
    lexicographically_larger(const DenseMatrix &B,
                             const Index        a,
                             const double       c_a,
                             const double       d_a,
                             const Index        b,
                             const double       c_b,
                             const double       d_b,
                             const Index        t)
    {
      for (Index j = 0; j < B.cols(); ++j)
        {
          const double x = (B(a, j) - (t >= 0 ? c_a * B(t, j) : 0.0)) / d_a;
          const double y = (B(b, j) - (t >= 0 ? c_b * B(t, j) : 0.0)) / d_b;
          if (x != y)
            return x > y;
        }
      return false;
    }

    class Graves : public Solver
    {
    public:
      using Solver::Solver;

      void
      solve(const Problem &problem,
            Solution      &solution,
            Report        &report,
            std::ostream  *progress) override
      {
        const Index n = problem.size();
        if (problem.n_constrained() != n)
          throw InputError(
            "graves solves LCPs in which every unknown is constrained; this "
            "one has " +
            std::to_string(n - problem.n_constrained()) +
            " unconstrained unknowns: set 'Solver/Schur complement = true'");

        // Diagonal scaling, as Ainsworth & Mihai do against round-off.
        Vector scale = Vector::Ones(n);
        for (Index i = 0; i < n; ++i)
          if (problem.A.coeff(i, i) > 0)
            scale[i] = 1.0 / std::sqrt(problem.A.coeff(i, i));
        DenseMatrix M = scale.asDiagonal() * DenseMatrix(problem.A) *
                        scale.asDiagonal();
        const Vector l_scaled = problem.lower_bound.cwiseQuotient(scale);
        Vector       q        = M * l_scaled - scale.cwiseProduct(problem.b);
        DenseMatrix  B        = DenseMatrix::Identity(n, n);
        // z_basic[i]: z_i (not w_i) is the basic variable of row i.
        std::vector<char> z_basic(n, 0);

        const double scale_q = std::max(1.0, q.lpNorm<Eigen::Infinity>());
        const double q_tolerance = 1e-14 * scale_q;
        const double pivot_tolerance = 1e-12;

        const unsigned int limit = iteration_limit(10 * n + 100);
        for (unsigned int iteration = 0;; ++iteration)
          {
            // Step 3's candidate: the lexicographic maximum of B_i / q_i over
            // q_i < 0.
            Index t = -1;
            for (Index i = 0; i < n; ++i)
              if (q[i] < -q_tolerance &&
                  (t < 0 ||
                   lexicographically_larger(B, i, 0, q[i], t, 0, q[t], -1)))
                t = i;
            if (t < 0) // Step 2
              {
                report.status = Status::converged;
                break;
              }
            if (iteration >= limit)
              {
                report.status  = Status::iteration_limit;
                report.message = "Graves reached " + std::to_string(limit) +
                                 " iterations (cycling through round-off?)";
                break;
              }
            report.iterations = iteration + 1;

            if (std::abs(M(t, t)) > pivot_tolerance) // Case 1
              pivot(M, q, B, {t});
            else // Case 2
              {
                Index s = -1;
                for (Index i = 0; i < n; ++i)
                  if (M(i, t) < -pivot_tolerance &&
                      (s < 0 || lexicographically_larger(B,
                                                         i,
                                                         q[i] / q[t],
                                                         M(i, t),
                                                         s,
                                                         q[s] / q[t],
                                                         M(s, t),
                                                         t)))
                    s = i;
                if (s < 0)
                  {
                    report.status  = Status::infeasible;
                    report.message = "Graves: the LCP has no solution (Case 2 "
                                     "with M_it >= 0 for all i, row " +
                                     std::to_string(t) + ")";
                    break;
                  }
                pivot(M, q, B, {s, t});
                z_basic[s] = !z_basic[s];
              }
            z_basic[t] = !z_basic[t];
            if (progress != nullptr && ((iteration + 1) & iteration) == 0)
              *progress << "    graves iteration " << iteration + 1
                        << std::endl;
          }

        // Basic z take the values of q; nonbasic ones are zero.
        solution.u.resize(n);
        for (Index i = 0; i < n; ++i)
          solution.u[i] =
            scale[i] * ((z_basic[i] ? std::max(q[i], 0.0) : 0.0) + l_scaled[i]);
      }

    private:
      /**
       * Principal pivot transform on the index set P (one or two indices):
       * with Q = M_PP^-1,
       *   M_PP <- Q,  M_PO <- -Q M_PO,  M_OP <- M_OP Q,
       *   M_OO <- M_OO - M_OP Q M_PO,  and q, B like a column of M_OP rows:
       *   q_P <- -Q q_P, q_O <- q_O - M_OP Q q_P (the same for B).
       */
      static void
      pivot(DenseMatrix &M, Vector &q, DenseMatrix &B, const std::vector<Index> &P)
      {
        const Index k = static_cast<Index>(P.size());
        DenseMatrix M_PP(k, k), M_P(k, M.cols()), B_P(k, B.cols()),
          M_colP(M.rows(), k);
        Vector q_P(k);
        for (Index a = 0; a < k; ++a)
          {
            for (Index b = 0; b < k; ++b)
              M_PP(a, b) = M(P[a], P[b]);
            M_P.row(a)    = M.row(P[a]);
            B_P.row(a)    = B.row(P[a]);
            M_colP.col(a) = M.col(P[a]);
            q_P[a]        = q[P[a]];
          }
        const DenseMatrix Q      = M_PP.inverse();
        const DenseMatrix QM     = Q * M_P;
        const DenseMatrix QB     = Q * B_P;
        const Vector      Qq     = Q * q_P;
        const DenseMatrix M_OP_Q = M_colP * Q;

        // The rank-k update on everything; rows and columns P are then
        // overwritten with their own formulas.
        M.noalias() -= M_colP * QM;
        B.noalias() -= M_colP * QB;
        q.noalias() -= M_colP * Qq;
        for (Index b = 0; b < k; ++b)
          M.col(P[b]) = M_OP_Q.col(b);
        for (Index a = 0; a < k; ++a)
          {
            M.row(P[a]) = -QM.row(a);
            for (Index b = 0; b < k; ++b)
              M(P[a], P[b]) = Q(a, b);
            q[P[a]]     = -Qq[a];
            B.row(P[a]) = -QB.row(a);
          }
      }
    };
  } // namespace

  UNILATERAL_REGISTER_SOLVER(Graves,
                             "graves",
                             "Graves' principal pivoting simplex method, dense, "
                             "lexicographic (use with 'Schur complement')",
                             false,
                             true,
                             true,
                             0,
                             false)
} // namespace unilateral::lcp
