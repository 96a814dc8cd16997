# SPDX-License-Identifier: LGPL-2.1-or-later
"""What the benchmark scripts share: running a case of prm/ with some
parameters changed, reading what the run wrote, and small helpers for the
tables and fits. Runs under /usr/bin/python3 (Debian's, with numpy and
matplotlib).
"""
import csv
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tools"))
# tools/fdem_run.py runs the cases (the tests' helper too); its names are
# used from here as common.ROOT, common.prm_settings etc.
from fdem_run import DEFAULT_EXE, PRM_DIR, ROOT, Run, parse_prm, prm_settings  # noqa: E402,F401
import fdem_run  # noqa: E402


def run_case(exe, prm, settings=None, files=None, timeout=1800, write_vtu=False, **kwargs):
    """fdem_run.run_case() as the benchmarks run a case: @p prm (a name in
    prm/ or a path) with @p settings, in a fresh temporary folder, the output
    in its folder 'output', and VTU output off unless asked for (it is not
    what the benchmarks measure). @p files and the other arguments: see
    fdem_run.run()."""
    settings = dict(settings or {})
    settings.setdefault("Output/Write VTU", "true" if write_vtu else "false")
    settings["Output/Directory"] = "output"
    return fdem_run.run_case(exe, prm, settings=settings, files=files, timeout=timeout, **kwargs)


def n_pairs(summary):
    """Node pairs of all interfaces of a run."""
    return sum(interface["n_pairs"] for interface in summary["interfaces"])


def fit_exponent(xs, ys):
    """Least-squares slope b of log y = a + b log x; NaN with fewer than two
    usable points (positive x and y, not all x equal)."""
    points = [(math.log(x), math.log(y)) for x, y in zip(xs, ys)
              if x and y and x > 0 and y > 0 and math.isfinite(x) and math.isfinite(y)]
    if len(points) < 2:
        return math.nan
    mx = sum(p[0] for p in points) / len(points)
    my = sum(p[1] for p in points) / len(points)
    sxx = sum((p[0] - mx) ** 2 for p in points)
    if sxx == 0:
        return math.nan
    return sum((p[0] - mx) * (p[1] - my) for p in points) / sxx


def number(x, significant=3):
    """A table cell: text as it is, integers (and floats of 100 or more)
    without decimals, '–' for None or a non-finite number, else
    @p significant digits (exponent form below 0.01)."""
    if isinstance(x, str):
        return x
    if isinstance(x, int):
        return str(x)
    if x is None or not math.isfinite(x):
        return "–"
    if x == 0:
        return "0"
    if abs(x) >= 100:
        return f"{x:.0f}"
    if abs(x) >= 0.01:
        return f"{x:.{significant}g}"
    return f"{x:.2e}"


def markdown_table(header, rows, align=None):
    """A markdown table; @p align is a string of 'l'/'r' per column (default
    all right-aligned)."""
    align = align or "r" * len(header)
    rule = ["---" if a == "l" else "---:" for a in align]
    lines = ["| " + " | ".join(header) + " |", "| " + " | ".join(rule) + " |"]
    lines += ["| " + " | ".join(str(cell) for cell in row) + " |" for row in rows]
    return lines


def git_description():
    """The commit of the source tree, with '+changes' if it has local changes."""
    def git(*args):
        return subprocess.run(["git", "-C", ROOT, *args], capture_output=True,
                              text=True).stdout.strip()
    commit = git("rev-parse", "--short", "HEAD") or "unknown"
    return commit + ("+changes" if git("status", "--porcelain", "--untracked-files=no") else "")


def read_typed_csv(path):
    """The rows of a CSV file as dicts, with integers and floats converted
    (the other cells stay text)."""
    rows = []
    with open(path) as f:
        for record in csv.DictReader(f):
            row = {}
            for key, value in record.items():
                for kind in (int, float):
                    try:
                        row[key] = kind(value)
                        break
                    except ValueError:
                        continue
                else:
                    row[key] = value
            rows.append(row)
    return rows


def put_benchmarks_section(md_path, lines, marker):
    """Replaces the section of @p md_path between "<!-- marker:" and
    "<!-- /marker -->" by @p lines (which carry both), or appends them."""
    text = open(md_path).read() if os.path.exists(md_path) else ""
    start, end = f"<!-- {marker}:", f"<!-- /{marker} -->"
    if start in text and end in text:
        a = text.index(start)
        b = text.index(end) + len(end)
        text = text[:a].rstrip("\n") + "\n\n" + "\n".join(lines).strip("\n") + text[b:]
    else:
        text = text.rstrip("\n") + "\n\n" + "\n".join(lines)
    with open(md_path, "w") as f:
        f.write(text)
