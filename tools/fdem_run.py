# SPDX-License-Identifier: LGPL-2.1-or-later
"""Running fdem-slope on a case and reading what the run wrote: the one
helper that tests/scripts/run_checks.py, tools/compare_runs.py and the
benchmarks (through benchmarks/common.py) share. It lives in tools/ since
neither the tests nor the benchmarks own it. Runs under /usr/bin/python3.

A case is a .prm file: a path, or the name of a file in prm/. In a .prm
file, and in the files it includes, @PRM_DIR@ stands for the project's prm/
folder and @DATA_DIR@ for the data/ folder beside that file; the program
itself knows neither, so they are filled in before the run.
"""
import contextlib
import json
import os
import re
import subprocess
import tempfile
import time

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
PRM_DIR = os.path.join(ROOT, "prm")
DEFAULT_EXE = os.path.join(ROOT, "build", "fdem-slope")

# Entries of summary.json that measure the run, not its result.
VOLATILE_KEYS = ("timings", "peak_memory_MiB")

PLACEHOLDERS = ("@PRM_DIR@", "@DATA_DIR@")
INCLUDE = re.compile(r"^(\s*include\s+)(\S.*?)\s*$", re.MULTILINE)
# The entries that name input files (parameters::input_file_entries()): the
# program reads them, as includes, relative to the file that sets them.
FILE_ENTRY = re.compile(r"^(\s*set\s+(?:Mesh file|Terrain file|Piezometric surface file|"
                        r"Acceleration record)\s*=\s*)([^#\n]*?)\s*$", re.MULTILINE)
# Where filled copies of included files go, inside the run's folder.
INCLUDED = "included"


def case_path(prm):
    """The absolute path of a case: @p prm as given if it exists, else the
    file of that name in prm/."""
    return os.path.abspath(prm if os.path.exists(prm) else os.path.join(PRM_DIR, prm))


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
    dict from 'Sub/Section/Entry' to the value's text. Includes are not
    followed: read a run's parameters.prm for everything a case sets."""
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


def fill_placeholders(prm, workdir, copy=None, being_filled=()):
    """The file to run for the case @p prm. When neither it nor a file it
    includes holds a placeholder, that is @p prm itself. Otherwise a copy
    with the placeholders filled, at @p copy (default: its name in
    @p workdir), whose includes point to filled copies where those hold
    placeholders (in workdir/included), and whose relative includes and file
    entries are made absolute from @p prm's folder (the program reads them
    relative to the file that names them, and the copy is elsewhere)."""
    prm = os.path.abspath(prm)
    being_filled = being_filled + (prm,)
    folder_of_prm = os.path.dirname(prm)
    original = open(prm).read()
    text = original.replace("@PRM_DIR@", PRM_DIR)
    text = text.replace("@DATA_DIR@", os.path.join(folder_of_prm, "data"))

    def absolute(match):
        target = match.group(2)
        if not target or os.path.isabs(target):
            return match.group(0)
        return match.group(1) + os.path.join(folder_of_prm, target)

    def filled_include(match):
        target = match.group(2)
        if not os.path.isabs(target):
            target = os.path.join(folder_of_prm, target)
        # A file that includes itself is left to the program to refuse.
        if not os.path.isfile(target) or os.path.abspath(target) in being_filled:
            return match.group(0)
        folder = os.path.join(workdir, INCLUDED)
        os.makedirs(folder, exist_ok=True)
        handle, name = tempfile.mkstemp(suffix="-" + os.path.basename(target), dir=folder)
        os.close(handle)
        filled = fill_placeholders(target, workdir, name, being_filled)
        return match.group(0) if filled == target else match.group(1) + filled

    text = INCLUDE.sub(filled_include, text)
    if text == original:
        return prm
    text = INCLUDE.sub(absolute, FILE_ENTRY.sub(absolute, text))
    copy = copy or os.path.join(workdir, os.path.basename(prm))
    with open(copy, "w") as f:
        f.write(text)
    return copy


class Run:
    """One run of the executable: the .prm file it ran (@c prm), the folder
    it ran in (@c workdir) and its output folder (@c output; both gone once
    a temporary folder is removed), the summary.json (None if it wrote none)
    and parameters.prm (a dict, see parse_prm; empty if none) found there,
    the exit code, stdout, stderr and wall time (s, measured from outside,
    start-up included)."""

    def __init__(self, prm, workdir, output, returncode, stdout, stderr, wall):
        self.prm = prm
        self.workdir = workdir
        self.output = output
        self.returncode = returncode
        self.stdout = stdout
        self.stderr = stderr
        self.wall = wall
        summary_file = os.path.join(output, "summary.json")
        self.summary = json.load(open(summary_file)) if os.path.exists(summary_file) else None
        parameters_file = os.path.join(output, "parameters.prm")
        self.parameters = (parse_prm(open(parameters_file).read())
                           if os.path.exists(parameters_file) else {})

    @property
    def ok(self):
        return self.returncode == 0 and self.summary is not None

    def failure(self):
        """Why the run gave no result, on one line ('' if it did)."""
        if self.ok:
            return ""
        lines = self.stderr.strip().splitlines()
        return f"exit code {self.returncode}: " + (lines[-1] if lines else "no message")

    def file(self, name):
        """The path of the output file @p name."""
        return os.path.join(self.output, name)


def makes_report(report):
    """Whether a run makes its report.html: @p report if given, else the
    case's own Output/Report, unless FDEM_RUN_NO_REPORT=1 is set (the tests
    set it, tests/CMakeLists.txt: only the report's own tests look at the
    report, which costs about a second a run)."""
    if report is not None:
        return report
    return os.environ.get("FDEM_RUN_NO_REPORT", "0") != "1"


def run(exe, prm, workdir, settings=None, files=None, args=(), launcher=(), env=None,
        timeout=600, report=None):
    """Runs the case @p prm (see case_path) in @p workdir, with the entries
    of @p settings (see prm_settings) set after the case's own; @p files maps
    names to texts written into workdir first (e.g. a refined .geo; a
    relative 'Mesh file' of such a case is relative to workdir). @p args go
    to the program before the .prm file (e.g. --validate), @p launcher
    before the program (e.g. mpirun -np 2). The output folder is the one of
    Output/Directory in @p settings (relative to workdir), else the
    program's default, workdir/<case>-output. With @p report False (or, by
    default, FDEM_RUN_NO_REPORT=1: see makes_report) the program runs with
    --no-report."""
    for name, text in (files or {}).items():
        with open(os.path.join(workdir, name), "w") as f:
            f.write(text)
    base = case_path(prm)
    name = os.path.basename(base)
    if settings:
        os.makedirs(os.path.join(workdir, INCLUDED), exist_ok=True)
        included = fill_placeholders(base, workdir, os.path.join(workdir, INCLUDED, name))
        path = os.path.join(workdir, name)
        with open(path, "w") as f:
            f.write(f"include {included}\n" + prm_settings(settings))
    else:
        path = fill_placeholders(base, workdir)
    # A relative Output/Directory is relative to the working folder.
    output = os.path.join(workdir, (settings or {}).get("Output/Directory") or
                          os.path.splitext(name)[0] + "-output")
    # The run's folder is not ours: a relative path to the program must not
    # depend on it (a bare name is looked up on PATH).
    if os.sep in exe:
        exe = os.path.abspath(exe)
    if not makes_report(report):
        args = ("--no-report", *args)
    start = time.perf_counter()
    try:
        result = subprocess.run([*launcher, exe, *args, path], cwd=workdir, capture_output=True,
                                text=True, timeout=timeout, env=env)
        returncode, stdout, stderr = result.returncode, result.stdout, result.stderr
    except subprocess.TimeoutExpired:
        returncode, stdout, stderr = -1, "", f"timed out after {timeout} s"
    wall = time.perf_counter() - start
    return Run(path, workdir, output, returncode, stdout, stderr, wall)


@contextlib.contextmanager
def temporary_run(exe, prm, **kwargs):
    """run() in a fresh temporary folder, removed when the with-block ends:
    read the output files inside it."""
    with tempfile.TemporaryDirectory(prefix="fdem-run-") as workdir:
        yield run(exe, prm, workdir, **kwargs)


def run_case(exe, prm, **kwargs):
    """run() in a fresh temporary folder; the Run keeps the summary and
    parameters, the output files are gone."""
    with temporary_run(exe, prm, **kwargs) as result:
        return result


def result_part(summary):
    """summary.json without what measures the run (wall times, peak memory):
    two runs of the same input must agree on all of it, byte for byte."""
    summary = json.loads(json.dumps(summary))
    for key in VOLATILE_KEYS:
        summary.pop(key, None)
    if isinstance(summary.get("stiffness_sensitivity"), dict):
        summary["stiffness_sensitivity"].pop("wall_seconds", None)
    if isinstance(summary.get("report"), dict):
        summary["report"].pop("wall_seconds", None)
    return summary
