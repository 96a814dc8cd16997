# SPDX-License-Identifier: LGPL-2.1-or-later
"""What the benchmark scripts share: running a case of prm/ with some
parameters changed, reading what the run wrote, and small helpers for the
tables and fits. Runs under /usr/bin/python3 (Debian's, with numpy and
matplotlib).
"""
import csv
import json
import math
import os
import subprocess
import tempfile
import time

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
PRM_DIR = os.path.join(ROOT, "prm")
DEFAULT_EXE = os.path.join(ROOT, "build", "fdem-slope")


def prm_settings(settings):
    """The .prm text that sets @p settings, a dict from 'Sub/Section/Entry'
    paths to values: entries of one subsection are grouped into one block."""
    tree = {}
    for path, value in settings.items():
        *sections, entry = path.split("/")
        node = tree
        for section in sections:
            node = node.setdefault(section, {})
        node[entry] = value

    def lines(node, indent):
        out = []
        for key, value in node.items():
            if isinstance(value, dict):
                out.append(f"{indent}subsection {key}")
                out += lines(value, indent + "  ")
                out.append(f"{indent}end")
            else:
                out.append(f"{indent}set {key} = {value}")
        return out

    return "\n".join(lines(tree, "")) + "\n"


def parse_prm(text):
    """Entries of a .prm file (e.g. the parameters.prm a run writes) as a
    dict from 'Sub/Section/Entry' to the value's text."""
    values, sections = {}, []
    for raw in text.splitlines():
        line = raw.split("#", 1)[0].strip()
        if line.startswith("subsection "):
            sections.append(line[len("subsection "):].strip())
        elif line == "end":
            sections.pop()
        elif line.startswith("set ") and "=" in line:
            key, value = line[4:].split("=", 1)
            values["/".join(sections + [key.strip()])] = value.strip()
    return values


class Run:
    """One run of the executable: its summary.json (None if it wrote none),
    the parameters it used, its exit code, stderr and wall time (s, measured
    from outside, start-up included)."""

    def __init__(self, summary, parameters, returncode, stderr, wall):
        self.summary = summary
        self.parameters = parameters
        self.returncode = returncode
        self.stderr = stderr
        self.wall = wall

    @property
    def ok(self):
        return self.returncode == 0 and self.summary is not None

    def failure(self):
        """Why the run gave no result, on one line ('' if it did)."""
        if self.ok:
            return ""
        lines = self.stderr.strip().splitlines()
        return f"exit code {self.returncode}: " + (lines[-1] if lines else "no message")


def run_case(exe, prm, settings=None, files=None, timeout=1800, write_vtu=False):
    """Runs prm/@p prm (a name in prm/ or a path) with @p settings (see
    prm_settings) in a fresh temporary folder. @p files maps names to texts
    written next to the .prm first (e.g. a refined .geo); a relative 'Mesh
    file' is relative to that folder. VTU output is off unless asked for: it
    is not what the benchmarks measure."""
    base = prm if os.path.isabs(prm) else os.path.join(PRM_DIR, prm)
    settings = dict(settings or {})
    settings.setdefault("Output/Write VTU", "true" if write_vtu else "false")
    with tempfile.TemporaryDirectory(prefix="fdem-bench-") as workdir:
        out = os.path.join(workdir, "output")
        settings["Output/Directory"] = out
        for name, text in (files or {}).items():
            with open(os.path.join(workdir, name), "w") as f:
                f.write(text)
        case_prm = os.path.join(workdir, os.path.basename(base))
        with open(case_prm, "w") as f:
            f.write(f"include {base}\n" + prm_settings(settings))
        start = time.perf_counter()
        try:
            result = subprocess.run([exe, case_prm], cwd=workdir, capture_output=True,
                                    text=True, timeout=timeout)
            returncode, stderr = result.returncode, result.stderr
        except subprocess.TimeoutExpired:
            returncode, stderr = -1, f"timed out after {timeout} s"
        wall = time.perf_counter() - start
        summary_file = os.path.join(out, "summary.json")
        summary = json.load(open(summary_file)) if os.path.exists(summary_file) else None
        parameters_file = os.path.join(out, "parameters.prm")
        parameters = parse_prm(open(parameters_file).read()) if os.path.exists(parameters_file) else {}
    return Run(summary, parameters, returncode, stderr, wall)


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
