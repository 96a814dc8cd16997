#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Command-line mistakes: each must give one line 'fdem-slope: error: ...'
naming the argument (or the problem and 'see --help'), a non-zero exit below
128 (no crash), and no files written.

  bad_arguments.py EXE
"""
import os
import subprocess
import sys
import tempfile

CASES = [
    ([], "no parameter file given; see --help"),
    (["a.prm", "b.prm"], "give one parameter file, not 'a.prm' and 'b.prm'; see --help"),
    (["--frobnicate"], "unknown option '--frobnicate'; see --help"),
    (["--quiet", "--verbose", "a.prm"], "give --quiet or --verbose, not both; see --help"),
    # --quiet keeps errors: one line on stderr.
    (["--quiet", "{dir}"], "'{dir}': is a directory"),
    (["{dir}"], "'{dir}': is a directory"),
    (["/dev/null"], "'/dev/null': is not a regular file"),
    (["/dev/zero"], "'/dev/zero': is not a regular file"),
    (["--validate", "/dev/zero"], "'/dev/zero': is not a regular file"),
    (["{dir}/case.txt"], "the name must end in .prm"),
]


def main(exe):
    failures = 0
    with tempfile.TemporaryDirectory() as workdir:
        open(os.path.join(workdir, "case.txt"), "w").write("set Dimension = 2\n")
        before = sorted(os.listdir(workdir))
        for args, expect in CASES:
            args = [a.format(dir=workdir) for a in args]
            expect = expect.format(dir=workdir)
            result = subprocess.run([exe] + args, cwd=workdir, capture_output=True,
                                    text=True, timeout=60)
            lines = result.stderr.strip().splitlines()
            ok = (0 < result.returncode < 128 and len(lines) == 1
                  and lines[0].startswith("fdem-slope: error: ") and expect in lines[0])
            print(("ok  " if ok else "FAIL"), args, "->", result.returncode, lines)
            failures += not ok
        assert sorted(os.listdir(workdir)) == before, "files were written"
    assert failures == 0, f"{failures} case(s) failed"


if __name__ == "__main__":
    main(sys.argv[1])
