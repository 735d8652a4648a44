/**
 * PETSc (Debian's 3.18, the one deal.II uses): the LCP as
 *  - a bound-constrained QP for TAO: min 1/2 u'Au - b'u, l_S <= u_S, the
 *    other unknowns free (PETSC_NINFINITY / PETSC_INFINITY), gradient Au - b,
 *    Hessian A (constant, assembled once);
 *      tao_bqpip  Mehrotra predictor-corrector interior point;
 *      tao_gpcg   gradient projection + Newton steps on the free face;
 *      tao_tron   trust-region Newton on the free face (More & Toraldo /
 *                 Lin & More), with gradient-projection steps;
 *  - a variational inequality for SNES: F(u) = Au - b, Jacobian A, bounds
 *    [l_S, +inf) on S and (-inf, inf) elsewhere;
 *      snes_vinewtonrsls  reduced-space active-set semismooth Newton;
 *      snes_vinewtonssls  semismooth Newton on the Fischer-Burmeister function.
 *
 * Linear algebra (option linear=...):
 *  - direct (default): KSP preonly + PC cholesky with the factorisation of
 *    option factor=cholmod|mumps|petsc (cholmod: SuiteSparse CHOLMOD, the
 *    library unilateral uses too; the default except for BQPIP, whose
 *    barrier-shifted matrices make CHOLMOD produce NaNs on the larger
 *    problems, so it gets MUMPS). TRON needs a trust-region Krylov method, so
 *    it gets KSP STCG preconditioned by that Cholesky factor (one CG step when
 *    the Newton step lies inside the trust region). SSLS's Jacobian is not
 *    symmetric: PC lu with UMFPACK (or factor=mumps|petsc).
 *  - cg: the packages' own Krylov defaults (BQPIP: CG; GPCG: NASH; TRON:
 *    STCG) with PC icc (incomplete Cholesky); SNES: CG + icc.
 * Extra PETSc options can be passed verbatim: petsc="-key value ...".
 *
 * Tolerances (option tol, default 1e-12, relative to ||b||_2):
 *  TAO: gatol = tol ||b||_2 on the projected gradient (BQPIP: on its
 *       sqrt(gap + dual infeasibility), tol 1e-7 by default, see below),
 *       grtol = gttol = 0;
 *  SNES: atol = tol ||b||_2 on the norm of the reduced / FB residual,
 *       rtol = stol = 0.
 * BQPIP also gets a box |u| <= box (default 1e6) instead of infinite bounds.
 */
#include "common/driver.h"

#include <petscsnes.h>
#include <petsctao.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace
{
  using namespace external;

  void
  check(const PetscErrorCode code, const char *what)
  {
    if (code != 0)
      {
        const char *text = nullptr;
        PetscErrorMessage(code, &text, nullptr);
        throw std::runtime_error(std::string("PETSc error in ") + what + ": " +
                                 (text != nullptr ? text : "unknown"));
      }
  }

#define CHECK(call) check((call), #call)

  /// PetscInitialize once per process, PetscFinalize at exit.
  struct PetscSession
  {
    PetscSession()
    {
      CHECK(PetscInitializeNoArguments());
    }
    ~PetscSession()
    {
      PetscFinalize();
    }
  };

  struct Data
  {
    Mat A     = nullptr;
    Vec b     = nullptr;
    Vec u     = nullptr;
    Vec lower = nullptr;
    Vec upper = nullptr;
    Vec work  = nullptr;

    ~Data()
    {
      MatDestroy(&A);
      VecDestroy(&b);
      VecDestroy(&u);
      VecDestroy(&lower);
      VecDestroy(&upper);
      VecDestroy(&work);
    }
  };

  /// A (both triangles, as stored in Problem) as SeqAIJ: Problem's column-
  /// compressed storage of a symmetric matrix is the row-compressed one.
  void
  build(const Problem &problem, Data &data, const double box = 0)
  {
    const PetscInt        n = problem.size();
    std::vector<PetscInt> row_lengths(n);
    for (PetscInt i = 0; i < n; ++i)
      row_lengths[i] =
        problem.A.outerIndexPtr()[i + 1] - problem.A.outerIndexPtr()[i];
    CHECK(
      MatCreateSeqAIJ(PETSC_COMM_SELF, n, n, 0, row_lengths.data(), &data.A));
    for (PetscInt i = 0; i < n; ++i)
      {
        const PetscInt        begin = problem.A.outerIndexPtr()[i];
        std::vector<PetscInt> columns(problem.A.innerIndexPtr() + begin,
                                      problem.A.innerIndexPtr() + begin +
                                        row_lengths[i]);
        CHECK(MatSetValues(data.A,
                           1,
                           &i,
                           row_lengths[i],
                           columns.data(),
                           problem.A.valuePtr() + begin,
                           INSERT_VALUES));
      }
    CHECK(MatAssemblyBegin(data.A, MAT_FINAL_ASSEMBLY));
    CHECK(MatAssemblyEnd(data.A, MAT_FINAL_ASSEMBLY));
    CHECK(MatSetOption(data.A, MAT_SYMMETRIC, PETSC_TRUE));

    CHECK(VecCreateSeq(PETSC_COMM_SELF, n, &data.b));
    CHECK(VecDuplicate(data.b, &data.u));
    CHECK(VecDuplicate(data.b, &data.lower));
    CHECK(VecDuplicate(data.b, &data.upper));
    CHECK(VecDuplicate(data.b, &data.work));
    PetscScalar *b, *lower, *upper, *u;
    CHECK(VecGetArray(data.b, &b));
    CHECK(VecGetArray(data.lower, &lower));
    CHECK(VecGetArray(data.upper, &upper));
    CHECK(VecGetArray(data.u, &u));
    for (PetscInt i = 0; i < n; ++i)
      {
        b[i]     = problem.b[i];
        lower[i] = box > 0 ? -box : PETSC_NINFINITY;
        upper[i] = box > 0 ? box : PETSC_INFINITY;
        u[i]     = 0;
      }
    // Start from 0 projected onto the feasible set.
    for (Index k = 0; k < problem.n_constrained(); ++k)
      {
        const Index i = problem.constrained[k];
        lower[i]      = problem.lower_bound[k];
        if (box > 0)
          upper[i] = problem.lower_bound[k] + 2 * box;
        u[i] = std::max(0.0, problem.lower_bound[k]);
      }
    CHECK(VecRestoreArray(data.b, &b));
    CHECK(VecRestoreArray(data.lower, &lower));
    CHECK(VecRestoreArray(data.upper, &upper));
    CHECK(VecRestoreArray(data.u, &u));
  }

  void
  copy_out(Vec from, Vector &to)
  {
    PetscInt n;
    CHECK(VecGetSize(from, &n));
    const PetscScalar *values;
    CHECK(VecGetArrayRead(from, &values));
    to = Eigen::Map<const Vector>(values, n);
    CHECK(VecRestoreArrayRead(from, &values));
  }

  /// Options for the KSP (neither TAO nor SNES give theirs a prefix).
  void
  set_linear_solver(const std::string &prefix,
                    const std::string &method,
                    Options           &options,
                    const std::string &default_factor = "cholmod")
  {
    const std::string linear = options.string("linear", "direct");
    const std::string factor = options.string("factor", default_factor);
    auto set = [&](const std::string &key, const std::string &value) {
      CHECK(PetscOptionsSetValue(nullptr,
                                 ("-" + prefix + key).c_str(),
                                 value.c_str()));
    };
    if (linear == "direct")
      {
        if (method == "tao_tron")
          set("ksp_type", "stcg");
        else
          set("ksp_type", "preonly");
        if (method == "snes_vinewtonssls")
          {
            // The Fischer-Burmeister Jacobian is not symmetric: LU, with
            // UMFPACK (SuiteSparse) standing in for CHOLMOD.
            set("pc_type", "lu");
            if (factor != "petsc")
              set("pc_factor_mat_solver_type",
                  factor == "cholmod" ? "umfpack" : factor);
          }
        else
          {
            set("pc_type", "cholesky");
            if (factor != "petsc")
              set("pc_factor_mat_solver_type", factor);
          }
      }
    else if (linear == "cg")
      {
        if (method.rfind("snes", 0) == 0)
          set("ksp_type", "cg");
        set("pc_type", "icc");
        set("ksp_rtol", "1e-14");
      }
    else
      throw unilateral::InputError("option linear=" + linear +
                                   ": use direct or cg");
    if (factor != "cholmod" && factor != "mumps" && factor != "petsc")
      throw unilateral::InputError("option factor=" + factor +
                                   ": use cholmod, mumps or petsc");
  }

  PetscErrorCode
  objective_and_gradient(Tao, Vec u, PetscReal *f, Vec g, void *context)
  {
    const Data &data = *static_cast<const Data *>(context);
    PetscScalar ub, uAu;
    // g = A u - b, f = 1/2 u'Au - b'u = 1/2 u'(g - b)
    PetscCall(MatMult(data.A, u, g));
    PetscCall(VecDot(u, g, &uAu));
    PetscCall(VecDot(u, data.b, &ub));
    PetscCall(VecAXPY(g, -1.0, data.b));
    *f = 0.5 * uAu - ub;
    return 0;
  }

  /// TAO's default test, plus: stop once the iterate's relative KKT residual
  /// (unilateral's yardstick) is below the target.
  struct KktStop
  {
    const Problem *problem;
    double         target;
  };

  PetscErrorCode
  kkt_convergence_test(Tao tao, void *context)
  {
    const KktStop &stop = *static_cast<const KktStop *>(context);
    PetscCall(TaoDefaultConvergenceTest(tao, nullptr));
    TaoConvergedReason reason;
    PetscCall(TaoGetConvergedReason(tao, &reason));
    if (reason != TAO_CONTINUE_ITERATING)
      return 0;
    Vec                u;
    const PetscScalar *values;
    PetscCall(TaoGetSolution(tao, &u));
    PetscCall(VecGetArrayRead(u, &values));
    const Vector copy = Eigen::Map<const Vector>(values, stop.problem->size());
    PetscCall(VecRestoreArrayRead(u, &values));
    if (unilateral::lcp::kkt_residuals(*stop.problem, copy).max() <=
        stop.target)
      PetscCall(TaoSetConvergedReason(tao, TAO_CONVERGED_USER));
    return 0;
  }

  PetscErrorCode
  hessian(Tao, Vec, Mat, Mat, void *)
  {
    return 0; // A, assembled once
  }

  PetscErrorCode
  residual(SNES, Vec u, Vec F, void *context)
  {
    const Data &data = *static_cast<const Data *>(context);
    PetscCall(MatMult(data.A, u, F));
    PetscCall(VecAXPY(F, -1.0, data.b));
    return 0;
  }

  PetscErrorCode
  jacobian(SNES, Vec, Mat, Mat, void *)
  {
    return 0; // A, assembled once
  }

  double
  norm2(const Problem &problem)
  {
    const double value = problem.b.norm();
    return value > 0 ? value : 1.0;
  }

  void
  solve_tao(const std::string &method,
            const Problem     &problem,
            Options           &options,
            Outcome           &outcome)
  {
    const Stopwatch setup;
    PetscSession    session;
    Data            data;
    // BQPIP replaces infinite bounds by +-1e20 and keeps them in its barrier
    // and duality gap, which then diverges; a finite box far from any of our
    // solutions (|u| <= 1e6, the KKT check is against the original problem)
    // makes it work. Its stopping measure sqrt(gap + dual infeasibility)
    // stalls near 1e-7 relative, which already gives KKT residuals ~1e-15.
    const bool bqpip = method == "tao_bqpip";
    build(problem, data, options.number("box", bqpip ? 1e6 : 0));
    const double tol = options.number("tol", bqpip ? 1e-7 : 1e-12);
    // BQPIP's own test often never fires (see above): cap its iterations.
    const int max_iterations =
      options.integer("max_iterations", bqpip ? 200 : 10000);
    set_linear_solver("", method, options, bqpip ? "mumps" : "cholmod");
    if (method == "tao_gpcg")
      CHECK(PetscOptionsSetValue(nullptr,
                                 "-tao_subset_type",
                                 options.string("subset", "subvec").c_str()));
    if (method == "tao_tron")
      CHECK(PetscOptionsSetValue(nullptr,
                                 "-tao_subset_type",
                                 options.string("subset", "subvec").c_str()));
    const std::string extra = options.string("petsc", "");
    CHECK(PetscOptionsInsertString(nullptr, extra.c_str()));

    Tao tao;
    CHECK(TaoCreate(PETSC_COMM_SELF, &tao));
    CHECK(TaoSetType(tao,
                     method == "tao_bqpip" ? TAOBQPIP :
                     method == "tao_gpcg"  ? TAOGPCG :
                                             TAOTRON));
    CHECK(TaoSetSolution(tao, data.u));
    CHECK(TaoSetVariableBounds(tao, data.lower, data.upper));
    CHECK(
      TaoSetObjectiveAndGradient(tao, nullptr, objective_and_gradient, &data));
    CHECK(TaoSetHessian(tao, data.A, data.A, hessian, &data));
    CHECK(TaoSetTolerances(tao, tol * norm2(problem), 0.0, 0.0));
    CHECK(TaoSetMaximumIterations(tao, max_iterations));
    CHECK(TaoSetMaximumFunctionEvaluations(tao, 100 * max_iterations));
    // BQPIP's own measure stalls (above): by default it is also stopped as
    // soon as its iterate meets the KKT target (stop=kkt); stop=own leaves
    // only TAO's tests. The check costs one product with A per iteration,
    // counted in its solve time.
    KktStop kkt_stop{&problem, options.number("kkt_target", 1e-12)};
    if (options.string("stop", bqpip ? "kkt" : "own") == "kkt")
      CHECK(TaoSetConvergenceTest(tao, kkt_convergence_test, &kkt_stop));
    CHECK(TaoSetFromOptions(tao));
    CHECK(TaoSetUp(tao));
    outcome.setup_time = setup.seconds();

    const Stopwatch      solve;
    const PetscErrorCode code = TaoSolve(tao);
    outcome.solve_time        = solve.seconds();

    if (code != 0)
      {
        const char *text = nullptr;
        PetscErrorMessage(code, &text, nullptr);
        outcome.status    = "error";
        outcome.converged = false;
        outcome.message   = std::string("TaoSolve: ") + (text ? text : "");
      }
    else
      {
        TaoConvergedReason reason;
        PetscInt           iterations;
        CHECK(TaoGetConvergedReason(tao, &reason));
        CHECK(TaoGetIterationNumber(tao, &iterations));
        outcome.iterations = iterations;
        outcome.converged  = reason > 0;
        outcome.status     = TaoConvergedReasons[reason];
      }
    KSP ksp;
    CHECK(TaoGetKSP(tao, &ksp));
    if (ksp != nullptr)
      {
        KSPType ksp_type;
        PC      pc;
        PCType  pc_type;
        CHECK(KSPGetType(ksp, &ksp_type));
        CHECK(KSPGetPC(ksp, &pc));
        CHECK(PCGetType(pc, &pc_type));
        outcome.message += std::string(outcome.message.empty() ? "" : "; ") +
                           "KSP " + (ksp_type ? ksp_type : "?") + ", PC " +
                           (pc_type ? pc_type : "?");
      }
    copy_out(data.u, outcome.u);
    TaoDestroy(&tao);
  }

  void
  solve_snes(const std::string &method,
             const Problem     &problem,
             Options           &options,
             Outcome           &outcome)
  {
    const Stopwatch setup;
    PetscSession    session;
    Data            data;
    build(problem, data);
    const double tol            = options.number("tol", 1e-12);
    const int    max_iterations = options.integer("max_iterations", 10000);
    set_linear_solver("", method, options);
    const std::string extra = options.string("petsc", "");
    CHECK(PetscOptionsInsertString(nullptr, extra.c_str()));

    SNES snes;
    CHECK(SNESCreate(PETSC_COMM_SELF, &snes));
    CHECK(SNESSetType(snes,
                      method == "snes_vinewtonrsls" ? SNESVINEWTONRSLS :
                                                      SNESVINEWTONSSLS));
    CHECK(SNESSetFunction(snes, data.work, residual, &data));
    CHECK(SNESSetJacobian(snes, data.A, data.A, jacobian, &data));
    CHECK(SNESVISetVariableBounds(snes, data.lower, data.upper));
    // atol on the norm of the VI residual; rtol and stol off so that only the
    // absolute test (tied to ||b||) stops the iteration.
    CHECK(SNESSetTolerances(snes,
                            tol * norm2(problem),
                            0.0,
                            0.0,
                            max_iterations,
                            100 * max_iterations));
    CHECK(SNESSetFromOptions(snes));
    CHECK(SNESSetSolution(snes, data.u));
    CHECK(SNESSetUp(snes));
    outcome.setup_time = setup.seconds();

    const Stopwatch      solve;
    const PetscErrorCode code = SNESSolve(snes, nullptr, data.u);
    outcome.solve_time        = solve.seconds();
    if (code != 0)
      {
        const char *text = nullptr;
        PetscErrorMessage(code, &text, nullptr);
        outcome.status    = "error";
        outcome.converged = false;
        outcome.message   = std::string("SNESSolve: ") + (text ? text : "");
      }
    else
      {
        SNESConvergedReason reason;
        PetscInt            iterations, linear_iterations;
        CHECK(SNESGetConvergedReason(snes, &reason));
        CHECK(SNESGetIterationNumber(snes, &iterations));
        CHECK(SNESGetLinearSolveIterations(snes, &linear_iterations));
        outcome.iterations = iterations;
        outcome.converged  = reason > 0;
        outcome.status     = SNESConvergedReasons[reason];
        outcome.message =
          std::to_string(linear_iterations) + " linear iterations";
      }
    KSP     ksp;
    KSPType ksp_type;
    PC      pc;
    PCType  pc_type;
    CHECK(SNESGetKSP(snes, &ksp));
    CHECK(KSPGetType(ksp, &ksp_type));
    CHECK(KSPGetPC(ksp, &pc));
    CHECK(PCGetType(pc, &pc_type));
    outcome.message += std::string("; KSP ") + (ksp_type ? ksp_type : "?") +
                       ", PC " + (pc_type ? pc_type : "?");
    copy_out(data.u, outcome.u);
    SNESDestroy(&snes);
  }

  void
  solve(const std::string &method,
        const Problem     &problem,
        Options           &options,
        Outcome           &outcome)
  {
    if (method == "tao_bqpip" || method == "tao_gpcg" || method == "tao_tron")
      solve_tao(method, problem, options, outcome);
    else if (method == "snes_vinewtonrsls" || method == "snes_vinewtonssls")
      solve_snes(method, problem, options, outcome);
    else
      throw unilateral::InputError(
        "unknown method '" + method +
        "'; use tao_bqpip, tao_gpcg, tao_tron, snes_vinewtonrsls or "
        "snes_vinewtonssls");
  }
} // namespace

int
main(int argc, char **argv)
{
  return external::run(argc, argv, "petsc", solve);
}
