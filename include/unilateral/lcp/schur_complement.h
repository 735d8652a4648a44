#pragma once

#include <unilateral/lcp/active_set_system.h>
#include <unilateral/lcp/problem.h>

#include <memory>

namespace unilateral::lcp
{
  /**
   * The reduced Schur-complement LCP of Ainsworth & Mihai (3.13)-(3.18):
   * with E the unconstrained indices,
   *   A_hat = A_SS - A_SE A_EE^-1 A_ES   (dense, |S| x |S|),
   *   b_hat = b_S  - A_SE A_EE^-1 b_E,
   * and u_E = A_EE^-1 (b_E - A_ES u_S) afterwards. A_EE is factorised once
   * (sparse) and its columns are solved in blocks.
   */
  class SchurComplement
  {
  public:
    /**
     * Throws InputError if |S| exceeds @p max_dense_size. Returns with
     * singular() true if A_EE is not positive definite.
     */
    SchurComplement(const Problem &problem,
                    unsigned int   max_dense_size,
                    Counters      &counters);

    bool
    singular() const
    {
      return is_singular;
    }

    /// The reduced LCP on S (all indices constrained, bounds l_S).
    const Problem &
    reduced_problem() const
    {
      return reduced;
    }

    /// Whether every entry of the reduced right-hand side is within 1e3
    /// epsilon of the terms it was computed from, |b_S| + |A_SE| |A_EE^-1
    /// b_E|: nothing but their rounding (where A_EE holds all of A's rank
    /// and the loads do no work on the reduced unknowns).
    bool
    loads_round_off() const
    {
      return all_loads_round_off;
    }

    /// The full u from the reduced solution u_S.
    Vector
    recover(const Vector &u_S);

  private:
    const Problem                   &problem;
    std::unique_ptr<ActiveSetSystem> eliminated;
    std::vector<char>                fixed;
    Problem                          reduced;
    bool                             is_singular         = false;
    bool                             all_loads_round_off = true;
  };
} // namespace unilateral::lcp
