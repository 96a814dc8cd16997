#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""The BLAS's threads: the same cases with OPENBLAS_NUM_THREADS = 1 and 2,
run alternately (each case once per setting per round, the order
alternating between rounds, so that the machine's load falls on both
alike). Times from summary.json: the contact phase (the dense mixed
system's LU in every status iteration), assembly and factorisation
(MUMPS), and the whole run; K of both (they differ by round-off only).

    /usr/bin/python3 benchmarks/blas_threads.py [build/fdem-slope] [--rounds 2]
        [--quick] [--output doc/benchmarks.md]

Writes the section "blas-threads" of the output file.
"""
import argparse
import os
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402

# (label, case, settings): 2D where the dense parts are small, 3D where they
# are most of the run.
CASES = [
    ("paper's slope (2D, h = 0.25 m)", "paper_slope.prm",
     {"Geometry/Slope/Mesh size": 0.25}),
    ("rock wedge, Mesh size 1.5 m", "rock_wedge.prm", {"Geometry/Wedge/Mesh size": 1.5}),
    ("slope on a sphere, Mesh size 1.5 m", "slope_3d.prm", {"Geometry/Slope 3D/Mesh size": 1.5}),
    ("slope on a sphere, Mesh size 1.25 m", "slope_3d.prm",
     {"Geometry/Slope 3D/Mesh size": 1.25}),
]
QUICK_CASES = [CASES[0], ("slope on a sphere, Mesh size 3 m", "slope_3d.prm",
                          {"Geometry/Slope 3D/Mesh size": 3})]


def measure(exe, prm, settings, n_threads):
    environment = dict(os.environ, OPENBLAS_NUM_THREADS=str(n_threads))
    result = common.run_case(exe, prm, settings, env=environment)
    if not result.ok:
        sys.exit(f"blas_threads.py: {prm} {settings}: {result.failure()}")
    s = result.summary
    if s["n_blas_threads"] != n_threads:
        sys.exit(f"blas_threads.py: asked for {n_threads} BLAS threads, the run had "
                 f"{s['n_blas_threads']} (0: not OpenBLAS; bootstrap.sh installs "
                 "libopenblas0-pthread)")
    t = s["timings"]
    return {"dofs": s["n_dofs"], "pairs": common.n_pairs(s), "K": s["safety_factor"],
            "contact": t["contact"], "fe": t["assembly"] + t["factorisation"],
            "total": t["total"]}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("exe", nargs="?", default=common.DEFAULT_EXE)
    parser.add_argument("--rounds", type=int, default=2)
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--output", default=os.path.join(common.ROOT, "doc", "benchmarks.md"))
    args = parser.parse_args()
    exe = os.path.abspath(args.exe)
    load_start = os.getloadavg()[0]
    rows = []
    for label, prm, settings in (QUICK_CASES if args.quick else CASES):
        runs = {1: [], 2: []}
        for r in range(args.rounds):
            for n in ((1, 2) if r % 2 == 0 else (2, 1)):
                runs[n].append(measure(exe, prm, settings, n))
        one, two = runs[1], runs[2]

        def median(runs, key):
            return statistics.median(m[key] for m in runs)

        rows.append([
            label, one[0]["dofs"], one[0]["pairs"],
            common.number(median(one, "fe")), common.number(median(two, "fe")),
            common.number(median(one, "contact")), common.number(median(two, "contact")),
            common.number(median(one, "total")), common.number(median(two, "total")),
            f"{median(one, 'contact') / median(two, 'contact'):.2f}",
            f"{median(one, 'total') / median(two, 'total'):.2f}",
            f"{two[0]['K'] / one[0]['K'] - 1:.1e}",
        ])
    load_end = os.getloadavg()[0]
    lines = [
        "<!-- blas-threads: written by benchmarks/blas_threads.py -->",
        "## The BLAS's threads",
        "",
        f"Each case with `OPENBLAS_NUM_THREADS` = 1 and 2 (Debian's threaded OpenBLAS, "
        f"libopenblas0-pthread), {args.rounds} runs each, alternating; medians of the "
        f"phases' wall times in summary.json (s). {common.git_description()}, 2 cores, load "
        f"average {load_start:.1f} at the start and {load_end:.1f} at the end. *FE* is "
        "assembly and factorisation (MUMPS), *contact* the status iterations' dense "
        "solves; the speed-ups are 1 thread's time over 2 threads'; *K difference* is "
        "K(2)/K(1) − 1. Only on free cores: on cores busy with other work two threads are "
        "slower than one (doc/theory.md, \"Threads\"), so a run uses one unless "
        "`OPENBLAS_NUM_THREADS` asks for more.",
        "",
    ]
    lines += common.markdown_table(
        ["case", "dofs", "pairs", "FE, 1 thread", "FE, 2 threads", "contact, 1 thread",
         "contact, 2 threads", "total, 1 thread", "total, 2 threads", "contact speed-up",
         "total speed-up", "K difference"],
        rows, align="lrrrrrrrrrrr")
    lines += ["", "<!-- /blas-threads -->"]
    common.put_benchmarks_section(args.output, lines, "blas-threads")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
