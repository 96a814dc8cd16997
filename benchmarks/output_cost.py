#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Output's share of the run time on every shipped case (prm/*.prm), as a
user runs them (the cases' own Output settings, VTU files included).

    /usr/bin/python3 benchmarks/output_cost.py --label after [--exe build/fdem-slope]
        [--repeat 3] [--output-dir doc]

Runs each case --repeat times and keeps the run with the median total time.
Its summary.json gives the phases' wall times: 'output' (the VTU/PVD, CSV
and JSON files, and the reactions) and 'recovery' (the block displacements:
once for the final state, and once per safety-factor step whose files are
written). Stores one row per case and label in DIR/benchmarks/output_cost.csv
(rows of other labels are kept: run it with --label before on an older
program, then with --label after) and writes the section "Output cost" of
DIR/benchmarks.md from that file (run_benchmarks.py keeps it).
"""
import argparse
import csv
import glob
import os
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import common  # noqa: E402
import fdem_run  # noqa: E402

FIELDS = ["case", "label", "program", "total_s", "output_s", "recovery_s", "output_share",
          "output_and_recovery_share", "files", "MB", "vtu_files", "load"]


def measure(exe, prm, repeat):
    """The run of @p prm with the median total of @p repeat runs: its row."""
    runs = []
    load = os.getloadavg()[0]
    for _ in range(repeat):
        with fdem_run.temporary_run(exe, prm) as run:
            if not run.ok:
                return {"total_s": "failed: " + run.failure()}
            files = [os.path.join(run.output, f) for f in os.listdir(run.output)]
            size = sum(os.path.getsize(f) for f in files if os.path.isfile(f))
        t = run.summary["timings"]
        runs.append({"total_s": t["total"], "output_s": t.get("output", 0.0),
                     "recovery_s": t.get("recovery", 0.0), "files": len(files),
                     "MB": size / 1e6,
                     "vtu_files": sum(1 for f in files if f.endswith(".vtu"))})
    median = statistics.median(r["total_s"] for r in runs)
    row = min(runs, key=lambda r: abs(r["total_s"] - median))
    row["load"] = load
    row["output_share"] = row["output_s"] / row["total_s"]
    row["output_and_recovery_share"] = (row["output_s"] + row["recovery_s"]) / row["total_s"]
    return row


def read_rows(path):
    return list(csv.DictReader(open(path))) if os.path.exists(path) else []


def benchmarks_section(csv_path):
    """The section 'Output cost' of doc/benchmarks.md, from output_cost.csv."""
    rows = read_rows(csv_path)
    labels = sorted({r["label"] for r in rows}, key=lambda l: (l != "before", l))
    cases = sorted({r["case"] for r in rows})
    by = {(r["case"], r["label"]): r for r in rows}
    lines = ["<!-- output cost: written by benchmarks/output_cost.py -->", "## Output cost", "",
             "What writing the results costs on every shipped case, run as a user runs it "
             "(`/usr/bin/python3 benchmarks/output_cost.py`: each case three times, the run "
             "with the median total kept). *output* is the phase 'output' of summary.json "
             "(VTU/PVD, CSV and JSON files, and the reactions); *recovery* the block "
             "displacements (once for the final state, which the summary needs too, and once "
             "per step whose VTU files are written). Programs: "
             + "; ".join(f"{label}: {next(r['program'] for r in rows if r['label'] == label)}"
                         for label in labels) + ".", "",
             "'before' wrote every safety-factor step's VTU files and the final state's, "
             "through deal.II's DataOut at its default (best) zlib compression; 'after' writes "
             "the final state only unless `Output/Write steps = true`, with the program's "
             "own writer (binary, appended raw, zlib at its fastest level), and adds the "
             "mechanism displacement (one more solve per block) to the final state.", ""]
    header = ["case"]
    for label in labels:
        header += [f"total (s), {label}", f"output (s), {label}", f"recovery (s), {label}",
                   f"output share, {label}", f"output + recovery share, {label}",
                   f"files (MB), {label}"]
    table = []
    for case in cases:
        row = [case]
        for label in labels:
            r = by.get((case, label))
            if r is None or r["total_s"].startswith("failed"):
                row += ["–"] * 6
                continue
            row += [f"{float(r['total_s']):.3g}", f"{float(r['output_s']):.3g}",
                    f"{float(r['recovery_s']):.3g}",
                    f"{100 * float(r['output_share']):.0f} %",
                    f"{100 * float(r['output_and_recovery_share']):.0f} %",
                    f"{float(r['MB']):.2g}"]
        table.append(row)
    lines += common.markdown_table(header, table, "l" + "r" * (len(header) - 1))
    for label in labels:
        shares = [float(by[(c, label)]["output_and_recovery_share"]) for c in cases
                  if (c, label) in by and not by[(c, label)]["total_s"].startswith("failed")]
        if shares:
            lines += ["", f"{label}: output and recovery take {100 * min(shares):.0f} % to "
                      f"{100 * max(shares):.0f} % of the run (median "
                      f"{100 * statistics.median(shares):.0f} %) over {len(shares)} cases."]
        loads = [float(by[(c, label)]["load"]) for c in cases
                 if (c, label) in by and by[(c, label)].get("load")]
        if loads:
            lines += [f"The machine's load average (1 minute) before each case of '{label}': "
                      f"{min(loads):.1f} to {max(loads):.1f} on {os.cpu_count()} cores, "
                      "shared with other work; the totals vary with it, the shares less."]
    lines += ["<!-- /output cost -->", ""]
    return lines


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--exe", default=common.DEFAULT_EXE)
    parser.add_argument("--label", required=True, help="e.g. before or after")
    parser.add_argument("--program", default=None,
                        help="what the program is (default: git description of the tree)")
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--cases", default=None, help="comma-separated names in prm/")
    parser.add_argument("--output-dir", default=os.path.join(common.ROOT, "doc"))
    args = parser.parse_args()
    exe = os.path.abspath(args.exe)
    names = (args.cases.split(",") if args.cases else
             sorted(os.path.basename(p)[:-4] for p in glob.glob(os.path.join(common.PRM_DIR, "*.prm"))))
    csv_path = os.path.join(args.output_dir, "benchmarks", "output_cost.csv")
    os.makedirs(os.path.dirname(csv_path), exist_ok=True)
    rows = [r for r in read_rows(csv_path)
            if not (r["label"] == args.label and r["case"] in names)]
    program = args.program or common.git_description()
    for name in names:
        row = measure(exe, name + ".prm", args.repeat)
        row.update(case=name, label=args.label, program=program)
        print(name, {k: row.get(k) for k in ("total_s", "output_s", "recovery_s", "MB")},
              flush=True)
        rows.append(row)
        # After each case: an interrupted run keeps what it measured.
        with open(csv_path, "w", newline="") as f:
            writer = csv.DictWriter(f, fieldnames=FIELDS, restval="")
            writer.writeheader()
            writer.writerows(sorted(rows, key=lambda r: (r["label"], r["case"])))
    common.put_benchmarks_section(os.path.join(args.output_dir, "benchmarks.md"),
                                  benchmarks_section(csv_path), "output cost")
    print(f"wrote {csv_path} and the Output cost section of benchmarks.md")
    return 0


if __name__ == "__main__":
    sys.exit(main())
