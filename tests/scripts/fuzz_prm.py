# SPDX-License-Identifier: LGPL-2.1-or-later
"""Fuzz test of the input contract (issue 16): mutate the shipped prm/*.prm
files many times with a fixed seed and run each mutant; every run must end in

  - a clean error: a non-zero exit (not a signal), exactly one line on
    stderr starting with 'fdem-slope: error: ', and no summary.json; or
  - a result: exit 0, 3 or 4 (see doc/usage: 3 = no static equilibrium,
    4 = no certified factor) with a summary.json that is valid JSON holding
    only finite numbers (nlohmann writes NaN and inf as null, so a null
    where the completed run's summary has a number is a failure too), and
    with --validate, exit 0 and '... valid.' on stdout;

within the time bound. Anything else is a failure, counted by kind: signal,
hang (time bound exceeded), message (not one clean line), summary (a
summary.json beside an error, or none beside a result, or one with NaN),
exit (an unexpected exit code).

  fuzz_prm.py EXE N_MUTANTS [--seed S] [--jobs J] [--validate-share F]
              [--timeout T] [--keep DIR]

Runs under /usr/bin/python3. Each mutant runs in its own temporary folder;
with --keep DIR the mutants that failed are copied there. The last line of
the output is the table of counts for doc/verification.md; the exit code is
1 if any run failed.

Besides the shipped files, the bases hold cases of the tests that carry
what the shipped files do not (EXTRA): the analyses' sections (a surface
search, probabilistic samples with a random water level, the yield
acceleration with a Newmark record), point lists (piezometric, perched and
weak-layer lines, layer boundaries) and the data files they read (a
terrain grid, an acceleration record), which are copied beside each
mutant and mutated in about a third of the mutants instead of the .prm.

The runs are made cheap without changing what is tested: the slowest cases
get coarser meshes (COARSER), VTU files are off
and Geometry/Memory limit is 2000 MiB (both appended to every base file
before it is mutated, so mutations hit them too), and the address space of
each run is limited to 4 GiB so that a mutant that asks for too much memory
meets a limit instead of the machine's swap.
"""
import argparse
import collections
import concurrent.futures
import glob
import json
import math
import os
import random
import re
import resource
import shutil
import subprocess
import sys
import tempfile
import time

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
PRM_DIR = os.path.join(ROOT, "prm")

# Appended to every shipped file before mutation: cheap runs, bounded ones.
FAST = """
subsection Output
  set Write VTU = false
end
subsection Geometry
  set Memory limit = 2000
  set Time limit   = 60
end
"""

# Coarser meshes of the slowest cases (each run a few seconds at most).
COARSER = {
    "hertz.prm": [("Elements in contact zone = 120", "Elements in contact zone = 20"),
                  ("Mesh size                = 20", "Mesh size                = 60")],
    "cattaneo_mindlin.prm": [("Elements in contact zone = 60", "Elements in contact zone = 20")],
    "hertz_sphere.prm": [("Elements in contact zone = 6", "Elements in contact zone = 3")],
    "rock_wedge.prm": [("Mesh size    = 4", "Mesh size    = 8")],
}

# Cases of the tests, as bases beside prm/*.prm: each file (its @PRM_DIR@
# and @DATA_DIR@ filled in) and the data files it reads.
RECORD = "".join(f"{0.01 * i:.2f},{0.3 * math.sin(2 * math.pi * i / 50):.6f}\n"
                 for i in range(301))
YIELD_WITH_RECORD = """include @PRM_DIR@/paper_slope.prm
subsection Yield acceleration
  set Compute             = true
  set Acceleration record = record.csv
  set Acceleration unit   = g
end
"""
EXTRA = {
    "search_cohesionless.prm": ("tests/surface_search/cohesionless_slope.prm", {}),
    "probabilistic_block_water.prm": ("tests/probabilistic/block_water.prm", {}),
    "layered_interslices.prm": ("tests/certificate/layered_interslices.prm", {}),
    "perched_interslices.prm": ("tests/certificate/perched_interslices.prm", {}),
    "kinked_water_table.prm": ("tests/limit_equilibrium/kinked_water_table.prm", {}),
    "yield_with_record.prm": (YIELD_WITH_RECORD, {"record.csv": RECORD}),
}

EXTREME = ["0", "-0", "-1", "1e308", "-1e308", "1e-308", "5e-324", "1e20", "-1e20",
           "1e-20", "nan", "inf", "-inf", "1e400", "4294967297", "-2147483649",
           "18446744073709551617", "0x10", "1/0", "0/0", "1e-9", "1e9", "3.", ".5e",
           "", "1,2", "1e-3", "1000"]
NUMBER = re.compile(r"(?<![\w.])[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")
SET_LINE = re.compile(r"^(\s*set\s+[^=]*=)(.*)$")


def mutate_bytes(text, rng):
    """@p text with 1 to 8 bytes replaced or inserted at random."""
    data = bytearray(text.encode("latin-1"))
    for _ in range(rng.choice([1, 1, 2, 4, 8])):
        position = rng.randrange(len(data) + 1)
        byte = rng.randrange(256)
        if rng.random() < 0.5 and position < len(data):
            data[position] = byte
        else:
            data.insert(position, byte)
    return data.decode("latin-1")


def mutate_table(text, rng):
    """One mutation of a data file (comma-separated numbers), and its name."""
    lines = text.split("\n")
    kind = rng.choice(["truncate", "delete lines", "duplicate line", "random bytes",
                       "extreme number", "extreme number"])
    if kind == "truncate":
        return text[:rng.randrange(max(1, len(text)))], "table " + kind
    if kind == "delete lines":
        start = rng.randrange(len(lines))
        del lines[start:start + rng.choice([1, 1, 2, 10])]
    elif kind == "duplicate line":
        lines.insert(rng.randrange(len(lines) + 1), rng.choice(lines))
    elif kind == "random bytes":
        return mutate_bytes(text, rng), "table " + kind
    else:
        rows = [i for i, l in enumerate(lines) if NUMBER.search(l)]
        if not rows:
            return mutate_bytes(text, rng), "table random bytes"
        i = rng.choice(rows)
        m = rng.choice(list(NUMBER.finditer(lines[i])))
        lines[i] = lines[i][:m.start()] + rng.choice(EXTREME) + lines[i][m.end():]
    return "\n".join(lines), "table " + kind


def extra_bases():
    """EXTRA's cases: name -> (text, {data file: text})."""
    bases = {}
    for name, (source, data) in EXTRA.items():
        text = open(os.path.join(ROOT, source)).read() if source.endswith(".prm") else source
        bases[name] = (text.replace("@PRM_DIR@", PRM_DIR), dict(data))
    # The terrain grid of the shipped 3D terrain case, mutated like the others.
    bases["slope_3d_terrain.prm"] = (None, {"slope_3d_terrain.csv": open(
        os.path.join(PRM_DIR, "slope_3d_terrain.csv")).read()})
    return bases


def mutate(text, rng):
    """One mutation of @p text, and its name."""
    lines = text.split("\n")
    kind = rng.choice(["truncate", "swap values", "delete lines", "duplicate line",
                       "random bytes", "extreme number", "extreme number", "swap values"])
    if kind == "truncate":
        return text[:rng.randrange(max(1, len(text)))], kind
    if kind == "swap values":
        sets = [i for i, l in enumerate(lines) if SET_LINE.match(l)]
        if len(sets) < 2:
            return mutate_bytes(text, rng), "random bytes"
        i, j = rng.sample(sets, 2)
        a, b = SET_LINE.match(lines[i]), SET_LINE.match(lines[j])
        lines[i], lines[j] = a.group(1) + b.group(2), b.group(1) + a.group(2)
    elif kind == "delete lines":
        start = rng.randrange(len(lines))
        del lines[start:start + rng.choice([1, 1, 1, 2, 3])]
    elif kind == "duplicate line":
        lines.insert(rng.randrange(len(lines) + 1), rng.choice(lines))
    elif kind == "random bytes":
        return mutate_bytes(text, rng), kind
    else:  # extreme number
        sets = [i for i, l in enumerate(lines) if SET_LINE.match(l) and NUMBER.search(SET_LINE.match(l).group(2))]
        if not sets:
            return mutate_bytes(text, rng), "random bytes"
        i = rng.choice(sets)
        head, value = SET_LINE.match(lines[i]).groups()
        numbers = list(NUMBER.finditer(value))
        m = rng.choice(numbers)
        lines[i] = head + value[:m.start()] + rng.choice(EXTREME) + value[m.end():]
    return "\n".join(lines), kind


def limit_memory():
    limit = 4 << 30
    resource.setrlimit(resource.RLIMIT_AS, (limit, limit))


# Where summary.json may hold null by its schema (source/postprocess/summary.cc,
# number_or_null: "not available"): no failed step (K_failed, the bracket's
# upper end), a step that was not solved (its K_star), the slope of K*
# of a step where not every pair slips (K_star_slope), and what the
# certificate, the stiffness check and the Hertz comparison's pressure fit
# (contact_radius) could not compute. Everywhere else a
# null is a NaN or an infinity that nlohmann wrote as null.
MAY_BE_NULL = {"K_failed", "safety_factor_bracket", "K_star", "K_star_slope",
               "relative_difference",
               "relative_distance_left", "K_stiffer", "K_softer", "relative_change",
               "contact_radius", "contact_radius_error"}


def no_nan(value, key=""):
    """Whether the JSON value holds only finite numbers, and nulls only
    under the keys of MAY_BE_NULL (nlohmann writes NaN as null) or in an
    object that says why it is not available (a non-empty "not_computed",
    e.g. a limit-equilibrium method's {"K": null, "not_computed": ...})."""
    if key in MAY_BE_NULL:
        return True
    if isinstance(value, dict):
        if value.get("not_computed"):
            return all(v is None or no_nan(v, k) for k, v in value.items())
        return all(no_nan(v, k) for k, v in value.items())
    if isinstance(value, list):
        return all(no_nan(v, key) for v in value)
    if isinstance(value, float):
        return math.isfinite(value)
    return value is not None


def bad_number(_):
    raise ValueError("NaN or infinity in summary.json")


def run_one(exe, case, data, files, validate, timeout, keep):
    """Runs one mutant (its .prm @p data and its data @p files); returns
    (outcome, detail), outcome in 'error', 'result' or 'failure: <kind>'."""
    workdir = tempfile.mkdtemp(prefix="fdem-fuzz-")
    try:
        for geo in glob.glob(os.path.join(PRM_DIR, "*.geo")):
            shutil.copy(geo, workdir)
        for name, text in files.items():
            with open(os.path.join(workdir, name), "wb") as f:
                f.write(text)
        prm = os.path.join(workdir, case)
        with open(prm, "wb") as f:
            f.write(data)
        args = [exe] + (["--validate"] if validate else []) + [case]
        start = time.time()
        try:
            p = subprocess.run(args, cwd=workdir, capture_output=True, timeout=timeout,
                               preexec_fn=limit_memory, env=dict(os.environ, OMP_NUM_THREADS="1"))
        except subprocess.TimeoutExpired:
            return "failure: hang", f"more than {timeout} s", keep_case(keep, workdir)
        wall = time.time() - start
        stderr = p.stderr.decode(errors="replace").strip()
        stdout = p.stdout.decode(errors="replace")
        summaries = [os.path.join(r, "summary.json") for r, _, files in os.walk(workdir)
                     if "summary.json" in files]
        lines = stderr.splitlines()
        if p.returncode < 0 or p.returncode >= 128:
            return "failure: signal", f"exit {p.returncode}: {stderr[-300:]}", keep_case(keep, workdir)
        if p.returncode in (1, 2):
            if len(lines) != 1 or not lines[0].startswith("fdem-slope: error: "):
                return "failure: message", stderr[:500], keep_case(keep, workdir)
            if summaries:
                return "failure: summary", "summary.json beside an error: " + lines[0], keep_case(keep, workdir)
            return "error", lines[0], None
        if validate:
            if p.returncode != 0 or not stdout.strip().endswith("valid."):
                return "failure: exit", f"--validate exit {p.returncode}", keep_case(keep, workdir)
            return "result", f"valid ({wall:.1f} s)", None
        if p.returncode not in (0, 3, 4):
            return "failure: exit", f"exit {p.returncode}: {stderr[:300]}", keep_case(keep, workdir)
        if len(summaries) != 1:
            return "failure: summary", f"exit {p.returncode} with {len(summaries)} summary.json", keep_case(keep, workdir)
        try:
            summary = json.load(open(summaries[0]), parse_constant=bad_number)
        except ValueError as e:
            return "failure: summary", f"invalid summary.json: {e}", keep_case(keep, workdir)
        if p.returncode in (3, 4):
            # No static equilibrium or no certified factor: the factor, its
            # certificate and the stiffness check are "not available".
            for key in ("safety_factor", "certificate", "stiffness_sensitivity"):
                summary.pop(key, None)
        if not no_nan(summary):
            return "failure: NaN", "null or non-finite number in summary.json", keep_case(keep, workdir)
        if p.returncode == 0 and (summary.get("status") != "completed" or not (
                "safety_factor" not in summary or isinstance(summary["safety_factor"], float))):
            return "failure: summary", "exit 0 without a completed, finite result", keep_case(keep, workdir)
        return "result", f"exit {p.returncode} ({wall:.1f} s)", None
    finally:
        shutil.rmtree(workdir, ignore_errors=True)


def keep_case(keep, workdir):
    if keep:
        os.makedirs(keep, exist_ok=True)
        target = tempfile.mkdtemp(prefix="case-", dir=keep)
        for name in os.listdir(workdir):
            source = os.path.join(workdir, name)
            if os.path.isfile(source):
                shutil.copy(source, target)
        return target
    return None


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("exe")
    parser.add_argument("n", type=int)
    parser.add_argument("--seed", type=int, default=16)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--validate-share", type=float, default=0.5)
    parser.add_argument("--timeout", type=float, default=120)
    parser.add_argument("--keep", default=None)
    args = parser.parse_args()
    args.exe = os.path.abspath(args.exe)

    # Texts as latin-1: one character per byte, so that random bytes survive.
    bases = {}
    for path in sorted(glob.glob(os.path.join(PRM_DIR, "*.prm"))):
        name = os.path.basename(path)
        text = open(path, "rb").read().decode("latin-1")
        for old, new in COARSER.get(name, []):
            assert old in text, f"{name}: '{old}' not found (update COARSER)"
            text = text.replace(old, new)
        bases[name] = (text + FAST, {})
    for name, (text, files) in extra_bases().items():
        bases[name] = (bases[name][0] if text is None else text + FAST, files)
    rng = random.Random(args.seed)
    mutants = []
    for i in range(args.n):
        case = rng.choice(sorted(bases))
        (data, files), kinds = bases[case], []
        files = dict(files)
        for _ in range(rng.choice([1, 1, 1, 2, 3])):
            if files and rng.random() < 1 / 3:
                name = rng.choice(sorted(files))
                files[name], kind = mutate_table(files[name], rng)
            else:
                data, kind = mutate(data, rng)
            kinds.append(kind)
        mutants.append((i, case, data.encode("latin-1"),
                        {k: v.encode("latin-1") for k, v in files.items()},
                        rng.random() < args.validate_share, "+".join(kinds)))

    counts = collections.Counter()
    failures = []
    start = time.time()
    with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
        futures = {pool.submit(run_one, args.exe, case, data, files, validate, args.timeout,
                               args.keep):
                   (i, case, validate, kinds) for i, case, data, files, validate, kinds in mutants}
        for n, future in enumerate(concurrent.futures.as_completed(futures), 1):
            i, case, validate, kinds = futures[future]
            outcome, detail, kept = future.result()
            mode = "validate" if validate else "run"
            counts[(mode, outcome)] += 1
            if outcome.startswith("failure"):
                failures.append((i, case, mode, kinds, outcome, detail, kept))
                print(f"#{i} {case} ({mode}, {kinds}): {outcome}: {detail}"
                      + (f" [kept in {kept}]" if kept else ""), flush=True)
            if n % 100 == 0:
                print(f"{n}/{len(mutants)} done, {time.time() - start:.0f} s", flush=True)

    print(f"{len(mutants)} mutants, seed {args.seed}, {time.time() - start:.0f} s")
    for mode in ("run", "validate"):
        row = {k[1]: v for k, v in counts.items() if k[0] == mode}
        print(f"  {mode}: " + ", ".join(f"{k} {v}" for k, v in sorted(row.items())))
    print("failures:", len(failures))
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
