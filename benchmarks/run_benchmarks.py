#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""The benchmark suite: the verification cases at increasing refinement,
with the error against the exact or published value, the wall time of each
phase of the run and the peak memory.

    /usr/bin/python3 benchmarks/run_benchmarks.py [--exe build/fdem-slope]
        [--quick] [--output-dir DIR] [--cases hertz,priest,...] [--check]

Writes DIR/benchmarks.md (default doc/), DIR/benchmarks/benchmarks.csv and
one plot DIR/benchmarks/<case>.png per case (run time against error). Every
number and every sentence about them in benchmarks.md comes from this run's
data. --quick runs two coarse levels per case (a smoke test, under a minute;
its default output folder is ./benchmarks-quick) and implies --check: the
tables must have rows and every error must be finite. The exit code is 1 if
a run failed or a check did not hold.
"""
import argparse
import csv
import datetime
import math
import os
import platform
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402
import output_cost  # noqa: E402
import scaling  # noqa: E402

# Hoek & Bray's plane-failure formula with Priest's (1993) data
# (tests/test_safety_factor.cc, PriestPlaneFailure.HoekBrayFormula);
# published F = 1.049.
PRIEST_K = 1.048980914752

# The phases summary.json times (seconds, not nested, in run order). Phases a
# newer program adds are shown after these, in alphabetical order.
PHASES = ["geometry", "setup", "assembly and factorisation", "assembly", "factorisation",
          "one solve", "interfaces", "flexibility", "contact", "safety factor", "recovery",
          "output"]
# What one linear solve of the same model costs: mesh, dofs, assembly,
# factorisation and the solve itself. The cost ratio is total / this.
ONE_SOLVE_PHASES = {"geometry", "setup", "assembly and factorisation", "assembly",
                    "factorisation", "one solve"}


class Case:
    """One benchmark case: a .prm of prm/, the refinement levels, how a level
    changes the parameters, and what is compared with which exact value."""

    def __init__(self, name, title, prm, level_name, levels, quick_levels, settings,
                 quantities, exact, description):
        self.name, self.title, self.prm = name, title, prm
        self.level_name, self.levels, self.quick_levels = level_name, levels, quick_levels
        self.settings = settings      # level -> (settings, files)
        self.quantities = quantities  # Run -> {quantity: value}
        self.exact = exact            # Run -> {quantity: exact value}, or None: finest level
        self.description = description


def number(parameters, path):
    return float(parameters[path])


def inclined_block_exact(run):
    """K = tan(phi)/tan(alpha) + c L / (W sin(alpha)), W = gamma L H: the
    planar limit of doc/theory.md, as in
    tests/test_safety_factor.cc."""
    p = run.parameters
    alpha = math.radians(number(p, "Geometry/Inclined block/Inclination"))
    L = number(p, "Geometry/Inclined block/Block length")
    H = number(p, "Geometry/Inclined block/Block height")
    W = number(p, "Blocks/block/Unit weight") * L * H
    phi = math.radians(number(p, "Interfaces/sliding surface/Friction angle"))
    c = number(p, "Interfaces/sliding surface/Cohesion")
    return {"K": math.tan(phi) / math.tan(alpha) + c * L / (W * math.sin(alpha))}


def priest_geo(h):
    """prm/priest_plane_failure.geo with element size @p h (m)."""
    text = open(os.path.join(common.PRM_DIR, "priest_plane_failure.geo")).read()
    text, n = re.subn(r"(?m)^h = [0-9.eE+-]+;", f"h = {h};", text)
    if n != 1:
        sys.exit("run_benchmarks.py: no line 'h = ...;' in prm/priest_plane_failure.geo")
    return text


def wedge_exact(run):
    """Vector limit equilibrium of the wedge (tests/scripts/wedge_reference.py)
    with the run's planes, strengths, wedge weight and plane areas."""
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                    "..", "tests", "scripts"))
    from wedge_reference import safety_factor_of_run
    K, _ = safety_factor_of_run(run.parameters, run.summary)
    return {"K": K}


def safety_factor(run):
    K = run.summary.get("safety_factor")
    return {"K": K if K is not None else math.nan}


CASES = [
    Case("hertz", "Hertz contact of a cylinder on a half-space", "hertz.prm",
         "N", [30, 60, 120, 240], [20, 30],
         lambda n: ({"Geometry/Hertz/Elements in contact zone": n,
                     "Geometry/Hertz/Mesh size": 1200 / n}, {}),
         lambda run: {"a": run.summary["hertz"]["contact_half_width"],
                      "q_max": run.summary["hertz"]["max_pressure"]},
         lambda run: {"a": run.summary["hertz"]["contact_half_width_exact"],
                      "q_max": run.summary["hertz"]["max_pressure_exact"]},
         "`prm/hertz.prm` (Q1, frictionless, no safety factor: one contact "
         "problem). N elements over the 15 mm contact zone, far-field size "
         "1200/N mm. Exact: Hertz's a = sqrt(4 p r / (pi E')) and "
         "q_max = 2 p / (pi a) (the `hertz` block of summary.json)."),
    Case("inclined_block", "Block on an inclined plane", "inclined_block.prm",
         "m", [1, 2, 4, 8, 16], [1, 2],
         lambda m: ({"Geometry/Inclined block/Elements along length": 10 * m,
                     "Geometry/Inclined block/Elements across height": 5 * m}, {}),
         safety_factor, inclined_block_exact,
         "`prm/inclined_block.prm` (Q1), 10m x 5m elements in the block. Exact: "
         "the planar limit K = tan(phi)/tan(alpha) + c L/(W sin(alpha)), which "
         "has the whole base in contact. The case has no tensile strength: pairs "
         "at the heel open at the limit and lose their cohesion (column 'open at "
         "the limit'), so the discrete K lies below the planar value."),
    Case("priest", "Plane failure with a water-filled tension crack (Priest 1993)",
         "priest_plane_failure.prm", "h (m)", [4.0, 2.8, 2.0, 1.4, 1.0], [4.0, 2.8],
         lambda h: ({"Geometry/Mesh file": "priest_plane_failure.geo"},
                    {"priest_plane_failure.geo": priest_geo(h)}),
         safety_factor, lambda run: {"K": PRIEST_K},
         "`prm/priest_plane_failure.prm` (Q2) with element size h in its .geo "
         f"(2 m by default). Exact: Hoek & Bray's formula, K = {PRIEST_K} "
         "(published 1.049). Equilibrium fixes the force sums on a plane, so "
         "every mesh should give it to round-off."),
    Case("paper_slope", "The paper's slope (Liu et al. 2012, example 4.B)", "paper_slope.prm",
         "mesh size (m)", [2.0, 1.0, 0.5, 0.25, 0.125], [4.0, 2.0],
         lambda h: ({"Geometry/Slope/Mesh size": h}, {}),
         safety_factor, None,
         "`prm/paper_slope.prm` (Q2, circular sliding surface). No exact value: "
         "the error is against the finest mesh of this table (its own row "
         "shows 0)."),
    Case("rock_wedge", "Symmetric rock wedge (3D, Hoek & Bray)", "rock_wedge.prm",
         "mesh size (m)", [8.0, 6.0, 4.0, 3.0, 2.5], [8.0, 6.0],
         lambda h: ({"Geometry/Wedge/Mesh size": h}, {}),
         safety_factor, wedge_exact,
         "`prm/rock_wedge.prm` (3D, Q1 hexahedra), planes 50/140 and 50/220, "
         "phi = 30 deg. Exact: the vector limit equilibrium of "
         "tests/scripts/wedge_reference.py, K = 0.726602."),
]


def phase_times(summary):
    timings = summary.get("timings", {}) if summary else {}
    return {k: v for k, v in timings.items() if k != "total"}


def run_level(exe, case, level):
    settings, files = case.settings(level)
    run = common.run_case(exe, case.prm, settings, files)
    row = {"case": case.name, "level": level, "status": "completed" if run.ok else run.failure()}
    if run.summary is not None and run.summary.get("status") != "completed" and run.ok:
        row["status"] = run.summary.get("status")
    s = run.summary or {}
    row["n_dofs"] = s.get("n_dofs", "")
    row["n_pairs"] = common.n_pairs(s) if s else ""
    row["n_contact_solves"] = sum(step.get("n_contact_iterations", 0)
                                  for step in s.get("iterations", [])) or \
        s.get("contact", {}).get("n_solves", "")
    row["n_safety_factor_steps"] = len(s.get("iterations", []))
    # Pairs open at the last step: they carry no cohesion (eq. 11).
    row["n_open_at_limit"] = s["iterations"][-1].get("n_open", "") if s.get("iterations") else ""
    try:
        values = case.quantities(run) if run.ok else {}
        exact = case.exact(run) if run.ok and case.exact else {}
    except (KeyError, TypeError, ValueError) as error:
        values, exact = {}, {}
        row["status"] = f"no result: {error!r}"
    for q, v in values.items():
        row[q] = v
        if case.exact:
            row[q + "_exact"] = exact.get(q, math.nan)
    times = phase_times(s)
    for phase, seconds in times.items():
        row["time " + phase] = seconds
    row["time total"] = s.get("timings", {}).get("total", math.nan)
    row["wall time outside"] = run.wall
    row["peak_memory_MiB"] = s.get("peak_memory_MiB", math.nan)
    baseline = sum(v for k, v in times.items() if k in ONE_SOLVE_PHASES)
    row["cost_ratio"] = row["time total"] / baseline if "one solve" in times and baseline > 0 \
        else math.nan
    return row, list(values)


def add_errors(case, rows, quantities):
    """Relative errors value/exact - 1; without an exact value, against the
    finest level that has one."""
    for q in quantities:
        if case.exact is None:
            finest = [r for r in rows if math.isfinite(r.get(q, math.nan))]
            reference = finest[-1][q] if finest else math.nan
            for r in rows:
                r[q + "_exact"] = reference
        for r in rows:
            value, exact = r.get(q, math.nan), r.get(q + "_exact", math.nan)
            r[q + "_error"] = value / exact - 1 if exact else math.nan


def fmt(x, digits=3):
    if x == "" or x is None:
        return ""
    if isinstance(x, str):
        return x
    if not math.isfinite(x):
        return "n/a"
    return f"{x:.{digits}g}" if abs(x) < 1e5 else f"{x:.0f}"


def fmt_seconds(x):
    if not isinstance(x, (int, float)) or not math.isfinite(x):
        return "n/a"
    return f"{x:.3f}" if x < 1 else f"{x:.2f}" if x < 100 else f"{x:.0f}"


def ordered_phases(rows):
    seen = {k[5:] for r in rows for k in r if k.startswith("time ") and k != "time total"}
    return [p for p in PHASES if p in seen] + sorted(seen - set(PHASES))


def growth(rows, phases):
    """Exponents of the total and of each phase against dofs and against
    pairs, fitted over the finest three completed levels (the coarse ones
    are dominated by fixed costs: start-up, Gmsh)."""
    done = [r for r in rows if r["status"] == "completed"][-3:]
    fits = {}
    for key in ["total"] + phases:
        times = [r.get("time " + key, math.nan) for r in done]
        fits[key] = (common.fit_exponent([r["n_dofs"] for r in done], times),
                     common.fit_exponent([r["n_pairs"] for r in done], times))
    return fits, len(done)


def case_section(case, rows, quantities, phases, image):
    lines = [f"## {case.title}", "", case.description, ""]
    with_open = any(r.get("n_open_at_limit", "") != "" for r in rows)
    header = [case.level_name, "dofs", "pairs"] + (["open at the limit"] if with_open else [])
    for q in quantities:
        header += [q, f"error of {q}"]
    header += [f"{p} (s)" for p in phases] + ["total (s)", "peak memory (MiB)", "cost ratio"]
    table = []
    for r in rows:
        row = [fmt(r["level"]), r["n_dofs"], r["n_pairs"]]
        row += [r.get("n_open_at_limit", "")] if with_open else []
        for q in quantities:
            row += [fmt(r.get(q, math.nan), 10), f"{r.get(q + '_error', math.nan):+.2e}"]
        row += [fmt_seconds(r["time " + p]) if "time " + p in r else "–" for p in phases]
        row += [fmt_seconds(r["time total"]), fmt(r["peak_memory_MiB"], 4), fmt(r["cost_ratio"])]
        table.append(row)
    lines += common.markdown_table(header, table)
    failed = [r for r in rows if r["status"] != "completed"]
    for r in failed:
        lines += ["", f"Level {r['level']} did not complete: {r['status']}."]
    fits, n_fit = growth(rows, phases)
    done = [r for r in rows if r["status"] == "completed"]
    if done:
        finest = done[-1]
        shares = sorted(((finest.get("time " + p, 0) / finest["time total"], p) for p in phases
                         if finest["time total"] > 0), reverse=True)
        top = ", ".join(f"{p} {100 * s:.0f} %" for s, p in shares[:3])
        dofs_fit, pairs_fit = fits["total"]
        lines += ["", f"At the finest level ({finest['n_dofs']} dofs, {finest['n_pairs']} pairs) "
                  f"the run takes {fmt_seconds(finest['time total'])} s, "
                  f"{fmt(finest['cost_ratio'])} times one linear solve of the same model; "
                  f"the largest phases: {top}."]
        if n_fit >= 2:
            phase_fits = "; ".join(f"{p}: dofs^{fits[p][0]:.2f}, pairs^{fits[p][1]:.2f}"
                                   for s, p in shares[:3] if math.isfinite(fits[p][0]))
            lines += ["", f"Fitted over the finest {n_fit} levels, the total time grows as "
                      f"dofs^{dofs_fit:.2f} and as pairs^{pairs_fit:.2f} "
                      f"(largest phases: {phase_fits})."]
    lines += ["", f"![run time against error, {case.name}]({image})", ""]
    return lines, fits


def joint_fit(rows, key):
    """Exponents (b, c) of time = a dofs^b pairs^c, least squares in log-log
    over @p rows; None if the rows do not determine them."""
    import numpy
    points = [(r["n_dofs"], r["n_pairs"], r.get(key, 0)) for r in rows]
    points = [p for p in points if p[2] and p[2] > 0 and math.isfinite(p[2])]
    if len(points) < 4:
        return None
    A = numpy.array([[1, math.log(d), math.log(n)] for d, n, _ in points])
    y = numpy.array([math.log(t) for _, _, t in points])
    coefficients, _, rank, _ = numpy.linalg.lstsq(A, y, rcond=None)
    return (coefficients[1], coefficients[2]) if rank == 3 else None


# Runs shorter than this are mostly fixed costs (start-up, libraries): the
# growth fits leave them out.
MIN_FIT_SECONDS = 1.0


def summary_section(all_rows, phases):
    """Across cases: what dominates at each case's finest level, and how the
    time and the cost ratio grow with dofs and pairs."""
    lines = ["## Where the time goes", ""]
    done = [r for r in all_rows if r["status"] == "completed"]
    finest = {}
    for r in done:
        finest[r["case"]] = r
    table = []
    dominant = {}
    for name, r in finest.items():
        shares = sorted(((r.get("time " + p, 0), p) for p in phases), reverse=True)
        dominant[name] = shares[0][1]
        beyond = r["time total"] - sum(r.get("time " + p, 0) for p in phases
                                       if p in ONE_SOLVE_PHASES)
        table.append([name, r["n_dofs"], r["n_pairs"], fmt_seconds(r["time total"]),
                      f"{shares[0][1]} ({100 * shares[0][0] / r['time total']:.0f} %)",
                      fmt_seconds(beyond), fmt(r["cost_ratio"]), fmt(r["peak_memory_MiB"], 4)])
    lines += common.markdown_table(["case (finest level)", "dofs", "pairs", "total (s)",
                                    "largest phase", "beyond one solve (s)", "cost ratio",
                                    "peak memory (MiB)"], table, "lrrrlrrr")
    counts = {}
    for phase in dominant.values():
        counts[phase] = counts.get(phase, 0) + 1
    if counts:
        top = max(counts, key=counts.get)
        lines += ["", f"The largest phase at the finest level is '{top}' in "
                  f"{counts[top]} of {len(dominant)} cases"
                  + ("" if len(counts) == 1 else
                     " (" + ", ".join(f"'{dominant[c]}' in {c}" for c in dominant
                                      if dominant[c] != top) + ")") + "."]

    # Growth: one fit over the runs of all cases that are long enough.
    long_runs = [r for r in done if r["time total"] >= MIN_FIT_SECONDS]
    total_time = sum(r["time total"] for r in long_runs)
    fit_rows = []
    for key in ["time total", "cost_ratio"] + ["time " + p for p in phases]:
        fit = joint_fit(long_runs, key)
        share = (sum(r.get(key, 0) for r in long_runs) / total_time
                 if key.startswith("time ") and total_time > 0 else math.nan)
        if fit:
            fit_rows.append([key[5:] if key.startswith("time ") else "cost ratio",
                             f"{fit[0]:.2f}", f"{fit[1]:.2f}",
                             "" if not math.isfinite(share) else f"{100 * share:.0f} %"])
    if fit_rows:
        coupling = common.fit_exponent([r["n_dofs"] for r in long_runs],
                                       [r["n_pairs"] for r in long_runs])
        lines += ["", f"How the cost grows: a least-squares fit of log(time) = a + b "
                  f"log(dofs) + c log(pairs) over the {len(long_runs)} runs of all cases "
                  f"that took at least {MIN_FIT_SECONDS:g} s. Under refinement pairs and dofs "
                  f"grow together (over these runs pairs ~ dofs^{coupling:.2f}); the "
                  "cases' different ratios of pairs to dofs separate b from c, so read "
                  "them as trends, not laws. Share: the phase's part of these runs' total "
                  "time.", ""]
        lines += common.markdown_table(["quantity", "b (dofs)", "c (pairs)", "share"],
                                       fit_rows, "lrrr")
        total_fit = joint_fit(long_runs, "time total")
        ratio_fit = joint_fit(long_runs, "cost_ratio")
        if total_fit and ratio_fit:
            lines += ["", f"The whole run grows as dofs^{total_fit[0]:.2f} pairs^{total_fit[1]:.2f}; "
                      f"its cost in units of one linear solve grows as dofs^{ratio_fit[0]:.2f} "
                      f"pairs^{ratio_fit[1]:.2f}, so the cost beyond one solve grows "
                      + ("mostly with the pairs." if abs(ratio_fit[1]) > abs(ratio_fit[0])
                         else "mostly with the dofs.")]
    elif len(long_runs) < 4:
        lines += ["", f"Fewer than 4 runs took {MIN_FIT_SECONDS:g} s or more: no growth fit."]
    lines.append("")
    return lines


def plot(case, rows, quantities, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 4.2))
    floor = 1e-16  # an error of exactly 0 (or below) is drawn at round-off
    for q, marker in zip(quantities, "os^v"):
        points = [(r["time total"], max(abs(r[q + "_error"]), floor), r["n_dofs"]) for r in rows
                  if r["status"] == "completed" and math.isfinite(r.get(q + "_error", math.nan))
                  and not (case.exact is None and r is rows[-1])]
        if not points:
            continue
        ax.loglog([p[0] for p in points], [p[1] for p in points], marker + "-", label=q)
        for t, e, dofs in points:
            ax.annotate(f"{dofs}", (t, e), textcoords="offset points", xytext=(4, 4), fontsize=7)
    ax.set_xlabel("run time (s, whole run)")
    ax.set_ylabel("|relative error|" + (" against the finest mesh" if case.exact is None else ""))
    ax.set_title(f"{case.name}: error against run time (labels: dofs)", fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    if ax.lines:
        ax.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=100)
    plt.close(fig)


def write_csv(path, rows):
    """One row per run; columns: the run, then each quantity with its exact
    value and error, then the phases in run order, then the totals."""
    fields = []
    for r in rows:
        fields += [k for k in r if k not in fields]
    times = ["time " + p for p in ordered_phases(rows)]
    quantities = [k for k in fields if k + "_exact" in fields]
    measured = [f for q in quantities for f in (q, q + "_exact", q + "_error")]
    first = [f for f in fields if f not in measured and not f.startswith("time ")
             and f not in ("wall time outside", "peak_memory_MiB", "cost_ratio")]
    fields = first + measured + times + [f for f in fields if f not in first + measured + times]
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=fields, restval="")
        writer.writeheader()
        writer.writerows(rows)


def check(csv_path, cases):
    """The table has rows for every case and every error is finite."""
    rows = list(csv.DictReader(open(csv_path)))
    problems = []
    for case in cases:
        mine = [r for r in rows if r["case"] == case.name]
        if not mine:
            problems.append(f"{case.name}: no rows")
        for r in mine:
            errors = {k: r[k] for k in r if k.endswith("_error") and r[k] != ""}
            if r["status"] != "completed":
                problems.append(f"{case.name} level {r['level']}: {r['status']}")
            elif not errors:
                problems.append(f"{case.name} level {r['level']}: no error column")
            for k, v in errors.items():
                if not math.isfinite(float(v or "nan")):
                    problems.append(f"{case.name} level {r['level']}: {k} = {v!r}")
    for p in problems:
        print("check failed:", p, file=sys.stderr)
    return not problems


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--exe", default=common.DEFAULT_EXE, help="the fdem-slope executable")
    parser.add_argument("--quick", action="store_true",
                        help="two coarse levels per case (smoke test); implies --check")
    parser.add_argument("--output-dir", help="where benchmarks.md goes (default doc/, "
                        "or ./benchmarks-quick with --quick)")
    parser.add_argument("--cases", help="comma-separated subset of: " +
                        ", ".join(c.name for c in CASES))
    parser.add_argument("--check", action="store_true",
                        help="fail unless every case has rows with finite errors")
    args = parser.parse_args()
    exe = os.path.abspath(args.exe)
    if not os.access(exe, os.X_OK):
        sys.exit(f"run_benchmarks.py: {exe} is not an executable (build it, or give --exe)")
    cases = CASES
    if args.cases:
        names = args.cases.split(",")
        unknown = set(names) - {c.name for c in CASES}
        if unknown:
            sys.exit(f"run_benchmarks.py: unknown case(s) {', '.join(sorted(unknown))}")
        cases = [c for c in CASES if c.name in names]
    out = os.path.abspath(args.output_dir or ("benchmarks-quick" if args.quick
                                              else os.path.join(common.ROOT, "doc")))
    figures = os.path.join(out, "benchmarks")
    os.makedirs(figures, exist_ok=True)

    load_before = os.getloadavg()
    started = datetime.datetime.now(datetime.timezone.utc)
    all_rows, sections, phases_by_case = [], {}, {}
    for case in cases:
        rows, quantities = [], []
        for level in (case.quick_levels if args.quick else case.levels):
            row, q = run_level(exe, case, level)
            quantities = quantities or q
            rows.append(row)
            print(f"{case.name} {case.level_name} = {level}: {row['status']}, "
                  f"{row['n_dofs']} dofs, {row['n_pairs']} pairs, "
                  f"{fmt_seconds(row['time total'])} s", flush=True)
        add_errors(case, rows, quantities)
        all_rows += rows
        sections[case.name] = (rows, quantities)
    load_after = os.getloadavg()
    phases = ordered_phases(all_rows)

    csv_path = os.path.join(figures, "benchmarks.csv")
    write_csv(csv_path, all_rows)
    doc_dir = os.path.dirname(os.path.join(out, "benchmarks.md"))
    lines = ["# Benchmarks: accuracy and cost", "",
             "Generated by `/usr/bin/python3 benchmarks/run_benchmarks.py"
             + (" --quick" if args.quick else "") + "` (do not edit by hand: rerun it). "
             f"Source {common.git_description()}, {started:%Y-%m-%d %H:%M} UTC, "
             f"{os.cpu_count()} cores ({platform.machine()}), load average "
             f"{load_before[0]:.1f} before and {load_after[0]:.1f} after the runs. "
             "One run per level; the times are wall-clock and vary from run to run, "
             "the more so the more loaded the machine.", "",
             "Each run's `summary.json` gives the wall time of every phase "
             "(`timings`, seconds, not nested, so they add up to `total` but for "
             "reading the parameters) and the peak resident memory "
             "(`peak_memory_MiB`, VmHWM from deal.II's get_memory_stats, the whole process). The phases: "
             "geometry (Gmsh mesh), limit equilibrium (every method on the section, 2D; in summaries of older programs outside every phase), setup (dofs, constraints, free rigid modes), "
             "assembly (K and F of each block), factorisation (K factorised; one "
             "phase 'assembly and factorisation' in summaries of older programs), "
             "one solve (u = K^-1 F for each block: one linear solve of the "
             "model), interfaces (node pairs), flexibility (C of eqs. 4-8), "
             "contact (the status iterations, all of them), safety factor (F_R "
             "and F_tau of each step), recovery (block displacements), output "
             "(files and the summary's reactions). "
             + ("Some runs here come from a program that timed assembly and "
                "factorisation as one phase. "
                if "assembly and factorisation" in phases else "")
             + "The safety-factor iteration costs its contact solves, its own "
             "'safety factor' phase, and with VTU output of every step (off here; "
             "Output/Write steps) recovery and output per step.", "",
             "The *cost ratio* is total / (geometry + setup + assembly + "
             "factorisation + one solve): what the run costs in units of one "
             "linear FE solve of the same model, measured in the same run.", "",
             f"Data: [benchmarks/benchmarks.csv](benchmarks/benchmarks.csv).", ""]
    lines += summary_section(all_rows, phases)
    for case in cases:
        rows, quantities = sections[case.name]
        image = os.path.join("benchmarks", case.name + ".png")
        plot(case, rows, quantities, os.path.join(out, image))
        case_lines, _ = case_section(case, rows, quantities, phases, image)
        lines += case_lines
    # The Scale section comes from benchmarks/scaling.py's data (a longer
    # run, made separately); it is kept when these cases are rerun.
    scaling_csv = os.path.join(figures, "scaling.csv")
    if os.path.exists(scaling_csv):
        lines += scaling.benchmarks_section(scaling_csv)
    # So is the Output cost section (benchmarks/output_cost.py).
    output_cost_csv = os.path.join(figures, "output_cost.csv")
    if os.path.exists(output_cost_csv):
        lines += [""] + output_cost.benchmarks_section(output_cost_csv)
    # And the Surface search section (benchmarks/surface_search.py).
    surface_search_md = os.path.join(figures, "surface_search.md")
    if os.path.exists(surface_search_md):
        lines += [""] + open(surface_search_md).read().splitlines()
    # What follows the Surface search section in the old file (the
    # probabilistic cost of benchmarks/probabilistic_cost.py and the text
    # that reads it) is kept as it is.
    md_path = os.path.join(doc_dir, "benchmarks.md")
    end_of_search = "<!-- /surface-search -->"
    if os.path.exists(md_path) and end_of_search in open(md_path).read():
        tail = open(md_path).read().split(end_of_search, 1)[1]
        if tail.strip():
            lines += tail.splitlines()
    with open(md_path, "w") as f:
        f.write("\n".join(lines))
    print(f"Wrote {os.path.join(doc_dir, 'benchmarks.md')} and {figures}/")

    ok = all(r["status"] == "completed" for r in all_rows)
    if args.check or args.quick:
        ok = check(csv_path, cases) and ok
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
