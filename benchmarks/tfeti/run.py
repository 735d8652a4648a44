#!/usr/bin/env python3
"""TFETI (the dual over blocks) beside the serial direct route (PDAS, and
the interior point in its predictor-corrector variant) on the masonry walls,
in one run: for each wall the methods run one after the other, so that the
machine's drift in speed falls on all alike. Prints a table and saves it as
CSV and Markdown, and plots products with F and time against m.

  /usr/bin/python3 benchmarks/tfeti/run.py [--m 25,50,100,225]
      [--geometries "stack bond,running bond,laminae"]
      [--methods tfeti,pdas,interior_point_pc] [--timeout 900]
      [--set "TFETI/Penalty=10" ...] [--name serial] [--ranks 1,2]
      [--dimension 3 --blocks-through 2]

Each run: g = H/2, no VTU output, peak memory from /usr/bin/time -v (the
largest rank's under mpirun; each rank's is in summary.json too), the rest
from summary.json (TFETI's figures are
its "method" object: outer and inner iterations, products with F, the
coarse problem's size, factor and time). A run over --timeout seconds is
stopped and reported as such. With --ranks 1,2 the methods that work over
the ranks run on each number of ranks in turn (mpirun -np N, also for
N = 1): TFETI (route 2: its subdomains shared among the ranks) and the
*_mumps methods (route 1: PDAS or the interior point with 'Factorisation =
mumps', every factorisation spread over the ranks); the other methods run
serially. Under mpirun every rank runs BLAS on --threads-per-rank threads
(default 1: the ranks already fill the cores). With --dimension 3 the walls
are the built-in 3D walls: the 2D wall extruded, --blocks-through blocks
behind each other, each one H deep ('Thickness' = blocks-through), the
front face on rollers as in prm/masonry_wall_3d.prm (without it every block
may slide along z: TFETI then refuses the wall as a mechanism); the table
names them "stack bond 3D" and so on.
"""
import argparse
import csv
import json
import os
import subprocess
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))

METHODS = {
    "tfeti": ("tfeti", []),
    "pdas": ("pdas", []),
    "interior_point_pc": ("interior_point",
                          [("Interior point", "Variant",
                            "predictor-corrector")]),
    "pdas_mumps": ("pdas", [("", "Factorisation", "mumps")]),
    "interior_point_pc_mumps": ("interior_point",
                                [("Interior point", "Variant",
                                  "predictor-corrector"),
                                 ("", "Factorisation", "mumps")]),
}


def over_ranks(method):
    """Whether the method works over the ranks of an MPI run."""
    return method == "tfeti" or method.endswith("_mumps")


def prm_text(geometry, m, method, settings, arguments, directory, name):
    solver_name, own = METHODS[method]
    lines = ["set Scene = masonry", "subsection Masonry",
             f"  set Geometry = {geometry}", f"  set Blocks per side = {m}",
             f"  set Refinement = {arguments.refinement}"]
    if arguments.dimension == 3:
        lines += ["  set Dimension = 3",
                  f"  set Blocks through the thickness = "
                  f"{arguments.blocks_through}",
                  f"  set Thickness = {arguments.blocks_through}",
                  "  subsection Boundary conditions",
                  "    set Normal displacement zero = left, right, front, "
                  "base where x > s", "  end"]
    lines += ["end",
             "subsection Solver", f"  set Method = {solver_name}"]
    for subsection, entry, value in own + settings:
        if subsection:
            lines += [f"  subsection {subsection}",
                      f"    set {entry} = {value}", "  end"]
        else:
            lines += [f"  set {entry} = {value}"]
    lines += ["end", "subsection Output", "  set Write VTU = false",
              "  set Progress = false", "  set Print timings = false",
              f"  set Directory = {directory}", f"  set Run name = {name}",
              "end"]
    return "\n".join(lines) + "\n"


def run(executable, geometry, m, method, ranks, arguments, directory):
    name = f"{geometry.replace(' ', '_')}_{m}_{method}_{ranks}"
    prm = os.path.join(directory, name + ".prm")
    settings = []
    if method == "tfeti":
        for setting in arguments.set:
            path, value = setting.split("=", 1)
            subsection, entry = path.rsplit("/", 1)
            settings.append((subsection, entry, value))
    with open(prm, "w") as f:
        f.write(prm_text(geometry, m, method, settings, arguments,
                         directory, name))
    command = ["/usr/bin/time", "-v", executable, prm]
    environment = dict(os.environ)
    if ranks > 0:
        threads = str(arguments.threads_per_rank)
        command = ["mpirun", "--oversubscribe", "-np", str(ranks),
                   "-x", f"OMP_NUM_THREADS={threads}",
                   "-x", f"OPENBLAS_NUM_THREADS={threads}"] + command
        environment.update(OMPI_ALLOW_RUN_AS_ROOT="1",
                           OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    start = time.time()
    try:
        process = subprocess.run(command, capture_output=True, text=True,
                                 timeout=arguments.timeout, env=environment)
    except subprocess.TimeoutExpired:
        return {"status": f"stopped after {arguments.timeout} s",
                "wall": time.time() - start}
    wall = time.time() - start
    peak_kb = 0
    for line in process.stderr.splitlines():
        if "Maximum resident set size" in line:
            peak_kb = max(peak_kb, int(line.split(":")[1]))
    try:
        with open(os.path.join(directory, name, "summary.json")) as f:
            summary = json.load(f)
    except (OSError, ValueError):
        return {"status": "no summary: " + process.stderr[-300:], "wall": wall}
    if "energy" not in summary:  # refused or failed before solving
        return {"status": summary["status"] + ": " + summary.get("message", ""),
                "wall": wall}
    figures = summary.get("method", {})
    result = {"wall": wall, "peak_gb": peak_kb / 1e6,
              "status": summary["status"], "energy": summary["energy"],
              "kkt": summary["kkt"]["max"],
              "n": summary["n_unknowns"],
              "iterations": summary["iterations"],
              "projection_iterations": summary["projection_iterations"],
              "solve": summary["time"].get("solve", float("nan"))}
    for key in ("outer_iterations", "inner_iterations", "products_with_F",
                "coarse_size", "coarse_factor_nonzeros",
                "coarse_factorisation_seconds", "coarse_solve_seconds",
                "coarse_solves", "products_with_F_seconds", "subdomains",
                "multipliers", "most_subdomains_on_a_rank",
                "factorisation_ranks", "lumped_products",
                "lumped_products_seconds"):
        if key in figures:
            result[key] = figures[key]
    if "ranks" in summary:
        result["peak_gb_per_rank"] = max(
            r["peak_memory_gb"] for r in summary["ranks"])
    return result


def describe(row):
    if "energy" not in row:
        return f"{row['status']}"
    text = (f"{row['wall']:7.1f} s (solve {row['solve']:7.1f}), "
            f"{row['peak_gb']:.2f} GB, {row['iterations']}+"
            f"{row['projection_iterations']} it, {row['status']}, "
            f"energy {row['energy']:.12e}, KKT {row['kkt']:.1e}")
    if "products_with_F" in row:
        text += (f"; F x {int(row['products_with_F'])}, outer "
                 f"{int(row['outer_iterations'])}, inner "
                 f"{int(row['inner_iterations'])}, coarse "
                 f"{int(row['coarse_size'])} ({row['coarse_factor_nonzeros']:.2e}"
                 f" in L, factorised {row['coarse_factorisation_seconds']:.2f}"
                 f" s, {int(row['coarse_solves'])} solves "
                 f"{row['coarse_solve_seconds']:.1f} s), F "
                 f"{row['products_with_F_seconds']:.1f} s")
    return text


def write_tables(rows, output, name):
    os.makedirs(output, exist_ok=True)
    keys = []
    for row in rows:
        keys += [k for k in row if k not in keys]
    with open(os.path.join(output, name + ".csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=keys)
        writer.writeheader()
        writer.writerows(rows)
    with open(os.path.join(output, name + ".md"), "w") as f:
        f.write("| geometry | m | unknowns | method | wall s | solve s | "
                "peak GB | "
                "iterations | products with F (outer/inner) | coarse size, "
                "factor, solves, time | status | energy |\n")
        f.write("|---|---|---|---|---|---|---|---|---|---|---|---|\n")
        for r in rows:
            method = r["method"] + (f" np {r['mpi_ranks']}"
                                    if r.get("mpi_ranks") else "")
            if "energy" not in r:
                f.write(f"| {r['geometry']} | {r['m']} | | {method} | "
                        f"{r['wall']:.1f} | | | | | | {r['status']} | |\n")
                continue
            dual = coarse = ""
            if "products_with_F" in r:
                dual = (f"{int(r['products_with_F'])} "
                        f"({int(r['outer_iterations'])}/"
                        f"{int(r['inner_iterations'])})")
                coarse = (f"{int(r['coarse_size'])}, "
                          f"{r['coarse_factor_nonzeros']:.2e}, "
                          f"{int(r['coarse_solves'])}, "
                          f"{r['coarse_factorisation_seconds'] + r['coarse_solve_seconds']:.1f} s")
            f.write(f"| {r['geometry']} | {r['m']} | {r['n']} | {method} | "
                    f"{r['wall']:.1f} | {r['solve']:.1f} | "
                    f"{r['peak_gb']:.2f} | {r['iterations']} + "
                    f"{r['projection_iterations']} | {dual} | {coarse} | "
                    f"{r['status']} | {r['energy']:.12e} |\n")


def plot(rows, output, name):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("no matplotlib: no plot")
        return
    geometries = sorted({r["geometry"] for r in rows})
    figure, axes = plt.subplots(1, 1 + len(geometries),
                                figsize=(4.2 * (1 + len(geometries)), 4.2),
                                squeeze=False)
    left = axes[0][0]
    styles = {"tfeti": "o-", "pdas": "s--", "interior_point_pc": "^:",
              "pdas_mumps": "D-.", "interior_point_pc_mumps": "v-."}
    runs = sorted({(r["method"], int(r.get("mpi_ranks") or 0))
                   for r in rows})
    for geometry, right in zip(geometries, axes[0][1:]):
        tfeti = [r for r in rows if r["geometry"] == geometry
                 and r["method"] == "tfeti" and r.get("products_with_F")
                 and int(r.get("mpi_ranks") or 0) <= 1]
        if tfeti:
            left.loglog([r["m"] for r in tfeti],
                        [r["products_with_F"] for r in tfeti], "o-",
                        label=geometry)
        # Wall time of each method (and number of ranks) on this geometry.
        for method, ranks in runs:
            done = [r for r in rows if r["geometry"] == geometry
                    and r["method"] == method
                    and int(r.get("mpi_ranks") or 0) == ranks
                    and r.get("energy")]
            if done:
                label = method + (f" np {ranks}" if ranks else "")
                right.loglog([r["m"] for r in done],
                             [r["wall"] for r in done],
                             styles.get(method, "x-"), label=label)
        right.set_title(geometry)
        right.set_xlabel("m (blocks per side)")
        right.set_ylabel("wall time, s")
        right.legend(fontsize=7)
    left.set_xlabel("m (blocks per side)")
    left.set_ylabel("TFETI's products with F")
    left.legend()
    figure.tight_layout()
    figure.savefig(os.path.join(output, name + ".png"), dpi=110)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--executable",
                        default=os.path.join(ROOT, "build", "unilateral"))
    parser.add_argument("--m", default="25,50,100,225")
    parser.add_argument("--geometries",
                        default="stack bond,running bond,laminae")
    parser.add_argument("--methods", default="tfeti,pdas,interior_point_pc")
    parser.add_argument("--refinement", type=int, default=0)
    parser.add_argument("--dimension", type=int, choices=(2, 3), default=2)
    parser.add_argument("--blocks-through", type=int, default=2,
                        help="3D: blocks behind each other in z")
    parser.add_argument("--timeout", type=float, default=900)
    parser.add_argument("--ranks", default="",
                        help="e.g. 1,2: TFETI and the *_mumps methods under "
                             "mpirun -np N for each N; empty: serially, "
                             "without mpirun (the *_mumps methods need it)")
    parser.add_argument("--threads-per-rank", type=int, default=1,
                        help="BLAS threads of each rank under mpirun")
    parser.add_argument("--set", action="append", default=[],
                        help="a TFETI option, 'TFETI/Penalty=10'")
    parser.add_argument("--name", default="serial",
                        help="the base name of the CSV, Markdown and plot")
    parser.add_argument("--output", default=os.path.join(
        ROOT, "benchmarks", "results", "tfeti"))
    parser.add_argument("--replot", action="store_true",
                        help="only the tables and the plot again, from "
                             "NAME.csv")
    arguments = parser.parse_args()
    if arguments.replot:
        def number(text):
            value = float(text)
            return int(value) if value.is_integer() else value
        with open(os.path.join(arguments.output,
                               arguments.name + ".csv")) as f:
            rows = [{k: (number(v) if k not in ("geometry", "method",
                                                 "status") and v else v)
                     for k, v in row.items() if v != ""}
                    for row in csv.DictReader(f)]
        write_tables(rows, arguments.output, arguments.name)
        plot(rows, arguments.output, arguments.name)
        return
    with open("/proc/loadavg") as f:
        print("load average at the start:", f.read().split()[:3])
    rows = []
    with tempfile.TemporaryDirectory() as directory:
        for m in [int(x) for x in arguments.m.split(",")]:
            for geometry in arguments.geometries.split(","):
                for method in arguments.methods.split(","):
                    counts = [0]
                    if over_ranks(method) and arguments.ranks:
                        counts = [int(n) for n in arguments.ranks.split(",")]
                    for ranks in counts:
                        row = run(arguments.executable, geometry, m, method,
                                  ranks, arguments, directory)
                        row.update(geometry=geometry + (
                            " 3D" if arguments.dimension == 3 else ""),
                                   m=m, method=method, mpi_ranks=ranks)
                        rows.append(row)
                        label = method + (f" np {ranks}" if ranks else "")
                        print(f"{row['geometry']:16s} m = {m:4d} {label:18s} "
                              f"{describe(row)}", flush=True)
                    write_tables(rows, arguments.output, arguments.name)
    with open("/proc/loadavg") as f:
        print("load average at the end:", f.read().split()[:3])
    plot(rows, arguments.output, arguments.name)


if __name__ == "__main__":
    main()
