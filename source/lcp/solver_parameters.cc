#include <unilateral/base/input_error.h>
#include <unilateral/lcp/solver.h>

#include <deal.II/base/parameter_handler.h>

namespace unilateral::lcp
{
  using dealii::Patterns::Bool;
  using dealii::Patterns::Double;
  using dealii::Patterns::Integer;
  using dealii::Patterns::Selection;

  void
  SolverParameters::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Solver");
    {
      prm.declare_entry("Method",
                        "pdas",
                        Selection(SolverRegistry::selection()),
                        "The LCP algorithm.\n" +
                          SolverRegistry::documentation());
      prm.declare_entry(
        "Schur complement",
        "false",
        Bool(),
        "Eliminate the unconstrained unknowns E and solve the reduced, dense "
        "LCP on the constrained set S (Ainsworth & Mihai, eqs. 3.13-3.18), "
        "then recover u_E = A_EE^-1 (b_E - A_ES u_S). Needs A_EE nonsingular "
        "and |S| <= 'Maximum dense size'.");
      prm.declare_entry(
        "Regularisation",
        "auto",
        dealii::Patterns::Anything(),
        "eps of the regularised matrix A + eps d I, where d is the mean of "
        "the diagonal of A (so eps is unit-free). Used only by methods that "
        "need a positive definite matrix (psor, lssnn, pdas, block_pivoting), "
        "followed by the projection step. 'auto' takes the scene's choice: "
        "1e-9 for masonry (whose A is singular: blocks are free to move), 0 "
        "for the plate and for LCP files, where 1e-9 follows if the method "
        "meets a singular system. A number >= 0 overrides it.");
      prm.declare_entry(
        "Projection",
        "true",
        Bool(),
        "After solving the regularised problem, run PDAS on the original A "
        "from u_eps (Ainsworth & Mihai, Section 4): it recovers the exact "
        "solution, usually in one iteration. The same step follows the "
        "approximate methods (psor, pdpc, interior_point), as Ainsworth & "
        "Mihai suggest for PDPC, and an exact method whose answer fails the "
        "KKT check. Switch it off to see a method's own answer (a "
        "regularised one is then reported 'inaccurate').");
      prm.declare_entry(
        "Maximum iterations",
        "0",
        Integer(0),
        "Iteration limit of the method; 0 takes each method's default "
        "(psor: 100000 sweeps, lssnn: 3|S| + 100, pdas/pdpc/interior_point: "
        "500, block_pivoting: 10|S| + 100, graves: 10|S| + 100). Reaching it "
        "is reported as status 'iteration limit', never as a solution; at 0, "
        "PDAS that cycles continues from the interior point (see PDAS/Safeguard).");
      prm.declare_entry(
        "Maximum dense size",
        "6000",
        Integer(1),
        "Largest number of unknowns a dense path takes (graves, Schur "
        "complement); larger problems are refused with a message instead of "
        "exhausting memory. Memory is about 16 n^2 bytes.");
      prm.declare_entry(
        "KKT tolerance",
        "1e-8",
        Double(0),
        "A method that reports convergence while the relative KKT residuals "
        "of its answer exceed this gets status 'inaccurate': no wrong answer "
        "is printed as converged.");

      prm.enter_subsection("PSOR");
      prm.declare_entry("Relaxation",
                        "0",
                        Double(0, 2),
                        "omega in (0, 2); 0 takes 2 / (1 + sin(pi / n)) as "
                        "Ainsworth & Mihai.");
      prm.declare_entry("Tolerance",
                        "0",
                        Double(0),
                        "Stop when ||u_old - u|| / ||u|| < tolerance; 0 takes "
                        "n * machine epsilon as Ainsworth & Mihai.");
      prm.leave_subsection();

      prm.enter_subsection("PDAS");
      prm.declare_entry("Tau",
                        "1e-3",
                        Double(0),
                        "tau > 0 of the active-set test u_i - l_i - tau "
                        "lambda_i < 0 (Ainsworth & Mihai: tau ~ 1e-3). Also "
                        "used by the projection step.");
      prm.declare_entry("Start",
                        "auto",
                        Selection("auto|zero|all active"),
                        "The initial iterate u0 (Ainsworth & Mihai allow any "
                        "u0 with u0_S >= l_S). 'zero': u0 = 0, as in the "
                        "paper. 'all active': u0 minimises the energy with "
                        "every constraint at its bound (the start of LSSNN "
                        "and block pivoting); the first active set is then "
                        "the set of compressed contacts, which for walls in "
                        "contact almost everywhere is nearly the answer (at "
                        "m = 225 stack bond: 7 iterations instead of 11) but "
                        "for an obstacle touched on a third of its nodes is "
                        "worse (34 instead of 24). 'auto': the scene's "
                        "choice, 'all active' for masonry, 'zero' otherwise.");
      prm.declare_entry(
        "Round-off tolerance",
        "1e-12",
        Double(0, 1e-3),
        "An index changes side only if it violates it by more than this "
        "times the magnitude of the terms of its multiplier, sum_j |A_ij u_j| "
        "+ |b_i| (the slack in the same units). Without it, a closed contact "
        "carrying exactly zero force (the top of a wall's vertical joints, an "
        "obstacle node touched with no pressure) flips sides on round-off and "
        "PDAS never stops. 0 compares exactly, as the paper.");
      prm.declare_entry(
        "Safeguard",
        "10",
        Integer(0),
        "After this many iterations without a new low in the number of "
        "violated indices (above 1000 violated, a new low must be a tenth "
        "lower), the indices that changed side meanwhile are resolved "
        "exactly at once (Schur complement on them, Graves' method); a "
        "singular step resolves the open constraints its free motion moves; "
        "at most 1000 violated indices that do not halve in number within 4 "
        "iterations (a creeping boundary of a separated zone) resolve those "
        "that changed side in them, with their neighbours. "
        "A cycle of more than 1000 indices, or more than 1000 violated "
        "indices whose fewest do not halve within 8 iterations, ends PDAS "
        "as cycling at the "
        "default 'Maximum iterations', and the solve continues from the "
        "interior point's answer (noted in the report); with a limit set, "
        "Judice & Pires' single pivots take over instead. 0: the paper's "
        "PDAS without any of these.");
      prm.leave_subsection();

      prm.enter_subsection("PDPC");
      prm.declare_entry("Initial point",
                        "1e-2",
                        Double(0),
                        "u0 = eps e, Sigma0 = -eps e (slacks and multipliers of "
                        "the scaled problem); Ainsworth & Mihai take eps in "
                        "(1e-6, 1e-2). The upper end is the default: a smaller "
                        "eps starts almost on the complementarity surface but "
                        "far from feasibility, and every step is then cut "
                        "short by a bound (on a 16129-unknown obstacle problem "
                        "1e-6 takes 185 iterations, 1e-2 takes 29).");
      prm.declare_entry("Complementarity tolerance",
                        "0",
                        Double(0),
                        "tol1 on |Sigma_S^T u_S| / n_c; 0: the total "
                        "|Sigma_S^T u_S| within n_c * machine epsilon (the "
                        "paper's tol1 on the mean lets large walls stop too "
                        "far from the answer for the projection), or the "
                        "mean within the paper's n_c * machine epsilon once "
                        "it no longer halves in four iterations (its "
                        "rounding floor).");
      prm.declare_entry("Residual tolerance",
                        "0",
                        Double(0),
                        "tol2 on ||b - A u - Sigma||_2; 0 takes n * "
                        "sqrt(machine epsilon) (scaled problem).");
      prm.declare_entry("Diagonal scaling",
                        "true",
                        Bool(),
                        "Scale A to unit diagonal first, as Ainsworth & Mihai "
                        "do to keep Step 4 solvable.");
      prm.declare_entry("Step to boundary",
                        "0.9995",
                        Double(0, 1),
                        "A step cut short by a bound (alpha_1 or alpha_2 < 1) "
                        "is multiplied by this factor so the iterate stays "
                        "strictly interior. 1 is the printed rule, which can "
                        "land exactly on the boundary and make Step 4 "
                        "singular.");
      prm.leave_subsection();

      prm.enter_subsection("Interior point");
      prm.declare_entry("Centering",
                        "0.1",
                        Double(0, 1),
                        "delta in (0, 1) of mu_k = delta gap / |J1| (eq. 42 of "
                        "Fernandes et al., who do not state its value).");
      prm.declare_entry("Step factor",
                        "0.99995",
                        Double(0, 1),
                        "beta of the step alpha = min(1, beta alpha_max) (eq. "
                        "50; the paper takes 0.99995).");
      prm.declare_entry("Residual tolerance",
                        "1e-10",
                        Double(0),
                        "epsilon_1 on ||C z - F - w||_2 (eq. 55).");
      prm.declare_entry("Complementarity tolerance",
                        "1e-8",
                        Double(0),
                        "epsilon_2 on (z - psi)^T w (eq. 56).");
      prm.declare_entry(
        "Variant",
        "basic",
        dealii::Patterns::Selection("basic|predictor-corrector"),
        "basic: the method of Fernandes et al. (one Newton step per "
        "iteration, centring delta). predictor-corrector: Mehrotra's, which "
        "starts from his heuristic point (one more factorisation), chooses "
        "the centring from an affine step and corrects its second "
        "order term: two solves with one factorisation per iteration, and "
        "far fewer iterations where the solution is degenerate (running bond "
        "walls, where the basic method converges only linearly). The "
        "hand-over from cycling PDAS always uses predictor-corrector.");
      prm.declare_entry(
        "Centrality correctors",
        "2",
        Integer(0, 10),
        "Gondzio's multiple centrality correctors per predictor-corrector "
        "iteration (ignored by the basic variant): each is one more solve "
        "with the iteration's factor that pulls the complementarity products "
        "far from their mean back towards it, and is kept only if it "
        "lengthens the step by 1 %. Where the affine step is short "
        "(degenerate walls) they save factorisations: running bond m = 100, "
        "22 -> 18 iterations. 0: Mehrotra's method alone.");
      prm.leave_subsection();

      prm.enter_subsection("Block pivoting");
      prm.declare_entry("p",
                        "10",
                        Integer(1),
                        "Block iterations allowed without a decrease of the "
                        "infeasibility count before single pivots take over "
                        "(Judice & Pires; the paper takes 10).");
      prm.declare_entry("Tolerance",
                        "1e-6",
                        Double(0),
                        "epsilon of the infeasibility set H (eq. 67).");
      prm.leave_subsection();
    }
    prm.leave_subsection();
  }

  void
  SolverParameters::parse_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Solver");
    {
      method           = prm.get("Method");
      schur_complement = prm.get_bool("Schur complement");
      const std::string eps = prm.get("Regularisation");
      if (eps == "auto")
        regularisation = -1;
      else
        {
          std::size_t used = 0;
          try
            {
              regularisation = std::stod(eps, &used);
            }
          catch (const std::exception &)
            {
              used = 0;
            }
          check_parameter(used == eps.size() && used > 0,
                          "Solver",
                          "Regularisation",
                          eps,
                          "must be 'auto' or a number >= 0");
          check_parameter(regularisation >= 0,
                          "Solver",
                          "Regularisation",
                          eps,
                          "must be >= 0 (eps < 0 would make A + eps I "
                          "indefinite)");
        }
      projection     = prm.get_bool("Projection");
      max_iterations = prm.get_integer("Maximum iterations");
      max_dense_size = prm.get_integer("Maximum dense size");
      kkt_tolerance  = prm.get_double("KKT tolerance");

      prm.enter_subsection("PSOR");
      psor.omega     = prm.get_double("Relaxation");
      psor.tolerance = prm.get_double("Tolerance");
      check_parameter(psor.omega < 2,
                      "Solver/PSOR",
                      "Relaxation",
                      psor.omega,
                      "must be in (0, 2) for convergence, or 0 for automatic");
      prm.leave_subsection();

      prm.enter_subsection("PDAS");
      pdas.tau              = prm.get_double("Tau");
      pdas.round_off        = prm.get_double("Round-off tolerance");
      pdas.safeguard        = prm.get_integer("Safeguard");
      const std::string start = prm.get("Start");
      pdas.start = start == "zero"       ? PdasStart::zero :
                   start == "all active" ? PdasStart::all_active :
                                           PdasStart::automatic;
      check_parameter(pdas.tau > 0, "Solver/PDAS", "Tau", pdas.tau,
                      "must be > 0");
      prm.leave_subsection();

      prm.enter_subsection("PDPC");
      pdpc.initial_point      = prm.get_double("Initial point");
      pdpc.tolerance_gap      = prm.get_double("Complementarity tolerance");
      pdpc.tolerance_residual = prm.get_double("Residual tolerance");
      pdpc.diagonal_scaling   = prm.get_bool("Diagonal scaling");
      pdpc.step_to_boundary   = prm.get_double("Step to boundary");
      check_parameter(pdpc.step_to_boundary > 0, "Solver/PDPC",
                      "Step to boundary", pdpc.step_to_boundary,
                      "must be in (0, 1]");
      check_parameter(pdpc.initial_point > 0, "Solver/PDPC", "Initial point",
                      pdpc.initial_point, "must be > 0 (interior start)");
      prm.leave_subsection();

      prm.enter_subsection("Interior point");
      interior_point.centering   = prm.get_double("Centering");
      interior_point.step_factor = prm.get_double("Step factor");
      interior_point.residual_tolerance =
        prm.get_double("Residual tolerance");
      interior_point.complementarity_tolerance =
        prm.get_double("Complementarity tolerance");
      interior_point.predictor_corrector =
        prm.get("Variant") == "predictor-corrector";
      interior_point.centrality_correctors =
        prm.get_integer("Centrality correctors");
      check_parameter(interior_point.centering > 0 &&
                        interior_point.centering < 1,
                      "Solver/Interior point", "Centering",
                      interior_point.centering, "must be in (0, 1)");
      check_parameter(interior_point.step_factor > 0 &&
                        interior_point.step_factor < 1,
                      "Solver/Interior point", "Step factor",
                      interior_point.step_factor, "must be in (0, 1)");
      prm.leave_subsection();

      prm.enter_subsection("Block pivoting");
      block_pivoting.p         = prm.get_integer("p");
      block_pivoting.tolerance = prm.get_double("Tolerance");
      prm.leave_subsection();
    }
    prm.leave_subsection();
  }
} // namespace unilateral::lcp
