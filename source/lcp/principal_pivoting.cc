#include <unilateral/lcp/principal_pivoting.h>

#include <Eigen/Dense>

#include <cmath>
#include <ostream>
#include <stdexcept>

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

    /**
     * Principal pivot transform on the index set P (one or two indices):
     * with Q = M_PP^-1,
     *   M_PP <- Q,  M_PO <- -Q M_PO,  M_OP <- M_OP Q,
     *   M_OO <- M_OO - M_OP Q M_PO,  and q, B like a column of M_OP rows:
     *   q_P <- -Q q_P, q_O <- q_O - M_OP Q q_P (the same for B).
     */
    void
    pivot(DenseMatrix              &M,
          Vector                   &q,
          DenseMatrix              &B,
          const std::vector<Index> &P)
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
  } // namespace

  void
  principal_pivoting(const Problem     &problem,
                     const unsigned int limit,
                     Solution          &solution,
                     Report            &report,
                     std::ostream      *progress)
  {
    const Index n = problem.size();
    if (problem.n_constrained() != n)
      throw std::logic_error("principal_pivoting: every unknown must be "
                             "constrained");

    // Diagonal scaling, as Ainsworth & Mihai do against round-off.
    Vector scale = Vector::Ones(n);
    for (Index i = 0; i < n; ++i)
      if (problem.A.coeff(i, i) > 0)
        scale[i] = 1.0 / std::sqrt(problem.A.coeff(i, i));
    DenseMatrix M =
      scale.asDiagonal() * DenseMatrix(problem.A) * scale.asDiagonal();
    const Vector l_scaled = problem.lower_bound.cwiseQuotient(scale);
    Vector       q        = M * l_scaled - scale.cwiseProduct(problem.b);
    DenseMatrix  B        = DenseMatrix::Identity(n, n);
    // z_basic[i]: z_i (not w_i) is the basic variable of row i.
    std::vector<char> z_basic(n, 0);

    const double scale_q         = std::max(1.0, q.lpNorm<Eigen::Infinity>());
    const double q_tolerance     = 1e-14 * scale_q;
    const double pivot_tolerance = 1e-12;

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
                  (s < 0 ||
                   lexicographically_larger(
                     B, i, q[i] / q[t], M(i, t), s, q[s] / q[t], M(s, t), t)))
                s = i;
            if (s < 0)
              {
                report.status  = Status::infeasible;
                report.message = "Graves: the LCP has no solution (Case 2 "
                                 "with M_it >= 0 for all i, row " +
                                 std::to_string(t + 1) + ", counted from 1)";
                break;
              }
            pivot(M, q, B, {s, t});
            z_basic[s] = !z_basic[s];
          }
        z_basic[t] = !z_basic[t];
        if (progress != nullptr && ((iteration + 1) & iteration) == 0)
          *progress << "    graves iteration " << iteration + 1 << std::endl;
      }

    // Basic z take the values of q; nonbasic ones are zero.
    solution.u.resize(n);
    for (Index i = 0; i < n; ++i)
      solution.u[i] =
        scale[i] * ((z_basic[i] ? std::max(q[i], 0.0) : 0.0) + l_scaled[i]);
  }
} // namespace unilateral::lcp
