#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""The rock wedge (prm/rock_wedge.prm) over mesh sizes: safety-factor steps,
contact solves, K against the limit equilibrium (Hoek & Bray's wedge,
tests/scripts/wedge_reference.py: 0.726602024686) and time, for one
executable or, with --before, two of them run alternately (each case once
per executable, the order alternating, so that the machine's load falls on
both alike).

    /usr/bin/python3 benchmarks/wedge_iteration.py [build/fdem-slope] \\
        [--before OLD_EXE --before-label TEXT] [--output doc/benchmarks.md]

Writes the section "wedge-iteration" of the output file.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402

K_LE = 0.726602024686
MESH_SIZES = [8.0, 6.0, 4.0, 3.0]


def measure(exe, mesh_size):
    result = common.run_case(exe, "rock_wedge.prm", {"Geometry/Wedge/Mesh size": mesh_size,
                                                      "Safety factor/Stiffness check": "false"})
    if not result.ok:
        sys.exit(f"wedge_iteration.py: Mesh size {mesh_size}: {result.failure()}")
    s = result.summary
    steps = s["iterations"]
    return {
        "dofs": s["n_dofs"],
        "pairs": common.n_pairs(s),
        "steps": len(steps),
        "solves": sum(step["n_contact_iterations"] + step.get("n_slope_solves", 0)
                      for step in steps),
        "K": s["safety_factor"],
        "error": (s["safety_factor"] - K_LE) / K_LE,
        "certificate": s["certificate"]["kind"],
        "contact": s["timings"]["contact"],
        "total": s["timings"]["total"],
    }


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("exe", nargs="?", default=common.DEFAULT_EXE)
    parser.add_argument("--before")
    parser.add_argument("--before-label", default="before")
    parser.add_argument("--output", default=os.path.join(common.ROOT, "doc", "benchmarks.md"))
    args = parser.parse_args()
    programs = [("now", os.path.abspath(args.exe))]
    if args.before:
        programs.append((args.before_label, os.path.abspath(args.before)))
    rows = []
    for i, h in enumerate(MESH_SIZES):
        order = programs if i % 2 == 0 else programs[::-1]
        measured = {label: measure(exe, h) for label, exe in order}
        for label, _ in programs:
            m = measured[label]
            rows.append([f"{h:g}", label, m["dofs"], m["pairs"], m["steps"], m["solves"],
                         f"{m['K']:.8f}", f"{m['error']:+.1e}", m["certificate"],
                         f"{m['contact']:.2f}", f"{m['total']:.2f}"])
    load = os.getloadavg()[0]
    lines = [
        "<!-- wedge-iteration: written by benchmarks/wedge_iteration.py -->",
        "## The rock wedge: safety-factor steps and accuracy",
        "",
        f"`prm/rock_wedge.prm` (Q1 hexahedra, stiffness check off) on {common.git_description()}, "
        f"one run per row, load average {load:.1f} at the end. K_LE = {K_LE} (Hoek & Bray's "
        "wedge); the relative error is (K − K_LE)/K_LE with Safety factor/Tolerance 1e-6. "
        "Steps are safety-factor steps (contact solves); solves are the linear solves of the "
        "mixed system over all steps: the status iterations' and, where a step computes the "
        "slope of K* (every pair slipping), its two. Times in seconds from summary.json (`contact`, `total`).",
        "",
    ]
    lines += common.markdown_table(
        ["Mesh size (m)", "program", "dofs", "pairs", "steps", "solves", "K", "error",
         "certificate", "contact (s)", "total (s)"],
        rows, align="llrrrrrrlrr")
    lines += ["", "<!-- /wedge-iteration -->"]
    common.put_benchmarks_section(args.output, lines, "wedge-iteration")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
