#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""The seismic load and the yield acceleration of runs of the executable
against closed forms (doc/verification.md):

  seismic_checks.py EXE block2d|block3d|yield|invariance

block2d, block3d: prm/inclined_block.prm (theta = 30, phi = 35, c = 10,
  L = 10, W = 1250) and prm/block_on_plane_3d.prm (dip 30 towards 120,
  phi = 30, c = 15, A = 60, W = 7500) under kh, kv: K = (c A + W ((1 - kv)
  cos(theta) - kh sin(theta)) tan(phi)) / (W ((1 - kv) sin(theta) + kh
  cos(theta))) (Kramer 1996, Sec. 10.6.1), to 1e-10 relative: the sums of
  the pair forces are fixed by equilibrium, so K* is exact at each step.
yield: k_y of the inclined block, c = 10 and c = 0 (phi = 40), kv = 0 and
  0.1: k_y = (c A / W + (1 - kv) (cos(theta) tan(phi) - sin(theta))) /
  (cos(theta) + sin(theta) tan(phi)) (c = 0: (1 - kv) tan(phi - theta)), to
  1e-10 (Brent to 1e-13); the result block and yield_acceleration.csv too.
invariance: K under kh = 0.15, kv = 0.05 and k_y of the inclined block in
  N-m-Pa (forces x 1000) and rotated by 25 degrees with its gravity: the same
  as in kN-m-kPa to 1e-10.
"""
import csv
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path[:0] = [os.path.join(HERE, "..", "..", "tools")]
import fdem_run  # noqa: E402


def pseudo_static_K(c, phi, A, W, theta, kh, kv):
    t = math.tan(math.radians(phi))
    N = W * ((1 - kv) * math.cos(theta) - kh * math.sin(theta))
    T = W * ((1 - kv) * math.sin(theta) + kh * math.cos(theta))
    return (c * A + N * t) / T


def yield_coefficient(c, phi, A, W, theta, kv):
    t = math.tan(math.radians(phi))
    return (c * A / W + (1 - kv) * (math.cos(theta) * t - math.sin(theta))) / \
        (math.cos(theta) + math.sin(theta) * t)


def run(exe, prm, settings, files=None):
    with fdem_run.temporary_run(exe, prm, settings=settings, files=files) as result:
        assert result.ok, result.failure()
        curve = None
        if os.path.exists(result.file("yield_acceleration.csv")):
            curve = list(csv.DictReader(open(result.file("yield_acceleration.csv"))))
        return result.summary, result.stdout, curve


def check(name, value, expected, tolerance):
    error = abs(value - expected) / abs(expected)
    print(f"{'ok  ' if error <= tolerance else 'FAIL'} {name}: {value!r} against {expected!r} "
          f"({error:.1e}, tolerance {tolerance:g})")
    assert error <= tolerance, name


COEFFICIENTS = [(0.1, 0.0), (0.1, 0.05), (0.2, -0.1), (0.0, 0.2), (-0.1, 0.0)]


def block(exe, prm, c, phi, A, W, theta, extra):
    for kh, kv in COEFFICIENTS:
        summary, stdout, _ = run(exe, prm, {**extra,
                                            "Loads/Horizontal seismic coefficient": kh,
                                            "Loads/Vertical seismic coefficient": kv})
        assert summary["seismic"]["kh"] == kh and summary["seismic"]["kv"] == kv
        assert summary["seismic"]["direction_from"] == "towards free face"
        assert "Seismic load" in stdout, "the result block names the seismic load"
        check(f"{prm} kh = {kh}, kv = {kv}", summary["safety_factor"],
              pseudo_static_K(c, phi, A, W, theta, kh, kv), 1e-10)


def yield_checks(exe):
    for c, phi in ((10, 35), (0, 40)):
        for kv in (0.0, 0.1):
            summary, stdout, curve = run(exe, "inclined_block.prm", {
                "Interfaces/sliding surface/Cohesion": c,
                "Interfaces/sliding surface/Friction angle": phi,
                "Interfaces/sliding surface/Tensile strength": "1e3",
                "Loads/Vertical seismic coefficient": kv,
                "Yield acceleration/Compute": "true",
                "Yield acceleration/Tolerance": "1e-13"})
            y = summary["seismic"]["yield_acceleration"]
            assert y["found"], y["not_found"]
            exact = yield_coefficient(c, phi, 10, 1250, math.radians(30), kv)
            check(f"k_y, c = {c}, phi = {phi}, kv = {kv}", y["k_y"], exact, 1e-10)
            assert y["bracket"][0] <= y["k_y"] <= y["bracket"][1]
            assert "Yield acceleration" in stdout and "k_y = " in stdout
            assert len(curve) == y["n_evaluations"] == len(y["curve"])
            for point in curve:
                if point["certified"] == "1":
                    K = float(point["K"])
                    expected = pseudo_static_K(c, phi, 10, 1250, math.radians(30), float(point["kh"]), kv)
                    assert abs(K - expected) <= 1e-9 * expected, f"curve at kh = {point['kh']}"
            # The K reported is that of the given kh (0 here), not of the search.
            check("  K after the search", summary["safety_factor"],
                  pseudo_static_K(c, phi, 10, 1250, math.radians(30), 0, kv), 1e-10)


def invariance(exe):
    base = {"Interfaces/sliding surface/Tensile strength": "1e3",
            "Loads/Horizontal seismic coefficient": 0.15,
            "Loads/Vertical seismic coefficient": 0.05,
            "Yield acceleration/Compute": "true",
            "Yield acceleration/Tolerance": "1e-13"}
    reference, _, _ = run(exe, "inclined_block.prm", base)
    newton = {**base, "Interfaces/sliding surface/Tensile strength": "1e6",
              "Interfaces/sliding surface/Cohesion": "1e4",
              "Blocks/block/Young's modulus": "1e8", "Blocks/block/Unit weight": "25e3",
              "Blocks/foundation/Young's modulus": "1e9", "Blocks/foundation/Unit weight": "25e3"}
    angle = math.radians(25)
    rotated = {**base, "Geometry/Rotation angle": 25,
               "Loads/Gravity direction": f"{math.sin(angle)!r}, {-math.cos(angle)!r}"}
    for name, settings in (("N-m-Pa", newton), ("rotated by 25 degrees", rotated)):
        summary, _, _ = run(exe, "inclined_block.prm", settings)
        check(f"K under kh, {name}", summary["safety_factor"], reference["safety_factor"], 1e-10)
        check(f"k_y, {name}", summary["seismic"]["yield_acceleration"]["k_y"],
              reference["seismic"]["yield_acceleration"]["k_y"], 1e-10)


def main(exe, what):
    if what == "block2d":
        block(exe, "inclined_block.prm", 10, 35, 10, 1250, math.radians(30),
              {"Interfaces/sliding surface/Tensile strength": "1e3"})
    elif what == "block3d":
        block(exe, "block_on_plane_3d.prm", 15, 30, 60, 7500, math.radians(30), {})
    elif what == "yield":
        yield_checks(exe)
    elif what == "invariance":
        invariance(exe)
    else:
        raise SystemExit(f"unknown check {what}")
    print("passed")


if __name__ == "__main__":
    main(*sys.argv[1:3])
