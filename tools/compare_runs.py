#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Runs two .prm files that should describe the same case (e.g. a test
file before and after it was rewritten to include its case from prm/) and
says whether the runs agree:

  compare_runs.py [--exe EXE] OLD.prm NEW.prm [OLD.prm NEW.prm ...]

For each pair: the exit codes, the parameters.prm the runs wrote (every
entry as the program read it), summary.json without wall times and peak
memory (byte for byte) and the safety factor bit for bit. Prints a markdown
table; exits with 1 if any pair differs.
"""
import argparse
import json
import sys

import fdem_run


def compare(exe, old, new):
    with fdem_run.temporary_run(exe, old) as a, fdem_run.temporary_run(exe, new) as b:
        same_parameters = (open(a.file("parameters.prm")).read() ==
                           open(b.file("parameters.prm")).read()) \
            if a.parameters and b.parameters else a.parameters == b.parameters
        summaries = [json.dumps(fdem_run.result_part(r.summary), sort_keys=True)
                     if r.summary is not None else None for r in (a, b)]
        K = [(r.summary or {}).get("safety_factor") for r in (a, b)]
        status = [(r.summary or {}).get("status") for r in (a, b)]
    same = (a.returncode == b.returncode and same_parameters and summaries[0] == summaries[1]
            and K[0] == K[1])
    return same, [new, f"{a.returncode} / {b.returncode}", "same" if same_parameters else "DIFFER",
                  "same" if summaries[0] == summaries[1] else "DIFFER",
                  "same" if K[0] == K[1] else "DIFFER",
                  repr(K[1]), str(status[1])]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--exe", default=fdem_run.DEFAULT_EXE)
    parser.add_argument("files", nargs="+", help="pairs OLD.prm NEW.prm")
    args = parser.parse_args()
    if len(args.files) % 2:
        sys.exit("compare_runs.py: give the .prm files in pairs OLD NEW")
    print("| file | exit codes | parameters.prm | summary.json | K bit for bit | K | status |")
    print("| --- | --- | --- | --- | --- | ---: | --- |")
    all_same = True
    for old, new in zip(args.files[0::2], args.files[1::2]):
        same, row = compare(args.exe, old, new)
        all_same &= same
        print("| " + " | ".join(row) + " |", flush=True)
    sys.exit(0 if all_same else 1)


if __name__ == "__main__":
    main()
