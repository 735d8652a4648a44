#include <unilateral/lcp/mprgp.h>

#include <cmath>
#include <limits>

namespace unilateral::lcp
{
  Mprgp::Mprgp(Operator     H,
               Vector       r,
               Vector       lower,
               const double alpha_bar,
               const double gamma)
    : H(std::move(H))
    , r(std::move(r))
    , lower(std::move(lower))
    , alpha_bar(alpha_bar)
    , gamma(gamma)
  {}

  Vector
  Mprgp::free_gradient(const Vector &x) const
  {
    Vector phi = g;
    for (Index i = 0; i < x.size(); ++i)
      if (!(x[i] > lower[i]))
        phi[i] = 0;
    return phi;
  }

  Vector
  Mprgp::chopped_gradient(const Vector &x) const
  {
    Vector beta = Vector::Zero(x.size());
    for (Index i = 0; i < x.size(); ++i)
      if (!(x[i] > lower[i]))
        beta[i] = std::min(g[i], 0.0);
    return beta;
  }

  Vector
  Mprgp::projected_gradient(const Vector &x) const
  {
    return free_gradient(x) + chopped_gradient(x);
  }

  double
  Mprgp::reduced_times_free(const Vector &x, const Vector &phi) const
  {
    double result = 0;
    for (Index i = 0; i < x.size(); ++i)
      {
        const double reduced =
          std::isfinite(lower[i]) ?
            std::min((x[i] - lower[i]) / alpha_bar, phi[i]) :
            phi[i];
        result += reduced * phi[i];
      }
    return result;
  }

  double
  Mprgp::feasible_step(const Vector &x, const Vector &d) const
  {
    double alpha = std::numeric_limits<double>::infinity();
    for (Index i = 0; i < x.size(); ++i)
      if (d[i] > 0 && std::isfinite(lower[i]))
        alpha = std::min(alpha, (x[i] - lower[i]) / d[i]);
    return alpha;
  }

  void
  Mprgp::project(Vector &x) const
  {
    x = x.cwiseMax(lower);
  }

  Vector
  Mprgp::product(const Vector &d)
  {
    Vector y;
    H(d, y);
    ++n_products;
    return y;
  }

  void
  Mprgp::moved(const double alpha) const
  {
    if (observer)
      observer(alpha);
  }

  Vector
  Mprgp::face_direction(const Vector &x, const Vector &phi) const
  {
    if (!preconditioner)
      return phi;
    Vector z;
    preconditioner(phi, z);
    for (Index i = 0; i < x.size(); ++i)
      if (!(x[i] > lower[i]))
        z[i] = 0;
    return z;
  }

  void
  Mprgp::restart(const Vector &x)
  {
    g = product(x) - r;
    moved(std::numeric_limits<double>::quiet_NaN());
    p = face_direction(x, free_gradient(x));
  }

  // The iterate is proportional: a conjugate gradient step on the free set,
  // or an expansion where that would leave the feasible set (to the
  // boundary, then a projected gradient step of fixed length that can add
  // active constraints). False if p^T H p <= 0.
  bool
  Mprgp::conjugate_gradient_or_expansion(Vector &x)
  {
    const Vector Hp      = product(p);
    const double pHp     = p.dot(Hp);
    curvature_overflowed = !std::isfinite(pHp);
    if (!(pHp > 0))
      return false;
    const double alpha_cg = g.dot(p) / pHp;
    const double alpha_f  = feasible_step(x, p);
    if (alpha_cg <= alpha_f)
      {
        x -= alpha_cg * p;
        moved(alpha_cg);
        g -= alpha_cg * Hp;
        const Vector z = face_direction(x, free_gradient(x));
        p              = z - (z.dot(Hp) / pHp) * p;
        return true;
      }
    x -= alpha_f * p;
    g -= alpha_f * Hp;
    moved(alpha_f);
    expand(x);
    return true;
  }

  // The projected step along the free gradient phi of an expansion. Its
  // fixed length alpha_bar lowers the energy for any alpha_bar <= 2 / ||H||
  // (Dostal & Schoberl), but where H's spectrum is wide (the penalised dual
  // of TFETI, ||H|| = rho) that is far shorter than the step the energy
  // wants along phi. The adaptive length is that step, phi^T phi / phi^T H
  // phi (one product more), kept only where the projected iterate's energy
  // is below the boundary point's, else the fixed step follows: the energy
  // still never rises.
  void
  Mprgp::expand(Vector &x)
  {
    const Vector phi = free_gradient(x);
    if (adaptive_expansion)
      {
        const double energy_before = energy(x);
        const Vector Hphi          = product(phi);
        const double curvature     = phi.dot(Hphi);
        if (curvature > 0)
          {
            Vector trial = x - (phi.squaredNorm() / curvature) * phi;
            project(trial);
            restart(trial);
            if (energy(trial) < energy_before)
              {
                x = std::move(trial);
                ++n_adaptive_expansions;
                return;
              }
          }
      }
    x -= alpha_bar * phi;
    project(x);
    restart(x);
  }

  double
  Mprgp::energy(const Vector &x) const
  {
    return 0.5 * x.dot(g - r);
  }

  // Proportioning: along the chopped gradient @p beta, releasing constraints
  // whose multipliers are negative. False if beta^T H beta <= 0.
  bool
  Mprgp::proportioning(Vector &x, const Vector &beta)
  {
    const Vector Hd      = product(beta);
    const double dHd     = beta.dot(Hd);
    curvature_overflowed = !std::isfinite(dHd);
    if (!(dHd > 0))
      return false;
    const double alpha = g.dot(beta) / dHd;
    x -= alpha * beta;
    moved(alpha);
    g -= alpha * Hd;
    p = face_direction(x, free_gradient(x));
    return true;
  }

  Mprgp::Outcome
  Mprgp::solve(Vector &x, const Stop &stop, const unsigned int max_steps)
  {
    project(x);
    restart(x);
    for (n_steps = 0;; ++n_steps)
      {
        const Vector phi                = free_gradient(x);
        const Vector beta               = chopped_gradient(x);
        const double projected_gradient = (phi + beta).norm();
        if (!std::isfinite(projected_gradient))
          return Outcome::diverged;
        if (stop(projected_gradient))
          return Outcome::converged;
        if (n_steps >= max_steps)
          return Outcome::iteration_limit;
        const bool proportional =
          beta.squaredNorm() <= gamma * gamma * reduced_times_free(x, phi);
        // A curvature that is not finite is an overflow of d^T H d (a
        // problem in numbers near 1e154 or beyond), not an indefinite H.
        if (!(proportional ? conjugate_gradient_or_expansion(x) :
                             proportioning(x, beta)))
          return curvature_overflowed ? Outcome::diverged :
                                        Outcome::not_definite;
      }
  }
} // namespace unilateral::lcp
