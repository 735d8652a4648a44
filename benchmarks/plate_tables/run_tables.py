#!/usr/bin/python3
"""Regenerate Tables 1-6 of the plate study (Fernandes, Figueiredo & Judice
2002) beside the paper's values, plus the convergence study without an
obstacle and (with --large) a 512 x 512 run with its peak memory.

For every row of plate_contact.csv it writes a parameter file, runs the
unilateral executable with each method (interior_point, block_pivoting,
pdas by default), reads summary.json and reports our |J|, |J1|, cn,
iterations and seconds next to the paper's. Results go to
benchmarks/results/plate_tables/ (git-ignored; --results DIR elsewhere):
plate_tables.csv, plate_tables.md, plate_tables.png (seconds against |J|
per method, one panel per table, ours and the paper's), convergence.csv,
large.md and the runs themselves.

Usage (from the repository root):
  /usr/bin/python3 benchmarks/plate_tables/run_tables.py \
      [--executable build/unilateral] [--methods interior_point,block_pivoting,pdas]
      [--max-elements 8100] [--large] [--large-elements 512]

Timings are wall-clock seconds of the solver phase on this machine; the
paper's are CPU seconds on a Pentium II at 350 MHz.
"""
import argparse
import csv
import json
import math
import os
import re
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
FORCE_NAME = {"-1": "f1", "-5": "f2", "-10": "f3"}

# Method variants: label -> (registered method, Solver settings).
#  interior_point: the paper's tolerances (eps1 = 1e-10 on ||C z - F - w||_2,
#    absolute), capped at 100 iterations (the paper needs <= 24);
#  ip_eps8: the same with eps1 = 1e-8, above the rounding floor of the
#    residual in these units (see README.md);
#  block_pivoting: p = 10, eps = 1e-6 as in the paper; pdas: exact.
VARIANTS = {
    "interior_point": ("interior_point", {"Maximum iterations": "100"}),
    "ip_eps8": ("interior_point",
                {"Interior point/Residual tolerance": "1e-8"}),
    "block_pivoting": ("block_pivoting", {}),
    "pdas": ("pdas", {}),
    # For 512 x 512: the residual's rounding floor grows with the mesh
    # (entries of C ~ D / h^2, sqrt(|J|) terms), so eps1 = 1e-6 there.
    "ip_eps6": ("interior_point",
                {"Interior point/Residual tolerance": "1e-6",
                 "Maximum iterations": "80"}),
    # ... and without the PDAS projection that follows it (its own answer).
    "ip_eps6_raw": ("interior_point",
                    {"Interior point/Residual tolerance": "1e-6",
                     "Maximum iterations": "80", "Projection": "false"}),
}
PAPER_COLUMN = {"interior_point": ("ip_it", "ip_cpu"),
                "ip_eps8": ("ip_it", "ip_cpu"),
                "block_pivoting": ("bp_it", "bp_cpu")}
SHORT = {"interior_point": "ip", "ip_eps8": "ip ε1=1e-8",
         "ip_eps6": "ip ε1=1e-6", "ip_eps6_raw": "ip ε1=1e-6, no projection",
         "block_pivoting": "bp", "pdas": "pdas"}


def solver_lines(settings):
    """'Sub/Entry' -> value as parameter-file lines inside subsection Solver."""
    lines = []
    for key, value in settings.items():
        if "/" in key:
            sub, entry = key.split("/", 1)
            lines.append(f"  subsection {sub}\n    set {entry} = {value}\n"
                         "  end")
        else:
            lines.append(f"  set {key} = {value}")
    return "\n".join(lines)
SERIES_COEFFICIENT = 0.00126532  # w = c q a^4 / D, clamped square plate


def read_paper_rows():
    with open(os.path.join(HERE, "plate_contact.csv")) as file:
        lines = [line for line in file if not line.startswith("#")]
    return list(csv.DictReader(lines))


def write_prm(path, n, material, obstacle, force, variant, output_directory,
              run_name, boundary="clamped", write_vtu=False, progress=False):
    method, settings = VARIANTS[variant]
    with open(path, "w") as prm:
        prm.write(f"""set Scene = plate
subsection Output
  set Directory     = {output_directory}
  set Run name      = {run_name}
  set Write VTU     = {"true" if write_vtu else "false"}
  set Print timings = false
  set Progress      = {"true" if progress else "false"}
end
subsection Solver
  set Method = {method}
{solver_lines(settings)}
end
subsection Plate
  subsection Geometry
    set Elements x         = {n}
    set Elements y         = {n}
    set Boundary condition = {boundary}
  end
  subsection Material
    set Name = {material}
  end
  subsection Obstacle
    set Function = {obstacle}
  end
  subsection Load
    set Force = {force}
  end
  subsection Output
    set Subdivisions = 2
  end
end
""")


def run(executable, prm, summary_file, measure_memory=False, log=None):
    command = [executable, prm]
    if measure_memory:
        command = ["/usr/bin/time", "-v"] + command
    start = time.time()
    if log is None:
        process = subprocess.run(command, capture_output=True, text=True)
    else:
        # Screen output (progress lines) straight into the log, as it comes.
        with open(log, "w") as file:
            process = subprocess.run(command, stdout=file,
                                     stderr=subprocess.PIPE, text=True)
        process.stdout = open(log).read()
    wall = time.time() - start
    if process.returncode == 1 or not os.path.exists(summary_file):
        sys.exit(f"run failed: {' '.join(command)}\n{process.stdout}\n"
                 f"{process.stderr}")
    summary = json.load(open(summary_file))
    summary["wall_seconds"] = wall
    summary["exit_code"] = process.returncode
    if measure_memory:
        match = re.search(r"Maximum resident set size \(kbytes\): (\d+)",
                          process.stderr)
        summary["max_rss_mb"] = int(match.group(1)) / 1024 if match else None
    return summary


def near_contact(run_directory):
    """Free interior nodes within 1e-6 mm of the obstacle (the paper's block
    pivoting tolerance) and the smallest contact force, from nodes.vtu."""
    import numpy
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(os.path.join(run_directory, "nodes.vtu"))
    reader.Update()
    grid = reader.GetOutput()
    points = vtk_to_numpy(grid.GetPoints().GetData())
    data = grid.GetPointData()
    fields = {data.GetArrayName(i): vtk_to_numpy(data.GetArray(i))
              for i in range(data.GetNumberOfArrays())}
    _, unique = numpy.unique(numpy.round(points[:, :2], 6), axis=0,
                             return_index=True)
    contact = fields["contact"][unique]
    gap = fields["gap"][unique].astype(float)
    force = fields["contact_force"][unique].astype(float)
    x, y = points[unique, 0], points[unique, 1]
    interior = (x > 1e-9) & (x < x.max() - 1e-9) & (y > 1e-9) & \
               (y < y.max() - 1e-9)
    free = interior & (contact == 0)
    return {"free_below_1e-6": int((gap[free] < 1e-6).sum()),
            "smallest_free_gap": float(gap[free].min()) if free.any()
            else float("nan"),
            "smallest_contact_force": float(force[contact == 1].min())
            if (contact == 1).any() else float("nan")}


def solver_seconds(summary):
    # The context timer's "solve" section: the whole solve_lcp call.
    return summary["time"].get("solve", float("nan"))


def tables(arguments, results):
    rows = read_paper_rows()
    runs = os.path.join(results, "runs")
    prms = os.path.join(results, "prm")
    os.makedirs(prms, exist_ok=True)
    methods = arguments.methods.split(",")
    records = []
    for row in rows:
        elements = int(row["ele"])
        if elements > arguments.max_elements:
            continue
        n = math.isqrt(elements)
        force = FORCE_NAME[row["force"]]
        record = {"table": row["table"], "material": row["material"],
                  "obstacle": row["obstacle"], "force": force, "n": n,
                  "paper": row}
        for method in methods:
            name = (f"table{row['table']}_{row['material']}_{row['obstacle']}_"
                    f"{force}_{n}_{method}")
            prm = os.path.join(prms, name + ".prm")
            write_prm(prm, n, row["material"], row["obstacle"], force, method,
                      runs, name, write_vtu=(method == "pdas"))
            record[method] = run(arguments.executable, prm,
                                 os.path.join(runs, name, "summary.json"))
            if method == "pdas":
                record["near"] = near_contact(os.path.join(runs, name))
        records.append(record)
        first = record[methods[0]]
        print(f"Table {row['table']} {row['material']:6} {row['obstacle']} "
              f"{force} {n:3}x{n:<3} |J| {first['n_free']:6} "
              f"(paper {row['J']:>6}) cn "
              + " ".join(f"{m}={record[m]['n_contact']}" for m in methods)
              + f" (paper {row['cn']})", flush=True)
    return records, methods


def write_table_files(records, methods, results):
    short = SHORT
    header = ["table", "material", "obstacle", "force", "elements", "J",
              "J_paper", "J1", "J1_paper", "cn_paper"]
    for method in methods:
        s = short.get(method, method)
        header += [f"cn_{s}", f"it_{s}", f"seconds_{s}", f"status_{s}"]
    header += ["ip_it_paper", "ip_cpu_paper", "bp_it_paper", "bp_cpu_paper",
               "max_rel_diff_centre_deflection", "free_nodes_gap_below_1e-6",
               "smallest_free_gap", "smallest_contact_force"]
    with open(os.path.join(results, "plate_tables.csv"), "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(header)
        for r in records:
            p = r["paper"]
            first = r[methods[0]]
            line = [r["table"], r["material"], r["obstacle"], r["force"],
                    r["n"] ** 2, first["n_free"], p["J"], first["n_bounds"],
                    p["J1"], p["cn"]]
            for m in methods:
                s = r[m]
                line += [s["n_contact"], s["iterations"],
                         f"{solver_seconds(s):.4f}", s["status"]]
            near = r.get("near", {})
            line += [p["ip_it"], p["ip_cpu"], p["bp_it"], p["bp_cpu"],
                     f"{centre_spread(r, methods):.1e}",
                     near.get("free_below_1e-6", ""),
                     f"{near.get('smallest_free_gap', float('nan')):.2e}",
                     f"{near.get('smallest_contact_force', float('nan')):.2e}"]
            writer.writerow(line)

    with open(os.path.join(results, "plate_tables.md"), "w") as md:
        md.write("# Plate study, Tables 1-6: ours beside the paper's\n\n"
                 "cn: interior nodes in contact (ours per method / paper). "
                 "it, s: iterations and seconds of the solve (ours: wall "
                 "clock on this machine; paper: CPU seconds, Pentium II "
                 "350 MHz). `!` marks a cn that differs from the paper's, "
                 "`*` a run that did not converge. Δw: largest relative "
                 "difference of the centre deflection between our methods.\n")
        table = None
        for r in records:
            p = r["paper"]
            if r["table"] != table:
                table = r["table"]
                md.write(f"\n## Table {table}\n\n")
                md.write("| material | ψ | f | ele | \\|J\\| (paper) | "
                         "\\|J1\\| (paper) | cn paper | "
                         + " | ".join(f"cn {short.get(m, m)}" for m in methods)
                         + " | " + " | ".join(f"it {short.get(m, m)} (paper)"
                                              if m in PAPER_COLUMN
                                              else f"it {short.get(m, m)}"
                                              for m in methods)
                         + " | " + " | ".join(f"s {short.get(m, m)} (paper)"
                                              if m in PAPER_COLUMN
                                              else f"s {short.get(m, m)}"
                                              for m in methods)
                         + " | Δw | free nodes, gap < 1e-6 mm | smallest "
                         "free gap (mm) |\n")
                md.write("|" + "---|" * (10 + 3 * len(methods)) + "\n")
            first = r[methods[0]]
            cells = [r["material"], r["obstacle"], r["force"], str(r["n"] ** 2),
                     f"{first['n_free']} ({p['J']})",
                     f"{first['n_bounds']} ({p['J1']})", p["cn"]]
            for m in methods:
                s = r[m]
                mark = ("" if str(s["n_contact"]) == p["cn"] else "!") + \
                       ("" if s["status"] == "converged" else "*")
                cells.append(f"{s['n_contact']}{mark}")
            for m in methods:
                s = r[m]
                paper_it = p[PAPER_COLUMN[m][0]] if m in PAPER_COLUMN else None
                cells.append(f"{s['iterations']}" +
                             (f" ({paper_it})" if paper_it is not None else ""))
            for m in methods:
                s = r[m]
                paper_s = p[PAPER_COLUMN[m][1]] if m in PAPER_COLUMN else None
                cells.append(f"{solver_seconds(s):.3f}" +
                             (f" ({paper_s})" if paper_s is not None else ""))
            cells.append(f"{centre_spread(r, methods):.0e}")
            near = r.get("near", {})
            cells.append(str(near.get("free_below_1e-6", "")))
            cells.append(f"{near.get('smallest_free_gap', float('nan')):.1e}")
            md.write("| " + " | ".join(cells) + " |\n")

        md.write("\n## Summary\n\n")
        total = len(records)
        for m in methods:
            equal = sum(str(r[m]["n_contact"]) == r["paper"]["cn"]
                        for r in records)
            converged = sum(r[m]["status"] == "converged" for r in records)
            md.write(f"- {m}: cn equal to the paper's in {equal} of {total} "
                     f"rows; converged in {converged} of {total}.\n")
        counts = sum(str(r[methods[0]]["n_free"]) == r["paper"]["J"] and
                     str(r[methods[0]]["n_bounds"]) == r["paper"]["J1"]
                     for r in records)
        md.write(f"- |J| and |J1| equal the paper's in {counts} of {total} "
                 "rows.\n")
    plot_tables(records, methods, results)


def plot_tables(records, methods, results):
    """plate_tables.png: solve seconds against |J|, one panel per table,
    each method's runs (filled: converged, open: not) and the paper's
    interior point and block pivoting (crosses)."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib missing: no plot")
        return
    tables = list(dict.fromkeys(r["table"] for r in records))
    if not tables:
        return
    columns = min(3, len(tables))
    rows_of_panels = (len(tables) + columns - 1) // columns
    figure, axes = plt.subplots(rows_of_panels, columns,
                                figsize=(4.5 * columns, 3.8 * rows_of_panels),
                                squeeze=False)
    for axis, table in zip(axes.flat, tables):
        selected = [r for r in records if r["table"] == table]
        for index, m in enumerate(methods):
            colour = f"C{index % 10}"
            for converged in (True, False):
                points = [(r[m]["n_free"], solver_seconds(r[m]))
                          for r in selected
                          if (r[m]["status"] == "converged") == converged]
                if points:
                    axis.loglog(*zip(*points), "o", color=colour,
                                fillstyle="full" if converged else "none",
                                label=SHORT.get(m, m) if converged else None)
        for index, (label, column) in enumerate((("ip (paper)", "ip_cpu"),
                                                 ("bp (paper)", "bp_cpu"))):
            points = []
            for r in selected:
                try:
                    seconds = float(r["paper"][column])
                except (TypeError, ValueError):
                    continue
                if seconds > 0:
                    points.append((r[methods[0]]["n_free"], seconds))
            if points:
                axis.loglog(*zip(*points), "x", color=f"C{7 + index}",
                            label=label)
        axis.set(title=f"Table {table}", xlabel="|J| (unknowns)",
                 ylabel="solve seconds")
        axis.grid(True, which="both", alpha=0.3)
    for axis in list(axes.flat)[len(tables):]:
        axis.set_visible(False)
    axes[0][0].legend(fontsize=7)
    figure.tight_layout()
    figure.savefig(os.path.join(results, "plate_tables.png"), dpi=100)
    plt.close(figure)


def centre_spread(record, methods):
    values = [record[m]["centre_deflection"] for m in methods
              if record[m]["status"] == "converged"]
    if len(values) < 2:
        return float("nan")
    scale = max(abs(v) for v in values)
    return (max(values) - min(values)) / scale


def convergence(arguments, results):
    runs = os.path.join(results, "runs")
    prms = os.path.join(results, "prm")
    lines = []
    for boundary in ("clamped", "fully clamped"):
        previous = None
        for n in (4, 8, 16, 32, 64, 128):
            name = f"convergence_{boundary.replace(' ', '_')}_{n}"
            prm = os.path.join(prms, name + ".prm")
            write_prm(prm, n, "steel", "none", "f1", "pdas", runs, name,
                      boundary)
            s = run(arguments.executable, prm,
                    os.path.join(runs, name, "summary.json"))
            # A deflection the program itself does not vouch for (exit 2)
            # is no point of a convergence study.
            if s["exit_code"] != 0:
                sys.exit(f"{name}: exit code {s['exit_code']}, the run did "
                         f"not pass its answer checks")
            series = -SERIES_COEFFICIENT * 1e8 / s["flexural_rigidity"]
            error = abs(s["centre_deflection"] / series - 1)
            lines.append({"boundary": boundary, "n": n,
                          "centre_deflection": s["centre_deflection"],
                          "series": series, "relative_error": error,
                          "order": (math.log2(previous / error)
                                    if previous else float("nan"))})
            previous = error
    for boundary in ("clamped", "fully clamped"):
        w = [l["centre_deflection"] for l in lines if l["boundary"] == boundary]
        for k in range(len(w) - 2):
            lines[[i for i, l in enumerate(lines)
                   if l["boundary"] == boundary][k + 2]]["richardson_order"] = \
                math.log2((w[k] - w[k + 1]) / (w[k + 1] - w[k + 2]))
    with open(os.path.join(results, "convergence.csv"), "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["boundary", "n", "centre_deflection", "series",
                         "relative_error", "order_vs_series",
                         "richardson_order"])
        for l in lines:
            writer.writerow([l["boundary"], l["n"],
                             f"{l['centre_deflection']:.10f}",
                             f"{l['series']:.10f}",
                             f"{l['relative_error']:.3e}",
                             f"{l['order']:.2f}",
                             f"{l.get('richardson_order', float('nan')):.2f}"])
    with open(os.path.join(results, "convergence.md"), "w") as md:
        md.write("# Centre deflection without obstacle vs the series value "
                 "0.00126532 q a^4 / D\n\n| boundary | n | w_centre (mm) | "
                 "rel. error | order vs series | Richardson order |\n"
                 "|---|---|---|---|---|---|\n")
        for l in lines:
            md.write(f"| {l['boundary']} | {l['n']} | "
                     f"{l['centre_deflection']:.8f} | "
                     f"{l['relative_error']:.2e} | {l['order']:.2f} | "
                     f"{l.get('richardson_order', float('nan')):.2f} |\n")
        md.write("\nThe series value is given to 6 digits (relative "
                 "precision 4e-6): errors below ~1e-5 are not resolved by "
                 "it, the Richardson order (from three successive meshes, no "
                 "reference) is.\n")
    for l in lines:
        print(f"convergence {l['boundary']:13} {l['n']:4}: error "
              f"{l['relative_error']:.2e} order {l['order']:.2f} Richardson "
              f"{l.get('richardson_order', float('nan')):.2f}", flush=True)


def large(arguments, results):
    runs = os.path.join(results, "runs")
    prms = os.path.join(results, "prm")
    n = arguments.large_elements
    with open(os.path.join(results, "large.md"), "w") as md:
        md.write(f"# {n} x {n} elements\n\n| obstacle | force | method | "
                 "\\|J\\| | \\|J1\\| | cn | it (+ projection) | assemble s | "
                 "solve s | total wall s | peak RSS MB | KKT | status |\n"
                 "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n")
        for obstacle, force, method in (
                [("none", "f1", "pdas")] +
                [("psi3", "f3", m) for m in arguments.large_methods.split(",")]):
            name = f"large_{n}_{obstacle}_{force}_{method}"
            prm = os.path.join(prms, name + ".prm")
            write_prm(prm, n, "steel", obstacle, force, method, runs, name,
                      progress=True)
            s = run(arguments.executable, prm,
                    os.path.join(runs, name, "summary.json"),
                    measure_memory=True,
                    log=os.path.join(results, name + ".log"))
            md.write(f"| {obstacle} | {force} | {method} | {s['n_free']} | "
                     f"{s['n_bounds']} | {s['n_contact']} | "
                     f"{s['iterations']} (+{s['projection_iterations']}) | "
                     f"{s['time'].get('assemble system', float('nan')):.2f} | "
                     f"{solver_seconds(s):.1f} | {s['wall_seconds']:.1f} | "
                     f"{s['max_rss_mb']:.0f} | {s['kkt']['max']:.1e} | "
                     f"{s['status']} |\n")
            md.flush()
            print(f"large {n}x{n} {obstacle} {force} {method}: |J| "
                  f"{s['n_free']}, it {s['iterations']}, wall "
                  f"{s['wall_seconds']:.1f} s, peak RSS {s['max_rss_mb']:.0f} "
                  f"MB, {s['status']}", flush=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--executable",
                        default=os.path.join(ROOT, "build", "unilateral"))
    parser.add_argument("--methods",
                        default="interior_point,ip_eps8,block_pivoting,pdas",
                        help="comma-separated labels of VARIANTS")
    parser.add_argument("--max-elements", type=int, default=8100)
    parser.add_argument("--results",
                        default=os.path.join(ROOT, "benchmarks", "results",
                                             "plate_tables"))
    parser.add_argument("--skip-tables", action="store_true")
    parser.add_argument("--skip-convergence", action="store_true")
    parser.add_argument("--large", action="store_true",
                        help="also run the 512 x 512 mesh (minutes, GBs)")
    parser.add_argument("--large-elements", type=int, default=512)
    parser.add_argument("--large-methods", default="ip_eps6,ip_eps6_raw",
                        help="variants for the 512 x 512 run with psi3, f3")
    arguments = parser.parse_args()
    # Absolute: the parameter files in results/prm/ name its runs/, and a
    # relative 'Output/Directory' would be taken from their folder.
    arguments.results = os.path.abspath(arguments.results)
    os.makedirs(arguments.results, exist_ok=True)
    if not arguments.skip_tables:
        records, methods = tables(arguments, arguments.results)
        write_table_files(records, methods, arguments.results)
    if not arguments.skip_convergence:
        convergence(arguments, arguments.results)
    if arguments.large:
        large(arguments, arguments.results)
    print(f"results in {arguments.results}/")


if __name__ == "__main__":
    main()
