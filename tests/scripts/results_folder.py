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
  results_folder.py owned EXE CASE.prm
      Output/Directory naming what the program did not make (a folder of
      the user's files, a file, the .prm's folder, the working folder, a
      folder above it, '/', a dangling link, a link to a folder, a
      '.previous' of the user's): two runs and --validate each refuse it in
      one line naming Output/Directory, and every file, folder and link the
      user had is still there byte for byte (an empty folder of the user's
      too); the program's own folders are replaced run after run
  results_folder.py sigkill EXE CASE.prm
      a run killed by SIGKILL leaves its partial folder; the next run into
      the same folder removes it and ends with the results complete
  results_folder.py disk_full EXE CASE.prm
      runs into a small tmpfs (mounted here: needs root, else skipped with
      exit code 77) of 5 % to 100 % of what the run's folder takes, and
      twice it: each ends either with
      exit 0 and a whole results folder, or with one error line naming the
      file it could not write, a non-zero exit and no summary.json that says
      completed anywhere on the tmpfs
"""
import json
import os
import shutil
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


def tree(root):
    """Every file (with its bytes), folder and link under root."""
    found = {}
    for folder, dirs, files in os.walk(root):
        for name in dirs + files:
            path = os.path.join(folder, name)
            rel = os.path.relpath(path, root)
            if os.path.islink(path):
                found[rel] = ("link", os.readlink(path))
            elif os.path.isdir(path):
                found[rel] = ("folder",)
            else:
                found[rel] = ("file", open(path, "rb").read())
    return found


def case_into(prm, folder, directory, mesh_size=2.0):
    text = open(prm).read().replace("@PRM_DIR@", os.path.abspath(PRM_DIR))
    path = os.path.join(folder, "case.prm")
    with open(path, "w") as f:
        f.write(f"include {os.path.abspath(prm)}\n" if "@PRM_DIR@" not in text else text)
        f.write("subsection Geometry\n  subsection Slope\n"
                f"    set Mesh size = {mesh_size}\n  end\nend\n"
                f"subsection Output\n  set Directory = {directory}\n  set Write VTU = false\nend\n")
    return path


def refused(exe, args, cwd, name):
    p = subprocess.run([exe] + args, cwd=cwd, capture_output=True, text=True, timeout=600)
    lines = p.stderr.strip().splitlines()
    assert p.returncode == 1 and len(lines) == 1 and \
        lines[0].startswith("fdem-slope: error: Output/Directory: ") and name in lines[0], \
        (args, p.returncode, p.stderr, p.stdout)
    return lines[0]


def check_owned(exe, prm):
    with tempfile.TemporaryDirectory() as top:
        project = os.path.join(top, "proj")
        os.makedirs(os.path.join(project, "mine", "sub"))
        os.makedirs(os.path.join(project, "empty"))
        for rel, text in (("notes.txt", "my notes\n"), ("mine/data.csv", "1,2\n"),
                          ("mine/sub/deep.txt", "deep\n"), ("afile", "a file\n"),
                          ("out.previous/keep.txt", "mine too\n")):
            os.makedirs(os.path.dirname(os.path.join(project, rel)), exist_ok=True)
            with open(os.path.join(project, rel), "w") as f:
                f.write(text)
        os.symlink(os.path.join(project, "nowhere"), os.path.join(project, "dangling"))
        os.symlink(os.path.join(project, "mine"), os.path.join(project, "tomine"))
        # The kinds the issue names (a user's folder, a file, the .prm's
        # folder, '.', '/', a dangling link) twice each and with --validate;
        # their variants (a trailing slash, an absolute name, a link to a
        # folder, an empty folder, a previous that is not ours) once: each
        # run of one folder decides alike, the second run checks that the
        # first left nothing that changes the decision.
        named = {"mine", "afile", "../proj", ".", "/", "dangling"}
        for directory, name in (("mine", "mine"), ("mine/", "mine"), ("afile", "afile"),
                                ("../proj", "../proj"), (".", "'.'"), ("./", "./"),
                                ("..", ".."), ("/", "'/'"), (project, project),
                                ("dangling", "dangling"), ("tomine", "tomine"), ("empty", "empty"),
                                ("out", "out.previous")):
            run = case_into(prm, project, directory)
            before = tree(top)
            for attempt in (1, 2) if directory in named else (1,):
                line = refused(exe, [run], project, name)
            if directory in named:
                refused(exe, ["--validate", run], project, name)
            assert tree(top) == before, f"Output/Directory = {directory}: the user's files changed"
            print(f"Output/Directory = {directory!r}: refused, nothing touched: {line}")
        # The program's own folders are replaced run after run, the
        # previous kept once.
        run = case_into(prm, project, "results")
        for attempt in (1, 2, 3):
            p = subprocess.run([exe, "--no-report", run], cwd=project, capture_output=True,
                               text=True, timeout=600)
            assert p.returncode == 0, p.stderr
        for folder in ("results", "results.previous"):
            marker = open(os.path.join(project, folder, ".fdem-slope-results")).read()
            assert marker.startswith("program: fdem-slope\n"), marker
            assert json.load(open(os.path.join(project, folder, "summary.json")))["status"] \
                == "completed"
        assert leftovers(project) == [], leftovers(project)
        print("three runs into a new folder: it and its .previous are whole runs")


def check_sigkill(exe, prm):
    with tempfile.TemporaryDirectory() as workdir:
        run = case_into(prm, workdir, "out", mesh_size=0.7)
        start = time.time()
        subprocess.run([exe, run], cwd=workdir, capture_output=True, check=True, timeout=600)
        duration = time.time() - start
        whole = sorted(os.listdir(os.path.join(workdir, "out")))
        killed = 0
        for fraction in (0.3, 0.6):
            p = subprocess.Popen([exe, run], cwd=workdir, stdout=subprocess.DEVNULL,
                                 stderr=subprocess.DEVNULL)
            time.sleep(fraction * duration)
            p.kill()
            p.wait(timeout=60)
            killed += len(leftovers(workdir))
        assert killed > 0, "no run was killed while it ran (the case is too short)"
        print(f"SIGKILL left {killed} partial folders: {leftovers(workdir)}")
        p = subprocess.run([exe, run], cwd=workdir, capture_output=True, text=True, timeout=600)
        assert p.returncode == 0, p.stderr
        assert leftovers(workdir) == [], leftovers(workdir)
        out = os.path.join(workdir, "out")
        assert sorted(os.listdir(out)) == whole, (sorted(os.listdir(out)), whole)
        assert json.load(open(os.path.join(out, "summary.json")))["status"] == "completed"
        print("the next run removed them and its results are complete")


def check_disk_full(exe, prm):
    if os.geteuid() != 0 or shutil.which("mount") is None:
        print("skipped: mounting a tmpfs needs root")
        sys.exit(77)
    with tempfile.TemporaryDirectory() as workdir:
        disk = os.path.join(workdir, "disk")
        os.makedirs(disk)
        run = case_into(prm, workdir, os.path.join(disk, "out"))
        failed = completed = 0
        # The disk sizes as fractions of what the whole folder takes on a
        # tmpfs (whole pages per file), so that they cut the files written
        # early (parameters.prm), in the middle (the log, the CSV tables)
        # and last (summary.json) whatever their sizes.
        subprocess.run([exe, "--no-report", run], cwd=workdir, capture_output=True, check=True,
                       timeout=600)
        out = os.path.join(disk, "out")
        pages = sum((os.path.getsize(os.path.join(out, n)) + 4095) // 4096 + 1
                    for n in os.listdir(out))
        shutil.rmtree(out)
        hit = set()
        for size_kib in sorted({max(8, int(4 * pages * f)) for f in
                                (0.05, 0.3, 0.5, 0.7, 0.8, 0.9, 0.95, 1.0)} | {8 * pages}):
            if subprocess.run(["mount", "-t", "tmpfs", "-o", f"size={size_kib}k", "tmpfs", disk],
                              capture_output=True).returncode != 0:
                print("skipped: this machine does not let the test mount a tmpfs")
                sys.exit(77)
            try:
                p = subprocess.run([exe, "--no-report", run], cwd=workdir, capture_output=True,
                                   text=True, timeout=600)
                summaries = [os.path.join(f, n) for f, _, names in os.walk(disk)
                             for n in names if n == "summary.json"]
                said_completed = [s for s in summaries
                                  if '"completed"' in open(s, errors="replace").read()]
                if p.returncode == 0:
                    out = os.path.join(disk, "out")
                    assert json.load(open(os.path.join(out, "summary.json")))["status"] \
                        == "completed" and leftovers(disk) == []
                    completed += 1
                    print(f"{size_kib} KiB: completed")
                else:
                    lines = p.stderr.strip().splitlines()
                    assert len(lines) == 1 and lines[0].startswith("fdem-slope: error: ") and \
                        "No space left on device" in lines[0], p.stderr
                    assert said_completed == [], said_completed
                    assert leftovers(disk) == [], leftovers(disk)
                    failed += 1
                    hit.add(os.path.basename(lines[0].split("'")[1]))
                    print(f"{size_kib} KiB: exit {p.returncode}: {lines[0]}")
            finally:
                subprocess.run(["umount", disk], check=True)
        print("files whose write failed:", sorted(hit))
        assert failed > 0 and completed > 0, (failed, completed)
        assert len(hit) >= 2, f"the sizes cut too few of the files: {sorted(hit)}"


if __name__ == "__main__":
    {"concurrent": check_concurrent, "interrupt": check_interrupt, "names": check_names,
     "stale": check_stale, "owned": check_owned, "sigkill": check_sigkill,
     "disk_full": check_disk_full}[sys.argv[1]](*sys.argv[2:])
