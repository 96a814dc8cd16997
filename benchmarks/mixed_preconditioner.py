#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""The preconditioners of the iterative mixed system (Solver/Mixed
preconditioner = pairs or Dirichlet) on prm/block_on_plane_3d.prm with
n x n elements along the plane ((n + 1)^2 pairs, as benchmarks/scaling.py
sets the sizes), run alternately (per level both, the order alternating
between levels and rounds, so that the machine's load falls on both alike).
From summary.json: the contact solves (status iterations of all steps), the
GMRES iterations per solve, the flexibility phase (the preconditioner's
setup), the contact phase and the whole run, peak memory, and K.

    /usr/bin/python3 benchmarks/mixed_preconditioner.py [build/fdem-slope]
        [--levels 6,20,40,64] [--rounds 1]

Prints a Markdown table.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402


def measure(exe, n, preconditioner):
    settings = {"Geometry/Block on plane/Elements along length": n,
                "Geometry/Block on plane/Elements along width": n,
                "Solver/Mixed system": "iterative",
                "Solver/Mixed preconditioner": preconditioner}
    result = common.run_case(exe, "block_on_plane_3d.prm", settings, timeout=3600)
    if not result.ok:
        sys.exit(f"mixed_preconditioner.py: n = {n}, {preconditioner}: {result.failure()}")
    s = result.summary
    solves = sum(step.get("n_contact_iterations", 0) for step in s.get("iterations", []))
    t = s["timings"]
    gmres = s["contact"].get("n_gmres_iterations", 0)
    return {"pairs": common.n_pairs(s), "dofs": s["n_dofs"], "solves": solves,
            "gmres": gmres, "per solve": gmres / solves if solves else float("nan"),
            "flexibility": t.get("flexibility", 0.0), "contact": t.get("contact", 0.0),
            "total": t.get("total", 0.0), "memory": s["peak_memory_MiB"],
            "K": s["safety_factor"]}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("exe", nargs="?", default=common.DEFAULT_EXE)
    parser.add_argument("--levels", default="6,20,40,64")
    parser.add_argument("--rounds", type=int, default=1)
    args = parser.parse_args()
    exe = os.path.abspath(args.exe)
    names = ["pairs", "Dirichlet"]
    rows = []
    for level, n in enumerate(int(x) for x in args.levels.split(",")):
        runs = {name: [] for name in names}
        for r in range(args.rounds):
            order = names if (level + r) % 2 == 0 else names[::-1]
            for name in order:
                runs[name].append(measure(exe, n, name))
                print(f"n = {n}, {name}: {runs[name][-1]}", file=sys.stderr, flush=True)
        rows.append((n, runs))

    print("| n | pairs | dofs | preconditioner | contact solves | GMRES per solve "
          "| flexibility (s) | contact (s) | total (s) | peak (MiB) | K |")
    print("| ---: | ---: | ---: | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |")
    for n, runs in rows:
        for name in names:
            first = runs[name][0]

            def times(key):
                return ", ".join(f"{run[key]:.3g}" for run in runs[name])
            print(f"| {n} | {first['pairs']} | {first['dofs']} | {name} | {first['solves']} "
                  f"| {first['per solve']:.1f} | {times('flexibility')} | {times('contact')} "
                  f"| {times('total')} | {first['memory']:.0f} | {first['K']:.17g} |")
    for n, runs in rows:
        old, new = runs["pairs"][0], runs["Dirichlet"][0]
        print(f"n = {n}: GMRES per solve {old['per solve']:.1f} -> {new['per solve']:.1f} "
              f"({new['per solve'] / old['per solve']:.2f}), contact "
              f"{new['contact'] / old['contact']:.2f}, total {new['total'] / old['total']:.2f}, "
              f"K relative difference {new['K'] / old['K'] - 1:.2e}")


if __name__ == "__main__":
    main()
