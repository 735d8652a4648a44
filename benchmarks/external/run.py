#!/usr/bin/python3
"""Established LCP/QP solvers and unilateral's, side by side on the same LCPs.

Installs what is missing (Debian packages), builds unilateral and the drivers,
exports the LCPs of our scenes (masonry, plate; plus synthetic obstacle
problems), solves each with our methods and with PETSc (TAO, SNES VI), Siconos
numerics and Ipopt, and prints one table per problem: time (solve phase and
total), relative KKT residual (unilateral's kkt_residuals() for everyone) and
the ratio of the solve time to our best. Results go to
benchmarks/results/external/ (--output DIR elsewhere): results.csv,
results.md, results.png (solve seconds per solver and problem), per-run JSON.

The external solvers' drivers need Debian's libpetsc-real-dev,
libsiconos-numerics-dev and coinor-libipopt-dev, which install.sh (run
first, unless --skip-install) installs with apt-get; without them the
drivers cannot be built and the script says so and stops (--no-external
runs our solvers alone).

Usage (from anywhere; paths are relative to the repository):
  benchmarks/external/run.py                 the full benchmark
  benchmarks/external/run.py --quick         small sizes only (minutes)
  benchmarks/external/run.py --only lap      problems whose name contains 'lap'
Options: --timeout SECONDS (per external run, default 600), --skip-install,
--skip-build, --repeats N (timed runs per solver below 5 s; the fastest
counts; default 3), --no-external, --output DIR.
"""
import argparse
import csv
import json
import os
import shutil
import signal
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
BUILD = os.path.join(ROOT, "build")
BUILD_EXTERNAL = os.path.join(ROOT, "build-external")
RESULTS = os.path.join(ROOT, "benchmarks", "results", "external")
UNILATERAL = os.path.join(BUILD, "unilateral")

# Our methods (all exact at the end: ~1e-14 relative KKT).
OURS = ["pdas", "pdpc", "interior_point", "block_pivoting"]
# Not in the default list: the interior point in its predictor-corrector
# variant (`--ours interior_point_pc`), the walls' fastest route on the
# running bond. A name here is a method with settings of its subsection.
OUR_VARIANTS = {
    "interior_point_pc": ("interior_point",
                          "  subsection Interior point\n"
                          "    set Variant = predictor-corrector\n"
                          "  end\n"),
}

# (label, driver, method, options). Drivers document their settings.
# Not in the default list: SNES VINEWTONSSLS (petsc_driver snes_vinewtonssls)
# stops on a wrong point or a failed line search on all our problems (see
# README), and Siconos' PGS/pivot_lumod variants, which add nothing.
THEIRS = [
    ("PETSc TAO BQPIP", "petsc_driver", "tao_bqpip", []),
    ("PETSc TAO GPCG", "petsc_driver", "tao_gpcg", []),
    ("PETSc TAO TRON", "petsc_driver", "tao_tron", []),
    ("PETSc SNES VI RSLS", "petsc_driver", "snes_vinewtonrsls", []),
    ("Siconos Lemke", "siconos_driver", "lemke", []),
    ("Siconos pivot", "siconos_driver", "pivot", []),
    ("Siconos Newton-min", "siconos_driver", "newton_min", []),
    ("Siconos Newton-FB", "siconos_driver", "newton_fb", []),
    ("Ipopt", "ipopt_driver", "qp", []),
]

# Runs whose solve phase is shorter than this are repeated (--repeats) and
# the fastest counts: the machine is shared, timings of short runs are noisy.
REPEAT_BELOW = 5.0

# Dense Siconos runs are refused by the driver above this size of M.
SICONOS_MAX_DENSE = 3000


def masonry(geometry, m):
    return ("masonry_%s_m%d" % (geometry.split()[0], m), "scene", """\
set Scene = masonry
subsection Masonry
  set Geometry = %s
  set Blocks per side = %d
end
""" % (geometry, m))


def plate(psi, elements):
    return ("plate_%s_%dx%d" % (psi, elements, elements), "scene", """\
set Scene = plate
subsection Plate
  subsection Geometry
    set Elements x = %d
    set Elements y = %d
  end
  subsection Obstacle
    set Function = %s
  end
end
""" % (elements, elements, psi))


def generated(kind, m):
    return ("%s_m%d" % ("laplacian" if kind == "laplacian" else "mixed", m),
            "generate", (kind, m))


def problem_list(quick, walls=""):
    if walls:  # the three walls at the given m alone (issue 24's m >= 100)
        return [masonry(geometry, int(m)) for m in walls.split(",")
                for geometry in ("stack bond", "running bond", "laminae")]
    if quick:
        return ([generated("laplacian", 30), generated("mixed", 15)] +
                [masonry(g, 5) for g in ("stack bond", "running bond",
                                         "laminae")] +
                [plate(p, 10) for p in ("psi1", "psi2", "psi3")])
    problems = [generated("laplacian", m) for m in (50, 100, 200)]
    problems += [generated("mixed", m) for m in (20, 40)]
    for geometry in ("stack bond", "running bond", "laminae"):
        problems += [masonry(geometry, m) for m in (10, 20, 40)]
    for psi in ("psi1", "psi2", "psi3"):
        problems += [plate(psi, e) for e in (10, 20, 40)]
    return problems


def log(message):
    print(message, flush=True)


def run_command(command, timeout=None, cwd=None):
    """Run in its own process group; kill the whole group on timeout.
    Returns (exit code or None on timeout, seconds, stdout, stderr)."""
    start = time.monotonic()
    process = subprocess.Popen(command, cwd=cwd, stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, text=True,
                               start_new_session=True)
    try:
        out, err = process.communicate(timeout=timeout)
        return process.returncode, time.monotonic() - start, out, err
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)
        out, err = process.communicate()
        return None, time.monotonic() - start, out, err


DRIVER_PACKAGES = ("libpetsc-real-dev libsiconos-numerics-dev "
                   "coinor-libipopt-dev")


def install_and_build(skip_install, skip_build, no_external):
    if not skip_install:
        # The top-level install.sh with the drivers' packages added.
        script = os.path.join(HERE, "install.sh")
        log("== " + os.path.relpath(script, ROOT))
        if subprocess.run(["sh", script]).returncode != 0:
            sys.exit("run.py: %s failed: the drivers need the Debian "
                     "packages %s (apt-get, as root or with sudo); install "
                     "them, or run with --skip-install --no-external for "
                     "our solvers alone" % (os.path.relpath(script, ROOT),
                                            DRIVER_PACKAGES))
    if not skip_build:
        log("== building unilateral (build/) and the drivers "
            "(build-external/)")
        subprocess.run(["cmake", "-S", ROOT, "-B", BUILD,
                        "-DCMAKE_BUILD_TYPE=Release"], check=True,
                       stdout=subprocess.DEVNULL)
        subprocess.run(["cmake", "--build", BUILD, "-j2", "--target",
                        "unilateral"], check=True, stdout=subprocess.DEVNULL)
        if no_external:
            return
        for command in (["cmake", "-S", HERE, "-B", BUILD_EXTERNAL,
                         "-DCMAKE_BUILD_TYPE=Release"],
                        ["cmake", "--build", BUILD_EXTERNAL, "-j2"]):
            if subprocess.run(command, stdout=subprocess.DEVNULL).returncode:
                sys.exit("run.py: building the drivers (build-external/) "
                         "failed: are %s installed? "
                         "benchmarks/external/install.sh installs them; "
                         "--no-external runs our solvers alone"
                         % DRIVER_PACKAGES)


def check_drivers(theirs):
    """Stop with one clear line if a driver that will run is not built."""
    drivers = sorted(set(
        driver for label, driver, _, _ in THEIRS
        if not theirs or any(part in label for part in theirs.split(","))))
    missing = [d for d in drivers
               if not os.access(os.path.join(BUILD_EXTERNAL, d), os.X_OK)]
    if missing:
        sys.exit("run.py: external solvers not available: %s missing in %s. "
                 "They need the Debian packages %s, which "
                 "benchmarks/external/install.sh installs (run.sh without "
                 "--skip-install), and a build (run.sh without --skip-build);"
                 " or run with --no-external for our solvers alone"
                 % (", ".join(missing), os.path.relpath(BUILD_EXTERNAL, ROOT),
                    DRIVER_PACKAGES))


def available_scenes():
    """The scenes this build has: the Scene parameter's pattern lists them
    (masonry and plate land on main while this benchmark is written)."""
    code, _, out, _ = run_command([UNILATERAL, "--print-parameters", "json"])
    try:
        pattern = json.loads(out)["Scene"]["pattern_description"]
    except (ValueError, KeyError):
        pattern = out
    return {name for name in ("masonry", "plate", "lcp")
            if name in pattern.replace("|", " ").replace("]", " ").split()}


def output_block(run_name, directory):
    return """\
subsection Output
  set Directory = %s
  set Run name = %s
  set Write VTU = false
  set Print timings = false
  set Progress = false
%send
""" % (directory, run_name, "%s")


def export_problem(name, kind, spec, scenes):
    """Make the three LCP files of a problem; returns their directory or
    (None, reason)."""
    directory = os.path.join(RESULTS, "problems", name)
    if os.path.exists(os.path.join(directory, "lcp_A.mtx")):
        return directory, None
    os.makedirs(directory, exist_ok=True)
    if kind == "generate":
        subprocess.run([sys.executable, os.path.join(HERE, "generate_lcp.py"),
                        spec[0], str(spec[1]), directory], check=True)
        return directory, None
    scene = "masonry" if "Scene = masonry" in spec else "plate"
    if scene not in scenes:
        shutil.rmtree(directory)
        return None, "scene '%s' is not in this build of unilateral" % scene
    prm = os.path.join(directory, "export.prm")
    with open(prm, "w") as f:
        f.write(spec)
        f.write(output_block("export", os.path.dirname(directory)) %
                "  set Export LCP = true\n")
        f.write("subsection Solver\n  set Method = pdas\nend\n")
    code, seconds, out, err = run_command([UNILATERAL, prm], timeout=3600)
    exported = os.path.join(os.path.dirname(directory), "export")
    if code not in (0, 2) or not os.path.exists(
            os.path.join(exported, "lcp_A.mtx")):
        shutil.rmtree(directory, ignore_errors=True)
        return None, "export failed: " + (err or out).strip().splitlines()[-1]
    for file in ("lcp_A.mtx", "lcp_b.txt", "lcp_constraints.txt"):
        shutil.move(os.path.join(exported, file), os.path.join(directory, file))
    shutil.rmtree(exported, ignore_errors=True)
    return directory, None


def problem_size(directory):
    with open(os.path.join(directory, "lcp_A.mtx")) as f:
        for line in f:
            if not line.startswith("%"):
                n = int(line.split()[0])
                break
    with open(os.path.join(directory, "lcp_constraints.txt")) as f:
        n_c = sum(1 for line in f if line.strip() and line[0] not in "%#")
    return n, n_c


def run_ours(method, directory, runs, repeats):
    prm = os.path.join(runs, "ours_%s.prm" % method)
    with open(prm, "w") as f:
        f.write("set Scene = lcp\n")
        f.write(output_block("ours_" + method, runs) % "")
        f.write("subsection LCP\n"
                "  set Matrix file = %s/lcp_A.mtx\n"
                "  set Right-hand side file = %s/lcp_b.txt\n"
                "  set Constraints file = %s/lcp_constraints.txt\n"
                "end\n" % (directory, directory, directory))
        name, settings = OUR_VARIANTS.get(method, (method, ""))
        f.write("subsection Solver\n  set Method = %s\n%send\n"
                % (name, settings))
    best = None
    for attempt in range(repeats):
        code, seconds, out, err = run_command([UNILATERAL, prm], timeout=3600)
        summary_file = os.path.join(runs, "ours_" + method, "summary.json")
        if code not in (0, 2) or not os.path.exists(summary_file):
            return {"solver": "unilateral " + method, "status": "error",
                    "message": (err or out).strip()[-300:]}
        with open(summary_file) as f:
            summary = json.load(f)
        os.remove(summary_file)
        phases = summary["time"].get("solver", {})
        solve = sum(v for k, v in phases.items() if k != "kkt check")
        total = summary["time"].get("assemble system", 0) + summary["time"]["solve"]
        result = {"solver": "unilateral " + method,
                  "status": summary["status"],
                  "converged": summary["converged"],
                  "iterations": summary["iterations"],
                  "solve": solve, "total": total,
                  "kkt": summary["kkt"]["max"],
                  "message": summary.get("message", "")}
        if best is None or result["solve"] < best["solve"]:
            best = result
        if solve > REPEAT_BELOW:
            break
    return best


def run_theirs(label, driver, method, options, directory, runs, timeout,
               repeats):
    best = None
    out_dir = os.path.join(runs, "%s_%s" % (driver.split("_")[0], method))
    for attempt in range(repeats):
        command = [os.path.join(BUILD_EXTERNAL, driver), method, directory,
                   out_dir] + options
        if driver == "siconos_driver":
            command.append("max_dense=%d" % SICONOS_MAX_DENSE)
        code, seconds, out, err = run_command(command, timeout=timeout)
        if code is None:
            return {"solver": label, "status": "timeout",
                    "message": "killed after %d s" % timeout,
                    "solve": None, "total": None, "kkt": None}
        result_file = os.path.join(out_dir, "result.json")
        if code == 1 or not os.path.exists(result_file):
            tail = (err or out).strip().splitlines()
            return {"solver": label, "status": "crashed (exit %s)" % code,
                    "message": tail[-1] if tail else ""}
        with open(result_file) as f:
            data = json.load(f)
        os.remove(result_file)
        result = {"solver": label, "status": data["status"],
                  "converged": data["converged"],
                  "iterations": data["iterations"],
                  "solve": data["time"]["solve"],
                  "total": data["time"]["total"],
                  "kkt": data["kkt"]["max"],
                  "message": data["message"], "options": data["options"]}
        if best is None or (result["solve"] or 0) < (best["solve"] or 0):
            best = result
        if not data["converged"] or (result["solve"] or 0) > REPEAT_BELOW:
            break
    return best


def fmt_time(seconds):
    if seconds is None:
        return "-"
    return "%.3g" % seconds


def fmt_kkt(value):
    return "-" if value is None else "%.1e" % value


def table(name, n, n_c, results):
    ours = [r for r in results if r["solver"].startswith("unilateral")
            and r.get("converged") and r.get("kkt") is not None
            and r["kkt"] <= 1e-10]
    best = min((r["solve"] for r in ours), default=None)
    lines = ["### %s  (n = %d, n_c = %d)" % (name, n, n_c), "",
             "| solver | status | iterations | solve [s] | total [s] | "
             "KKT | solve / our best |",
             "|---|---|---:|---:|---:|---:|---:|"]
    for r in results:
        ratio = "-"
        ran = r.get("status") not in ("too large", "not applicable",
                                      "timeout", "error")
        if ran and best and r.get("solve") and best > 0:
            ratio = "%.2f" % (r["solve"] / best)
        lines.append("| %s | %s | %s | %s | %s | %s | %s |" % (
            r["solver"], r["status"], r.get("iterations", "-"),
            fmt_time(r.get("solve")), fmt_time(r.get("total")),
            fmt_kkt(r.get("kkt")), ratio))
        r["ratio"] = ratio
    return "\n".join(lines) + "\n"


def main():
    global RESULTS
    parser = argparse.ArgumentParser(
        description=__doc__.split("\n\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--only", default="",
                        help="comma-separated substrings of problem names")
    parser.add_argument("--timeout", type=float, default=600)
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--skip-install", action="store_true")
    parser.add_argument("--skip-build", action="store_true")
    parser.add_argument("--no-external", action="store_true",
                        help="run only our solvers")
    parser.add_argument("--walls", default="",
                        help="e.g. 100,225: only the three masonry walls "
                             "at these m (instead of the default list)")
    parser.add_argument("--ours", default=",".join(OURS),
                        help="our methods to run (comma-separated)")
    parser.add_argument("--kkt-target", type=float, default=None,
                        help="stop BQPIP as soon as its iterate's relative "
                        "KKT residual is at most this (the driver's "
                        "default: 1e-12); the walls' target is 1e-10")
    parser.add_argument("--theirs", default="",
                        help="comma-separated substrings of the external "
                             "solvers' labels to run (default: all)")
    parser.add_argument("--output", default=RESULTS,
                        help="folder for the results, problems and runs "
                             "(default benchmarks/results/external)")
    args = parser.parse_args()
    RESULTS = os.path.abspath(args.output)

    # A run of the large walls alone keeps the full list's results.
    base = "walls" if args.walls else "results"
    install_and_build(args.skip_install, args.skip_build, args.no_external)
    if not args.no_external:
        check_drivers(args.theirs)
    scenes = available_scenes()
    os.makedirs(RESULTS, exist_ok=True)
    markdown = ["# unilateral vs established solvers", "",
                "Generated by benchmarks/external/run.py on %s. Times in "
                "seconds (solve phase only; total includes reading the "
                "files and building the package's data). KKT: unilateral's "
                "relative KKT residual (max of stationarity, feasibility, "
                "min-map complementarity) of the returned u. Ratio: solve "
                "time / fastest of our converged methods." %
                time.strftime("%Y-%m-%d %H:%M"), ""]
    rows = []
    plotted = []   # (problem, results) for the plot
    for name, kind, spec in problem_list(args.quick, args.walls):
        if args.only and not any(part in name for part in args.only.split(",")):
            continue
        directory, why = export_problem(name, kind, spec, scenes)
        if directory is None:
            log("\n## %s: skipped, %s" % (name, why))
            markdown.append("### %s\n\nnot run: %s\n" % (name, why))
            continue
        n, n_c = problem_size(directory)
        log("\n## %s: n = %d, n_c = %d" % (name, n, n_c))
        runs = os.path.join(RESULTS, "runs", name)
        os.makedirs(runs, exist_ok=True)
        results = []
        for method in args.ours.split(","):
            result = run_ours(method, directory, runs, args.repeats)
            log("  %-28s %-24s solve %-9s KKT %s" % (
                result["solver"], result["status"],
                fmt_time(result.get("solve")), fmt_kkt(result.get("kkt"))))
            results.append(result)
        if not args.no_external:
            for label, driver, method, options in THEIRS:
                if args.theirs and not any(
                        part in label for part in args.theirs.split(",")):
                    continue
                if args.kkt_target is not None and method == "tao_bqpip":
                    options = options + ["kkt_target=%g" % args.kkt_target]
                result = run_theirs(label, driver, method, options, directory,
                                    runs, args.timeout, args.repeats)
                log("  %-28s %-24s solve %-9s KKT %s" % (
                    label, result["status"][:24],
                    fmt_time(result.get("solve")),
                    fmt_kkt(result.get("kkt"))))
                results.append(result)
        plotted.append((name, results))
        text = table(name, n, n_c, results)
        log("")
        log(text)
        markdown.append(text)
        for r in results:
            rows.append({"problem": name, "n": n, "n_constraints": n_c,
                         "solver": r["solver"], "status": r["status"],
                         "iterations": r.get("iterations", ""),
                         "solve_seconds": r.get("solve", ""),
                         "total_seconds": r.get("total", ""),
                         "kkt": r.get("kkt", ""),
                         "ratio_to_our_best": r.get("ratio", ""),
                         "message": r.get("message", "")})
        # Write as we go: a long run that is stopped keeps what it did.
        with open(os.path.join(RESULTS, base + ".csv"), "w",
                  newline="") as f:
            writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
            writer.writeheader()
            writer.writerows(rows)
        with open(os.path.join(RESULTS, base + ".md"), "w") as f:
            f.write("\n".join(markdown) + "\n")
    plot(plotted, os.path.join(RESULTS, base + ".png"))
    log("results: %s/%s.{csv,md,png}" % (os.path.relpath(RESULTS, os.getcwd()),
                                          base))


def plot(plotted, path):
    """Solve seconds of every solver on every problem, log scale; filled:
    KKT <= 1e-10 and converged, open: any other answer."""
    if not plotted:
        return
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        log("matplotlib missing: no plot")
        return
    solvers = list(dict.fromkeys(r["solver"] for _, results in plotted
                                 for r in results))
    figure, axis = plt.subplots(figsize=(max(6, 1.2 * len(plotted) + 3), 5))
    markers = "osD^v<>ph*"
    for index, solver in enumerate(solvers):
        for good in (True, False):
            points = []
            for column, (_, results) in enumerate(plotted):
                for r in results:
                    if r["solver"] != solver or not r.get("solve"):
                        continue
                    ok = (r.get("converged", True) and r.get("kkt") is not None
                          and r["kkt"] <= 1e-10)
                    if ok == good:
                        points.append((column, r["solve"]))
            if points:
                axis.semilogy([p[0] for p in points], [p[1] for p in points],
                              markers[index % len(markers)],
                              color="C%d" % (index % 10),
                              fillstyle="full" if good else "none",
                              linestyle="none",
                              label=solver if good else None)
    axis.set_xticks(range(len(plotted)))
    axis.set_xticklabels([name for name, _ in plotted], rotation=30,
                         ha="right", fontsize=8)
    axis.set_ylabel("solve seconds")
    axis.set_title("solve time per solver (open: KKT > 1e-10 or not "
                   "converged)", fontsize=10)
    axis.legend(fontsize=7, loc="center left", bbox_to_anchor=(1, 0.5))
    figure.tight_layout()
    figure.savefig(path, dpi=100)
    plt.close(figure)


if __name__ == "__main__":
    main()
