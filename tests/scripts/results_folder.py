#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""A results folder is always the output of exactly one run.

  results_folder.py concurrent EXE CASE.prm [REPEATS]
      two runs of CASE with different mesh sizes into one Output/Directory,
      started together, REPEATS times (default 5): each time the folder must
      be one whole run, file for file equal to a run of that variant made
      alone (interfaces.csv byte for byte, the same file names), with no
      partial folder nor .lock file left beside it
  results_folder.py stale EXE CASE.prm
      a run with VTU files, one with Write VTU = false and a failed one into
      one folder: no VTU beside the second run's summary.json, the first
      kept whole as .previous, and the failed run leaves the folder as it was
  results_folder.py interrupt EXE CASE.prm
      runs stopped by SIGINT and by SIGTERM after 0.2 to 1.5 s: no partial
      folder remains, and the results folder is absent or a whole earlier
      run
"""
import json
import os
import signal
import subprocess
import sys
import tempfile
import time

PRM_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "prm")


def variant(prm, workdir, name, mesh_size):
    text = open(prm).read().replace("@PRM_DIR@", os.path.abspath(PRM_DIR))
    path = os.path.join(workdir, name + ".prm")
    with open(path, "w") as f:
        f.write(f"include {os.path.abspath(prm)}\n" if "@PRM_DIR@" not in text else text)
        f.write("subsection Geometry\n  subsection Slope\n"
                f"    set Mesh size = {mesh_size}\n  end\nend\n"
                "subsection Output\n  set Directory = shared-output\nend\n")
    return path


def snapshot(folder):
    files = sorted(os.listdir(folder))
    csv = open(os.path.join(folder, "interfaces.csv")).read()
    summary = json.load(open(os.path.join(folder, "summary.json")))
    return files, csv, summary


def leftovers(workdir):
    return [n for n in os.listdir(workdir) if ".partial-" in n]


def check_concurrent(exe, prm, repeats=5):
    with tempfile.TemporaryDirectory() as workdir:
        runs = [variant(prm, workdir, "coarse", 2.0), variant(prm, workdir, "fine", 1.5)]
        out = os.path.join(workdir, "shared-output")
        reference, reference_prm = {}, {}
        for r in runs:
            subprocess.run([exe, r], cwd=workdir, capture_output=True, check=True, timeout=600)
            reference[r] = snapshot(out)
            reference_prm[r] = open(os.path.join(out, "parameters.prm")).read()
        assert reference[runs[0]][1] != reference[runs[1]][1], "the variants do not differ"
        for repeat in range(int(repeats)):
            procs = [subprocess.Popen([exe, r], cwd=workdir, stdout=subprocess.DEVNULL,
                                      stderr=subprocess.PIPE, text=True) for r in runs]
            codes = [p.wait(timeout=600) for p in procs]
            assert codes == [0, 0], (codes, [p.stderr.read() for p in procs])
            files, csv, summary = snapshot(out)
            assert summary["status"] == "completed"
            matches = [r for r in runs if (files, csv) == reference[r][:2]]
            assert len(matches) == 1, f"repeat {repeat}: the folder mixes runs"
            which = matches[0]
            assert open(os.path.join(out, "parameters.prm")).read() == \
                reference_prm[which], f"repeat {repeat}: parameters.prm of the other run"
            assert leftovers(workdir) == [], leftovers(workdir)
            # The lock file goes with the last run that held it.
            assert not os.path.exists(out + ".lock"), "the .lock file was left"
            print(f"repeat {repeat}: one whole run ({os.path.basename(which)}), {len(files)} files")


def check_interrupt(exe, prm):
    with tempfile.TemporaryDirectory() as workdir:
        run = variant(prm, workdir, "case", 0.7)
        out = os.path.join(workdir, "shared-output")
        start = time.time()
        subprocess.run([exe, run], cwd=workdir, capture_output=True, check=True, timeout=600)
        duration = time.time() - start
        whole = snapshot(out)
        print(f"a whole run takes {duration:.2f} s")
        for sig in (signal.SIGINT, signal.SIGTERM):
            for fraction in (0.1, 0.3, 0.6):
                p = subprocess.Popen([exe, run], cwd=workdir, stdout=subprocess.DEVNULL,
                                     stderr=subprocess.DEVNULL)
                time.sleep(fraction * duration)
                p.send_signal(sig)
                code = p.wait(timeout=600)
                assert leftovers(workdir) == [], (sig, fraction, leftovers(workdir))
                # Stopped: the folder is the earlier whole run; finished
                # first: it is this run, whole as well.
                assert snapshot(out)[:2] == whole[:2], (sig, fraction)
                print(f"{signal.Signals(sig).name} after {fraction * duration:.2f} s: exit {code}, "
                      "no partial folder, the results folder whole")


def check_stale(exe, prm):
    """A run with VTU files, then one without into the same folder, then a
    failed one: the folder is each time one run, never with the earlier
    run's files beside the new summary.json."""
    with tempfile.TemporaryDirectory() as workdir:
        run = variant(prm, workdir, "case", 2.0)
        subprocess.run([exe, run], cwd=workdir, capture_output=True, check=True, timeout=600)
        out = os.path.join(workdir, "shared-output")
        with_vtu = sorted(os.listdir(out))
        assert "solution.pvd" in with_vtu, with_vtu
        with open(run, "a") as f:
            f.write("subsection Output\n  set Write VTU = false\nend\n")
        subprocess.run([exe, run], cwd=workdir, capture_output=True, check=True, timeout=600)
        without = sorted(os.listdir(out))
        print("with VTU:", len(with_vtu), "files; without:", without)
        assert not [n for n in without if n.endswith((".vtu", ".pvd"))], without
        assert sorted(os.listdir(out + ".previous")) == with_vtu, "the previous run is not kept whole"
        whole = snapshot(out)
        with open(run, "a") as f:
            f.write("subsection Blocks\n  subsection foundation\n"
                    "    set Young's modulus = -1\n  end\nend\n")
        p = subprocess.run([exe, run], cwd=workdir, capture_output=True, text=True, timeout=600)
        print("failed run:", p.returncode, p.stderr.strip())
        assert p.returncode == 1 and p.stderr.startswith("fdem-slope: error: "), p.stderr
        assert snapshot(out) == whole, "a failed run changed the results folder"
        assert leftovers(workdir) == [] and not os.path.exists(out + ".lock")


def check_names(exe, prm):
    with tempfile.TemporaryDirectory() as workdir:
        subprocess.run([exe, os.path.abspath(prm)], cwd=workdir, capture_output=True,
                       check=True, timeout=600)
        out = os.path.join(workdir, os.path.splitext(os.path.basename(prm))[0] + "-output")
        summary = json.load(open(os.path.join(out, "summary.json")))
        pvd = open(os.path.join(out, "solution.pvd")).read()
        files = [part.split('"')[0] for part in pvd.split('file="')[1:]]
        print(files)
        assert len(files) == len(summary["blocks"]) + len(summary["interfaces"]), files
        assert len(set(files)) == len(files), "a file is listed twice"
        assert all(os.path.exists(os.path.join(out, f)) for f in files)


if __name__ == "__main__":
    {"concurrent": check_concurrent, "interrupt": check_interrupt, "names": check_names,
     "stale": check_stale}[sys.argv[1]](*sys.argv[2:])
