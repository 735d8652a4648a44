#!/usr/bin/python3
"""Time against error: every scene, every solver, mesh and tolerance sweeps.

    /usr/bin/python3 benchmarks/evidence/run_evidence.py [--quick] [options]

Scenes: the three masonry walls (stack bond, running bond, laminae, g = H/2;
Ainsworth & Mihai) and the clamped steel plate under f1 over psi1, psi2,
psi3 (Fernandes, Figueiredo & Judice). For each scene it runs (FULL and
QUICK below hold the lists)

  size        the mesh sweep with every solver at its defaults (exact methods,
              and the approximate ones followed by the projection step):
              masonry m = 5, 10, 20, 50, 100 at r = 0; plate n1 = 8..64;
  refinement  masonry only: m = 5, r = 0..3 (the plate's size sweep is its
              refinement sweep);
  tolerance   psor, pdpc, interior_point and block_pivoting with
              'Projection = false' and their tolerances swept (1e-2..1e-12),
              on one mesh (masonry m = 20; plate n1 = 32);
  reference   per case one much finer mesh (masonry m = 5, r = 5; plate
              n1 = 256), solved once, for the discretisation error.

A solver is not run on sizes where it is known to be hopeless (skip_reason:
dense methods on many constraints, PSOR and LSSNN on large meshes, the
interior point with the paper's eps1 on the plate, ...) nor on a larger mesh
of a case on which it already hit the time limit; runs.csv gives the reason
and the script prints it. --no-skip runs everything (the time limit still
applies).

Each configuration runs 3 times (the solve time is the median of
summary.json's wall-clock 'solve' section); a run slower than --repeat-below
(5 s) runs once (column 'repeats'). The first run also writes the LCP
solution in double precision (Output/Write solution), and the first run on
each mesh the LCP itself (Output/Export LCP), so that

  algebraic error       = against the most accurate (smallest KKT residual)
                          converged exact run on the same mesh:
                          max |u - u_ref| / max |u_ref| (plotted),
                          ||u - u_ref||_A / ||u_ref||_A (a seminorm on the
                          masonry: blind to rigid-body motions) and
                          |E - E_ref| / |E_ref|;
  discretisation error  = against the fine reference: sqrt(|E_h - E_ref| /
                          |E_ref|) (the relative energy-norm error for nested
                          conforming spaces without contact, since
                          E = -||u||_A^2 / 2 at a solution), the relative
                          error of the peak (masonry: max displacement, the
                          settlement; plate: max deflection = -min nodal
                          deflection) and, for the plate, of the obstacle
                          force sum(lambda).

Writes benchmarks/results/evidence/: runs.csv (one row per configuration,
skipped ones with the reason), references.csv, convergence.csv and
convergence_orders.csv, error_time_<case>.png (error against time, one curve
per solver), convergence_<family>.png, and runs/ (parameter files, summaries,
solutions, state.json; not committed).

Options: --quick (small sizes, 1 repeat, about 2 min), --cases (comma
separated subset of stack_bond, running_bond, laminae, psi1, psi2, psi3),
--studies (size, refinement, tolerance), --timeout S (per run; 60, quick 20),
--repeats N, --repeat-below S, --no-skip, --output DIR (default
benchmarks/results/evidence), --executable PATH, --plots-only
(CSV and plots again from runs/state.json), --keep-lcp (keep the exported
lcp_A.mtx files).
"""
import argparse
import csv
import json
import math
import os
import shutil
import signal
import statistics
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
RESULTS = os.path.join(ROOT, "benchmarks", "results", "evidence")
RUNS = os.path.join(RESULTS, "runs")

# ---------------------------------------------------------------------------
# What is run
# ---------------------------------------------------------------------------

# label -> (method, Schur complement, extra Solver settings)
SOLVERS = {
    "pdas": ("pdas", False, {}),
    "pdpc": ("pdpc", False, {}),
    "psor": ("psor", False, {}),
    "lssnn": ("lssnn", False, {}),
    "interior_point": ("interior_point", False, {}),
    # The plate study's eps1 = 1e-10 lies below the rounding floor of its
    # residual from 20 x 20 elements up (benchmarks/plate_tables/README.md);
    # 1e-8 is the setting that converges there.
    "interior_point_eps8": ("interior_point", False,
                            {"Interior point/Residual tolerance": "1e-8"}),
    # The fine reference of the plate: on 256 x 256 elements the residual's
    # rounding floor is higher still.
    "interior_point_eps6": ("interior_point", False,
                            {"Interior point/Residual tolerance": "1e-6"}),
    "block_pivoting": ("block_pivoting", False, {}),
    "pdas_sc": ("pdas", True, {}),
    "pdpc_sc": ("pdpc", True, {}),
    "lssnn_sc": ("lssnn", True, {}),
    "graves_sc": ("graves", True, {}),
}
# The first solver on a mesh also exports the LCP and tells the sizes the
# skip rules need: a fast, robust one.
MASONRY_SOLVERS = ["pdpc", "pdas", "psor", "lssnn", "interior_point",
                   "block_pivoting", "pdas_sc", "pdpc_sc", "lssnn_sc",
                   "graves_sc"]
PLATE_SOLVERS = ["interior_point_eps8", "pdas", "pdpc", "psor", "lssnn",
                 "interior_point", "block_pivoting", "pdas_sc",
                 "pdpc_sc", "lssnn_sc", "graves_sc"]

# Tolerance sweeps (Projection = false): label -> (method, [settings that
# all take the swept value]).
SWEEPS = {
    "psor": ("psor", ["PSOR/Tolerance"]),
    "pdpc": ("pdpc", ["PDPC/Complementarity tolerance",
                      "PDPC/Residual tolerance"]),
    "interior_point": ("interior_point",
                       ["Interior point/Residual tolerance",
                        "Interior point/Complementarity tolerance"]),
    "block_pivoting": ("block_pivoting", ["Block pivoting/Tolerance"]),
}

CASES = {
    "stack_bond": ("masonry", "stack bond"),
    "running_bond": ("masonry", "running bond"),
    "laminae": ("masonry", "laminae"),
    "psi1": ("plate", "psi1"),
    "psi2": ("plate", "psi2"),
    "psi3": ("plate", "psi3"),
}

FULL = {
    "masonry_m": [5, 10, 20, 50, 100],
    "masonry_refinement_m": 5,
    "masonry_r": [0, 1, 2, 3],
    "masonry_reference_r": 5,
    "masonry_tolerance_m": 20,
    "plate_n": [8, 16, 32, 64],
    "plate_reference_n": 256,
    "plate_tolerance_n": 32,
    "tolerances": [1e-2, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12],
    "repeats": 3,
    "timeout": 60,
}
QUICK = {
    "masonry_m": [5, 10],
    "masonry_refinement_m": 5,
    "masonry_r": [0, 1],
    "masonry_reference_r": 3,
    "masonry_tolerance_m": 5,
    "plate_n": [8, 16],
    "plate_reference_n": 64,
    "plate_tolerance_n": 16,
    "tolerances": [1e-3, 1e-6, 1e-9],
    "repeats": 1,
    "timeout": 20,
}


def skip_reason(label, case, n, n_c, tolerance=None):
    """Sizes on which a solver is known to be hopeless, with the reason
    (measured on this machine where it says so). n, n_c: unknowns and
    constraints of the mesh; tolerance: set in a tolerance sweep. --no-skip
    turns these off."""
    family = CASES[case][0]
    schur = label.endswith("_sc")
    if label == "graves_sc" and n_c > 1000:
        return (f"Graves pivots on a dense tableau: n_c = {n_c} > 1000 "
                "(running bond m = 20, n_c = 1735: cycles for 2 min, "
                "masonry_tables README)")
    if schur and n_c > 2500:
        return (f"dense Schur complement with n_c = {n_c} > 2500 "
                "(8 n_c^2 bytes, O(n_c^3) per factorisation; already slower "
                "than the sparse methods at m = 20)")
    if label == "psor" and family == "masonry" and n > 20000:
        return (f"PSOR on n = {n} > 20000 (measured: 97 s at stack bond "
                "m = 50, 95 s of it in the projection's slow PDAS "
                "factorisations, benchmarks/README.md)")
    if label == "psor" and family == "plate" and n > 10000:
        return (f"PSOR on n = {n} > 10000 (measured: more than 60 s at "
                "n1 = 64)")
    if label in ("lssnn", "block_pivoting") and case == "running_bond" and \
            n_c > 4000:
        return (f"{label} on running bond with n_c = {n_c} > 4000 "
                "(measured: more than 120 s at m = 50)")
    if label == "lssnn" and case == "laminae" and n_c > 4000:
        return (f"LSSNN on laminae with n_c = {n_c} > 4000 (measured: more "
                "than 60 s at m = 50)")
    if label == "lssnn" and family == "plate" and n_c > 2000:
        return (f"LSSNN on n_c = {n_c} > 2000 (measured: more than 60 s at "
                "n1 = 64)")
    if tolerance is not None:
        return None
    if label == "interior_point" and family == "plate" and n > 2000:
        return ("interior point with the paper's eps1 = 1e-10 (absolute): "
                "below the rounding floor of its residual from 20 x 20 "
                "elements up, it breaks down (measured: n1 = 64, 381 "
                "iterations, 46 s; plate_tables README); see "
                "interior_point_eps8")
    if label == "pdpc" and family == "plate" and n > 20000:
        return (f"PDPC on the plate with n = {n} (measured: 361 iterations, "
                "54 s at n1 = 64; the 500-iteration limit after 479 s at "
                "n1 = 128)")
    return None


# ---------------------------------------------------------------------------
# Parameter files and runs
# ---------------------------------------------------------------------------

def scene_block(case, mesh):
    family, name = CASES[case]
    if family == "masonry":
        m, r = mesh
        return ("set Scene = masonry\n"
                "subsection Masonry\n"
                f"  set Geometry        = {name}\n"
                f"  set Blocks per side = {m}\n"
                f"  set Refinement      = {r}\n"
                "end\n")
    (n1,) = mesh
    return ("set Scene = plate\n"
            "subsection Plate\n"
            "  subsection Geometry\n"
            f"    set Elements x = {n1}\n"
            f"    set Elements y = {n1}\n"
            "  end\n"
            "  subsection Material\n    set Name = steel\n  end\n"
            f"  subsection Obstacle\n    set Function = {name}\n  end\n"
            "  subsection Load\n    set Force = f1\n  end\n"
            "end\n")


def solver_block(method, schur, settings):
    lines = ["subsection Solver", f"  set Method = {method}",
             f"  set Schur complement = {'true' if schur else 'false'}"]
    for key, value in settings.items():
        if "/" in key:
            sub, entry = key.split("/", 1)
            lines += [f"  subsection {sub}", f"    set {entry} = {value}",
                      "  end"]
        else:
            lines.append(f"  set {key} = {value}")
    return "\n".join(lines + ["end", ""])


def mesh_name(case, mesh):
    family, _ = CASES[case]
    if family == "masonry":
        return f"{case}_m{mesh[0]}_r{mesh[1]}"
    return f"{case}_n{mesh[0]}"


def mesh_label(case, mesh):
    if CASES[case][0] == "masonry":
        return f"m = {mesh[0]}, r = {mesh[1]}"
    return f"n1 = {mesh[0]}"


def config_name(case, mesh, label, tolerance=None):
    name = f"{mesh_name(case, mesh)}__{label}"
    if tolerance is not None:
        name += f"__noproj_tol{tolerance:.0e}"
    return name


def write_prm(path, case, mesh, method, schur, settings, run_name,
              write_solution, export_lcp):
    with open(path, "w") as f:
        f.write("# generated by benchmarks/evidence/run_evidence.py\n")
        f.write(scene_block(case, mesh))
        f.write(solver_block(method, schur, settings))
        f.write("subsection Output\n"
                f"  set Directory      = {RUNS}\n"
                f"  set Run name       = {run_name}\n"
                "  set Write VTU      = false\n"
                f"  set Export LCP     = {'true' if export_lcp else 'false'}\n"
                f"  set Write solution = {'true' if write_solution else 'false'}\n"
                "  set Print timings  = false\n"
                "  set Progress       = false\n"
                "end\n")


def run_once(executable, prm, run_directory, timeout):
    summary_file = os.path.join(run_directory, "summary.json")
    if os.path.exists(summary_file):
        os.remove(summary_file)
    start = time.time()
    try:
        process = subprocess.run([executable, prm], capture_output=True,
                                 text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return {"status": "timeout", "wall": time.time() - start,
                "message": f"killed after {timeout:.0f} s"}
    wall = time.time() - start
    # Bad input (exit code 1) may leave a summary.json of status "error".
    if process.returncode == 1 or not os.path.exists(summary_file):
        lines = (process.stderr or process.stdout).strip().splitlines()
        return {"status": "error", "wall": wall, "exit_code":
                process.returncode,
                "message": lines[-1] if lines else "no summary.json"}
    with open(summary_file) as f:
        summary = json.load(f)
    return {"status": summary["status"], "wall": wall,
            "exit_code": process.returncode, "summary": summary,
            "message": summary.get("message", "")}


class Runner:
    def __init__(self, arguments, plan):
        self.executable = arguments.executable
        self.plan = plan
        self.repeats = (arguments.repeats if arguments.repeats else
                        plan["repeats"])
        self.repeat_below = arguments.repeat_below
        self.timeout = arguments.timeout or plan["timeout"]
        self.keep_lcp = arguments.keep_lcp
        self.no_skip = arguments.no_skip
        self.results = {}   # config name -> result dict
        self.meshes = {}    # mesh name -> {"n", "n_c", "lcp": directory}
        self.fine = {}      # case -> config name of the fine reference
        self.references = []
        self.started = time.time()

    @property
    def STATE(self):
        return os.path.join(RUNS, "state.json")

    def save(self):
        """Everything measured so far (for --plots-only)."""
        results = {}
        for name, r in self.results.items():
            r = dict(r)
            r["studies"] = sorted(r["studies"])
            r["mesh"] = list(r["mesh"])
            results[name] = r
        with open(self.STATE + ".tmp", "w") as f:
            json.dump({"results": results, "meshes": self.meshes,
                       "fine": self.fine, "references": self.references,
                       "timeout": self.timeout}, f)
        os.replace(self.STATE + ".tmp", self.STATE)

    def load(self):
        with open(self.STATE) as f:
            state = json.load(f)
        for name, r in state["results"].items():
            r["studies"] = set(r["studies"])
            r["mesh"] = tuple(r["mesh"])
            self.results[name] = r
        self.meshes = state["meshes"]
        self.fine = state["fine"]
        self.references = state["references"]
        self.timeout = state["timeout"]

    def run(self, case, mesh, label, tolerance=None, timeout=None,
            study="", export=True):
        """One configuration, repeated; returns its result dict."""
        name = config_name(case, mesh, label, tolerance)
        if name in self.results:
            self.results[name]["studies"].add(study)
            return self.results[name]
        family, _ = CASES[case]
        if tolerance is None:
            method, schur, settings = SOLVERS[label]
            settings = dict(settings)
        else:
            method, keys = SWEEPS[label]
            schur = False
            settings = {key: f"{tolerance:g}" for key in keys}
            settings["Projection"] = "false"
        key = mesh_name(case, mesh)
        info = self.meshes.get(key)
        result = {"name": name, "case": case, "family": family,
                  "mesh": mesh, "mesh_key": key, "label": label,
                  "method": method, "schur": schur,
                  "projection": tolerance is None, "tolerance": tolerance,
                  "studies": {study}, "times": [], "walls": []}
        self.results[name] = result
        if info is not None:
            reason = (None if self.no_skip else
                      skip_reason(label, case, info["n"], info["n_c"],
                                  tolerance))
            smaller = [r for r in self.results.values()
                       if r["case"] == case and r["label"] == label and
                       r["tolerance"] == tolerance and
                       r.get("status") == "timeout" and
                       r["mesh_key"] in self.meshes and
                       self.meshes[r["mesh_key"]]["n"] < info["n"]]
            if smaller and not reason:
                reason = (f"timed out (> {self.timeout:.0f} s) on the "
                          f"smaller mesh {smaller[0]['mesh_key']}")
            if reason:
                result.update(status="skipped", message=reason)
                print(f"  skip {name}: {reason}", flush=True)
                return result
        run_directory = os.path.join(RUNS, name)
        os.makedirs(run_directory, exist_ok=True)
        export = export and info is None
        for attempt in range(self.repeats):
            prm = os.path.join(RUNS, name + ".prm")
            write_prm(prm, case, mesh, method, schur, settings, name,
                      write_solution=(attempt == 0),
                      export_lcp=(export and attempt == 0))
            outcome = run_once(self.executable, prm, run_directory,
                               timeout or self.timeout)
            result["walls"].append(outcome["wall"])
            if attempt == 0:
                result.update(status=outcome["status"],
                              message=outcome.get("message", ""),
                              exit_code=outcome.get("exit_code"))
                if "summary" in outcome:
                    result["summary"] = outcome["summary"]
                    # The run's own files, kept apart from the repeats.
                    for file in ("u.txt", "lambda.txt", "summary.json"):
                        source = os.path.join(run_directory, file)
                        if os.path.exists(source):
                            shutil.copy(source, os.path.join(
                                run_directory, "first_" + file))
            if "summary" not in outcome:
                break
            result["times"].append(outcome["summary"]["time"]["solve"])
            if outcome["status"] != result["status"]:
                result["message"] += (f" (repeat {attempt + 1}: "
                                      f"{outcome['status']})")
            if outcome["summary"]["time"]["solve"] > self.repeat_below:
                break
        if info is None and "summary" in result:
            # Without a summary the mesh stays unknown: the next run on it
            # tries again.
            summary = result["summary"]
            self.meshes[key] = {"n": summary["n_unknowns"],
                                "n_c": summary["n_constraints"],
                                "lcp": run_directory if export else None}
        self.save()
        solve = (f"{statistics.median(result['times']):.3g} s"
                 if result["times"] else "-")
        print(f"  {name}: {result['status']}, solve {solve} "
              f"({len(result['times'])} runs) "
              f"[{time.time() - self.started:.0f} s elapsed]", flush=True)
        return result


# ---------------------------------------------------------------------------
# Errors
# ---------------------------------------------------------------------------

def read_vector(path):
    with open(path) as f:
        return np.array(f.read().split(), dtype=float)


def read_matrix_market(path):
    """Symmetric or general Matrix Market coordinate file -> scipy CSR."""
    import scipy.sparse
    with open(path) as f:
        header = f.readline()
        line = f.readline()
        while line.startswith("%"):
            line = f.readline()
        n_rows, n_cols, _ = (int(x) for x in line.split())
        data = np.array(f.read().split(), dtype=float).reshape(-1, 3)
    rows = data[:, 0].astype(np.int64) - 1
    cols = data[:, 1].astype(np.int64) - 1
    values = data[:, 2]
    A = scipy.sparse.coo_matrix((values, (rows, cols)),
                                shape=(n_rows, n_cols)).tocsr()
    if "symmetric" in header:
        A = A + A.T - scipy.sparse.diags(A.diagonal())
    return A.tocsr()


def solution_of(result):
    path = os.path.join(RUNS, result["name"], "first_u.txt")
    return read_vector(path) if os.path.exists(path) else None


def usable(result):
    """Has a solution and a summary (whatever its status)."""
    return "summary" in result and solution_of(result) is not None


def algebraic_errors(runner):
    """Per mesh: the reference (the converged exact run with the smallest
    KKT residual), then every run's error against it."""
    references = []
    by_mesh = {}
    for result in runner.results.values():
        by_mesh.setdefault(result["mesh_key"], []).append(result)
    for key, results in sorted(by_mesh.items()):
        candidates = [r for r in results if r["projection"] and usable(r)
                      and r["status"] == "converged"]
        flagged = ""
        if not candidates:
            candidates = [r for r in results if r["projection"] and usable(r)
                          and r["summary"]["kkt"]["max"] is not None]
            flagged = "no converged exact run; "
        if not candidates:
            references.append({"mesh": key, "reference": "",
                               "note": "no solution on this mesh"})
            continue
        reference = min(candidates,
                        key=lambda r: r["summary"]["kkt"]["max"])
        u_ref = solution_of(reference)
        info = runner.meshes.get(key)
        A = None
        if info and info["lcp"] and \
                os.path.exists(os.path.join(info["lcp"], "lcp_A.mtx")):
            A = read_matrix_market(os.path.join(info["lcp"], "lcp_A.mtx"))
            b = read_vector(os.path.join(info["lcp"], "lcp_b.txt"))
        E_ref = reference["summary"]["energy"]
        norm_ref = math.sqrt(max(u_ref @ (A @ u_ref), 0.0)) if A is not None \
            else float("nan")
        agreement = 0.0
        for other in candidates:
            u = solution_of(other)
            if other is not reference and u.shape == u_ref.shape:
                agreement = max(agreement, float(np.max(np.abs(u - u_ref)) /
                                                 np.max(np.abs(u_ref))))
        references.append({
            "mesh": key, "reference": reference["label"],
            "status": reference["status"],
            "kkt": reference["summary"]["kkt"]["max"],
            "energy": E_ref,
            "n_converged_exact": len(candidates),
            "max_difference_of_other_converged_exact": agreement,
            "note": flagged + ("" if A is not None else "no exported A")})
        for r in results:
            if not usable(r):
                continue
            u = solution_of(r)
            if u.shape != u_ref.shape:
                continue
            e = u - u_ref
            r["alg_err_inf"] = float(np.max(np.abs(e)) /
                                     np.max(np.abs(u_ref)))
            E = r["summary"]["energy"]
            r["alg_err_energy"] = (abs(E - E_ref) / abs(E_ref)
                                   if E is not None else float("nan"))
            if A is not None:
                r["alg_err_A"] = float(math.sqrt(max(e @ (A @ e), 0.0)) /
                                       norm_ref)
                # The files belong together: the energy of u.txt is the
                # energy the run reported.
                E_check = 0.5 * u @ (A @ u) - b @ u
                if E is not None and abs(E_check - E) > 1e-9 * abs(E) + 1e-300:
                    r["message"] = (r.get("message", "") +
                                    f" [u.txt energy {E_check:.12e} != "
                                    f"summary {E:.12e}]")
        if not runner.keep_lcp and info and info["lcp"]:
            for file in ("lcp_A.mtx", "lcp_b.txt", "lcp_constraints.txt"):
                path = os.path.join(info["lcp"], file)
                if os.path.exists(path):
                    os.remove(path)
    return references


def contact_force_of(result):
    """Plate: the total obstacle force sum(lambda_S) (kg) of a run."""
    path = os.path.join(RUNS, result["name"], "first_lambda.txt")
    if result["family"] != "plate" or not os.path.exists(path):
        return None
    return float(np.sum(read_vector(path)))


def peak_of(summary):
    if summary["scene"] == "masonry":
        return summary["max_displacement"]
    return -summary["min_deflection"]


def h_of(case, mesh):
    family, _ = CASES[case]
    if family == "masonry":
        m, r = mesh
        return 1.0 / (m * 2 ** r)
    return 100.0 / mesh[0]


def fit_order(hs, errors):
    """Least-squares slope of log(error) against log(h)."""
    points = [(math.log(h), math.log(e)) for h, e in zip(hs, errors)
              if e and e > 0 and math.isfinite(e)]
    if len(points) < 2:
        return float("nan")
    x = np.array([p[0] for p in points])
    y = np.array([p[1] for p in points])
    return float(np.polyfit(x, y, 1)[0])


def discretisation_errors(runner, fine):
    """fine: case -> reference result on the fine mesh. Adds disc_err_* to
    every result on a mesh of that case with the same m (masonry)."""
    rows = []
    for case, reference in fine.items():
        if "summary" not in reference or reference["status"] not in (
                "converged",):
            # Use it anyway if it has an answer, but say so.
            if "summary" not in reference:
                continue
        E_ref = reference["summary"]["energy"]
        peak_ref = peak_of(reference["summary"])
        force_ref = contact_force_of(reference)
        for r in runner.results.values():
            if r["case"] != case or "summary" not in r or r is reference:
                continue
            if CASES[case][0] == "masonry" and r["mesh"][0] != \
                    reference["mesh"][0]:
                continue
            E = r["summary"]["energy"]
            if E is None:
                continue
            r["disc_err_energy_signed"] = (E - E_ref) / abs(E_ref)
            r["disc_err_enorm"] = math.sqrt(abs(E - E_ref) / abs(E_ref))
            r["disc_err_peak"] = abs(peak_of(r["summary"]) - peak_ref) / \
                abs(peak_ref)
        # The convergence table: per mesh, the algebraic reference's answer.
        meshes = sorted({r["mesh"] for r in runner.results.values()
                         if r["case"] == case and r is not reference and
                         (CASES[case][0] == "plate" or
                          r["mesh"][0] == reference["mesh"][0])},
                        key=lambda mesh: -h_of(case, mesh))
        for mesh in meshes:
            best = best_on_mesh(runner, case, mesh)
            if best is None:
                continue
            force = contact_force_of(best)
            force_error = (abs(force - force_ref) / abs(force_ref)
                           if force is not None and force_ref else None)
            rows.append({
                "case": case, "mesh": mesh_name(case, mesh),
                "h": h_of(case, mesh), "n": best["summary"]["n_unknowns"],
                "solver": best["label"], "status": best["status"],
                "energy": best["summary"]["energy"],
                "peak": peak_of(best["summary"]),
                "energy_error_signed": best.get("disc_err_energy_signed"),
                "energy_norm_error": best.get("disc_err_enorm"),
                "peak_error": best.get("disc_err_peak"),
                "peak_error_signed": (peak_of(best["summary"]) - peak_ref) /
                abs(peak_ref),
                "contact_force": force, "contact_force_error": force_error,
                "reference_contact_force": force_ref,
                "reference_mesh": mesh_name(case, reference["mesh"]),
                "reference_h": h_of(case, reference["mesh"]),
                "reference_solver": reference["label"],
                "reference_status": reference["status"],
                "reference_energy": E_ref, "reference_peak": peak_ref})
    return rows


def best_on_mesh(runner, case, mesh):
    candidates = [r for r in runner.results.values()
                  if r["case"] == case and r["mesh"] == mesh and
                  r["projection"] and "summary" in r and
                  r["summary"]["kkt"]["max"] is not None]
    converged = [r for r in candidates if r["status"] == "converged"]
    pool = converged or candidates
    if not pool:
        return None
    return min(pool, key=lambda r: r["summary"]["kkt"]["max"])


# ---------------------------------------------------------------------------
# Output
# ---------------------------------------------------------------------------

RUN_FIELDS = ["study", "case", "scene", "m", "r", "n1", "h", "solver",
              "method", "schur_complement", "projection", "tolerance", "n",
              "n_c", "status", "exit_code", "iterations",
              "projection_iterations", "repeats", "solve_seconds_median",
              "solve_seconds_min", "solve_seconds_max",
              "process_seconds_median", "kkt", "energy", "peak",
              "alg_err_A", "alg_err_inf", "alg_err_energy",
              "disc_err_energy_norm", "disc_err_energy_signed",
              "disc_err_peak", "message"]


def fmt(value, spec=".6e"):
    if value is None:
        return ""
    if isinstance(value, float):
        if not math.isfinite(value):
            return str(value)
        return format(value, spec)
    return str(value)


def run_row(r):
    family = r["family"]
    summary = r.get("summary", {})
    row = {
        "study": "+".join(sorted(s for s in r["studies"] if s)),
        "case": r["case"], "scene": family,
        "m": r["mesh"][0] if family == "masonry" else "",
        "r": r["mesh"][1] if family == "masonry" else "",
        "n1": r["mesh"][0] if family == "plate" else "",
        "h": fmt(h_of(r["case"], r["mesh"]), ".6g"),
        "solver": r["label"], "method": r["method"],
        "schur_complement": r["schur"], "projection": r["projection"],
        "tolerance": fmt(r["tolerance"], "g"),
        "n": summary.get("n_unknowns", ""),
        "n_c": summary.get("n_constraints", ""),
        "status": r.get("status", ""), "exit_code": r.get("exit_code", ""),
        "iterations": summary.get("iterations", ""),
        "projection_iterations": summary.get("projection_iterations", ""),
        "repeats": len(r["times"]),
        "solve_seconds_median": fmt(statistics.median(r["times"]), ".4g")
        if r["times"] else "",
        "solve_seconds_min": fmt(min(r["times"]), ".4g") if r["times"] else "",
        "solve_seconds_max": fmt(max(r["times"]), ".4g") if r["times"] else "",
        "process_seconds_median": fmt(statistics.median(r["walls"]), ".4g")
        if r["walls"] else "",
        "kkt": fmt(summary.get("kkt", {}).get("max"), ".2e"),
        "energy": fmt(summary.get("energy"), ".12e"),
        "peak": fmt(peak_of(summary), ".10e") if summary else "",
        "alg_err_A": fmt(r.get("alg_err_A"), ".3e"),
        "alg_err_inf": fmt(r.get("alg_err_inf"), ".3e"),
        "alg_err_energy": fmt(r.get("alg_err_energy"), ".3e"),
        "disc_err_energy_norm": fmt(r.get("disc_err_enorm"), ".4e"),
        "disc_err_energy_signed": fmt(r.get("disc_err_energy_signed"),
                                      ".4e"),
        "disc_err_peak": fmt(r.get("disc_err_peak"), ".4e"),
        "message": (r.get("message") or "").replace("\n", " "),
    }
    return row


def write_csv(path, fields, rows):
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=fields)
        writer.writeheader()
        for row in rows:
            writer.writerow({k: row.get(k, "") for k in fields})


def run_sort_key(r):
    return (list(CASES).index(r["case"]), r["mesh"],
            r["tolerance"] is not None, r["label"],
            -(r["tolerance"] or 0))


def write_all(runner, references, convergence, orders):
    rows = [run_row(r) for r in sorted(runner.results.values(),
                                       key=run_sort_key)]
    write_csv(os.path.join(RESULTS, "runs.csv"), RUN_FIELDS, rows)
    write_csv(os.path.join(RESULTS, "references.csv"),
              ["mesh", "reference", "status", "kkt", "energy",
               "n_converged_exact", "max_difference_of_other_converged_exact",
               "note"],
              [{**ref, "kkt": fmt(ref.get("kkt"), ".2e"),
                "energy": fmt(ref.get("energy"), ".12e"),
                "max_difference_of_other_converged_exact":
                    fmt(ref.get("max_difference_of_other_converged_exact"),
                        ".2e")}
               for ref in references])
    fields = ["case", "mesh", "h", "n", "solver", "status", "energy", "peak",
              "energy_error_signed", "energy_norm_error", "peak_error",
              "peak_error_signed", "contact_force", "contact_force_error",
              "reference_contact_force",
              "reference_mesh", "reference_h", "reference_solver",
              "reference_status", "reference_energy", "reference_peak"]
    write_csv(os.path.join(RESULTS, "convergence.csv"), fields,
              [{k: fmt(v, ".6e") if isinstance(v, float) else v
                for k, v in row.items()} for row in convergence])
    write_csv(os.path.join(RESULTS, "convergence_orders.csv"),
              ["case", "quantity", "order", "slope", "fitted_on",
               "reference"],
              [{**o, "order": fmt(o["order"], ".3f"),
                "slope": fmt(o["slope"], ".3f")} for o in orders])


SHORT_STATUS = {"iteration limit": "iteration limit", "singular": "singular",
                "timeout": "timeout", "inaccurate": "inaccurate",
                "infeasible": "infeasible", "error": "error"}


def write_summary_md(runner, path):
    """One table per scene family: for every mesh the solvers with their
    default settings, fastest first; converged ones with their median solve
    time, the others with their status."""
    lines = ["# Time against error: solvers by mesh, fastest first", "",
             "Generated by `benchmarks/evidence/run_evidence.py` from "
             "`runs.csv`. Median solve time in seconds (wall clock, "
             "`summary.json` 'solve'), default settings (the approximate "
             "methods followed by the projection step). **Bold**: fastest "
             "converged. Not converged: status in brackets (with its time). "
             "Skipped: see `runs.csv`.", ""]
    for family in ("masonry", "plate"):
        lines += [f"## {family}", "",
                  "| case | mesh | n | n_c | converged, fastest first | "
                  "not converged |", "|---|---|---|---|---|---|"]
        meshes = {}
        for r in runner.results.values():
            if r["family"] == family and r["projection"]:
                meshes.setdefault((list(CASES).index(r["case"]),
                                   r["mesh"], r["case"]), []).append(r)
        for (_, mesh, case), results in sorted(meshes.items()):
            if not any(r["times"] for r in results):
                continue
            summary = next(r["summary"] for r in results if "summary" in r)
            good = sorted([r for r in results if r.get("status") ==
                           "converged" and r["times"]], key=solve_time)
            bad = [r for r in results if r.get("status") not in
                   ("converged", "skipped")]
            cells = [f"{r['label']} {solve_time(r):.3g}" for r in good]
            if cells:
                cells[0] = f"**{cells[0]}**"
            failed = [f"{r['label']} ({r.get('status')}"
                      + (f", {solve_time(r):.3g}" if r["times"] else "")
                      + ")" for r in bad]
            lines.append(f"| {CASES[case][1]} | "
                         f"{mesh_label(case, mesh)} | "
                         f"{summary['n_unknowns']} | "
                         f"{summary['n_constraints']} | "
                         f"{', '.join(cells)} | {', '.join(failed)} |")
        lines.append("")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


# ---------------------------------------------------------------------------
# Plots
# ---------------------------------------------------------------------------

STYLE = {
    "pdas": ("tab:blue", "o"), "pdpc": ("tab:orange", "s"),
    "psor": ("tab:green", "^"), "lssnn": ("tab:red", "v"),
    "interior_point": ("tab:purple", "D"),
    "interior_point_eps8": ("tab:pink", "d"),
    "interior_point_eps6": ("black", "*"),
    "block_pivoting": ("tab:brown", "P"),
    "pdas_sc": ("tab:cyan", "o"), "pdpc_sc": ("gold", "s"),
    "lssnn_sc": ("salmon", "v"), "graves_sc": ("tab:gray", "h"),
}
FLOOR = 1e-16


def category(result):
    status = result.get("status")
    if status == "converged":
        return "converged"
    if status == "inaccurate":
        return "inaccurate"
    return "failed"


def plot_points(ax, points, label, top, connect=True, exact=False):
    """points: (x, y, result) along the curve. Converged: filled and joined;
    inaccurate (stopped by its own test, KKT above 1e-8): open and joined;
    failed (iteration limit, breakdown, singular): a cross, never joined.
    Values above top are drawn at top (off scale). exact: a single point
    of a method with the projection step, drawn large with a black edge."""
    color, marker = STYLE.get(label, ("black", "o"))
    # A breakdown leaves a non-finite answer: drawn at the top, off scale.
    points = [(x, y if y is not None and math.isfinite(y) else math.inf, r)
              for x, y, r in points]
    clip = [(x, min(max(y, FLOOR), top), r, y > top) for x, y, r in points]
    y_of = {id(r): y for x, y, r in points}
    good = [(x, y) for x, y, r, _ in clip if category(r) != "failed"]
    if connect and len(good) > 1:
        ax.plot([p[0] for p in good], [p[1] for p in good], "-",
                color=color, lw=1.2, alpha=0.8)
    size, edge = (9, "black") if exact else (6, color)
    for x, y, r, off in clip:
        c = category(r)
        if c == "failed":
            ax.plot(x, y, "x", color=color, ms=size + 2, mew=2.5,
                    ls="none")
        else:
            ax.plot(x, y, marker, mfc=color if c == "converged" else "white",
                    mec=edge, mew=1.2 if exact else 1.0, ms=size, ls="none")
        if off:
            ax.annotate("off scale" if math.isfinite(y_of[id(r)]) else "NaN",
                        (x, y), textcoords="offset points",
                        xytext=(0, -11), ha="center", fontsize=6,
                        color=color)


def legend_handles(labels):
    from matplotlib.lines import Line2D
    handles = [Line2D([], [], color=STYLE[l][0], marker=STYLE[l][1], ls="-",
                      label=l) for l in labels]
    handles += [
        Line2D([], [], ls="none", label=""),
        Line2D([], [], color="k", marker="o", ls="none",
               label="filled: converged"),
        Line2D([], [], color="k", marker="o", mfc="white", ls="none",
               label="open: own stopping test met,\n   KKT residual > 1e-8"),
        Line2D([], [], color="k", marker="x", mew=2, ls="none",
               label="cross: not converged\n   (status in runs.csv)"),
    ]
    return handles


def solve_time(r):
    return statistics.median(r["times"]) if r["times"] else None


def top_of(values):
    """Upper plot limit: a decade above the largest value of a run that did
    not fail, so that a diverged run cannot squash the rest."""
    finite = [v for v in values if v is not None and math.isfinite(v)]
    return max(10.0, 10 * max(finite)) if finite else 10.0


def plot_case(runner, case, plan, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    family, name = CASES[case]
    results = [r for r in runner.results.values() if r["case"] == case]
    labels_used = []
    fig, axes = plt.subplots(1, 3, figsize=(18, 5.8))
    title = (f"masonry, {name} (g = H/2)" if family == "masonry" else
             f"plate, steel, f1, {name}")

    # (a) algebraic error against time on the tolerance mesh.
    ax = axes[0]
    if family == "masonry":
        tol_mesh = (plan["masonry_tolerance_m"], 0)
        where = f"m = {tol_mesh[0]}, r = 0"
    else:
        tol_mesh = (plan["plate_tolerance_n"],)
        where = f"n1 = {tol_mesh[0]}"
    on_mesh = [r for r in results if r["mesh"] == tol_mesh and r["times"]
               and r.get("alg_err_inf") is not None]
    top = top_of([r["alg_err_inf"] for r in on_mesh
                  if category(r) != "failed"])
    for label in dict.fromkeys(r["label"] for r in on_mesh):
        sweep = sorted([r for r in on_mesh if r["label"] == label and
                        not r["projection"]], key=lambda r: -r["tolerance"])
        if sweep:
            plot_points(ax, [(solve_time(r), r["alg_err_inf"], r)
                             for r in sweep], label, top)
            labels_used.append(label)
        exact = [r for r in on_mesh if r["label"] == label and
                 r["projection"]]
        if exact:
            plot_points(ax, [(solve_time(r), r["alg_err_inf"], r)
                             for r in exact], label, top, connect=False,
                        exact=True)
            labels_used.append(label)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_ylim(FLOOR / 3, top * 3)
    ax.set_xlabel("solve time [s] (median)")
    ax.set_ylabel("algebraic error  max|u - u_ref| / max|u_ref|")
    ax.set_title(f"(a) algebraic error on one mesh, {where}\n"
                 "small symbols joined: tolerance sweep, projection off; "
                 "large black-edged: defaults\n(exact, or approximate + "
                 f"projection); errors below {FLOOR:.0e} drawn at {FLOOR:.0e}",
                 fontsize=9)
    ax.grid(True, which="major", alpha=0.3)

    # (b) discretisation error against time over the mesh sweep.
    ax = axes[1]
    if family == "masonry":
        m0 = plan["masonry_refinement_m"]
        sweep_results = [r for r in results if r["projection"] and
                         r["mesh"][0] == m0 and "refinement" in r["studies"]]
        where = (f"m = {m0}, r = {min(plan['masonry_r'])}.."
                 f"{max(plan['masonry_r'])}, reference r = "
                 f"{plan['masonry_reference_r']}")
    else:
        sweep_results = [r for r in results if r["projection"] and
                         "size" in r["studies"]]
        where = (f"n1 = {min(plan['plate_n'])}..{max(plan['plate_n'])}, "
                 f"reference n1 = {plan['plate_reference_n']}")
    with_error = [r for r in sweep_results if r["times"] and
                  r.get("disc_err_enorm") is not None]
    top = top_of([r["disc_err_enorm"] for r in with_error
                  if category(r) != "failed"])
    for label in dict.fromkeys(r["label"] for r in with_error):
        points = sorted([(solve_time(r), r["disc_err_enorm"], r)
                         for r in with_error if r["label"] == label],
                        key=lambda p: p[2]["summary"]["n_unknowns"])
        plot_points(ax, points, label, top)
        labels_used.append(label)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_ylim(None, top * 3)
    ax.set_xlabel("solve time [s] (median)")
    ax.set_ylabel("discretisation error  sqrt(|E_h - E_ref| / |E_ref|)")
    ax.set_title(f"(b) energy error over the mesh sweep\n{where}; "
                 "each solver's own answer", fontsize=9)
    ax.grid(True, which="major", alpha=0.3)

    # (c) time against size over the size sweep.
    ax = axes[2]
    size_results = [r for r in results if r["projection"] and
                    "size" in r["studies"]]
    for label in dict.fromkeys(r["label"] for r in size_results):
        points = sorted([(r["summary"]["n_unknowns"], solve_time(r), r)
                         for r in size_results if r["label"] == label and
                         r["times"] and "summary" in r],
                        key=lambda p: p[0])
        if points:
            plot_points(ax, points, label, float("inf"))
            labels_used.append(label)
    for r in size_results:
        if r.get("status") == "timeout":
            n = runner.meshes.get(r["mesh_key"], {}).get("n")
            if n:
                color, _ = STYLE[r["label"]]
                ax.plot(n, runner.timeout, "x", color=color, ms=9, mew=2.5)
                ax.annotate("timeout", (n, runner.timeout),
                            textcoords="offset points", xytext=(0, 6),
                            ha="center", fontsize=6, color=color)
                labels_used.append(r["label"])
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("unknowns n")
    ax.set_ylabel("solve time [s] (median)")
    sizes = (f"m = {', '.join(str(m) for m in plan['masonry_m'])}, r = 0"
             if family == "masonry" else
             f"n1 = {', '.join(str(n) for n in plan['plate_n'])}")
    ax.set_title(f"(c) time against size, {sizes}\ndefaults; runs "
                 f"stopped at the {runner.timeout:.0f} s limit drawn there; "
                 "skipped sizes in runs.csv", fontsize=9)
    ax.grid(True, which="major", alpha=0.3)

    labels = [l for l in STYLE if l in labels_used]
    fig.legend(handles=legend_handles(labels), loc="center right",
               fontsize=9, frameon=False)
    fig.suptitle(f"Time against error: {title}", fontsize=12)
    fig.tight_layout(rect=(0, 0, 0.85, 0.95))
    fig.savefig(path, dpi=80)
    plt.close(fig)


QUANTITIES = {
    "energy_norm_error": "energy error  sqrt(|E_h - E_ref| / |E_ref|)",
    "peak_error": None,   # set per family
    "contact_force_error": "relative error of the obstacle force sum(lambda)",
}


def plot_convergence(family, convergence, orders, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    cases = [c for c in CASES if CASES[c][0] == family]
    quantities = ["energy_norm_error", "peak_error"]
    if family == "plate":
        quantities.append("contact_force_error")
    fig, axes = plt.subplots(1, len(quantities),
                             figsize=(6 * len(quantities), 5))
    colors = ["tab:blue", "tab:orange", "tab:green"]
    for quantity, ax in zip(quantities, axes):
        ylabel = QUANTITIES[quantity] or (
            "relative error of the max displacement (settlement)"
            if family == "masonry" else
            "relative error of the max deflection")
        for case, color in zip(cases, colors):
            rows = [row for row in convergence if row["case"] == case]
            points = [(row["h"], row[quantity]) for row in rows
                      if row.get(quantity) is not None]
            if not points:
                continue
            order = next((o for o in orders if o["case"] == case and
                          o["quantity"] == quantity), None)
            label = CASES[case][1]
            if order and math.isfinite(order["order"]):
                label += (f": order {order['order']:.2f} "
                          f"(slope {order['slope']:.2f})")
            positive = [(h, e) for h, e in points if e > 0]
            zero = [(h, e) for h, e in points if not e > 0]
            if zero:
                label += f": error 0 on {len(zero)} of {len(points)} meshes"
            ax.plot([p[0] for p in positive], [p[1] for p in positive],
                    "o-", color=color, label=label)
            if order and math.isfinite(order["order"]) and \
                    len(order["hs"]) > 1:
                x = np.geomspace(min(order["hs"]), max(order["hs"]), 50)
                ax.plot(x, order["constant"] * model(
                    x, order["h_ref"], order["order"], order["power"]),
                    "--", color=color, lw=0.9)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("h" + (" (cell size; unit square wall)" if family ==
                             "masonry" else " (element size, mm)"))
        ax.set_ylabel(ylabel)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=8)
    reference = convergence[0] if convergence else {}
    ref_mesh = reference.get("reference_mesh", "?").split("_")[-1]
    fig.suptitle(
        f"Convergence in h, {family}: errors against the solution on the "
        f"reference mesh {ref_mesh}\ndashed: C |h^q - h_ref^q| (energy: "
        "C |h^2q - h_ref^2q|^1/2) fitted on the three finest meshes; order = "
        "q, slope = plain log-log slope there", fontsize=10)
    fig.tight_layout(rect=(0, 0, 1, 0.91))
    fig.savefig(path, dpi=80)
    plt.close(fig)


# Power of the error model per quantity: the energy error is the square
# root of E_h - E_ref, which behaves like h^(2q) - h_ref^(2q).
MODEL_POWER = {"energy_norm_error": 2, "peak_error": 1,
               "contact_force_error": 1}


def model(h, h_ref, q, power):
    """Error against a reference on h_ref of a quantity converging like h^q:
    (|h^(power q) - h_ref^(power q)|)^(1 / power)."""
    return np.abs(np.asarray(h) ** (power * q) - h_ref ** (power * q)) ** \
        (1.0 / power)


def fit_order_with_reference(hs, errors, h_ref, power):
    """Order q and constant C of e(h) = C model(h, h_ref, q) by least squares
    in log(e): the reference's own error is part of the model, so the order
    is not inflated as h approaches h_ref."""
    points = [(h, e) for h, e in zip(hs, errors)
              if e is not None and e > 0 and math.isfinite(e)]
    if len(points) < 2:
        return float("nan"), float("nan")
    h = np.array([p[0] for p in points])
    y = np.log([p[1] for p in points])
    best = None
    for q in np.linspace(0.05, 8, 3181):
        g = np.log(model(h, h_ref, q, power))
        log_c = np.mean(y - g)
        residual = np.sum((y - log_c - g) ** 2)
        if best is None or residual < best[0]:
            best = (residual, q, math.exp(log_c))
    return float(best[1]), float(best[2])


def fit_orders(convergence):
    """Per case and quantity, on the three finest meshes below the reference:
    the order with the reference's error modelled, and the plain log-log
    slope."""
    orders = []
    for case in CASES:
        rows = [row for row in convergence if row["case"] == case]
        if not rows:
            continue
        for quantity, power in MODEL_POWER.items():
            if quantity == "contact_force_error" and \
                    CASES[case][0] != "plate":
                continue
            usable_rows = sorted([row for row in rows
                                  if row.get(quantity) is not None],
                                 key=lambda row: row["h"])[:3]
            hs = [row["h"] for row in usable_rows]
            errors = [row[quantity] for row in usable_rows]
            h_ref = rows[0]["reference_h"]
            order, constant = fit_order_with_reference(hs, errors, h_ref,
                                                       power)
            orders.append({"case": case, "quantity": quantity,
                           "order": order, "constant": constant,
                           "h_ref": h_ref, "power": power,
                           "slope": fit_order(hs, errors), "hs": hs,
                           "fitted_on": " ".join(row["mesh"].split("_")[-1]
                                                 for row in usable_rows),
                           "reference": rows[0]["reference_mesh"]})
    return orders


# ---------------------------------------------------------------------------
# Main
# ---------------------------------------------------------------------------

def install_python_packages():
    """scipy (the errors read the exported LCPs) and matplotlib (the plots)
    through the repository's install.sh, which installs only what is
    missing: found missing only after a 40 minute run otherwise."""
    missing = []
    for module, package in (("scipy", "python3-scipy"),
                            ("matplotlib", "python3-matplotlib")):
        try:
            __import__(module)
        except ImportError:
            missing.append(package)
    if missing:
        subprocess.run([os.path.join(ROOT, "install.sh")] + missing,
                       check=True)
        os.execv(sys.executable, [sys.executable] + sys.argv)


def main():
    global RESULTS, RUNS
    install_python_packages()
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--cases", default=",".join(CASES))
    parser.add_argument("--studies", default="size,refinement,tolerance")
    parser.add_argument("--timeout", type=float, default=None)
    parser.add_argument("--repeats", type=int, default=None)
    parser.add_argument("--repeat-below", type=float, default=5.0)
    parser.add_argument("--keep-lcp", action="store_true")
    parser.add_argument("--plots-only", action="store_true")
    parser.add_argument("--no-skip", action="store_true")
    parser.add_argument("--output", default=RESULTS)
    parser.add_argument("--executable",
                        default=os.path.join(ROOT, "build", "unilateral"))
    arguments = parser.parse_args()
    RESULTS = os.path.abspath(arguments.output)
    RUNS = os.path.join(RESULTS, "runs")
    plan = QUICK if arguments.quick else FULL
    cases = [c.strip() for c in arguments.cases.split(",") if c.strip()]
    for case in cases:
        if case not in CASES:
            sys.exit(f"unknown case '{case}': choose from {', '.join(CASES)}")
    studies = set(s.strip() for s in arguments.studies.split(","))
    state = os.path.join(RUNS, "state.json")
    if arguments.plots_only and not os.path.exists(state):
        sys.exit(f"--plots-only: no {state} (runs/ is not versioned): run "
                 f"this script without --plots-only first (e.g. --quick "
                 f"--output {arguments.output})")
    if not os.access(arguments.executable, os.X_OK):
        sys.exit(f"no executable {arguments.executable}: build first")
    if os.nice(0) < 10:
        os.nice(10 - os.nice(0))   # shared machine: everything at nice 10
    # On SIGTERM, end the running child too (subprocess.run kills it on any
    # exception).
    signal.signal(signal.SIGTERM, lambda *_: sys.exit("terminated"))
    runner = Runner(arguments, plan)
    if arguments.plots_only:
        runner.load()
        # A run that stopped right after a fine reference has not recorded
        # it as the case's: take the converged one (else any) of the run.
        for name, r in runner.results.items():
            if "reference" in r["studies"] and (
                    r["case"] not in runner.fine or
                    r.get("status") == "converged"):
                runner.fine[r["case"]] = name
        if not runner.references:
            # A run that stopped before its errors (the exported LCPs are
            # still there): compute them now.
            print("== errors", flush=True)
            runner.references = algebraic_errors(runner)
            runner.save()
        report(runner, plan, cases)
        return
    shutil.rmtree(RUNS, ignore_errors=True)
    os.makedirs(RUNS, exist_ok=True)
    start = time.time()
    print(f"{'quick' if arguments.quick else 'full'} mode, cases "
          f"{', '.join(cases)}, studies {', '.join(sorted(studies))}, "
          f"{runner.repeats} repeats below {runner.repeat_below:g} s, "
          f"timeout {runner.timeout:g} s per run", flush=True)

    for case in cases:
        family, name = CASES[case]
        print(f"== {family}: {name}", flush=True)
        solvers = MASONRY_SOLVERS if family == "masonry" else PLATE_SOLVERS
        if family == "masonry":
            size_meshes = [(m, 0) for m in plan["masonry_m"]]
            refinement_meshes = [(plan["masonry_refinement_m"], r)
                                 for r in plan["masonry_r"]]
            tolerance_mesh = (plan["masonry_tolerance_m"], 0)
            fine_mesh = (plan["masonry_refinement_m"],
                         plan["masonry_reference_r"])
        else:
            size_meshes = [(n,) for n in plan["plate_n"]]
            refinement_meshes = []
            tolerance_mesh = (plan["plate_tolerance_n"],)
            fine_mesh = (plan["plate_reference_n"],)
        meshes = []
        if "size" in studies:
            meshes += [(mesh, "size") for mesh in size_meshes]
        if "refinement" in studies:
            meshes += [(mesh, "refinement") for mesh in refinement_meshes]
        for mesh, study in meshes:
            for label in solvers:
                runner.run(case, mesh, label, study=study)
        if "tolerance" in studies:
            for label in solvers:
                runner.run(case, tolerance_mesh, label, study="tolerance")
            for label in SWEEPS:
                for tolerance in plan["tolerances"]:
                    runner.run(case, tolerance_mesh, label, tolerance,
                               study="tolerance")
        if "refinement" in studies or (family == "plate" and
                                       "size" in studies):
            # The fine reference: one run, the fastest robust exact method
            # for the family, a second one if it does not converge.
            for label in (["pdpc", "pdas"] if family == "masonry" else
                          ["interior_point_eps6", "pdas"]):
                result = runner.run(case, fine_mesh, label,
                                    timeout=max(runner.timeout, 900),
                                    study="reference", export=False)
                if result.get("status") == "converged":
                    break
            runner.fine[case] = result["name"]

    print("== errors", flush=True)
    runner.references = algebraic_errors(runner)
    runner.save()
    report(runner, plan, cases)
    print(f"done in {time.time() - start:.0f} s; results in {RESULTS}")


def report(runner, plan, cases):
    """CSV files and plots from what the runner holds."""
    fine = {case: runner.results[name] for case, name in runner.fine.items()}
    convergence = discretisation_errors(runner, fine)
    orders = fit_orders(convergence)
    write_all(runner, runner.references, convergence, orders)
    write_summary_md(runner, os.path.join(RESULTS, "summary.md"))
    print("== plots", flush=True)
    for case in cases:
        plot_case(runner, case, plan,
                  os.path.join(RESULTS, f"error_time_{case}.png"))
    for family in ("masonry", "plate"):
        rows = [row for row in convergence if CASES[row["case"]][0] == family]
        if rows:
            plot_convergence(family, rows, orders,
                             os.path.join(RESULTS,
                                          f"convergence_{family}.png"))
    for o in orders:
        print(f"  order {o['case']} {o['quantity']}: {o['order']:.2f} "
              f"(meshes {o['fitted_on']})")


if __name__ == "__main__":
    main()
