#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Passive bars (Reinforcement/Bar ...) of runs of the executable against
closed forms (doc/verification.md, "Passive bars"):

  bar_checks.py EXE block|pile|block3d|stiffness|invariance|paper

block: prm/inclined_block.prm (plane at beta = 30 degrees, phi = 35, c = 10,
  A = 10, W = 1250) with one bar from a head in the block, pointing upslope
  at theta below the plane into the foundation. At the limit the block
  slides, the bar is stretched to its capacity N_y and both conventions
  have a closed form: the sums of the pairs' normal and shear forces are
  fixed by the free block's equilibrium (eq. 7) with the bar's force
  N_y along it, whatever the elastic distribution:
  - capacities not reduced by K: the bar is a force N_y, so
      K = (c A + (W cos(beta) + N_y sin(theta)) tan(phi)) / (W sin(beta) - N_y cos(theta));
  - capacities reduced by K: the bar yields at N_y / K, so K solves
      K W sin(beta) = c A + (W cos(beta) + N_y sin(theta) / K) tan(phi) + N_y cos(theta),
    a quadratic in K.
  The fixed point is reached to the iteration's tolerance (Safety
  factor/Tolerance = 1e-11 here, so 1e-10). N_y is the tensile capacity,
  or with a pull-out resistance q the least of it, q L (the bar's length in
  the block, head to surface) and q L' (surface to end). Also summary.json's
  and bars.csv's forces (at the limit the bar's force is its applied
  capacity) and the result block's line.
pile: a pile normal to the plane with a shear capacity: the closed forms
  with its shear capacity along the plane (see pile()).
block3d: the closed forms of block on the 3D block on a plane (see block3d()).
stiffness: the same K for axial stiffnesses 1e4 and 1e7 (the limit does not
  depend on it), 1e-10.
invariance: both conventions in N-m-Pa (forces x 1000, stiffnesses x 1000),
  with every modulus and the bar's stiffness x 1000, and rotated by 25
  degrees with gravity and the bar: the same K to 1e-10.
paper: the paper's slope with two nails against Bishop and Spencer on the
  same circle with the nails as forces at their capacities.
"""
import csv
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path[:0] = [os.path.join(HERE, "..", "..", "tools")]
import fdem_run  # noqa: E402
# The same block, plane and check as the anchors'.
from anchor_checks import BETA, C, PHI, A, W, BASE, NEWTON_BLOCK, plane_point, check  # noqa: E402,F401


def bar(capacity, theta_deg, s=2.0, n=2.0, length=8.0, reduced=False, pullout=None,
        stiffness=1e5):
    """Settings of one bar with its head at (s, n) in the block, pointing
    upslope at theta below the plane, its end length further on."""
    theta = math.radians(theta_deg)
    head = plane_point(s, n)
    end = plane_point(s + length * math.cos(theta), n - length * math.sin(theta))
    settings = {"Reinforcement/Bar heads": f"{head[0]!r}, {head[1]!r}",
                "Reinforcement/Bar ends": f"{end[0]!r}, {end[1]!r}",
                "Reinforcement/Bar tensile capacities": repr(capacity),
                "Reinforcement/Bar axial stiffnesses": repr(stiffness),
                "Reinforcement/Bar capacity reduced by K": "true" if reduced else "false"}
    if pullout is not None:
        settings["Reinforcement/Bar pull-out resistances"] = repr(pullout)
    return settings


def unreduced_K(N, theta):
    return (C * A + (W * math.cos(BETA) + N * math.sin(theta)) * math.tan(PHI)) / \
        (W * math.sin(BETA) - N * math.cos(theta))


def reduced_K(N, theta):
    a = W * math.sin(BETA)
    b = C * A + W * math.cos(BETA) * math.tan(PHI) + N * math.cos(theta)
    c = N * math.sin(theta) * math.tan(PHI)
    return (b + math.sqrt(b * b + 4 * a * c)) / (2 * a)


def run(exe, prm, settings):
    with fdem_run.temporary_run(exe, prm, settings=settings) as result:
        assert result.ok, result.failure()
        rows = list(csv.DictReader(open(result.file("bars.csv"))))
        return result.summary, result.stdout, rows


# Capacity, theta (degrees), the head's height above the plane, the bar's
# length, and a pull-out resistance (None: none). The last two cases are
# limited by the bond: in the block (2 m / sin 30 = 4 m of bar, q = 20 gives
# 80 < 150) and in the ground (8 - 0.5 / sin 5 = 2.26 m beyond the surface,
# q = 25 gives 56 < 100).
CASES = [(100.0, 20.0, 2.0, 8.0, None), (200.0, 45.0, 2.0, 8.0, None),
         (50.0, 5.0, 0.5, 8.0, None), (150.0, 30.0, 2.0, 8.0, 20.0),
         (100.0, 5.0, 0.5, 8.0, 25.0)]


def capacity_of(T, theta, n, length, q):
    if q is None:
        return T
    in_block = n / math.sin(theta)
    return min(T, q * in_block, q * (length - in_block))


def block(exe):
    for reduced in (False, True):
        for T, theta_deg, n, length, q in CASES:
            theta = math.radians(theta_deg)
            N_y = capacity_of(T, theta, n, length, q)
            summary, stdout, rows = run(exe, "inclined_block.prm",
                                        {**BASE, **bar(T, theta_deg, n=n, length=length,
                                                       reduced=reduced, pullout=q)})
            name = (f"{'reduced' if reduced else 'unreduced'} T = {T}, theta = {theta_deg}"
                    + (f", pull-out {q}" if q else ""))
            assert summary["converged"], name
            r = summary["reinforcement"]["passive_bars"]
            assert r["capacity_reduced_by_K"] == reduced and len(r["bars"]) == 1
            b = r["bars"][0]
            assert b["head_block"] == "block" and b["end_block"] == "foundation"
            assert b["interface"] == "sliding surface"
            check(f"  {name}: axial capacity", b["axial_capacity"], N_y, 1e-9)
            K = summary["safety_factor"]
            applied = N_y / K if reduced else N_y
            # The iteration reaches the limit from below, where the bar is
            # still elastic: its force is its capacity to the distance left
            # (K* - K = K (N_y - N) cos(theta) / F_tau, below 1e-11 K).
            check(f"  {name}: axial force at the limit", b["axial_force"], applied, 1e-9)
            assert len(rows) == 1
            check(f"  {name}: bars.csv axial force", float(rows[0]["axial_force"]), applied, 1e-9)
            assert "Passive bars" in stdout and "1 bar, " in stdout, \
                "the result block names the bar"
            assert summary["certificate"]["kind"] == "fixed point", name
            for step in summary["iterations"]:
                assert step["n_open"] == 0, f"{name}: a pair opened (the closed form assumes none)"
            expected = reduced_K(N_y, theta) if reduced else unreduced_K(N_y, theta)
            check(name, K, expected, 1e-10)


def pile(exe):
    """A pile normal to the plane (theta = 90 degrees) with a shear
    capacity V_y: sliding shears it across, and at the limit its shear
    force is V_y along the plane, against the slide; its axial force N
    (elastic, tension pressing the block on) is what the solve gives, so the
    closed forms take the reported N:
      not reduced: K = (c A + (W cos(beta) + N) tan(phi)) / (W sin(beta) - V_y),
      reduced:     K = (c A + (W cos(beta) + N) tan(phi) + V_y) / (W sin(beta))."""
    V_y = 100.0
    for reduced in (False, True):
        settings = {**BASE, **bar(1e6, 90.0, n=2.0, length=5.0, reduced=reduced),
                    "Reinforcement/Bar shear capacities": repr(V_y),
                    "Reinforcement/Bar shear stiffnesses": "1e5"}
        summary, _, _ = run(exe, "inclined_block.prm", settings)
        name = f"pile, {'reduced' if reduced else 'not reduced'}"
        assert summary["converged"] and summary["certificate"]["holds"], name
        b = summary["reinforcement"]["passive_bars"]["bars"][0]
        K, N = summary["safety_factor"], b["axial_force"]
        check(f"  {name}: shear force at the limit", b["shear_force"],
              V_y / K if reduced else V_y, 1e-9)
        if reduced:
            expected = (C * A + (W * math.cos(BETA) + N) * math.tan(PHI) + V_y) / (W * math.sin(BETA))
        else:
            expected = (C * A + (W * math.cos(BETA) + N) * math.tan(PHI)) / (W * math.sin(BETA) - V_y)
        print(f"  {name}: axial force {N:.6g} (elastic, below its capacity)")
        assert abs(N) < 1e6
        check(name, K, expected, 1e-10)


def block3d(exe):
    """prm/block_on_plane_3d.prm (dip 30 degrees towards azimuth 120,
    c = 15, phi = 30, A = 60, W = 7500) with one bar from the block at 2 m
    above the plane into the foundation, 45 degrees below the plane and
    pointing up the dip: the closed forms of block() in 3D. Safety factor/
    Tolerance = 1e-9: the certified fixed point has K* = K to 1e-9, and the
    limit is (K* - K) / (1 - m) away (m = dK*/dK, below 0.9 here), so 1e-8
    (measured 2e-10 not reduced, 4e-11 reduced; 17 and 43 steps)."""
    beta, azimuth, theta = math.radians(30), math.radians(120), math.radians(45)
    dd = (math.sin(azimuth) * math.cos(beta), math.cos(azimuth) * math.cos(beta), -math.sin(beta))
    up = (math.sin(azimuth) * math.sin(beta), math.cos(azimuth) * math.sin(beta), math.cos(beta))

    def point(x, z):  # x down the dip from the origin, z above the plane
        return ", ".join(repr(x * dd[i] + z * up[i]) for i in range(3))
    c, phi, area, weight, N = 15.0, math.radians(30), 60.0, 7500.0, 1000.0
    for reduced in (False, True):
        settings = {"Safety factor/Tolerance": "1e-9",
                    "Reinforcement/Bar heads": point(5, 2),
                    "Reinforcement/Bar ends": point(1.5, -1.5),
                    "Reinforcement/Bar tensile capacities": repr(N),
                    "Reinforcement/Bar axial stiffnesses": "1e6",
                    "Reinforcement/Bar capacity reduced by K": "true" if reduced else "false"}
        summary, _, _ = run(exe, "block_on_plane_3d.prm", settings)
        name = f"3D, {'reduced' if reduced else 'not reduced'}"
        assert summary["converged"] and summary["certificate"]["kind"] == "fixed point", name
        if reduced:
            a = weight * math.sin(beta)
            b = c * area + weight * math.cos(beta) * math.tan(phi) + N * math.cos(theta)
            q = N * math.sin(theta) * math.tan(phi)
            expected = (b + math.sqrt(b * b + 4 * a * q)) / (2 * a)
        else:
            expected = (c * area + (weight * math.cos(beta) + N * math.sin(theta)) * math.tan(phi)) / \
                (weight * math.sin(beta) - N * math.cos(theta))
        check(name, summary["safety_factor"], expected, 1e-8)


def stiffness(exe):
    for reduced in (False, True):
        K = []
        for k_a in (1e4, 1e7):
            summary, _, _ = run(exe, "inclined_block.prm",
                                {**BASE, **bar(100.0, 20.0, reduced=reduced, stiffness=k_a)})
            K.append(summary["safety_factor"])
        check(f"{'reduced' if reduced else 'unreduced'}: K with axial stiffness 1e7 and 1e4",
              K[1], K[0], 1e-10)


def invariance(exe):
    for reduced in (False, True):
        settings = {**BASE, **bar(150.0, 30.0, reduced=reduced)}
        reference, _, _ = run(exe, "inclined_block.prm", settings)
        newton = {**settings, **NEWTON_BLOCK,
                  "Reinforcement/Bar tensile capacities": "150e3",
                  "Reinforcement/Bar axial stiffnesses": "1e8"}
        stiffer = {**settings, "Blocks/block/Young's modulus": "1e8",
                   "Blocks/foundation/Young's modulus": "1e9",
                   "Reinforcement/Bar axial stiffnesses": "1e8"}
        angle = math.radians(25)
        rotated = {**settings, "Geometry/Rotation angle": 25,
                   "Loads/Gravity direction": f"{math.sin(angle)!r}, {-math.cos(angle)!r}"}
        for name, changed in (("N-m-Pa", newton), ("every stiffness x 1000", stiffer),
                              ("rotated by 25 degrees", rotated)):
            summary, _, _ = run(exe, "inclined_block.prm", changed)
            check(f"{'reduced' if reduced else 'unreduced'}, {name}", summary["safety_factor"],
                  reference["safety_factor"], 1e-10)


# Two nails through the paper's slope face, 20 degrees below the horizontal,
# 12 m long, 60 kN/m each (a row of bars of 150 kN at 2.5 m spacing),
# stiffness 1e5 kN/m/m.
def paper_nails(reduced):
    heads, ends = [], []
    for x, y in ((18.0, 28.5), (24.0, 31.5)):
        heads.append(f"{x!r}, {y!r}")
        ends.append(f"{x + 12 * math.cos(math.radians(20))!r}, {y - 12 * math.sin(math.radians(20))!r}")
    return {"Reinforcement/Bar heads": "; ".join(heads),
            "Reinforcement/Bar ends": "; ".join(ends),
            "Reinforcement/Bar tensile capacities": "60, 60",
            "Reinforcement/Bar axial stiffnesses": "1e5, 1e5",
            "Reinforcement/Bar capacity reduced by K": "true" if reduced else "false",
            "Safety factor/Stiffness check": "false"}


# As for the anchors (anchor_checks.py, PAPER_TOLERANCE): the methods differ
# by their own assumptions, so the ratio of the contact K to each LE factor
# with the nails is compared with the ratio without them.
PAPER_TOLERANCE = 5e-3


def paper(exe):
    with fdem_run.temporary_run(exe, "paper_slope.prm",
                                settings={"Safety factor/Stiffness check": "false"}) as result:
        assert result.ok, result.failure()
        base = result.summary
    methods = ("bishop_simplified", "spencer")
    ratio0 = {m: base["safety_factor"] / base["limit_equilibrium"]["methods"][m]["K"] for m in methods}
    for reduced in (False, True):
        summary, _, rows = run(exe, "paper_slope.prm", paper_nails(reduced))
        assert summary["converged"] and summary["certificate"]["holds"]
        K = summary["safety_factor"]
        assert K > base["safety_factor"], "the nails raise K"
        statuses = [b["status"] for b in summary["reinforcement"]["passive_bars"]["bars"]]
        for m in methods:
            le = summary["limit_equilibrium"]["methods"][m]["K"]
            change = (K / le) / ratio0[m] - 1
            print(f"{'reduced' if reduced else 'unreduced'}: K = {K:.6f} (without the nails "
                  f"{base['safety_factor']:.6f}), {m} {le:.6f} "
                  f"(without {base['limit_equilibrium']['methods'][m]['K']:.6f}); "
                  f"ratio changes by {change:.2e}; bars {statuses}")
            assert abs(change) <= PAPER_TOLERANCE, m


def main(exe, what):
    {"block": block, "pile": pile, "block3d": block3d, "stiffness": stiffness,
     "invariance": invariance, "paper": paper}[what](exe)
    print("passed")


if __name__ == "__main__":
    main(*sys.argv[1:3])
