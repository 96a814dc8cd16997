#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""The cost of trusting K: the certificate's extra solves and the stiffness
check (K again with the moving blocks 10 times stiffer and softer, contact
solves only) as shares of the whole run, measured inside each run (the
check's own wall time is in summary.json, so each ratio comes from one run).

    /usr/bin/python3 benchmarks/trust_cost.py [--exe build/fdem-slope]
        [--quick] [--output doc/trust_cost.md]
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402

# (case, settings, label): the paper's slope up to about 2e5 dofs, and the
# cases whose limit is planar (one certification solve) or creeping (wedge).
CASES = [
    ("paper_slope.prm", {"Geometry/Slope/Mesh size": 1.0}, "paper's slope, h = 1"),
    ("paper_slope.prm", {"Geometry/Slope/Mesh size": 0.4}, "paper's slope, h = 0.4"),
    ("paper_slope.prm", {"Geometry/Slope/Mesh size": 0.16}, "paper's slope, h = 0.16"),
    ("priest_plane_failure.prm", {}, "Priest plane failure"),
    ("rock_wedge.prm", {}, "rock wedge"),
    (os.path.join(common.ROOT, "tests", "three_d", "block_on_plane_3d.prm"), {}, "3D block on a plane"),
]
QUICK = [CASES[0], CASES[3]]


def certification_solves(summary):
    """Solves made only to certify a planar limit: steps at K*(1 - tol/4)
    of the step before."""
    steps, tolerance = summary["iterations"], summary["certificate"]["tolerance"]
    return sum(1 for a, b in zip(steps, steps[1:])
               if a["K_star"] is not None and b["K"] == a["K_star"] * (1 - 0.25 * tolerance))


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--exe", default=common.DEFAULT_EXE)
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--output", default=os.path.join(common.ROOT, "doc", "trust_cost.md"))
    args = parser.parse_args()
    rows = []
    for prm, settings, label in (QUICK if args.quick else CASES):
        # Priest's case reads its .geo next to the .prm.
        geo = os.path.join(common.PRM_DIR, "priest_plane_failure.geo")
        files = {"priest_plane_failure.geo": open(geo).read()} if prm.startswith("priest") else None
        run = common.run_case(args.exe, prm, settings, files=files)
        if not run.ok:
            sys.exit(f"trust_cost.py: {label}: {run.failure()}")
        s = run.summary
        total = s["timings"]["total"]
        n_steps = len(s["iterations"])
        check = s["stiffness_sensitivity"]
        extra = certification_solves(s)
        # A contact solve of the iteration costs its share of the contact and
        # safety-factor phases; the check's solves are inside them too.
        iteration_time = s["timings"].get("contact", 0) + s["timings"].get("safety factor", 0) - check["wall_seconds"]
        certificate_time = extra * iteration_time / n_steps
        rows.append([label, str(s["n_dofs"]), f"{s['safety_factor']:.8f}", s["certificate"]["kind"],
                     str(n_steps), str(extra), f"{100 * certificate_time / total:.2f}",
                     f"{check['relative_change']:.2e}", f"{check['wall_seconds']:.2f}", f"{total:.2f}",
                     f"{100 * check['wall_seconds'] / total:.1f}"])
        print(" | ".join(rows[-1]), flush=True)
    header = ["case", "dofs", "K", "certificate", "steps", "certification solves",
              "certificate % of run", "stiffness sensitivity", "check s", "run s", "check % of run"]
    text = ["# The cost of trusting K", "",
            f"Measured by `benchmarks/trust_cost.py` on {common.git_description()}; each row is one",
            "run, and its shares are of that run's own total (wall time, 2-core machine).",
            "The certificate itself is a few comparisons; its cost is the solves made",
            "only to certify (the solve just below a planar limit). The stiffness check",
            "is two more safety-factor iterations, started from the K found, on the same",
            "factorisation.", ""] + common.markdown_table(header, rows, "lrrlrrrrrrr") + [""]
    if not args.quick:
        # The reading of the numbers (written by hand, after the table) stays.
        reading = ""
        if os.path.exists(args.output):
            old = open(args.output).read()
            if "## Reading" in old:
                reading = old[old.index("## Reading"):]
        with open(args.output, "w") as f:
            f.write("\n".join(text) + ("\n" + reading if reading else ""))
        print(f"wrote {args.output}")


if __name__ == "__main__":
    main()
