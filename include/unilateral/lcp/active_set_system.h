#pragma once

#include <unilateral/lcp/sparse_cholesky.h>

#include <memory>
#include <vector>

namespace unilateral::lcp
{
  /**
   * A factorisation of K(X): A with the indices X fixed, i.e. A_FF on the
   * free indices F and a diagonal D_X on the fixed ones. Either A_FF was
   * extracted and factorised on its own (in the ordering of A restricted to
   * F), or the full pattern was factorised with the fixed rows and columns
   * replaced by D_X. Kept so that a later system on a nearby matrix can use it
   * as a preconditioner: the next active set, or the projection step (A
   * instead of A + eps I).
   */
  struct ActiveSetFactor
  {
    std::vector<char> fixed;
    /// Position of each free index in A_FF, -1 for fixed ones; empty when
    /// the full pattern was factorised.
    std::vector<Index> reduced_index;
    Index              n_free = 0;
    /// D_X on the fixed indices.
    Vector fixed_diagonal;
    /// The AMD ordering of A's pattern the factor was made in (new-to-old),
    /// for a later system on the same pattern.
    std::vector<Index> ordering_of_A;
    SparseCholesky     cholesky;

    /// X = K(X)^-1 B.
    void
    solve(const DenseMatrix &B, DenseMatrix &X) const;

    /// No factor of K(X) for any X: the analysis of A's full pattern,
    /// and the storage of a factor made in it (see analysis_of).
    bool analysis_only = false;

    /**
     * The symbolic analysis of A's pattern and its ordering, taken from
     * @p analysed (left empty), for the systems of a later stage: the
     * projection after an interior-point method, whose Newton matrix has
     * A's pattern and was analysed once (in METIS's nested dissection where
     * AMD's fronts are large). The storage of @p analysed's factor comes
     * with it (its values are of no use), so that the projection factorises
     * into memory already touched; whoever does not take it must drop it.
     */
    static std::shared_ptr<const ActiveSetFactor>
    analysis_of(SparseCholesky &analysed);

    /// G = B' K(X)^-1 B for sparse columns B that vanish on X (the Schur
    /// complement's A_FU): SparseCholesky::inverse_gram on the factored
    /// rows. False if that declines; the caller then solves in full.
    bool
    inverse_gram(const SparseMatrix &B, DenseMatrix &G) const;
  };

  /**
   * The linear systems of every active-set and pivoting method: for a set X
   * of fixed indices with given values x_X, solve
   *     A_FF x_F = r_F - A_FX x_X,      F = complement of X,
   * i.e. minimise 1/2 x^T A x - r^T x with x_X fixed (the "QEP" of
   * Ainsworth & Mihai, eq. (57) of Fernandes et al.).
   *
   * Two ways to factorise K(X), chosen by the size of X: with few fixed
   * indices the full pattern is kept (fixed rows and columns replaced by the
   * diagonal), so the one symbolic analysis of A serves every active set
   * (so it does, while at least half the unknowns are free, after a stage
   * that analysed A's pattern and handed over that analysis: the
   * projection after an interior point);
   * with many (more than a sixth of the unknowns, where the smaller factor
   * pays for a symbolic pass) A_FF is extracted and factorised in the AMD
   * ordering of A restricted to F, "in the ordering established in the
   * Analyse phase" as Fernandes et al. do for C_RR. Once the active set is
   * settling (few changes since the nearest factor) the full pattern is
   * taken whatever the size of X, so that the next, smaller changes can be
   * made row by row.
   *
   * Factorisations are reused. A factor for exactly this X is used directly.
   * A factor of the full pattern for another X is updated row by row to
   * this X (CHOLMOD's rowdel for each newly fixed index, rowadd for each
   * newly free one) as long as the updates, predicted from the factor's
   * structure, cost less than modification_budget times a numeric
   * factorisation in floating-point operations and its copy fits in
   * memory; the answer is then checked by the CG below, started from
   * it. Otherwise a factor for a nearby matrix, one whose fixed set differs
   * in at most max_changes indices (K then differs by a matrix of rank
   * <= 2 changes), or
   * an inherited factor of A + eps I for the same X, preconditions conjugate
   * gradients, which then converge in about 2 changes + 1 iterations, if
   * those are expected to cost less than a factorisation
   * (cg_iteration_cost). Only if CG does not reach the direct solver's
   * accuracy within that break-even count is K(X) factorised anew. The
   * rule is deterministic.
   */
  class ActiveSetSystem
  {
  public:
    /// @p inherited: a factor of a nearby matrix (e.g. of A + eps I) to
    /// try first; may be null.
    ActiveSetSystem(const SparseMatrix                    &A,
                    Counters                              &counters,
                    std::shared_ptr<const ActiveSetFactor> inherited = {});

    /**
     * On entry x holds the fixed values on X (other entries are ignored); on
     * exit x_F is the solution. Returns false if A_FF is not positive
     * definite (the reduced system is singular).
     */
    bool
    solve(const std::vector<char> &fixed, const Vector &r, Vector &x);

    /// The same for several right-hand sides (columns of R and X) at once.
    bool
    solve(const std::vector<char> &fixed, const DenseMatrix &R, DenseMatrix &X);

    /**
     * Make the own factor one of K(X) for exactly @p fixed (updated row by
     * row within the budget, else factorised), so that many right-hand sides
     * can follow without the conjugate gradients of a nearby factor (the
     * Schur complement of a subset, one column per index). Returns false if
     * A_FF is singular.
     */
    bool
    prepare_factor(const std::vector<char> &fixed);

    /**
     * Directions in which K(X) is singular or nearly so (a body that the
     * fixed set X leaves free to move): one step of inverse iteration with
     * K(X) + delta I (delta = 1e-10 times the mean diagonal) on a random
     * vector of the free indices, scaled to a largest entry of one. Its
     * entries are of order one where a nearly free motion moves an index
     * and of order delta elsewhere. Empty if even the shifted matrix cannot
     * be factorised. The own factor is not kept (it is of the shifted
     * matrix). If @p loads and @p driven are given, two steps from the
     * loads on the free indices are put in @p driven: the motion the loads
     * drive, a null vector to round-off where a body floats (its error
     * along a stiff direction of stiffness lambda falls by delta / lambda
     * per step), for unbounded_direction.h.
     */
    Vector
    near_null_direction(const std::vector<char> &fixed,
                        const Vector            *loads  = nullptr,
                        Vector                  *driven = nullptr);

    /// The most recent factor (own or inherited), for a follow-up system.
    std::shared_ptr<const ActiveSetFactor>
    factor() const;

    /// Fixed-set changes up to which a factor is reused through CG.
    static constexpr unsigned int max_changes = 16;

    /**
     * Cost of one preconditioned CG iteration (a pair of triangular solves
     * and a product with A, memory-bound) in flops of a numeric
     * factorisation, per entry of L. A nearby factor preconditions CG only
     * if the expected 2 changes + 2 iterations cost less than factorising
     * anew, and CG stops at that break-even count: a CG that fails after
     * more has cost more than the factorisation it must then make anyway.
     * The solves are memory-bound while the factorisation runs in dense
     * kernels, so an iteration costs many flops of a factorisation per
     * entry; 15 is the ratio measured on the stack bond wall's A_FF
     * (benchmarks/masonry_tables/README.md, "Design measurements").
     */
    static constexpr double cg_iteration_cost = 15;

    /// Flops of row modifications, as a fraction of those of a numeric
    /// factorisation, up to which a factor is updated rather than
    /// recomputed. Modifications run simplicial and memory-bound, while
    /// the supernodal factorisation speeds up with size, so the break-even
    /// fraction falls with size. 0.25 gains on the walls and costs the
    /// largest plates little; more gains nothing
    /// (benchmarks/plate_tables/README.md, "Design measurements"). The
    /// cost is predicted before the first update copies the factor
    /// (flops_per_path_entry).
    static constexpr double modification_budget = 0.25;

    /// Fraction of fixed indices above which A_FF is factorised on its own,
    /// unless the active set is settling.
    static constexpr double reduced_threshold = 1.0 / 6.0;

    /// Fraction of fixed indices up to which an analysis of the full
    /// pattern handed over by the stage before is taken and kept: where at
    /// least half the unknowns are free, its factor costs a few times A_FF's
    /// at most, and A_FF's analysis and copy are saved; with more fixed
    /// (the dense Schur complement of a wall whose contacts are mostly
    /// closed) A_FF is far smaller.
    static constexpr double taken_analysis_threshold = 1.0 / 2.0;

    /// Changes against the nearest factor, as a fraction of the unknowns,
    /// up to which the active set counts as settling: its next changes are
    /// then likely few enough to be made row by row, which only a factor
    /// of the full pattern allows, so that pattern is factorised even where
    /// A_FF alone would be smaller (benchmarks/masonry_tables/README.md,
    /// "Design measurements").
    static constexpr double settling_fraction = 1.0 / 500;

    /// Flops of the full pattern's factorisation, as a multiple of A_FF's,
    /// above which a settling active set keeps to A_FF: where the fixed
    /// indices are what keeps the fill low, the larger factor costs more
    /// than the row modifications save (benchmarks/masonry_tables/README.md,
    /// "Design measurements").
    static constexpr double full_pattern_allowance = 1.25;

  private:
    /// Factorise K(X), plus @p shift on the diagonal of the free part.
    bool
    factorise(const std::vector<char> &fixed, double shift = 0);

    /// Compute the AMD ordering of A unless it is known (computed before,
    /// or inherited with a factor of the same pattern).
    void
    order_once();

    /// Update the own full-pattern factor to the fixed set @p fixed; false
    /// (and the own factor dropped) if that would exceed the budget, if
    /// CHOLMOD fails, or if the result is numerically singular.
    bool
    modify_factor(const std::vector<char> &fixed);

    /// Whether the fixed set @p fixed differs from the nearest factor's
    /// (own, else inherited) in at most settling_fraction of the unknowns,
    /// the full pattern has not proved too costly (full_pattern_allowance),
    /// and its factor with the modification copy is expected to fit in
    /// memory.
    bool
    active_set_settling(const std::vector<char> &fixed) const;

    /// Whether the simplicial copy the first update makes fits in half the
    /// memory the run has left (memory::available). It doubles the factor's
    /// memory, which on the largest problems sets the run's peak, while
    /// refactorising instead is only a little slower; on a smaller machine
    /// it refactorises (benchmarks/plate_tables/README.md, "Design
    /// measurements").
    bool
    room_for_modified_copy() const;

    /// K(X) y: A on the free part, the diagonal on the fixed part.
    void
    apply(const std::vector<char> &fixed,
          const DenseMatrix       &Y,
          DenseMatrix             &KY) const;

    /// CG iterations allowed with the factor of a fixed set @p changes
    /// indices away, 0 if factorising anew is expected to be cheaper.
    static unsigned int
    cg_iteration_budget(const SparseCholesky &nearby, unsigned int changes);

    /// Solve with @p factor, counting the triangular solves.
    void
    solve_with(const ActiveSetFactor &factor,
               const DenseMatrix     &B,
               DenseMatrix           &X) const;

    /// Preconditioned CG on K(X) X = B with @p preconditioner; true if
    /// every column reached the tolerance within @p max_iterations.
    bool
    preconditioned_cg(const std::vector<char> &fixed,
                      const ActiveSetFactor   &preconditioner,
                      const DenseMatrix       &B,
                      DenseMatrix             &X,
                      unsigned int             max_iterations);

    const SparseMatrix &A;
    Counters           &counters;
    /// AMD ordering of A (new-to-old), computed on first need.
    std::vector<Index>                     full_ordering;
    std::shared_ptr<ActiveSetFactor>       own;
    bool                                   own_valid = false;
    std::shared_ptr<const ActiveSetFactor> inherited;
    /// The analysis of A's full pattern a stage before left (an
    /// ActiveSetFactor::analysis_of), until the first factorisation takes
    /// or drops it; and whether the own factor holds it (then every K(X) is
    /// factorised in the full pattern, with no analysis of its own).
    std::shared_ptr<const ActiveSetFactor> analysis_of_A;
    bool                                   took_analysis_of_A = false;
    /// Diagonal used for fixed rows: A_jj if positive, else the mean diagonal.
    Vector fixed_diagonal;
    /// Flops of the latest factorisation of A_FF on its own (own or
    /// inherited), 0 if none; and whether the full pattern, once factorised
    /// for a settling active set, stayed within full_pattern_allowance of
    /// it.
    double reduced_factor_flops = 0;
    bool   full_pattern_pays    = true;
    /// Modification flops per entry of L on the changed rows' elimination
    /// paths (SparseCholesky::modification_path_entries), as measured in
    /// the last update: predicts the cost of the next one. CHOLMOD's update
    /// and downdate do about four per entry, whatever the size (measured on
    /// the plates: benchmarks/plate_tables/README.md, "Design
    /// measurements").
    double flops_per_path_entry = 4;
  };
} // namespace unilateral::lcp
