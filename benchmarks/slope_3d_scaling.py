#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""The 3D slope on a sphere refined: time per phase, peak memory against the
estimate made before meshing, and the memory model fitted to the runs.

    /usr/bin/python3 benchmarks/slope_3d_scaling.py [--exe build/fdem-slope]
        [--sizes 2,1.75,1.5,1.25] [--budget SECONDS] [--output-dir DIR]

prm/slope_3d.prm (P1 tetrahedra, the dense mixed system) with
Geometry/Slope 3D/Mesh size set to each of --sizes, in order, until one run
takes longer than --budget (default 900 s). For each size the estimate
(geometry/mesh_estimate.cc) is read first from the refusal of a run with
Geometry/Memory limit = 1e-6 MiB, then the case runs with the limit off.
Fits peak MiB = a + b dofs + c (3 pairs)^2 to the runs (least squares) and
writes the section "3D: a slope on a sphere" of DIR/scaling.md (default
doc/) between its markers, and DIR/benchmarks/slope_3d_scaling.csv.
"""
import argparse
import csv
import datetime
import math
import os
import platform
import re
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402

MEMORY_GIB = 24.0
PRM = "slope_3d.prm"
SIZE = "Geometry/Slope 3D/Mesh size"
LIMIT = "Geometry/Memory limit"
ESTIMATE = re.compile(r"about (\S+) elements, (\S+) nodes and (\S+) node pairs, "
                      r"which would need about (\S+) MiB")


def estimate(exe, h):
    """The estimate the program makes before meshing at Mesh size @p h."""
    run = common.run_case(exe, PRM, {SIZE: h, LIMIT: 1e-6}, timeout=120)
    match = ESTIMATE.search(run.stderr + run.stdout)
    if run.ok or not match:
        raise RuntimeError(f"Mesh size {h}: no refusal with the estimate: {run.failure()}")
    cells, nodes, pairs, mib = (float(x) for x in match.groups())
    return {"estimated pairs": pairs, "estimate (MiB)": mib}


def timing(summary, *names):
    return sum(summary["timings"].get(name, 0.0) for name in names)


def row_of(h, run, guess):
    s = run.summary
    steps = s.get("iterations", [])
    return {
        "Mesh size (m)": h,
        "dofs": s["n_dofs"],
        "pairs": common.n_pairs(s),
        "estimated pairs": guess["estimated pairs"],
        "steps": len(steps),
        "contact iterations": sum(step.get("n_contact_iterations", 0) for step in steps),
        "slope solves": sum(step.get("n_slope_solves", 0) for step in steps),
        "mesh and setup (s)": timing(s, "geometry", "setup", "interfaces"),
        "assembly and factorisation (s)": timing(s, "assembly", "factorisation", "one solve"),
        "flexibility (s)": timing(s, "flexibility"),
        "contact (s)": timing(s, "contact"),
        "total (s)": timing(s, "total"),
        "peak (MiB)": s["peak_memory_MiB"],
        "estimate (MiB)": guess["estimate (MiB)"],
        "K": s.get("safety_factor"),
        "BLAS threads": s.get("n_blas_threads"),
    }


COLUMNS = ["Mesh size (m)", "dofs", "pairs", "estimated pairs", "steps", "contact iterations",
           "slope solves",
           "mesh and setup (s)", "assembly and factorisation (s)", "flexibility (s)",
           "contact (s)", "total (s)", "peak (MiB)", "estimate (MiB)", "K"]


def fmt(x):
    return common.number(x, 4)


def fit(rows):
    """Least-squares a (MiB), b (bytes per dof), c (bytes per (3 pairs)^2)
    of peak = a + b dofs + c (3 pairs)^2; None with fewer than 3 rows."""
    if len(rows) < 3:
        return None
    A = np.array([[1.0, r["dofs"], (3.0 * r["pairs"]) ** 2] for r in rows])
    y = np.array([r["peak (MiB)"] * 2.0 ** 20 for r in rows])
    (a, b, c), *_ = np.linalg.lstsq(A, y, rcond=None)
    return a / 2.0 ** 20, b, c


def largest_pairs(rows, model):
    """Pairs at which the fitted model reaches MEMORY_GIB, the dofs growing
    with the pairs as in the last two runs (a power law)."""
    a, b, c = model
    r0, r1 = rows[-2], rows[-1]
    k = math.log(r1["dofs"] / r0["dofs"]) / math.log(r1["pairs"] / r0["pairs"])
    limit = MEMORY_GIB * 2.0 ** 30
    lo, hi = float(r1["pairs"]), 1e7
    for _ in range(200):
        p = math.sqrt(lo * hi)
        dofs = r1["dofs"] * (p / r1["pairs"]) ** k
        if a * 2.0 ** 20 + b * dofs + c * (3 * p) ** 2 > limit:
            hi = p
        else:
            lo = p
    return lo, r1["dofs"] * (lo / r1["pairs"]) ** k, k


def section(rows, stop, model, load, command):
    known = [r.get("BLAS threads") for r in rows if r.get("BLAS threads") is not None]
    threads = f" ({known[0]} BLAS threads)" if known else ""
    lines = ["<!-- slope3d: written by benchmarks/slope_3d_scaling.py -->",
             "## 3D: a slope on a sphere", "",
             f"Written by `{command}` on {datetime.date.today()} "
             f"({common.git_description()}), {platform.node()}, {os.cpu_count()} cores"
             f"{threads}, load average {' '.join(load)} at the start.", "",
             "prm/slope_3d.prm (the paper's section extruded 40 m, a sphere, P1 tetrahedra, the "
             "dense mixed system) with its Mesh size refined. The pairs lie on a cap of the "
             "sphere: they grow as h^-2, the dofs a little faster; the dense parts (3 pairs "
             "unknowns) soon outweigh the FE part. *estimated pairs* and *estimate* are the "
             "program's own, made before meshing (geometry/mesh_estimate.cc); *steps* are the "
             "safety-factor steps to K (the stiffness check then runs the iteration twice more, "
             "not counted here, but in the times), *contact iterations* their status "
             "iterations, *slope solves* the two solves of the mixed system by which each step "
             "with every pair slipping computes the slope of K* (doc/theory.md).", "",
             *common.markdown_table(COLUMNS, [[fmt(r[c]) for c in COLUMNS] for r in rows],
                                    "r" * len(COLUMNS)),
             "", f"The series stopped: {stop}.", ""]
    if model:
        a, b, c = model
        p, dofs, k = largest_pairs(rows, model)
        lines += [
            f"- Peak memory fitted to these runs: {fmt(a)} MiB + {fmt(b)} bytes per dof + "
            f"{fmt(c)} bytes per (3 pairs)^2 entry ({fmt(c / 8)} dense n x n matrices of "
            "doubles, n = 3 pairs, alive at the peak).",
            f"- By that model {MEMORY_GIB:.0f} GiB hold about {fmt(round(p))} pairs (with "
            f"{fmt(round(dofs))} dofs, the dofs growing as pairs^{k:.2f}); the dense n x n "
            "matrices take "
            f"{fmt(100 * c * (3 * p) ** 2 / (MEMORY_GIB * 2.0 ** 30))} % of it. 10^4 pairs "
            f"would need {fmt((a * 2.0 ** 20 + b * dofs * (1e4 / p) ** k + c * 9e8) / 2.0 ** 30)} "
            "GiB.",
        ]
    return lines + ["<!-- /slope3d -->", ""]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--exe", default=common.DEFAULT_EXE)
    parser.add_argument("--sizes", default="2,1.75,1.5,1.25")
    parser.add_argument("--budget", type=float, default=900.0)
    parser.add_argument("--output-dir", default=None)
    parser.add_argument("--estimates-only", action="store_true",
                        help="keep the runs of DIR/benchmarks/slope_3d_scaling.csv and "
                        "only ask the program for its estimates again (after a change of "
                        "the memory model)")
    args = parser.parse_args()
    args.exe = os.path.abspath(args.exe)
    doc_dir = args.output_dir or os.path.join(common.ROOT, "doc")
    os.makedirs(os.path.join(doc_dir, "benchmarks"), exist_ok=True)
    load = open("/proc/loadavg").read().split()[:3]
    command = "/usr/bin/python3 benchmarks/slope_3d_scaling.py --sizes " + args.sizes

    rows, stop = [], "all sizes ran"
    csv_path = os.path.join(doc_dir, "benchmarks", "slope_3d_scaling.csv")
    if args.estimates_only:
        rows = common.read_typed_csv(csv_path)
        for r in rows:
            r.update(estimate(args.exe, r["Mesh size (m)"]))
        command += " (estimates: --estimates-only)"
    for h in [] if args.estimates_only else [float(x) for x in args.sizes.split(",")]:
        guess = estimate(args.exe, h)
        run = common.run_case(args.exe, PRM, {SIZE: h, LIMIT: 1e9},
                              timeout=max(3 * args.budget, 60))
        if not run.ok:
            stop = f"Mesh size {h}: {run.failure()}"
            break
        rows.append(row_of(h, run, guess))
        r = rows[-1]
        print(f"  Mesh size {h}: {r['dofs']} dofs, {r['pairs']} pairs "
              f"(estimate {r['estimated pairs']:.0f}), {r['total (s)']:.1f} s, "
              f"{r['peak (MiB)']:.0f} MiB (estimate {r['estimate (MiB)']:.0f})", flush=True)
        if r["total (s)"] > args.budget:
            stop = f"Mesh size {h} took {r['total (s)']:.0f} s, more than the budget of " \
                   f"{args.budget:.0f} s"
            break

    with open(csv_path, "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(COLUMNS)
        for r in rows:
            writer.writerow([r[c] for c in COLUMNS])
    common.put_benchmarks_section(os.path.join(doc_dir, "scaling.md"),
                                  section(rows, stop, fit(rows), load, command), "slope3d")
    print(f"wrote the section 3D: a slope on a sphere of {os.path.join(doc_dir, 'scaling.md')}")
    return 0 if rows else 1


if __name__ == "__main__":
    sys.exit(main())
