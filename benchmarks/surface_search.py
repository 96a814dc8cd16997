#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""The surface search's cost and the convergence of the critical circle's
factors (doc/surface_search.md), on the paper's slope (ACADS 1(a)).

    /usr/bin/python3 benchmarks/surface_search.py [--exe build/fdem-slope]
        [--contact-evaluations 30] [--polyline-refinements 10] [--output-dir doc]

1. A full search: the grid of tests/surface_search/paper_slope_search.prm
   (7 x 7 centres, 9 tangent elevations, Bishop with 50 slices), the
   refinement, --contact-evaluations contact evaluations on a 2 m screening
   mesh (5 candidates, then the pattern search on the contact K), and the
   run on the critical circle at the case's 1 m: its wall time from
   outside and the stages' times from summary.json, the time of limit
   equilibrium per screened circle and of one contact evaluation.
2. Bishop's and Spencer's K on the critical circle with 25 to 1600 slices
   (the run's own limit equilibrium, the circle from the search).
3. The same search with the non-circular stage (Non-circular = true) and
   --contact-evaluations in all, --polyline-refinements of them for the
   contact refinement of the best polyline: the time of limit equilibrium
   per polyline, of its contact evaluations and of the whole run (the
   issue's 60 s on 2 cores).
The machine is shared: the 1-minute load average is written beside each
number. Writes the section "Surface search" of DIR/benchmarks.md and keeps
it in DIR/benchmarks/surface_search.md (run_benchmarks.py puts it back).
"""
import argparse
import csv
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402

SEARCH_PRM = os.path.join(common.ROOT, "tests", "surface_search", "paper_slope_search.prm")


def full_search(exe, n_contact):
    load = os.getloadavg()[0]
    run = common.run_case(exe, SEARCH_PRM, settings={
        "Surface search/Maximum contact evaluations": str(n_contact),
        "Surface search/Contact candidates": "5",
        "Output/Report": "false"})
    if not run.ok:
        sys.exit("the search failed: " + run.failure())
    return run, load


def non_circular_search(exe, n_contact, n_refinements):
    """The same search with the non-circular stage: polylines of 7 vertices
    from the best circles of 2 centres, by Spencer; n_contact contact
    evaluations, of which 2 for the polyline candidates and n_refinements
    for the contact refinement of the best polyline, the circles the
    rest."""
    load = os.getloadavg()[0]
    run = common.run_case(exe, SEARCH_PRM, settings={
        "Surface search/Non-circular": "true",
        "Surface search/Maximum contact evaluations": str(n_contact),
        "Surface search/Non-circular contact refinements": str(n_refinements),
        "Output/Report": "false"})
    if not run.ok:
        sys.exit("the non-circular search failed: " + run.failure())
    return run, load


def non_circular_lines(exe, n_contact, n_refinements):
    run, load = non_circular_search(exe, n_contact, n_refinements)
    search = run.summary["surface_search"]
    polylines = search["non_circular"]
    t, counts, minimum = polylines["timings"], polylines["counts"], polylines["minimum"]
    refinement = polylines["contact_refinement"]
    r = refinement["counts"]
    n_candidates = counts["contact_evaluations"] - r["contact_evaluations"]
    lines = ["",
             "The non-circular stage on the same slope (`Surface search/Non-circular = true` "
             "added to `tests/surface_search/paper_slope_search.prm`: polylines of "
             f"{polylines['n_vertices']} vertices from the best circles of {counts['starts']} "
             f"centres, {polylines['method']} with 50 slices; {n_contact} contact evaluations "
             f"in all, `Non-circular contact refinements = {n_refinements}`; 1-minute load "
             f"average {load:.1f} at the start):",
             ""]
    lines += common.markdown_table(
        ["what", "count", "wall time (s)", "per item (ms)"],
        [(f"limit equilibrium, polylines ({polylines['method']}, 50 slices)",
          counts["screened"], f"{t['screening']:.2f}",
          f"{1000 * t['screening'] / max(counts['screened'], 1):.2f}"),
         ("contact evaluations of circles (2 m mesh, no output)",
          search["counts"]["contact_evaluations"] - counts["contact_evaluations"],
          f"{search['timings']['contact_evaluations']:.2f}", ""),
         ("contact evaluations of the polyline candidates", n_candidates,
          f"{t['contact_evaluations']:.2f}",
          f"{1000 * t['contact_evaluations'] / max(n_candidates, 1):.0f}"),
         ("contact refinement of the best polyline", r["contact_evaluations"],
          f"{t['contact_refinement']:.2f}",
          f"{1000 * t['contact_refinement'] / max(r['contact_evaluations'], 1):.0f}"),
         ("the whole run, measured from outside", 1, f"{run.wall:.2f}", "")],
        "lrrr")
    critical = search["critical"]
    if refinement["performed"]:
        refined = (f"the contact refinement took the best polyline's contact K from "
                   f"{refinement['from']['contact_K']:.4f} to "
                   f"{refinement['best']['contact_K']:.4f} ({r['moves']} moves kept of "
                   f"{r['contact_evaluations']} evaluations, {r['not_certified']} not "
                   f"certified, steps {refinement['first_step']:g} to "
                   f"{refinement['last_step']:g})")
    else:
        refined = f"no contact refinement ({refinement['why_not'] or 'none asked'})"
    lines += ["",
              f"Lowest polyline factor {minimum['le_K']:.4f} ({polylines['method']}), the "
              f"circles' screening minimum {search['screening_minimum']['le_K']:.4f} "
              f"({search['method']}); {refined}; critical surface: {critical['shape']}, "
              f"chosen by the {critical['chosen_by']}, contact K {critical['K']:.4f} at 1 m "
              f"({counts['contact_certified']} of {counts['contact_evaluations']} polyline "
              "contact evaluations certified)."]
    return lines


def slices(exe, centre, radius):
    rows = []
    for n in (25, 50, 100, 200, 400, 800, 1600):
        run = common.run_case(exe, "paper_slope.prm", settings={
            "Geometry/Slope/Circle centre": f"{centre[0]!r}, {centre[1]!r}",
            "Geometry/Slope/Circle radius": repr(radius),
            "Geometry/Slope/Mesh size": "2.0",
            "Safety factor/Compute": "false",
            "Output/Report": "false",
            "Limit equilibrium/Methods": "Bishop, Spencer",
            "Limit equilibrium/Number of slices": str(n)})
        # K < 1 here: at full strength the contact problem has no
        # equilibrium (exit 3), and limit equilibrium is in the summary all
        # the same.
        if run.summary is None or "limit_equilibrium" not in run.summary:
            sys.exit("the slices run failed: " + run.failure())
        methods = run.summary["limit_equilibrium"]["methods"]
        rows.append((n, methods["bishop_simplified"]["K"], methods["spencer"]["K"]))
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--exe", default=common.DEFAULT_EXE)
    parser.add_argument("--contact-evaluations", type=int, default=30)
    parser.add_argument("--polyline-refinements", type=int, default=10,
                        help="Non-circular contact refinements of the non-circular search")
    parser.add_argument("--output-dir", default=os.path.join(common.ROOT, "doc"))
    args = parser.parse_args()

    run, load = full_search(args.exe, args.contact_evaluations)
    search = run.summary["surface_search"]
    t, counts, critical = search["timings"], search["counts"], search["critical"]
    n_screened = counts["grid"] + counts["refinement"]
    total = run.summary["timings"]["total"]
    lines = ["<!-- surface-search: written by benchmarks/surface_search.py -->",
             "## Surface search",
             "",
             "The search of `tests/surface_search/paper_slope_search.prm` (the paper's slope, "
             "ACADS 1(a)) with "
             f"{args.contact_evaluations} contact evaluations: "
             f"`/usr/bin/python3 benchmarks/surface_search.py --contact-evaluations "
             f"{args.contact_evaluations}`, program {common.git_description()}, on the shared "
             f"machine (2 cores shared by other sessions; 1-minute load average {load:.1f} "
             "at the start): the times are upper bounds of what the program needs alone.",
             ""]
    lines += common.markdown_table(
        ["what", "count", "wall time (s)", "per item (ms)"],
        [("limit equilibrium, grid (Bishop, 50 slices)", counts["grid"],
          f"{t['screening']:.3f}", f"{1000 * t['screening'] / counts['grid']:.3f}"),
         ("limit equilibrium, refinement", counts["refinement"], f"{t['refinement']:.3f}",
          f"{1000 * t['refinement'] / max(counts['refinement'], 1):.3f}"),
         ("contact evaluations (2 m mesh, no output)", counts["contact_evaluations"],
          f"{t['contact_evaluations']:.2f}",
          f"{1000 * t['contact_evaluations'] / max(counts['contact_evaluations'], 1):.0f}"),
         ("the run on the critical circle (1 m mesh) and the search, in the program", 1,
          f"{total + t['screening'] + t['refinement'] + t['contact_evaluations']:.2f}", ""),
         ("the whole run, measured from outside", 1, f"{run.wall:.2f}", "")],
        "lrrr")
    lines += ["",
              f"Critical circle: centre ({critical['centre'][0]:.4f}, "
              f"{critical['centre'][1]:.4f}), radius {critical['radius']:.4f}, chosen by the "
              f"{critical['chosen_by']}; contact K {critical['K']:.4f} at 1 m "
              f"({critical['contact_K']:.4f} on the 2 m screening mesh), Bishop "
              f"{critical['limit_equilibrium'].get('bishop_simplified', float('nan')):.4f} with 400 slices "
              f"({n_screened} circles screened, {counts['contact_certified']} of "
              f"{counts['contact_evaluations']} contact evaluations certified).",
              "",
              "Bishop's and Spencer's K on this critical circle against the number of slices "
              "(the change is from the row before):",
              ""]
    rows = slices(args.exe, critical["centre"], critical["radius"])
    table = []
    for k, (n, bishop, spencer) in enumerate(rows):
        change = ("", "") if k == 0 else (f"{(bishop - rows[k - 1][1]) / bishop:+.1e}",
                                           f"{(spencer - rows[k - 1][2]) / spencer:+.1e}")
        table.append((n, f"{bishop:.6f}", change[0], f"{spencer:.6f}", change[1]))
    lines += common.markdown_table(["slices", "Bishop K", "change", "Spencer K", "change"],
                                   table, "rrrrr")
    lines += non_circular_lines(args.exe, args.contact_evaluations,
                                args.polyline_refinements)
    lines += ["", "<!-- /surface-search -->"]
    common.put_benchmarks_section(os.path.join(args.output_dir, "benchmarks.md"), lines,
                                  "surface-search")
    # Kept for run_benchmarks.py, which rewrites benchmarks.md.
    os.makedirs(os.path.join(args.output_dir, "benchmarks"), exist_ok=True)
    with open(os.path.join(args.output_dir, "benchmarks", "surface_search.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
