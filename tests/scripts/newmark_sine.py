#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""The Newmark displacement of a run against an independent integration.

  newmark_sine.py EXE

Runs prm/inclined_block.prm with Yield acceleration/Compute = true and a
sine pulse a(t) = A sin(2 pi t / T_p), A = 4 m/s^2, T_p = 0.8 s, sampled
every 2 ms (written here, in m/s^2), then integrates the same record,
linear between samples, with its own explicit scheme on a step of 1e-6 s
(numpy): the sliding mass's relative velocity v >= 0 grows by (a - k_y g)
dt while it slides, sliding starting where a > k_y g. The scheme is first
order: its error is about 1e-6 / 0.8 relative; the bound 1e-4 of the
largest displacement leaves room for it and nothing else. k_y is checked
against the closed form of the block on the plane (doc/verification.md),
and the files newmark.csv and yield_acceleration.csv against summary.json.
"""
import csv
import math
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path[:0] = [os.path.join(HERE, "..", "..", "tools")]
import fdem_run  # noqa: E402

G = 9.80665


def main(exe):
    A, Tp, dt = 4.0, 0.8, 0.002
    t = np.arange(0, 1.5 * Tp + dt / 2, dt)
    a = np.where(t <= Tp, A * np.sin(2 * np.pi * t / Tp), 0.0)
    record = "time,acceleration\n" + "".join(f"{ti:.6f},{ai:.12g}\n" for ti, ai in zip(t, a))
    settings = {"Yield acceleration/Compute": "true",
                "Yield acceleration/Tolerance": "1e-12",
                "Yield acceleration/Acceleration record": "sine.csv",
                "Yield acceleration/Acceleration unit": "m/s^2",
                "Interfaces/sliding surface/Tensile strength": "1e3"}
    with fdem_run.temporary_run(exe, "inclined_block.prm", settings=settings,
                                files={"sine.csv": record}) as result:
        assert result.ok, result.failure()
        seismic = result.summary["seismic"]
        k_y = seismic["yield_acceleration"]["k_y"]
        # prm/inclined_block.prm: theta = 30, phi = 35, c = 10, L = 10, W = 25 * 10 * 5.
        th, tp, W = math.radians(30), math.tan(math.radians(35)), 25 * 10 * 5
        exact = (10 * 10 / W + math.cos(th) * tp - math.sin(th)) / (math.cos(th) + math.sin(th) * tp)
        print(f"k_y = {k_y!r}, closed form {exact!r}")
        assert abs(k_y - exact) < 1e-9 * exact, "k_y is not the closed form"
        rows = list(csv.DictReader(open(result.file("newmark.csv"))))
        d_run = np.array([float(r["displacement_m"]) for r in rows])
        t_run = np.array([float(r["time_s"]) for r in rows])
        curve = list(csv.DictReader(open(result.file("yield_acceleration.csv"))))
        assert len(curve) == seismic["yield_acceleration"]["n_evaluations"], "curve CSV"
        newmark = seismic["newmark"]
        assert newmark["unit"] == "m/s^2" and newmark["sliding"] == "one-directional"
        assert abs(newmark["max_displacement_m"] - d_run.max()) < 1e-12 * d_run.max()

    # The independent integration.
    a_y = k_y * G
    h = 1e-6
    tf = np.arange(0, t[-1] + h / 2, h)
    af = np.interp(tf, t, a)
    v, d = 0.0, 0.0
    d_fine = np.empty_like(tf)
    # Vectorised by sliding episodes would be faster; a plain loop over
    # 1.2e6 steps takes a second or two.
    for i in range(len(tf)):
        if v > 0 or af[i] > a_y:
            v = max(0.0, v + (af[i] - a_y) * h)
        d += v * h
        d_fine[i] = d
    d_ref = np.interp(t_run, tf, d_fine)
    scale = d_ref.max()
    print(f"largest displacement: run {d_run.max()!r} m, independent {scale!r} m")
    assert scale > 0.01, "the pulse should make the block slide"
    assert np.abs(d_run - d_ref).max() < 1e-4 * scale, "histories differ"
    print("passed")


if __name__ == "__main__":
    main(sys.argv[1])
