#!/usr/bin/env python3
"""Two builds side by side: the same runs with an old and a new executable,
interleaved (old, new, old, new, ...) so that the machine's drift in speed
(up to 1.7x over a day) falls on both alike. Prints a table of wall time,
peak memory and iterations, and saves it as CSV and Markdown (m<M>.csv,
m<M>.md) and plots the wall time of each run per geometry and build
(m<M>.png).

  /usr/bin/python3 benchmarks/compare_builds/compare.py \\
      --old OLD/unilateral --new build/unilateral [--m 225] [--repeat 2]

Each run is a masonry wall (stack bond, running bond, laminae) with the
default method and no VTU output; peak memory from /usr/bin/time -v.
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


def run(executable, geometry, m, directory):
    name = geometry.replace(" ", "_")
    prm = os.path.join(directory, name + ".prm")
    with open(prm, "w") as f:
        f.write("set Scene = masonry\nsubsection Masonry\n"
                f"  set Geometry = {geometry}\n  set Blocks per side = {m}\n"
                "end\nsubsection Output\n  set Write VTU = false\n"
                "  set Progress = false\n  set Print timings = false\n"
                f"  set Directory = {directory}\nend\n")
    start = time.time()
    process = subprocess.run(["/usr/bin/time", "-v", executable, prm],
                             capture_output=True, text=True)
    wall = time.time() - start
    peak_kb = 0
    for line in process.stderr.splitlines():
        if "Maximum resident set size" in line:
            peak_kb = int(line.split(":")[1])
    with open(os.path.join(directory, name, "summary.json")) as f:
        summary = json.load(f)
    return {"wall": wall, "peak_gb": peak_kb / 1e6,
            "status": summary["status"], "energy": summary["energy"],
            "iterations": f"{summary['iterations']}+"
                          f"{summary['projection_iterations']}",
            "solve": summary["time"].get("solve", float("nan"))}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--old", required=True, help="the old executable")
    parser.add_argument("--new", required=True, help="the new executable")
    parser.add_argument("--m", type=int, default=225, help="blocks per side")
    parser.add_argument("--repeat", type=int, default=2,
                        help="runs of each build per geometry")
    parser.add_argument("--geometries",
                        default="stack bond,running bond,laminae",
                        help="comma separated")
    parser.add_argument("--output", default=os.path.join(
        ROOT, "benchmarks", "results", "compare_builds"),
        help="where the CSV and Markdown go")
    arguments = parser.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as directory:
        for geometry in arguments.geometries.split(","):
            for repeat in range(arguments.repeat):
                for build in ("old", "new"):
                    executable = getattr(arguments, build)
                    result = run(executable, geometry, arguments.m, directory)
                    result.update(geometry=geometry, build=build,
                                  repeat=repeat + 1)
                    rows.append(result)
                    print(f"{geometry:13s} {build} #{repeat + 1}: "
                          f"{result['wall']:6.1f} s, solve "
                          f"{result['solve']:6.1f} s, "
                          f"{result['peak_gb']:.2f} GB, "
                          f"{result['iterations']}, {result['status']}, "
                          f"energy {result['energy']:.12e}", flush=True)
    os.makedirs(arguments.output, exist_ok=True)
    fields = ["geometry", "build", "repeat", "wall", "solve", "peak_gb",
              "iterations", "status", "energy"]
    with open(os.path.join(arguments.output, f"m{arguments.m}.csv"), "w",
              newline="") as f:
        writer = csv.DictWriter(f, fieldnames=fields)
        writer.writeheader()
        for row in rows:
            writer.writerow({k: row[k] for k in fields})
    lines = [f"# Old and new build side by side, m = {arguments.m}", "",
             "| geometry | build | run | wall s | solve s | peak GB | "
             "iterations | status | energy |",
             "|---|---|---|---|---|---|---|---|---|"]
    for row in rows:
        lines.append(f"| {row['geometry']} | {row['build']} | "
                     f"{row['repeat']} | {row['wall']:.1f} | "
                     f"{row['solve']:.1f} | {row['peak_gb']:.2f} | "
                     f"{row['iterations']} | {row['status']} | "
                     f"{row['energy']:.12e} |")
    with open(os.path.join(arguments.output, f"m{arguments.m}.md"),
              "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    plot(rows, arguments)


def plot(rows, arguments):
    """m<M>.png: wall and solve seconds of every run, old beside new."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("matplotlib missing: no plot")
        return
    geometries = list(dict.fromkeys(row["geometry"] for row in rows))
    figure, axis = plt.subplots(figsize=(8, 4))
    for offset, build, colour in ((-0.2, "old", "tab:blue"),
                                  (0.2, "new", "tab:orange")):
        for key, marker in (("wall", "o"), ("solve", "x")):
            points = [(geometries.index(row["geometry"]) + offset, row[key])
                      for row in rows if row["build"] == build]
            axis.plot([p[0] for p in points], [p[1] for p in points], marker,
                      color=colour, linestyle="none",
                      label=f"{build} {key}")
    axis.set_xticks(range(len(geometries)))
    axis.set_xticklabels(geometries)
    axis.set_ylabel("seconds")
    axis.set_ylim(bottom=0)
    axis.set_title(f"old and new build, m = {arguments.m}, every run",
                   fontsize=10)
    axis.legend(fontsize=8)
    figure.tight_layout()
    path = os.path.join(arguments.output, f"m{arguments.m}.png")
    figure.savefig(path, dpi=100)
    plt.close(figure)
    print(f"written: {path} (and .csv, .md)")


if __name__ == "__main__":
    main()
