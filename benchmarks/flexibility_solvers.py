#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
# Copyright (C) 2026 the fdem-slope authors
"""Direct solvers and flexibility methods on the paper's slope.

For each mesh size and each value of Solver/Direct solver, runs the whole
safety-factor computation (fdem-slope, no VTU) and the yardstick, one
factorisation and one solve of the plain FE model of the same slope with
the same solver (fdem-fe-solve-time), and writes a markdown table:

  /usr/bin/python3 benchmarks/flexibility_solvers.py --build build \
      --mesh-sizes 1.0 0.6 0.45 --output doc/flexibility_solvers.md

Times are wall seconds of one run each on the machine it runs on.
"""
import argparse
import json
import os
import platform
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tools"))
import fdem_run  # noqa: E402  tools/fdem_run.py: run a case, read its outputs
from fdem_run import ROOT  # noqa: E402
SOLVERS = ["MUMPS_Schur", "MUMPS", "CHOLMOD", "Amesos_Klu", "Amesos_Mumps", "UMFPACK"]
METHOD = {"MUMPS_Schur": "Schur complement"}


def run(command, cwd):
    """The stdout of @p command run in @p cwd, which must succeed."""
    result = subprocess.run(command, cwd=cwd, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit("%s failed:\n%s%s" % (" ".join(command), result.stdout, result.stderr))
    return result.stdout


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--mesh-sizes", type=float, nargs="+", default=[1.0, 0.6, 0.45])
    parser.add_argument("--solvers", nargs="+", default=SOLVERS)
    parser.add_argument("--output", default=os.path.join(ROOT, "doc", "flexibility_solvers.md"))
    parser.add_argument("--from-log", help="write the table from the JSON lines a previous "
                        "run printed, instead of running")
    args = parser.parse_args()
    slope = os.path.join(args.build, "fdem-slope")
    yardstick = os.path.join(args.build, "fdem-fe-solve-time")

    load_before = os.getloadavg()[0]
    rows = []
    if args.from_log:
        with open(args.from_log) as f:
            rows = [json.loads(line) for line in f if line.startswith("{")]
        args.mesh_sizes = []
    for h in args.mesh_sizes:
        for solver in args.solvers:
            # paper_slope.prm with another mesh size and solver; the yardstick
            # reads the very .prm file the run read, in the run's folder.
            settings = {"Geometry/Slope/Mesh size": h, "Solver/Direct solver": solver,
                        "Output/Write VTU": "false"}
            with fdem_run.temporary_run(slope, "paper_slope.prm", settings=settings,
                                        timeout=None) as result:
                if not result.ok:
                    sys.exit("paper_slope.prm with %s failed: %s" % (solver, result.failure()))
                summary, whole = result.summary, result.wall
                fe_out = run([yardstick, result.prm], result.workdir)
            fe = json.loads(fe_out.strip().splitlines()[-1])
            timings = summary["timings"]
            row = {
                "mesh_size": h,
                "dofs": summary["n_dofs"],
                "pairs": sum(i["n_pairs"] for i in summary["interfaces"]),
                "solver": solver,
                "method": METHOD.get(solver, "blocked solves (64 RHS)"),
                # Timed apart since the phase was split; one phase before.
                "assembly_factorisation": timings.get("assembly and factorisation") or
                (timings.get("assembly", 0) + timings.get("factorisation", 0)),
                "flexibility": timings.get("flexibility"),
                "contact": timings.get("contact"),
                # The phases add up to "total" (older summaries have no total).
                "sections": timings.get("total") or sum(timings.values()),
                "whole": whole,
                "fe_dofs": fe["n_dofs"],
                "fe_assembly": fe["assembly"],
                "fe_factorisation": fe["factorization"],
                "fe_solve": fe["solve"],
                "safety_factor": summary.get("safety_factor"),
            }
            row["ratio"] = whole / (fe["factorization"] + fe["solve"])
            row["ratio_sections"] = row["sections"] / (fe["factorization"] + fe["solve"])
            rows.append(row)
            print(json.dumps(row), flush=True)

    lines = [
        "# Direct solvers and the interface flexibility (paper's slope)",
        "",
        "Written by `/usr/bin/python3 benchmarks/flexibility_solvers.py %s` on %s "
        "(%s, %d cores shared with other work%s); one run per row, wall seconds."
        % (" ".join(sys.argv[1:]), time.strftime("%Y-%m-%d"), platform.machine(),
           os.cpu_count(),
           "" if args.from_log else ", load average %.1f before and %.1f after the runs"
           % (load_before, os.getloadavg()[0])),
        "",
        "- *dofs*: all blocks of the mixed model; *pairs*: node pairs on the sliding surface.",
        "- *assembly + factorisation*, *flexibility*: the run's timer sections (summary.json);",
        "  with MUMPS_Schur the Schur complement is formed inside the factorisation and",
        "  *flexibility* is its dense inverse (LAPACK potri) and the mixed system's assembly.",
        "- *contact*: the run's contact solves (the dense mixed system, all status",
        "  iterations of all safety-factor steps).",
        "- *whole run*: wall time of `fdem-slope` on the case (mesh, safety-factor",
        "  iteration, CSV and summary output; no VTU), process start (MPI, libraries)",
        "  included; *timed*: the sum of the run's timer sections, without the start.",
        "- *FE assembly*, *FE factorise*, *FE solve*: `fdem-fe-solve-time`, the assembly,",
        "  one factorisation and one solve of the plain FE model of the same slope (the",
        "  blocks merged, nodes shared, *FE dofs*) with the same solver.",
        "- *ratio* = whole run / (FE factorise + FE solve); *ratio timed* = timed /",
        "  (FE factorise + FE solve).",
        "",
        "| mesh size (m) | dofs | pairs | solver | method | assembly + factorisation (s) "
        "| flexibility (s) | contact (s) | whole run (s) | timed (s) | FE dofs "
        "| FE assembly (s) | FE factorise (s) | FE solve (s) | ratio | ratio timed "
        "| safety factor |",
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|",
    ]
    for r in rows:
        lines.append("| %g | %d | %d | %s | %s | %.2f | %.2f | %.2f | %.2f | %.2f | %d | %.2f "
                     "| %.2f | %.3f | %.2f | %.2f | %.12f |" % (
            r["mesh_size"], r["dofs"], r["pairs"], r["solver"], r["method"],
            r["assembly_factorisation"], r["flexibility"], r["contact"], r["whole"],
            r["sections"], r["fe_dofs"], r["fe_assembly"], r["fe_factorisation"],
            r["fe_solve"], r["ratio"],
            r["ratio_sections"], r["safety_factor"]))
    # A hand-written "## Reading" section of the previous file is kept.
    reading = ""
    if os.path.exists(args.output):
        with open(args.output) as f:
            previous = f.read()
        if "\n## Reading" in previous:
            reading = previous[previous.index("\n## Reading"):]
    with open(args.output, "w") as f:
        f.write("\n".join(lines) + "\n" + reading)
    print("wrote", args.output)


if __name__ == "__main__":
    main()
