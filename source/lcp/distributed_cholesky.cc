#include <unilateral/base/input_error.h>
#include <unilateral/base/memory.h>
#include <unilateral/lcp/distributed_cholesky.h>

#include <petscmat.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace unilateral::lcp
{
  namespace
  {
    /// A failed PETSc call is a broken build or an exhausted machine, not
    /// bad input: an exception that names the step.
    void
    check(const PetscErrorCode code, const char *step)
    {
      if (code != 0)
        throw std::runtime_error(std::string("PETSc failed in ") + step +
                                 " (error code " + std::to_string(code) + ")");
    }

    /// The first row of @p rank's contiguous run among @p n_ranks.
    Index
    first_row(const Index n, const unsigned int rank, const unsigned int ranks)
    {
      return static_cast<Index>(static_cast<std::int64_t>(n) * rank / ranks);
    }

    std::uint64_t
    hash_pattern(const SparseMatrix &A)
    {
      std::uint64_t hash = 1469598103934665603ull;
      const auto    mix  = [&hash](const std::uint64_t value) {
        hash ^= value;
        hash *= 1099511628211ull;
      };
      mix(A.rows());
      for (Index j = 0; j <= A.cols(); ++j)
        mix(A.outerIndexPtr()[j]);
      for (Index k = 0; k < A.nonZeros(); ++k)
        mix(A.innerIndexPtr()[k]);
      return hash;
    }

    thread_local const DistributedFactorisations *innermost_scope = nullptr;
  } // namespace

  struct DistributedCholesky::Implementation
  {
    MPI_Comm      communicator;
    unsigned int  rank;
    unsigned int  n_ranks;
    Mat           matrix = nullptr; ///< this rank's rows of A (PETSc's AIJ)
    Mat           factor = nullptr; ///< MUMPS's factor of the analysed pattern
    std::uint64_t pattern_hash = 0;
    Index         n            = 0;
    Index         local_first  = 0; ///< first row of this rank
    Index         local_end    = 0;
    bool          factor_valid = false;
    // This rank's rows of the analysed pattern, in compressed rows with
    // global columns (PETSc's index type), kept for the values of every
    // later factorisation.
    std::vector<PetscInt> row_start, columns;

    ~Implementation()
    {
      destroy();
    }

    void
    destroy()
    {
      if (factor != nullptr)
        MatDestroy(&factor);
      if (matrix != nullptr)
        MatDestroy(&matrix);
      factor_valid = false;
    }

    /// The symbolic analysis of A's pattern (fingerprint @p hash): this
    /// rank's rows (A is symmetric: its column j, as Eigen stores it, is row
    /// j), the distributed matrix, then MUMPS's ordering and symbolic
    /// factorisation.
    void
    analyse(const SparseMatrix &A, const std::uint64_t hash, Counters &counters)
    {
      destroy();
      n                 = A.rows();
      local_first       = first_row(n, rank, n_ranks);
      local_end         = first_row(n, rank + 1, n_ranks);
      const auto *start = A.outerIndexPtr();
      row_start.assign(1, 0);
      for (Index i = local_first; i < local_end; ++i)
        row_start.push_back(start[i + 1] - start[local_first]);
      columns.assign(A.innerIndexPtr() + start[local_first],
                     A.innerIndexPtr() + start[local_end]);
      const std::vector<PetscScalar> values(A.valuePtr() + start[local_first],
                                            A.valuePtr() + start[local_end]);
      const PetscInt                 local = local_end - local_first;
      check(MatCreate(communicator, &matrix), "MatCreate");
      check(MatSetSizes(matrix, local, local, n, n), "MatSetSizes");
      check(MatSetType(matrix, MATAIJ), "MatSetType");
      check(MatSeqAIJSetPreallocationCSR(
              matrix, row_start.data(), columns.data(), values.data()),
            "MatSeqAIJSetPreallocationCSR");
      check(MatMPIAIJSetPreallocationCSR(
              matrix, row_start.data(), columns.data(), values.data()),
            "MatMPIAIJSetPreallocationCSR");

      check(MatGetFactor(matrix, MATSOLVERMUMPS, MAT_FACTOR_CHOLESKY, &factor),
            "MatGetFactor (MUMPS)");
      MatFactorInfo info;
      check(MatFactorInfoInitialize(&info), "MatFactorInfoInitialize");
      check(MatCholeskyFactorSymbolic(factor, matrix, nullptr, &info),
            "MatCholeskyFactorSymbolic");
      pattern_hash = hash;
      ++counters.symbolic_analyses;
    }

    /// A's values into the analysed matrix (the same pattern).
    void
    update_values(const SparseMatrix &A)
    {
      const double *values = A.valuePtr() + A.outerIndexPtr()[local_first];
      for (Index i = local_first; i < local_end; ++i)
        {
          const PetscInt row   = i;
          const PetscInt begin = row_start[i - local_first];
          const PetscInt end   = row_start[i - local_first + 1];
          check(MatSetValues(matrix,
                             1,
                             &row,
                             end - begin,
                             columns.data() + begin,
                             values + begin,
                             INSERT_VALUES),
                "MatSetValues");
        }
      check(MatAssemblyBegin(matrix, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
      check(MatAssemblyEnd(matrix, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
    }

    PetscInt
    infog(const PetscInt entry) const
    {
      PetscInt value = 0;
      check(MatMumpsGetInfog(factor, entry, &value), "MatMumpsGetInfog");
      return value;
    }
  };

  DistributedCholesky::DistributedCholesky(const MPI_Comm &communicator)
    : implementation(std::make_unique<Implementation>())
  {
    require_available();
    implementation->communicator = communicator;
    implementation->rank =
      dealii::Utilities::MPI::this_mpi_process(communicator);
    implementation->n_ranks =
      dealii::Utilities::MPI::n_mpi_processes(communicator);
  }

  DistributedCholesky::~DistributedCholesky() = default;

  void
  DistributedCholesky::require_available()
  {
    PetscBool initialised = PETSC_FALSE;
    if (!dealii::Utilities::MPI::job_supports_mpi() ||
        PetscInitialized(&initialised) != 0 || !initialised)
      throw InputError(
        "'Solver/Factorisation' = mumps factorises over the ranks of an MPI "
        "run, and this run was not started by an MPI launcher: run it as "
        "'mpirun -np 2 ./build/unilateral file.prm', or set 'Factorisation' "
        "to auto or cholmod");
  }

  bool
  DistributedCholesky::factorise(const SparseMatrix &A,
                                 const double        minimum_rcond,
                                 Counters           &counters)
  {
    auto &impl        = *implementation;
    impl.factor_valid = false;
    if (A.rows() == 0)
      {
        impl.destroy();
        impl.n            = 0;
        impl.factor_valid = true;
        return true;
      }
    if (!A.isCompressed())
      throw std::logic_error("DistributedCholesky needs a compressed matrix");
    // Every rank holds the same A; the analysis is kept only if every rank
    // finds its pattern unchanged (they must all call MUMPS alike).
    const std::uint64_t hash = hash_pattern(A);
    const bool          same_pattern =
      impl.factor != nullptr && impl.n == A.rows() && impl.pattern_hash == hash;
    if (dealii::Utilities::MPI::min(same_pattern ? 1 : 0, impl.communicator) ==
        1)
      impl.update_values(A);
    else
      impl.analyse(A, hash, counters);

    // Null pivots detected and counted (INFOG(28)) rather than factorised
    // into a solve that moves a floating body by 1e10: CNTL(3) is their
    // threshold relative to the matrix's largest entry. Both are read by the
    // numeric phase.
    check(MatMumpsSetIcntl(impl.factor, 24, minimum_rcond > 0 ? 1 : 0),
          "MatMumpsSetIcntl(24)");
    if (minimum_rcond > 0)
      check(MatMumpsSetCntl(impl.factor, 3, minimum_rcond),
            "MatMumpsSetCntl(3)");
    MatFactorInfo info;
    check(MatFactorInfoInitialize(&info), "MatFactorInfoInitialize");
    check(MatCholeskyFactorNumeric(impl.factor, impl.matrix, &info),
          "MatCholeskyFactorNumeric");
    ++counters.numeric_factorisations;
    MatFactorError error = MAT_FACTOR_NOERROR;
    check(MatFactorGetError(impl.factor, &error), "MatFactorGetError");
    // A zero pivot, structural or numerical, says that A is singular, which
    // the caller handles. Any other failure of MUMPS (an internal error, a
    // feature this build of MUMPS lacks) says nothing about A: reported as
    // a singular system, it would send the method down a wrong path.
    if (error == MAT_FACTOR_OUTMEMORY || error == MAT_FACTOR_OTHER)
      {
        const std::string step =
          "the factorisation of a system with " + std::to_string(A.rows()) +
          " unknowns (MUMPS's INFOG(1) = " + std::to_string(impl.infog(1)) +
          ", INFOG(2) = " + std::to_string(impl.infog(2)) + ")";
        if (error == MAT_FACTOR_OUTMEMORY)
          throw OutOfMemory("MUMPS ran out of memory in " + step);
        throw std::runtime_error("MUMPS failed in " + step +
                                 "; its user's guide lists the codes");
      }
    if (error != MAT_FACTOR_NOERROR)
      {
        // PETSc keeps MUMPS's error and returns at once from every later
        // numeric factorisation of this analysis: start afresh next time.
        impl.destroy();
        return false;
      }
    // INFOG(12): negative pivots (A indefinite); INFOG(28): null pivots
    // (A singular, with detection on). Both global.
    impl.factor_valid = impl.infog(12) == 0 && impl.infog(28) == 0;
    return impl.factor_valid;
  }

  void
  DistributedCholesky::solve(const DenseMatrix &B, DenseMatrix &X) const
  {
    const auto &impl = *implementation;
    if (!impl.factor_valid)
      throw std::logic_error("DistributedCholesky::solve without a factor");
    X.resize(B.rows(), B.cols());
    if (impl.n == 0 || B.cols() == 0)
      return;
    const PetscInt local   = impl.local_end - impl.local_first;
    const PetscInt columns = B.cols();
    // This rank's rows of B, column by column (PETSc's dense layout).
    std::vector<PetscScalar> local_B(static_cast<std::size_t>(local) * columns);
    for (PetscInt c = 0; c < columns; ++c)
      for (PetscInt i = 0; i < local; ++i)
        local_B[c * local + i] = B(impl.local_first + i, c);
    Mat B_matrix = nullptr, X_matrix = nullptr;
    check(MatCreateDense(impl.communicator,
                         local,
                         PETSC_DECIDE,
                         impl.n,
                         columns,
                         local_B.data(),
                         &B_matrix),
          "MatCreateDense");
    check(MatCreateDense(impl.communicator,
                         local,
                         PETSC_DECIDE,
                         impl.n,
                         columns,
                         nullptr,
                         &X_matrix),
          "MatCreateDense");
    check(MatMatSolve(impl.factor, B_matrix, X_matrix), "MatMatSolve");

    // Every rank's rows of X to every rank.
    const PetscScalar *local_X = nullptr;
    PetscInt           lda     = 0;
    check(MatDenseGetLDA(X_matrix, &lda), "MatDenseGetLDA");
    check(MatDenseGetArrayRead(X_matrix, &local_X), "MatDenseGetArrayRead");
    std::vector<double> mine(static_cast<std::size_t>(local) * columns);
    for (PetscInt c = 0; c < columns; ++c)
      for (PetscInt i = 0; i < local; ++i)
        mine[c * local + i] = local_X[c * lda + i];
    check(MatDenseRestoreArrayRead(X_matrix, &local_X),
          "MatDenseRestoreArrayRead");
    MatDestroy(&X_matrix);
    MatDestroy(&B_matrix);

    std::vector<int> counts(impl.n_ranks), offsets(impl.n_ranks);
    for (unsigned int r = 0; r < impl.n_ranks; ++r)
      {
        const Index rows = first_row(impl.n, r + 1, impl.n_ranks) -
                           first_row(impl.n, r, impl.n_ranks);
        counts[r]  = static_cast<int>(rows * columns);
        offsets[r] = r == 0 ? 0 : offsets[r - 1] + counts[r - 1];
      }
    std::vector<double> all(static_cast<std::size_t>(impl.n) * columns);
    const int           failed = MPI_Allgatherv(mine.data(),
                                      static_cast<int>(mine.size()),
                                      MPI_DOUBLE,
                                      all.data(),
                                      counts.data(),
                                      offsets.data(),
                                      MPI_DOUBLE,
                                      impl.communicator);
    if (failed != MPI_SUCCESS)
      throw std::runtime_error("MPI_Allgatherv failed in a distributed solve");
    for (unsigned int r = 0; r < impl.n_ranks; ++r)
      {
        const Index first = first_row(impl.n, r, impl.n_ranks);
        const Index rows  = first_row(impl.n, r + 1, impl.n_ranks) - first;
        for (PetscInt c = 0; c < columns; ++c)
          for (Index i = 0; i < rows; ++i)
            X(first + i, c) = all[offsets[r] + c * rows + i];
      }
  }

  bool
  DistributedCholesky::has_factor() const
  {
    return implementation->factor_valid;
  }

  double
  DistributedCholesky::factor_nonzeros() const
  {
    const auto &impl = *implementation;
    if (impl.factor == nullptr)
      return 0;
    // Negative: in millions (MUMPS's convention against overflow).
    const PetscInt entries = impl.infog(29);
    return entries < 0 ? -1e6 * entries : static_cast<double>(entries);
  }

  double
  DistributedCholesky::factorisation_flops() const
  {
    const auto &impl = *implementation;
    if (impl.factor == nullptr)
      return 0;
    PetscReal flops = 0;
    check(MatMumpsGetRinfog(impl.factor, 3, &flops), "MatMumpsGetRinfog");
    return flops;
  }

  unsigned int
  DistributedCholesky::n_ranks() const
  {
    return implementation->n_ranks;
  }

  DistributedFactorisations::DistributedFactorisations(
    const MPI_Comm &communicator)
    : communicator(communicator)
    , enclosing(innermost_scope)
  {
    innermost_scope = this;
  }

  DistributedFactorisations::~DistributedFactorisations()
  {
    innermost_scope = enclosing;
  }

  const MPI_Comm *
  DistributedFactorisations::current()
  {
    return innermost_scope != nullptr ? &innermost_scope->communicator :
                                        nullptr;
  }
} // namespace unilateral::lcp
