#!/usr/bin/env /usr/bin/python3
"""Issue 22: the psi3 f1 steel plate (the paper's Table 4 configuration) on
n x n meshes, solved by TNNMG (the plate's hierarchy of BFS meshes) and by
PDAS (today's default: sparse Cholesky with the coarse-mesh start), side by
side in one run: end-to-end wall time, solve time, peak memory
(/usr/bin/time -v), multigrid cycles per level, the ratio of the solve time to the
time of one product with the finest A, and whether both found the same
plate (cn, smallest and centre deflection).

  /usr/bin/python3 benchmarks/plate_multigrid/run_multigrid.py [--sizes 90 64 128 256 512]
      [--pdas-max 256] [--executable build/unilateral] [--baseline old/unilateral]
      [--output DIR]

PDAS above --pdas-max is not run (512 x 512: about 12 GB and six minutes,
363 s measured; see README.md).
--baseline: TNNMG of another build too, run just before the new one on each
mesh (so that the machine's drift falls on both alike), compared in a second
table (baseline.csv).
Prints the table, writes results.csv and multigrid.png here, the committed
table, when --sizes are the committed table's (COMMITTED_SIZES, in any
order); a run at other sizes writes them to --directory instead (scratch,
default /tmp/plate_multigrid), unless --output DIR names a folder
(--table-only: both again from the results.csv of --output, default here).
"""
import argparse
import csv
import json
import os
import re
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
# The sizes of the committed results.csv: a run at other sizes does not
# replace it unless --output says so.
COMMITTED_SIZES = [90, 64, 128, 256, 512, 1024]


def write_prm(path, n, method, directory, run_name=None):
    with open(path, "w") as prm:
        prm.write(f"""set Scene = plate
subsection Output
  set Directory     = {directory}
  set Run name      = {run_name or f"{method}_{n}"}
  set Write VTU     = false
  set Print timings = false
  set Progress      = true
end
subsection Solver
  set Method = {method}
end
subsection Plate
  subsection Geometry
    set Elements x = {n}
    set Elements y = {n}
  end
  subsection Material
    set Name = steel
  end
  subsection Obstacle
    set Function = psi3
  end
  subsection Load
    set Force = f1
  end
end
""")


def run(executable, n, method, directory, label=None):
    label = label or method
    prm = os.path.join(directory, f"{label}_{n}.prm")
    write_prm(prm, n, method, directory, f"{label}_{n}")
    start = time.time()
    process = subprocess.run(["/usr/bin/time", "-v", executable, prm],
                             capture_output=True, text=True)
    wall = time.time() - start
    summary_file = os.path.join(directory, f"{label}_{n}", "summary.json")
    if process.returncode == 1 or not os.path.exists(summary_file):
        sys.exit(f"run failed: {label} {n}\n{process.stdout}\n"
                 f"{process.stderr}")
    summary = json.load(open(summary_file))
    rss = re.search(r"Maximum resident set size \(kbytes\): (\d+)",
                    process.stderr)
    levels = re.findall(r"tnnmg level (\d+) \((\d+) unknowns\): (\d+) "
                        r"iterations, (\d+) [VW]-cycles", process.stdout)
    product = re.search(r"one product with A on the finest level (\S+) s",
                        process.stdout)
    return {"n": n, "method": label, "unknowns": summary["n_unknowns"],
            "wall_s": wall, "solve_s": summary["time"]["solve"],
            "max_rss_gb": int(rss.group(1)) / 1024**2 if rss else float("nan"),
            "status": summary["status"], "kkt": summary["kkt"]["max"],
            "cn": summary["n_contact"],
            "min_deflection": summary["min_deflection"],
            "centre_deflection": summary["centre_deflection"],
            "cycles_per_level": " ".join(c for _, _, _, c in levels),
            "iterations_per_level": " ".join(i for _, _, i, _ in levels),
            "product_s": float(product.group(1)) if product else float("nan")}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--sizes", type=int, nargs="+",
                        default=[90, 64, 128, 256, 512])
    parser.add_argument("--pdas-max", type=int, default=256)
    parser.add_argument("--executable",
                        default=os.path.join(HERE, "../../build/unilateral"))
    parser.add_argument("--baseline", default=None,
                        help="another build's executable, for TNNMG side "
                        "by side")
    parser.add_argument("--directory", default="/tmp/plate_multigrid")
    parser.add_argument("--table-only", action="store_true",
                        help="the table and plot again from results.csv")
    parser.add_argument("--output", default=None,
                        help="folder for results.csv, baseline.csv and "
                        "multigrid.png (default: this folder if --sizes are "
                        "the committed table's, else --directory)")
    arguments = parser.parse_args()
    output = arguments.output
    if output is None:
        output = (HERE if arguments.table_only or
                  sorted(arguments.sizes) == sorted(COMMITTED_SIZES)
                  else arguments.directory)
    if arguments.table_only:
        with open(os.path.join(output, "results.csv")) as file:
            rows = [{k: (v if k in ("method", "status", "cycles_per_level",
                                    "iterations_per_level") else
                         float(v) if "." in v or "e" in v or v == "nan"
                         else int(v)) for k, v in row.items()}
                    for row in csv.DictReader(file)]
        table_and_plot(rows, output)
        return
    os.makedirs(arguments.directory, exist_ok=True)
    os.makedirs(output, exist_ok=True)
    print("load (uptime):", os.getloadavg())

    rows = []
    for n in arguments.sizes:
        runs = [("tnnmg", "tnnmg", arguments.executable)]
        if arguments.baseline:
            runs.insert(0, ("tnnmg", "baseline", arguments.baseline))
        if n <= arguments.pdas_max:
            runs.append(("pdas", "pdas", arguments.executable))
        for method, label, executable in runs:
            rows.append(run(executable, n, method, arguments.directory,
                            label))
            r = rows[-1]
            print(f"{n:5d} {label:8s} |J| {r['unknowns']:8d}  wall "
                  f"{r['wall_s']:7.2f} s  solve {r['solve_s']:7.2f} s  "
                  f"peak {r['max_rss_gb']:5.2f} GB  {r['status']}  KKT "
                  f"{r['kkt']:.1e}  cn {r['cn']}", flush=True)
    print("load (uptime):", os.getloadavg())

    baseline = [r for r in rows if r["method"] == "baseline"]
    rows = [r for r in rows if r["method"] != "baseline"]
    for name, selection in [("results.csv", rows), ("baseline.csv", baseline)]:
        if not selection:
            continue
        with open(os.path.join(output, name), "w", newline="") as file:
            writer = csv.DictWriter(file, fieldnames=list(selection[0].keys()))
            writer.writeheader()
            writer.writerows(selection)
    table_and_plot(rows, output)
    if baseline:
        side_by_side(baseline, rows)
    print(f"wrote results.csv and multigrid.png to {output}"
          + ("" if os.path.samefile(output, HERE) else
             " (not the committed table: --sizes differ from "
             f"{' '.join(map(str, COMMITTED_SIZES))}, or --output)"))


def side_by_side(baseline, rows):
    """TNNMG of the baseline build against the new one, mesh by mesh."""
    print("\n|   n | solve baseline / new | wall baseline / new | finest-level"
          " iterations baseline / new | cycles per level baseline | cycles"
          " per level new | cn baseline / new |")
    print("|---|---|---|---|---|---|---|")
    for b in baseline:
        r = next(q for q in rows if q["method"] == "tnnmg" and q["n"] == b["n"])
        print(f"| {b['n']} | {b['solve_s']:.2f} / {r['solve_s']:.2f} s | "
              f"{b['wall_s']:.2f} / {r['wall_s']:.2f} s | "
              f"{b['iterations_per_level'].split()[-1]} / "
              f"{r['iterations_per_level'].split()[-1]} | "
              f"{b['cycles_per_level']} | {r['cycles_per_level']} | "
              f"{b['cn']} / {r['cn']} |")


def table_and_plot(rows, output):
    print("\n|   n | unknowns | TNNMG wall | TNNMG solve | TNNMG peak |"
          " PDAS wall | PDAS solve | PDAS peak | cn TNNMG / PDAS | deflection"
          " difference | KKT TNNMG / PDAS | cycles per level (coarsest"
          " first) | solve / product |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        if r["method"] != "tnnmg":
            continue
        p = next((q for q in rows if q["method"] == "pdas"
                  and q["n"] == r["n"]), None)
        if p is None:
            pdas = ["-"] * 3
            cn, difference, kkt = f"{r['cn']} / -", "-", f"{r['kkt']:.0e} / -"
        else:
            pdas = [f"{p['wall_s']:.2f} s", f"{p['solve_s']:.2f} s",
                    f"{p['max_rss_gb']:.2f} GB"]
            cn = f"{r['cn']} / {p['cn']}"
            # Relative, of the smallest and the centre deflection.
            difference = max(
                abs(r[k] - p[k]) / abs(p[k])
                for k in ["min_deflection", "centre_deflection"])
            difference = f"{difference:.0e}"
            kkt = f"{r['kkt']:.0e} / {p['kkt']:.0e}"
        print(f"| {r['n']} | {r['unknowns']} | {r['wall_s']:.2f} s | "
              f"{r['solve_s']:.2f} s | {r['max_rss_gb']:.2f} GB | {pdas[0]} | "
              f"{pdas[1]} | {pdas[2]} | {cn} | {difference} | {kkt} | "
              f"{r['cycles_per_level']} | "
              f"{r['solve_s'] / r['product_s']:.0f} |")
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        figure, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
        for method in ["tnnmg", "pdas"]:
            data = sorted((r["unknowns"], r["solve_s"], r["max_rss_gb"])
                          for r in rows if r["method"] == method)
            left.loglog([d[0] for d in data], [d[1] for d in data], "o-",
                        label=method)
            right.loglog([d[0] for d in data], [d[2] for d in data], "o-",
                         label=method)
        left.set(xlabel="unknowns |J|", ylabel="solve time (s)")
        right.set(xlabel="unknowns |J|", ylabel="peak memory (GB)")
        left.legend()
        figure.tight_layout()
        figure.savefig(os.path.join(output, "multigrid.png"), dpi=100)
    except ImportError:
        print("matplotlib missing: no plot")



if __name__ == "__main__":
    main()
