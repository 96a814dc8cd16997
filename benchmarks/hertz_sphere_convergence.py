#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Mesh convergence of the 3D Hertz sphere case (prm/hertz_sphere.prm)
against the exact solution: contact radius a and maximum pressure p0, with
run time, and the effect of the truncated bodies.

    /usr/bin/python3 benchmarks/hertz_sphere_convergence.py [build/fdem-slope]
    /usr/bin/python3 benchmarks/hertz_sphere_convergence.py --from-csv

(--from-csv rewrites the .md and .png from doc/hertz_sphere_convergence.csv
without running anything.)

Refines the contact zone (n elements over Lc = 7.5 mm; the grading by 1.4
outside it then adds elements everywhere); then, at one level, enlarges the
sphere's cut and the foundation, and halves the far-field size, to measure
what the finite bodies contribute. Writes doc/hertz_sphere_convergence.md,
.csv and .png. Needs Debian's python3-matplotlib.
"""
import csv
import json
import os
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
FROM_CSV = sys.argv[1:] == ["--from-csv"]
EXE = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 and not FROM_CSV
                      else os.path.join(ROOT, "build", "fdem-slope"))
LEVELS = [int(n) for n in os.environ.get("LEVELS", "6 8 12 16").split()]
# Quarter of the load P = 1.0e5 N, spread over the sphere's cut S x S.
QUARTER_LOAD = 2.5e4
DEFAULT = {"S": 50, "H": 60, "W": 100, "D": 100, "h_max": 25, "g": 1.4}
# The finite-size study at one level: each row changes one thing.
SIZE_LEVEL = int(os.environ.get("SIZE_LEVEL", "6"))
SIZES = [("default", {}),
         ("foundation 200 x 200 x 200", {"W": 200, "D": 200}),
         ("sphere cut at S = 65, H = 90", {"S": 65, "H": 90}),
         ("far-field size 12.5", {"h_max": 12.5}),
         ("growth ratio 1.25", {"g": 1.25})]


def run(n, sizes):
    g = dict(DEFAULT, **sizes)
    with tempfile.TemporaryDirectory() as workdir:
        prm = os.path.join(workdir, "hertz_sphere.prm")
        with open(prm, "w") as f:
            f.write(f"include {os.path.join(ROOT, 'prm', 'hertz_sphere.prm')}\n"
                    "subsection Geometry\n  subsection Hertz sphere\n"
                    f"    set Elements in contact zone = {n}\n"
                    f"    set Cap half width = {g['S']}\n"
                    f"    set Load height = {g['H']}\n"
                    f"    set Foundation width = {g['W']}\n"
                    f"    set Foundation depth = {g['D']}\n"
                    f"    set Mesh size = {g['h_max']}\n"
                    f"    set Growth ratio = {g['g']}\n  end\nend\n"
                    "subsection Boundaries\n  subsection load\n"
                    f"    set Pressure = {QUARTER_LOAD / g['S'] ** 2}\n  end\nend\n"
                    "subsection Output\n  set Write VTU = false\nend\n")
        start = time.perf_counter()
        subprocess.run([EXE, prm], cwd=workdir, check=True, capture_output=True)
        wall = time.perf_counter() - start
        summary = json.load(open(os.path.join(workdir, "hertz_sphere-output", "summary.json")))
    h = summary["hertz"]
    interface = summary["interfaces"][0]
    return {"contact_zone_elements": n, "n_dofs": summary["n_dofs"],
            "n_pairs": interface["n_pairs"],
            "pairs_in_contact": interface["n_stick"] + interface["n_slip"],
            "load": h["load"],
            "a": h["contact_radius"], "a_error": h["contact_radius_error"],
            "a_area": h["contact_radius_from_area"],
            "a_area_error": h["contact_radius_from_area_error"],
            "p0": h["max_pressure"], "p0_error": h["max_pressure_error"],
            "seconds": wall, "a_exact": h["contact_radius_exact"],
            "p0_exact": h["max_pressure_exact"],
            "contact_solves": summary["contact"]["n_solves"]}


def read_csv(path):
    rows = common.read_typed_csv(path)
    return ([r for r in rows if r["study"] == "refinement"],
            [r for r in rows if r["study"] != "refinement"])


def main():
    doc = os.path.join(ROOT, "doc")
    csv_path = os.path.join(doc, "hertz_sphere_convergence.csv")
    if FROM_CSV:
        rows, size_rows = read_csv(csv_path)
    else:
        rows = [dict(run(n, {}), study="refinement") for n in LEVELS]
        size_rows = []
        for name, sizes in SIZES:
            if name == "default" and SIZE_LEVEL in LEVELS:
                row = dict(next(r for r in rows if r["contact_zone_elements"] == SIZE_LEVEL))
            else:
                row = run(SIZE_LEVEL, sizes)
            size_rows.append(dict(row, study=name))
        with open(csv_path, "w", newline="") as f:
            writer = csv.DictWriter(f, fieldnames=list(rows[0]))
            writer.writeheader()
            writer.writerows(rows + size_rows)
    size_level = size_rows[0]["contact_zone_elements"]
    base = size_rows[0]
    da = max(abs(r["a"] / base["a"] - 1) for r in size_rows[1:])
    dp = max(abs(r["p0"] / base["p0"] - 1) for r in size_rows[1:])
    finest = rows[-1]

    a_exact, p_exact = rows[0]["a_exact"], rows[0]["p0_exact"]
    lines = ["# Hertz sphere (3D): mesh convergence", "",
             "Generated by `/usr/bin/python3 benchmarks/hertz_sphere_convergence.py` "
             "(do not edit by hand). Case: `prm/hertz_sphere.prm`: an elastic "
             "sphere on an elastic half-space, E = 1.0e5 MPa, nu = 0.3 for both, "
             "R = 100 mm, P = 1.0e5 N, frictionless, quarter model with two "
             "symmetry planes; the sphere cut at x, y = S = 50 mm and loaded on "
             "its cut z = H = 60 mm, the foundation 100 x 100 x 100 mm, fixed at "
             "its bottom. Exact (Hertz; Johnson 1985, Sec. 4.2): "
             f"a = (3PR/(4E*))^(1/3) = {a_exact:.4f} mm, "
             f"p0 = 3P/(2 pi a^2) = {p_exact:.2f} N/mm^2, with P the computed "
             "total normal force (4 times that of the quarter model).", "",
             "n is the number of elements along each side of the contact zone "
             "[0, 7.5]^2 mm (and down to 7.5 mm into both bodies), so a spans "
             "about 0.69 n elements; outside, sizes grow by 1.4 up to 25 mm. "
             "a is the root of the least-squares fit of p^2 = c0 + c1 rho^2 "
             "(Hertz's profile) over the closed pairs in the outer half of the "
             "contact zone (doc/theory.md); a from the area is sqrt(4A/pi) with "
             "A the tributary area of the closed pairs (it moves in steps of a "
             "ring of pairs). p0 is the largest nodal pressure f_n/A (at the "
             "centre). Time: wall-clock seconds of the whole run on this "
             "machine (2 cores shared with other jobs, load about 7-10: "
             "indicative only; the n = 6 case needs about 5 s of CPU), one run "
             "each.", "",
             "## Refinement of the contact zone (Q1)", "",
             "| n | dofs | pairs | pairs in contact | a (mm) | error of a | a from area: error | p0 (N/mm^2) | error of p0 | contact solves | time (s) |",
             "| ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |"]
    for r in rows:
        lines.append(f"| {r['contact_zone_elements']} | {r['n_dofs']} | {r['n_pairs']} | "
                     f"{r['pairs_in_contact']} | {r['a']:.4f} | {100 * r['a_error']:+.3f} % | "
                     f"{100 * r['a_area_error']:+.2f} % | {r['p0']:.2f} | "
                     f"{100 * r['p0_error']:+.3f} % | {r['contact_solves']} | {r['seconds']:.1f} |")
    a_bound = max(abs(r["a_error"]) for r in rows[1:])
    lines += ["", "The error of a changes sign between levels and does not fall "
              "monotonically: which pairs are closed, and so which enter the fit, "
              "changes in steps with the mesh. It stays within "
              f"{100 * a_bound:.2f} % from n = {rows[1]['contact_zone_elements']} on. "
              "p0, the largest nodal pressure f_n/A (that of the centre pair, with "
              "a lumping error of order h^2 p''), converges monotonically from "
              "below. "
              f"At n = {finest['contact_zone_elements']} a spans about "
              f"{0.69 * finest['contact_zone_elements']:.0f} elements; "
              "`prm/hertz_sphere.prm` and its ctest use n = 6, the quick level.",
              "", f"## Truncated bodies (n = {size_level})", "",
              "Each row changes one size of the default model; the differences "
              "from the default row bound what the finite sphere and foundation "
              "(and the far-field mesh) contribute to the errors above.", "",
              "| model | dofs | a (mm) | error of a | p0 (N/mm^2) | error of p0 | time (s) |",
              "| --- | ---: | ---: | ---: | ---: | ---: | ---: |"]
    for r in size_rows:
        lines.append(f"| {r['study']} | {r['n_dofs']} | {r['a']:.4f} | {100 * r['a_error']:+.3f} % | "
                     f"{r['p0']:.2f} | {100 * r['p0_error']:+.3f} % | {r['seconds']:.1f} |")
    a_min = min(abs(r["a_error"]) for r in rows)
    p_min = min(abs(r["p0_error"]) for r in rows)
    lines += ["", f"Enlarging the bodies, or refining or grading the far field more "
              f"gently, changes a by at most {100 * da:.3f} % and p0 by at most "
              f"{100 * dp:.3f} %: the effect of truncating the sphere and the "
              f"half-space (a/R = {base['a_exact'] / 100:.3f}, a/S = {base['a_exact'] / 50:.2f}, "
              f"a/W = a/D = {base['a_exact'] / 100:.3f}) is {a_min / da:.0f} and "
              f"{p_min / dp:.0f} times smaller than the smallest discretisation errors "
              f"of the table above ({100 * a_min:.3f} % for a, {100 * p_min:.3f} % "
              "for p0).",
              "", "![errors against run time](hertz_sphere_convergence.png)", ""]
    open(os.path.join(doc, "hertz_sphere_convergence.md"), "w").write("\n".join(lines))

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(10, 4))
    for ax, key, title in zip(axes, ["a_error", "p0_error"], ["contact radius a", "p0"]):
        ax.loglog([r["seconds"] for r in rows], [abs(r[key]) for r in rows], "o-", label="Q1")
        for r in rows:
            ax.annotate(f"n={r['contact_zone_elements']}", (r["seconds"], abs(r[key])))
        ax.set_title(f"Hertz sphere: |relative error| of {title}")
        ax.set_xlabel("run time (s)")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(doc, "hertz_sphere_convergence.png"), dpi=100)
    print("\n".join(lines))


if __name__ == "__main__":
    main()
