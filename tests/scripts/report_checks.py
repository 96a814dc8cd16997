# SPDX-License-Identifier: LGPL-2.1-or-later
"""Checks of a run's report and of interfaces.csv (tests/CMakeLists.txt):

  report EXE PRM       the run makes report.html whose PNGs are valid
                       images of sensible size, and the page loads in a
                       headless Chromium without errors, its images
                       decoded (exit 77, skipped, only if no chromium is
                       installed)
  no_python EXE PRM    with FDEM_PYTHON naming no Python, the run still
                       succeeds, says so in one warning line, and
                       summary.json records that no report was made
  csv_order EXE PRM    interfaces.csv lists each interface's pairs along
                       the surface from its upper end, with an arc length
                       that adds up the distances between them
  my_first_slope EXE PRM  the guide's case (doc/build_your_own_model.md)
  installed BUILD_DIR CASE  the program installed by `cmake --install`
                       into a fresh prefix makes the report of CASE

Runs under /usr/bin/python3 (matplotlib, numpy).
"""
import csv
import math
import os
import re
import shutil
import struct
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
import fdem_run  # noqa: E402

SKIP = 77
PICTURES = ("model.png", "stresses.png", "iterations.png")


def png_size(path):
    """Width and height from the PNG signature and IHDR chunk, or fail."""
    data = open(path, "rb").read(33)
    assert data[:8] == b"\x89PNG\r\n\x1a\n", f"{path}: not a PNG file"
    assert data[12:16] == b"IHDR", f"{path}: no IHDR chunk"
    return struct.unpack(">II", data[16:24])


def check_pictures(folder):
    import matplotlib.image
    for name in PICTURES:
        path = os.path.join(folder, name)
        assert os.path.exists(path), f"no {name}"
        width, height = png_size(path)
        pixels = matplotlib.image.imread(path)
        assert pixels.shape[:2] == (height, width), (name, pixels.shape, width, height)
        # Sensible: large enough to read, not a page-sized accident, and
        # not blank (a plot has many colours).
        assert 600 <= width <= 3000 and 300 <= height <= 3000, f"{name}: {width} x {height}"
        n_colours = len({tuple(p) for p in pixels.reshape(-1, pixels.shape[2])[::7]})
        assert n_colours > 20, f"{name}: {n_colours} colours, looks blank"
        print(f"{name}: {width} x {height} px, {n_colours} colours (sampled)")


def chromium():
    for name in ("chromium", "chromium-browser", "google-chrome"):
        path = shutil.which(name)
        if path:
            return path
    return None


def check_in_browser(folder, browser):
    """Loads a copy of report.html, with a script that records each image's
    decoded size after the load event, in headless Chromium; the dumped DOM
    must show every image decoded and the log no console error."""
    page = open(os.path.join(folder, "report.html")).read()
    n_images = page.count('<img src="data:image/png;base64,')
    assert n_images == len(PICTURES), f"{n_images} embedded images, expected {len(PICTURES)}"
    assert not re.search(r'src="(?!data:)', page), "the page refers to an external file"
    probe = """<script>
window.addEventListener('load', () => {
  const sizes = [...document.images].map(i => i.complete ? i.naturalWidth + 'x' + i.naturalHeight : 'pending');
  document.body.setAttribute('data-image-sizes', sizes.join(' '));
  if (sizes.some(s => s === 'pending' || s.startsWith('0x'))) console.error('image not decoded: ' + sizes);
});
</script></body>"""
    test_page = os.path.join(folder, "report-browser-check.html")
    with open(test_page, "w") as f:
        f.write(page.replace("</body>", probe))
    result = subprocess.run([browser, "--headless", "--no-sandbox", "--disable-gpu",
                             "--enable-logging=stderr", "--v=0", "--virtual-time-budget=5000",
                             "--dump-dom", "file://" + os.path.abspath(test_page)],
                            capture_output=True, text=True, timeout=120)
    os.remove(test_page)
    console = [l for l in result.stderr.splitlines() if "CONSOLE" in l or "Uncaught" in l]
    print("chromium exit", result.returncode, "; console lines:", console)
    assert result.returncode == 0, result.stderr[-2000:]
    assert not console, "console messages: " + "\n".join(console)
    match = re.search(r'data-image-sizes="([^"]*)"', result.stdout)
    assert match, "the page's load handler did not run: " + result.stdout[:500]
    sizes = match.group(1).split()
    expected = ["%dx%d" % png_size(os.path.join(folder, n)) for n in PICTURES]
    print("decoded in the browser:", sizes)
    assert sorted(sizes) == sorted(expected), (sizes, expected)
    assert "<h2>Results</h2>" in result.stdout and "safety factor K" in result.stdout


def check_report(exe, prm):
    browser = chromium()
    with fdem_run.temporary_run(exe, prm) as run:
        assert run.ok, run.failure()
        report = run.summary["report"]
        print("report:", report)
        assert report["made"] is True and report["file"] == "report.html", report
        assert os.path.exists(run.file("report.html"))
        assert "Report: report.html" in open(run.file("log.txt")).read()
        check_pictures(run.output)
        # The page states the run's safety factor.
        page = open(run.file("report.html")).read()
        assert f"<b>{run.summary['safety_factor']:.4g}</b>" in page
        if browser is None:
            print("SKIP: no chromium installed, the page was not loaded in a browser")
            sys.exit(SKIP)
        check_in_browser(run.output, browser)


def check_no_python(exe, prm):
    env = dict(os.environ, FDEM_PYTHON="/nonexistent/python3")
    with fdem_run.temporary_run(exe, prm, env=env) as run:
        assert run.ok, run.failure()
        warnings = [l for l in run.stdout.splitlines() if "no-report" in l]
        print(warnings)
        assert len(warnings) == 1 and warnings[0].startswith("warning: [no-report] "), warnings
        report = run.summary["report"]
        assert report["made"] is False and "/nonexistent/python3" in report["reason"], report
        assert any(w.startswith("[no-report] ") for w in run.summary["warnings"])
        files = set(os.listdir(run.output))
        assert "report.html" not in files and not files & set(PICTURES), files
        assert {"summary.json", "interfaces.csv", "parameters.prm"} <= files, files


def check_report_off(exe, prm):
    """--no-report (fdem_run's report=False): no report.html and no pictures,
    no warning about the report, and otherwise the files of a run with the
    report, the same K."""
    with fdem_run.temporary_run(exe, prm, report=True) as run:
        assert run.ok, run.failure()
        with_report = set(os.listdir(run.output))
        K = run.summary["safety_factor"]
    assert "report.html" in with_report, with_report
    with fdem_run.temporary_run(exe, prm, report=False) as run:
        assert run.ok, run.failure()
        files = set(os.listdir(run.output))
        assert files == with_report - {"report.html", *PICTURES}, (files, with_report)
        assert run.summary["safety_factor"] == K, (run.summary["safety_factor"], K)
        assert not run.summary.get("report", {}).get("made", False), run.summary["report"]
        assert not any("no-report" in w for w in run.summary["warnings"]), run.summary["warnings"]


def read_rows(path):
    rows = list(csv.DictReader(open(path)))
    interfaces = {}
    for r in rows:
        interfaces.setdefault(r["interface"], []).append(r)
    return interfaces


def check_csv_order(exe, prm):
    with fdem_run.temporary_run(exe, prm) as run:
        assert run.ok, run.failure()
        interfaces = read_rows(run.file("interfaces.csv"))
        for name, rows in interfaces.items():
            x = [(float(r["x"]), float(r["y"])) for r in rows]
            s = [float(r["arc_length"]) for r in rows]
            assert s[0] == 0, s[0]
            # Each step along the table is a step to a neighbour on the
            # curve: the arc length grows by the distance, and no step is
            # longer than three times the median (no jump across the curve).
            steps = [math.dist(a, b) for a, b in zip(x, x[1:])]
            for k, d in enumerate(steps):
                assert abs(s[k + 1] - s[k] - d) <= 1e-9 * (1 + s[-1]), (k, s[k + 1] - s[k], d)
            median = sorted(steps)[len(steps) // 2]
            assert max(steps) <= 3 * median, (max(steps), median)
            # The upper end first (gravity is -y in this case).
            assert x[0][1] >= x[-1][1], (x[0], x[-1])
            # Every pair once.
            pairs = sorted(int(r["pair"]) for r in rows)
            assert pairs == list(range(len(rows))), "pairs missing or repeated"
            print(f"{name}: {len(rows)} pairs from {x[0]} to {x[-1]}, arc length {s[-1]:.4f}")


def check_my_first_slope(exe, prm):
    """The guide's layered Gmsh slope: a certified K, the three layers all
    used on the sliding surface (their c and phi in summary.json's
    strengths), and the report made."""
    with fdem_run.temporary_run(exe, prm) as run:
        assert run.ok, run.failure()
        s = run.summary
        print("K =", s["safety_factor"], "certificate:", s["certificate"]["kind"], s["certificate"]["holds"])
        assert s["status"] == "completed" and s["converged"] and s["certificate"]["holds"]
        # The value that doc/build_your_own_model.md and README.md quote (4
        # decimals): they must stay true of the shipped case.
        assert abs(s["safety_factor"] - 1.4280) < 5e-5, s["safety_factor"]
        # The layers of prm/my_first_slope.prm: (c, phi) of each.
        materials = {}
        for key, value in run.parameters.items():
            parts = key.split("/")
            if parts[0] == "Materials" and len(parts) == 3 and parts[2] in ("Cohesion", "Friction angle"):
                materials.setdefault(parts[1], {})[parts[2]] = float(value.split("#")[0])
        assert len(materials) == 3, materials
        strengths = s["interfaces"][0]["strengths"]
        print("strengths on the surface:", strengths)
        for name, m in materials.items():
            assert any(abs(e["cohesion"] - m["Cohesion"]) < 1e-9 and
                       abs(e["friction_angle"] - m["Friction angle"]) < 1e-9 for e in strengths), \
                f"material {name} is not on the sliding surface"
        assert s["report"]["made"], s["report"]
        # The blocks are the groups the guide names.
        assert {b["name"] for b in s["blocks"]} == {"sliding mass", "foundation"}


def check_installed(build_dir, case):
    """`cmake --install` into a fresh prefix: the installed program finds
    its report script (share/fdem-slope/fdem_report.py) and makes the report
    of an installed case, run from an unrelated folder."""
    import tempfile
    with tempfile.TemporaryDirectory(prefix="fdem-install-") as prefix:
        subprocess.run(["cmake", "--install", build_dir, "--prefix", prefix], check=True,
                       capture_output=True, text=True)
        exe = os.path.join(prefix, "bin", "fdem-slope")
        prm = os.path.join(prefix, "share", "fdem-slope", "prm", case)
        assert os.path.exists(os.path.join(prefix, "share", "fdem-slope", "fdem_report.py"))
        with fdem_run.temporary_run(exe, prm) as run:
            assert run.ok, run.failure()
            print("report:", run.summary["report"])
            assert run.summary["report"]["made"] is True, run.summary["report"]
            check_pictures(run.output)


if __name__ == "__main__":
    checks = {"report": check_report, "no_python": check_no_python, "off": check_report_off,
              "csv_order": check_csv_order,
              "my_first_slope": check_my_first_slope, "installed": check_installed}
    if len(sys.argv) != 4 or sys.argv[1] not in checks:
        print(f"usage: report_checks.py {{{'|'.join(checks)}}} EXE PRM (installed: BUILD_DIR CASE)")
        sys.exit(2)
    checks[sys.argv[1]](sys.argv[2], sys.argv[3])
    print("ok")
