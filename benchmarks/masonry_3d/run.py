#!/usr/bin/env python3
"""How the masonry scene scales in 3D against 2D (issue 23, "Scale").

The paper's running-bond wall (m x m blocks, settlement g = H/2 under the
left half, PDAS with the sparse Cholesky factorisation) in 2D, and the same
wall extruded into 3D, two blocks through a thickness of 2H, with rollers on
its front and back faces (so that the 3D answer is the 2D one, and the
sizes compare). Each run is one process, timed by the program (phases from
summary.json) and by /usr/bin/time -v (wall time, peak memory). The 3D
series grows m until a run takes more than a minute.

  python3 benchmarks/masonry_3d/run.py [--build build] [--quick] [--output DIR]

Prints a table, writes benchmarks/results/masonry_3d/scale.{csv,md} and
scale.svg (time and memory against unknowns, log-log, 2D and 3D), the
committed results; --quick writes them to /tmp/masonry_3d_quick instead,
and --output DIR to DIR in either case.
"""
import argparse
import csv
import json
import math
import os
import re
import subprocess
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
PHASES = ["make grid", "setup system", "assemble system", "solve"]


def parameters(dim, m, directory):
    rollers = "left, right, base where x > s"
    three_d = ""
    if dim == 3:
        rollers = "left, right, front, back, base where x > s"
        three_d = ("  set Blocks through the thickness = 2\n"
                   "  set Thickness = 2\n")
    return f"""set Scene = masonry
subsection Masonry
  set Dimension = {dim}
  set Geometry = running bond
  set Blocks per side = {m}
  set Element = Q2
{three_d}  subsection Boundary conditions
    set Relative gap = 0.5
    set Normal displacement zero = {rollers}
    set Signorini = base where x < s
  end
end
subsection Solver
  set Method = pdas
end
subsection Output
  set Directory = {directory}
  set Run name = run
  set Write VTU = false
  set Progress = false
end
"""


def run(executable, dim, m):
    with tempfile.TemporaryDirectory() as folder:
        prm = os.path.join(folder, "run.prm")
        with open(prm, "w") as f:
            f.write(parameters(dim, m, folder))
        start = time.time()
        done = subprocess.run(["/usr/bin/time", "-v", executable, prm],
                              capture_output=True, text=True)
        wall = time.time() - start
        memory = re.search(r"Maximum resident set size \(kbytes\): (\d+)",
                           done.stderr)
        try:
            with open(os.path.join(folder, "run", "summary.json")) as f:
                summary = json.load(f)
        except (OSError, ValueError):
            summary = {}
    row = {"dim": dim, "m": m,
           "blocks": summary.get("n_blocks", ""),
           "n": summary.get("n_unknowns", ""),
           "n_c": summary.get("n_constraints", ""),
           "status": summary.get("status", f"exit {done.returncode}"),
           "iterations": summary.get("iterations", ""),
           "factorisations": summary.get("counters", {}).get(
               "numeric_factorisations", ""),
           "wall_s": round(wall, 2),
           "peak_mb": round(int(memory.group(1)) / 1024) if memory else ""}
    for phase in PHASES:
        value = summary.get("time", {}).get(phase)
        row[phase] = round(value, 3) if value is not None else ""
    return row


def slope(rows, key):
    """Least-squares exponent of key ~ n^a over the rows."""
    points = [(math.log(r["n"]), math.log(r[key])) for r in rows
              if r["n"] and r[key] and r[key] > 0]
    if len(points) < 2:
        return float("nan")
    mx = sum(p[0] for p in points) / len(points)
    my = sum(p[1] for p in points) / len(points)
    sxx = sum((p[0] - mx) ** 2 for p in points)
    return sum((p[0] - mx) * (p[1] - my) for p in points) / sxx


def svg(rows, path):
    """Two log-log panels, solve seconds and peak MB against n."""
    width, height, pad = 440, 320, 50
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{2 * width}" '
           f'height="{height}" font-family="sans-serif" font-size="12">',
           '<rect width="100%" height="100%" fill="white"/>']
    colours = {2: "#1f77b4", 3: "#d62728"}
    for panel, (key, label) in enumerate([("solve", "solve (s)"),
                                          ("peak_mb", "peak memory (MB)")]):
        points = [(r["n"], r[key], r["dim"]) for r in rows
                  if r["n"] and r[key] and r[key] > 0]
        if not points:
            continue
        lx = [math.log10(p[0]) for p in points]
        ly = [math.log10(p[1]) for p in points]
        x0, x1 = math.floor(min(lx)), math.ceil(max(lx))
        y0, y1 = math.floor(min(ly)), math.ceil(max(ly))
        left = panel * width

        def X(v):
            return left + pad + (v - x0) / (x1 - x0) * (width - 2 * pad)

        def Y(v):
            return height - pad - (v - y0) / max(y1 - y0, 1) * (height - 2 * pad)
        out.append(f'<rect x="{left + pad}" y="{pad}" width="{width - 2 * pad}"'
                   f' height="{height - 2 * pad}" fill="none" stroke="black"/>')
        for e in range(x0, x1 + 1):
            out.append(f'<text x="{X(e)}" y="{height - pad + 16}" '
                       f'text-anchor="middle">1e{e}</text>')
        for e in range(y0, y1 + 1):
            out.append(f'<text x="{left + pad - 6}" y="{Y(e) + 4}" '
                       f'text-anchor="end">1e{e}</text>')
        out.append(f'<text x="{left + width / 2}" y="{height - 12}" '
                   f'text-anchor="middle">unknowns n</text>')
        out.append(f'<text x="{left + width / 2}" y="{pad - 14}" '
                   f'text-anchor="middle">{label}</text>')
        for dim in (2, 3):
            series = sorted((math.log10(p[0]), math.log10(p[1]))
                            for p in points if p[2] == dim)
            if not series:
                continue
            out.append('<polyline fill="none" stroke="%s" points="%s"/>' % (
                colours[dim], " ".join(f"{X(a)},{Y(b)}" for a, b in series)))
            for a, b in series:
                out.append(f'<circle cx="{X(a)}" cy="{Y(b)}" r="3" '
                           f'fill="{colours[dim]}"/>')
            a, b = series[-1]
            out.append(f'<text x="{X(a) - 8}" y="{Y(b) - 8}" text-anchor="end" '
                       f'fill="{colours[dim]}">{dim}D</text>')
    out.append("</svg>")
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--quick", action="store_true",
                        help="small walls only (a check of the script; "
                        "written to /tmp/masonry_3d_quick unless --output)")
    parser.add_argument("--output", default=None,
                        help="folder for scale.{csv,md,svg} (default: "
                        "benchmarks/results/masonry_3d, the committed "
                        "results; with --quick /tmp/masonry_3d_quick)")
    args = parser.parse_args()
    executable = os.path.join(args.build, "unilateral")
    # 3D: m = 5, 10, ... until a run takes more than a minute (at most
    # m = 100, about 1.5 million unknowns).
    series = {2: [25, 50, 100, 150], 3: list(range(5, 101, 5))}
    if args.quick:
        series = {2: [10, 20], 3: [4, 6]}
    rows = []
    for dim in (2, 3):
        for m in series[dim]:
            row = run(executable, dim, m)
            rows.append(row)
            print(f"{dim}D m = {m}: n = {row['n']}, {row['status']}, "
                  f"solve {row['solve']} s, wall {row['wall_s']} s, "
                  f"{row['peak_mb']} MB", flush=True)
            if dim == 3 and row["wall_s"] > 60:
                break
    results = args.output or (
        os.path.join(tempfile.gettempdir(), "masonry_3d_quick") if args.quick
        else os.path.join(ROOT, "benchmarks", "results", "masonry_3d"))
    os.makedirs(results, exist_ok=True)
    fields = ["dim", "m", "blocks", "n", "n_c", "status", "iterations",
              "factorisations"] + \
        PHASES + ["wall_s", "peak_mb"]
    with open(os.path.join(results, "scale.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=fields)
        writer.writeheader()
        writer.writerows(rows)
    lines = ["| dim | m | blocks | n | n_c | status | PDAS iter | "
             "factorisations | " +
             " | ".join(PHASES) + " | wall s | peak MB |",
             "|" + "---|" * (len(fields))]
    for r in rows:
        lines.append("| " + " | ".join(str(r[k]) for k in fields) + " |")
    lines.append("")
    for dim in (2, 3):
        part = [r for r in rows if r["dim"] == dim and r["status"] == "converged"]
        lines.append(f"{dim}D: solve ~ n^{slope(part, 'solve'):.2f}, "
                     f"peak memory ~ n^{slope(part, 'peak_mb'):.2f} "
                     f"(least squares over the converged runs)")
    load = os.getloadavg()[0]
    lines.append(f"load average at the end: {load:.2f}")
    text = "\n".join(lines) + "\n"
    print(text)
    with open(os.path.join(results, "scale.md"), "w") as f:
        f.write(text)
    svg(rows, os.path.join(results, "scale.svg"))
    print(f"wrote scale.csv, scale.md and scale.svg to {results}")


if __name__ == "__main__":
    main()
