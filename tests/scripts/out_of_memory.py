#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""A run that runs out of memory ends with one error line, not a stack trace.

  out_of_memory.py EXE

The hertz case at Mesh size = 1e-4 with Geometry/Memory limit raised past
its estimate, in an address space of 1.5 GiB (ulimit -v): Gmsh's allocation
fails inside an OpenMP loop, where a std::bad_alloc ended the run in
std::terminate with SIGABRT and a stack trace (found by the fuzz test). The
run must exit 1 with one line 'fdem-slope: error: out of memory...', and
leave no summary.json, results folder or partial folder.
"""
import os
import resource
import subprocess
import sys
import tempfile

PRM_DIR = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "prm"))


def limit():
    resource.setrlimit(resource.RLIMIT_AS, (1536 << 20, 1536 << 20))


def main(exe):
    with tempfile.TemporaryDirectory() as folder:
        with open(os.path.join(folder, "oom.prm"), "w") as f:
            f.write(f"include {PRM_DIR}/hertz.prm\n"
                    "subsection Geometry\n  set Memory limit = 1e30\n"
                    "  subsection Hertz\n    set Mesh size = 1e-4\n  end\nend\n")
        p = subprocess.run([exe, "oom.prm"], cwd=folder, capture_output=True, text=True,
                           timeout=300, preexec_fn=limit)
        print("exit", p.returncode, "stderr:", p.stderr.strip())
        lines = p.stderr.strip().splitlines()
        assert p.returncode == 1, "not exit 1"
        assert len(lines) == 1 and lines[0].startswith("fdem-slope: error: out of memory"), lines
        assert sorted(os.listdir(folder)) == ["oom.prm"], os.listdir(folder)
    print("passed")


if __name__ == "__main__":
    main(os.path.abspath(sys.argv[1]))
