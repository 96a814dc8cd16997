#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""How the cost grows with degrees of freedom and with node pairs, and what
limits the size of a model.

    /usr/bin/python3 benchmarks/scaling.py [--exe build/fdem-slope]
        [--budget SECONDS] [--quick] [--output-dir DIR]

Three series, each refined until one run takes longer than --budget (default
600 s) or fails:
- 2D: the paper's slope (prm/paper_slope.prm), Geometry/Slope/Mesh size
  halved and more: dofs grow as h^-2, pairs only as h^-1;
- 3D: a block on a plane (prm/block_on_plane_3d.prm), elements along the
  plane n x n with two across each block's height: pairs grow as n^2, as
  fast as the dofs;
- the same 3D series with Solver/Mixed system = iterative (C never formed,
  applied through the factorisations inside GMRES), further out, and the
  crossover of the two 3D series.
Writes DIR/scaling.md (default doc/) with the tables, fitted exponents and
the extrapolation to 24 GiB, and DIR/benchmarks/scaling.csv. Every number in
scaling.md comes from this run.
"""
import argparse
import csv
import datetime
import math
import os
import platform
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402

MEMORY_GIB = 24.0
BLOCK_ON_PLANE_K = 1.24  # prm/block_on_plane_3d.prm, planar limit


def series_2d(quick):
    sizes = [1.0, 0.5] if quick else [1.0, 0.5, 0.25, 0.16, 0.1, 0.07, 0.05, 0.035]
    return [({"Geometry/Slope/Mesh size": h}, f"h = {h} m", None) for h in sizes]


def series_3d(quick, iterative=False):
    if quick:
        counts = [6, 10]
    else:
        counts = [6, 10, 16, 24, 32, 40, 48] + ([64, 80, 96] if iterative else [])
    extra = {"Solver/Mixed system": "iterative"} if iterative else {}
    return [({"Geometry/Block on plane/Elements along length": n,
              "Geometry/Block on plane/Elements along width": n, **extra},
             f"n = {n}", BLOCK_ON_PLANE_K) for n in counts]


def timing(summary, *names):
    return sum(summary["timings"].get(name, 0.0) for name in names)


def row_of(run, label, exact):
    s = run.summary
    pairs = common.n_pairs(s)
    solves = sum(step.get("n_contact_iterations", 0) for step in s.get("iterations", []))
    contact = timing(s, "contact")
    K = s.get("safety_factor")
    return {
        "level": label,
        "dofs": s["n_dofs"],
        "pairs": pairs,
        "mesh and setup (s)": timing(s, "geometry", "setup", "interfaces"),
        "assembly and factorisation (s)": timing(s, "assembly and factorisation", "assembly",
                                                 "factorisation"),
        "flexibility (s)": timing(s, "flexibility"),
        "contact solves": solves,
        "contact (s)": contact,
        "per contact solve (s)": contact / solves if solves else math.nan,
        "total (s)": timing(s, "total"),
        "peak memory (MiB)": s["peak_memory_MiB"],
        "K": K,
        "error": (K / exact - 1) if (exact and isinstance(K, (int, float))) else math.nan,
        "GMRES per contact solve": (s["contact"].get("n_gmres_iterations", 0) / solves
                                    if solves else math.nan),
    }


def run_series(exe, prm, levels, budget):
    rows, stop = [], ""
    for settings, label, exact in levels:
        run = common.run_case(exe, prm, settings, timeout=max(3 * budget, 60))
        if not run.ok:
            stop = f"{label}: {run.failure()}"
            break
        rows.append(row_of(run, label, exact))
        print(f"  {prm} {label}: {rows[-1]['dofs']} dofs, {rows[-1]['pairs']} pairs, "
              f"{rows[-1]['total (s)']:.1f} s, {rows[-1]['peak memory (MiB)']:.0f} MiB",
              flush=True)
        if rows[-1]["total (s)"] > budget:
            stop = f"{label} took {rows[-1]['total (s)']:.0f} s, more than the budget of {budget:.0f} s"
            break
    return rows, stop or "all levels ran"


def fmt(x):
    return common.number(x, 3)


COLUMNS = ["level", "dofs", "pairs", "mesh and setup (s)", "assembly and factorisation (s)",
           "flexibility (s)", "contact solves", "per contact solve (s)", "contact (s)",
           "total (s)", "peak memory (MiB)", "K", "error"]


def exponents(rows, key):
    """Exponents of the phases against @p key ('dofs' or 'pairs') over the
    last three levels (the asymptotic range)."""
    tail = rows[-3:]
    xs = [r[key] for r in tail]
    out = {}
    for phase in ["assembly and factorisation (s)", "flexibility (s)", "per contact solve (s)",
                  "total (s)", "peak memory (MiB)"]:
        out[phase] = common.fit_exponent(xs, [r[phase] for r in tail])
    return out


def extrapolate(rows, key, phase, target):
    """@p key at which @p phase reaches @p target along the power law of
    the last three levels (NaN if it does not grow)."""
    b = exponents(rows, key)[phase]
    last = rows[-1]
    if not (b > 0) or not last[phase] > 0:
        return math.nan, b
    return last[key] * (target / last[phase]) ** (1 / b), b


def growth_lines(rows):
    """Bullets on how the cost of a series grows, from its last three
    levels, and where it would reach the machine's memory."""
    if len(rows) < 3:
        return ["- Fewer than three levels ran: no growth fitted."]
    lines = []
    for key in ("dofs", "pairs"):
        e = exponents(rows, key)
        lines.append(f"- Growth against {key} (power-law exponent over the last three "
                     "levels): " + ", ".join(f"{k.split(' (')[0]} {fmt(v)}"
                                             for k, v in e.items()) + ".")
    last = rows[-1]
    phases = ["mesh and setup (s)", "assembly and factorisation (s)", "flexibility (s)",
              "contact (s)"]
    top = max(phases, key=lambda k: last[k])
    lines.append(f"- At the largest level ({last['dofs']} dofs, {last['pairs']} pairs) "
                 f"{top.split(' (')[0]} takes {fmt(100 * last[top] / last['total (s)'])} % "
                 f"of the {fmt(last['total (s)'])} s.")
    memory_dofs, b = extrapolate(rows, "dofs", "peak memory (MiB)", MEMORY_GIB * 1024)
    if b < 1:
        # Below linear growth the process's fixed part still dominates the
        # peak: an extrapolation of the fit would say nothing about the limit.
        lines.append(f"- Peak memory grows as dofs^{fmt(b)}, less than linearly: the "
                     "process's fixed part still dominates it, so memory is not what "
                     "limits this series.")
    elif math.isfinite(memory_dofs):
        time_b = exponents(rows, "dofs")["total (s)"]
        seconds = last["total (s)"] * (memory_dofs / last["dofs"]) ** time_b
        lines.append(f"- Peak memory grows as dofs^{fmt(b)}: {MEMORY_GIB:.0f} GiB would be "
                     f"reached at about {fmt(memory_dofs)} dofs, where the run would take "
                     f"about {fmt(seconds)} s (total time as dofs^{fmt(time_b)}).")
    return lines


def section(title, rows, stop, description, columns=COLUMNS):
    lines = [f"## {title}", "", description, "",
             *common.markdown_table(columns, [[fmt(r[c]) for c in columns] for r in rows],
                                    "l" + "r" * (len(columns) - 1)),
             "", f"The series stopped: {stop}.", ""]
    return lines + growth_lines(rows) + [""]


SERIES = [("2D paper slope", "2D: the paper's slope"), ("3D block on plane", "3D: block on a plane"),
          ("3D block on plane, iterative", "3D: block on a plane, iterative mixed system")]
ITERATIVE_COLUMNS = COLUMNS[:-2] + ["GMRES per contact solve", "K", "error"]


def crossover_lines(dense, iterative, table=True):
    """The dense and the iterative 3D series side by side, level by level
    (if @p table), and where the iterative one becomes the faster."""
    by_level = {r["level"]: r for r in dense}
    columns = ["level", "pairs", "dense total (s)", "iterative total (s)", "time ratio",
               "dense memory (MiB)", "iterative memory (MiB)", "memory ratio",
               "K difference"]
    rows, first_faster = [], None
    for r in iterative:
        d = by_level.get(r["level"])
        if d is None:
            rows.append([r["level"], r["pairs"], "–", fmt(r["total (s)"]), "–", "–",
                          fmt(r["peak memory (MiB)"]), "–", "–"])
            continue
        ratio = d["total (s)"] / r["total (s)"]
        if ratio > 1 and first_faster is None:
            first_faster = r
        rows.append([r["level"], r["pairs"], fmt(d["total (s)"]), fmt(r["total (s)"]),
                      fmt(ratio), fmt(d["peak memory (MiB)"]), fmt(r["peak memory (MiB)"]),
                      fmt(d["peak memory (MiB)"] / r["peak memory (MiB)"]),
                      fmt(r["K"] - d["K"]) if isinstance(r["K"], float) and
                      isinstance(d["K"], float) else "–"])
    lines = ["## Crossover: dense against iterative mixed system (3D)", "",
             "The two 3D series level by level (ratios dense / iterative; above 1 the "
             "iterative solver is the cheaper).", "",
             *common.markdown_table(columns, rows, "l" + "r" * (len(columns) - 1)),
             ""] if table else []
    if first_faster is not None:
        lines.append(f"- The iterative solver is the faster from {first_faster['level']} "
                     f"({first_faster['pairs']} pairs) on, in this run.")
    else:
        lines.append("- The iterative solver was not the faster at any level both series ran.")
    if iterative and dense and iterative[-1]["pairs"] > dense[-1]["pairs"]:
        lines.append(f"- The iterative series went on to {iterative[-1]['pairs']} pairs "
                     f"({iterative[-1]['dofs']} dofs) in {fmt(iterative[-1]['total (s)'])} s "
                     f"and {fmt(iterative[-1]['peak memory (MiB)'])} MiB.")
    return lines + [""]


def read_csv(path):
    """The rows of scaling.csv by series, numbers as numbers."""
    by_series = {}
    for row in common.read_typed_csv(path):
        by_series.setdefault(row.pop("series"), []).append(row)
    return by_series


def benchmarks_section(csv_path):
    """The section 'Scale' of doc/benchmarks.md, from scaling.csv: how the
    cost grows in each series and what limits it (the tables are in
    doc/scaling.md)."""
    lines = ["<!-- scale: written from benchmarks/scaling.csv -->", "## Scale", "",
             "How the cost grows with dofs and with pairs, from `benchmarks/scaling.py` "
             "(tables and the machine's load in [scaling.md](scaling.md)):", ""]
    by_series = read_csv(csv_path)
    for key, title in SERIES:
        rows = by_series.get(key, [])
        lines += [f"**{title}**", ""] + growth_lines(rows) + [""]
    dense, iterative = by_series.get(SERIES[1][0], []), by_series.get(SERIES[2][0], [])
    if dense and iterative:
        lines += ["**3D: dense against iterative**", ""] + crossover_lines(dense, iterative,
                                                                           table=False)
    return lines + ["<!-- /scale -->", ""]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--exe", default=common.DEFAULT_EXE)
    parser.add_argument("--budget", type=float, default=600.0)
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--output-dir", default=None)
    args = parser.parse_args()
    args.exe = os.path.abspath(args.exe)
    doc_dir = args.output_dir or (os.path.join(os.getcwd(), "scaling-quick") if args.quick
                                  else os.path.join(common.ROOT, "doc"))
    os.makedirs(os.path.join(doc_dir, "benchmarks"), exist_ok=True)
    load = open("/proc/loadavg").read().split()[:3]

    print("2D: the paper's slope", flush=True)
    rows_2d, stop_2d = run_series(args.exe, "paper_slope.prm", series_2d(args.quick), args.budget)
    print("3D: block on a plane", flush=True)
    rows_3d, stop_3d = run_series(args.exe, "block_on_plane_3d.prm", series_3d(args.quick),
                                  args.budget)
    print("3D: block on a plane, iterative mixed system", flush=True)
    rows_it, stop_it = run_series(args.exe, "block_on_plane_3d.prm",
                                  series_3d(args.quick, iterative=True), args.budget)

    with open(os.path.join(doc_dir, "benchmarks", "scaling.csv"), "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["series"] + ITERATIVE_COLUMNS)
        for (name, _), rows in zip(SERIES, (rows_2d, rows_3d, rows_it)):
            for r in rows:
                writer.writerow([name] + [r[c] for c in ITERATIVE_COLUMNS])

    lines = [
        "# Scale: how the cost grows, and what limits it", "",
        f"Written by `benchmarks/scaling.py` on {datetime.date.today()} ({common.git_description()}), "
        f"{platform.node()}, {os.cpu_count()} cores, load average {' '.join(load)} at the start, "
        f"run budget {args.budget:.0f} s. Single runs: times are noisy, ratios within a row "
        "are what to read.", "",
        "Columns: the phases as `summary.json` times them; *contact solves* is the number of "
        "solves of the mixed system (eq. 9) over all status and safety-factor iterations, "
        "*per contact solve* the contact time over that number; *error* is against the exact "
        "K where there is one (the 3D block: planar limit 1.24).", "",
    ]
    lines += section("2D: the paper's slope", rows_2d, stop_2d,
                     "prm/paper_slope.prm with its mesh size refined. The interface is a line: "
                     "pairs grow as the square root of the dofs, so the dense mixed system "
                     "(2 per pair) stays small and the FE part dominates.")
    lines += section("3D: block on a plane", rows_3d, stop_3d,
                     "prm/block_on_plane_3d.prm with n x n elements along the plane and two "
                     "across each block's height: pairs (n + 1)^2 grow as fast as the dofs, "
                     "the case where the dense parts (the interface flexibility C, the Schur "
                     "complement of the interface dofs, the mixed system's LU) count most.")
    lines += section("3D: block on a plane, iterative mixed system", rows_it, stop_it,
                     "The same series with Solver/Mixed system = iterative: C is never formed "
                     "but applied through the blocks' factorisations (one solve per block) in "
                     "each GMRES iteration, preconditioned by the pairs' own blocks of P C P "
                     "(P onto ker W^T) with a coarse correction on groups of neighbouring "
                     "pairs; *flexibility* is then only those blocks and the coarse space. *GMRES per contact "
                     "solve* is the mean number of iterations.", ITERATIVE_COLUMNS)
    lines += crossover_lines(rows_3d, rows_it)
    # The section of benchmarks/slope_3d_scaling.py is kept as it is.
    scaling_md = os.path.join(doc_dir, "scaling.md")
    old = open(scaling_md).read() if os.path.exists(scaling_md) else ""
    if "<!-- slope3d:" in old and "<!-- /slope3d -->" in old:
        lines += [old[old.index("<!-- slope3d:"):old.index("<!-- /slope3d -->")] +
                  "<!-- /slope3d -->", ""]
    with open(scaling_md, "w") as f:
        f.write("\n".join(lines))
    csv_path = os.path.join(doc_dir, "benchmarks", "scaling.csv")
    common.put_benchmarks_section(os.path.join(doc_dir, "benchmarks.md"), benchmarks_section(csv_path),
                                  "scale")
    print(f"wrote {os.path.join(doc_dir, 'scaling.md')} and the Scale section of benchmarks.md")
    return 0 if rows_2d and rows_3d and rows_it else 1


if __name__ == "__main__":
    sys.exit(main())
