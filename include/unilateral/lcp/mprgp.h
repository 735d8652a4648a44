#pragma once

#include <unilateral/lcp/problem.h>

#include <functional>

namespace unilateral::lcp
{
  /**
   * MPRGP, modified proportioning with reduced gradient projections (Dostal
   * & Schoberl, "Minimizing quadratic functions subject to bound
   * constraints with the rate of convergence and finite termination",
   * Comput. Optim. Appl. 30 (2005) 23-43; Dostal, "Optimal Quadratic
   * Programming Algorithms", 2009, ch. 5), for
   *     min 1/2 x^T H x - r^T x   subject to x >= lower
   * (lower_i = -infinity for a free entry), H symmetric positive definite
   * and given only by its products: conjugate gradients on the free set,
   * with projections. The primal method 'mprgp' (H = A) and the dual of
   * TFETI (H = P F P + rho Q) use it.
   *
   * With g = H x - r, the free set F = {i : x_i > lower_i}, the free
   * gradient phi (g on F, 0 elsewhere), the chopped gradient beta
   * (min(g_i, 0) off F), the reduced free gradient phi~_i =
   * min((x_i - lower_i) / alpha_bar, phi_i) on F, and the projected
   * gradient g^P = phi + beta, each step is one of:
   *   - if ||beta||^2 <= Gamma^2 phi~^T phi (the iterate is proportional):
   *     alpha_cg = g^T p / p^T H p, alpha_f = the largest feasible step;
   *     a CG step (alpha_cg <= alpha_f): x -= alpha_cg p, p = phi - gamma p
   *     with gamma = phi^T H p / p^T H p; else an expansion: x -= alpha_f p,
   *     then x = P(x - alpha_bar phi(x)), p = phi(x) (or, adaptive, the
   *     step phi^T phi / phi^T H phi instead of alpha_bar where the
   *     projected iterate's energy is below the boundary point's);
   *   - else proportioning: x -= (g^T beta / beta^T H beta) beta,
   *     p = phi(x).
   * alpha_bar in (0, 2 / ||H||]; Gamma = 1 as Dostal recommends.
   */
  class Mprgp
  {
  public:
    /// y = H x; the number of calls is the cost.
    using Operator = std::function<void(const Vector &x, Vector &y)>;

    /// True when the iterate is good enough, given ||g^P||_2.
    using Stop = std::function<bool(double projected_gradient)>;

    enum class Outcome
    {
      converged,       ///< @p stop returned true
      iteration_limit, ///< max_steps steps taken
      not_definite,    ///< a direction d with d^T H d <= 0
      diverged         ///< a non-finite iterate or curvature d^T H d
    };

    /**
     * Told of every move of the iterate, so that a caller can keep a
     * linear function of it up to date from what its products compute
     * anyway (TFETI: G x and the coarse solve of ||Q x||): x -= alpha d, d
     * the input of the last product; or, with alpha NaN, x is now the
     * input of the last product itself.
     */
    using Observer = std::function<void(double alpha)>;

    Mprgp(Operator H, Vector r, Vector lower, double alpha_bar, double gamma);

    void
    observe(Observer observer)
    {
      this->observer = std::move(observer);
    }

    /// z = M^-1 phi for a preconditioner M of H (symmetric positive
    /// definite), used in the face (Dostal 2009, "preconditioning in
    /// face"): the conjugate gradient steps on the free set F take z
    /// restricted to F, the preconditioner of H_FF that the restriction of
    /// M^-1 is. The expansion and proportioning steps stay unpreconditioned.
    using Preconditioner = std::function<void(const Vector &phi, Vector &z)>;

    void
    precondition(Preconditioner preconditioner)
    {
      this->preconditioner = std::move(preconditioner);
    }

    /// Expansion steps of the length the energy wants along the free
    /// gradient instead of alpha_bar, where the projected iterate's energy
    /// is below the boundary point's (expand() in the source says why).
    void
    use_adaptive_expansion(const bool adaptive)
    {
      adaptive_expansion = adaptive;
    }

    /**
     * From @p x (projected onto the feasible set first) until @p stop holds
     * or @p max_steps steps. On return x is the iterate, gradient() its
     * g = H x - r, and steps() the steps taken.
     */
    Outcome
    solve(Vector &x, const Stop &stop, unsigned int max_steps);

    const Vector &
    gradient() const
    {
      return g;
    }

    /// phi + beta at the last iterate.
    Vector
    projected_gradient(const Vector &x) const;

    unsigned int
    steps() const
    {
      return n_steps;
    }

    unsigned int
    products() const
    {
      return n_products;
    }

    /// Expansions that took the adaptive length.
    unsigned int
    adaptive_expansions() const
    {
      return n_adaptive_expansions;
    }

  private:
    /// The last curvature computed was not finite (overflow).
    bool curvature_overflowed = false;

    Vector
    free_gradient(const Vector &x) const;

    Vector
    chopped_gradient(const Vector &x) const;

    double
    reduced_times_free(const Vector &x, const Vector &phi) const;

    double
    feasible_step(const Vector &x, const Vector &p) const;

    void
    project(Vector &x) const;

    Vector
    product(const Vector &d);

    /// The first conjugate direction in the face of x, from its free
    /// gradient @p phi: phi, or M^-1 phi restricted to the free set.
    Vector
    face_direction(const Vector &x, const Vector &phi) const;

    /// g from x, and p its face direction.
    void
    restart(const Vector &x);

    bool
    conjugate_gradient_or_expansion(Vector &x);

    bool
    proportioning(Vector &x, const Vector &beta);

    /// The projected free-gradient step that ends an expansion.
    void
    expand(Vector &x);

    /// 1/2 x^T H x - r^T x, from g = H x - r.
    double
    energy(const Vector &x) const;

    /// x -= alpha d for the last product's input d (moved), or x = d.
    void
    moved(double alpha) const;

    Operator       H;
    Observer       observer;
    Preconditioner preconditioner;
    Vector         r, lower;
    double         alpha_bar, gamma;
    bool           adaptive_expansion = false;
    Vector         g, p;
    unsigned int   n_steps = 0, n_products = 0, n_adaptive_expansions = 0;
  };
} // namespace unilateral::lcp
