#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Active anchors (Reinforcement) of runs of the executable against closed
forms (doc/verification.md, "Anchors"):

  anchor_checks.py EXE block|invariance|paper

block: prm/inclined_block.prm (plane at beta = 30 degrees, phi = 35, c = 10,
  A = 10, W = 1250) with one anchor of force T pulling the block upslope at
  angle theta below the plane, so T sin(theta) presses it onto the plane and
  T cos(theta) acts upslope. The sums of the pairs' normal and shear forces
  are fixed by the free block's equilibrium (eq. 7), whatever the elastic
  distribution, so:
  - unreduced loads (Duncan & Wright's method A):
      K = (c A + (W cos(beta) + T sin(theta)) tan(phi)) / (W sin(beta) - T cos(theta)),
    K* independent of K: the run's K to 1e-10 relative;
  - shear reduced by K (method B): at every solved step
      K* = (c A + (W cos(beta) + T sin(theta)) tan(phi)) / (W sin(beta) - T cos(theta) / K),
    to 1e-10 (each step is exact), and its fixed point
      K = (c A + (W cos(beta) + T sin(theta)) tan(phi) + T cos(theta)) / (W sin(beta)),
    to the iteration's tolerance (Safety factor/Tolerance = 1e-11 here, so 1e-10).
  Also summary.json's and anchors.csv's components, and the result block's line.
invariance: the reduced and the unreduced case in N-m-Pa (forces x 1000),
  and rotated by 25 degrees with gravity and the anchor's points: the same K
  to 1e-10.
"""
import csv
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path[:0] = [os.path.join(HERE, "..", "..", "tools")]
import fdem_run  # noqa: E402

BETA = math.radians(30)
C, PHI, A, W = 10.0, math.radians(35), 10.0, 1250.0
BASE = {"Interfaces/sliding surface/Tensile strength": "1e3",
        "Safety factor/Tolerance": "1e-11"}


# The inclined block's entries in N-m-Pa (forces x 1000), for the invariance checks.
NEWTON_BLOCK = {"Interfaces/sliding surface/Tensile strength": "1e6",
                "Interfaces/sliding surface/Cohesion": "1e4",
                "Blocks/block/Young's modulus": "1e8", "Blocks/block/Unit weight": "25e3",
                "Blocks/foundation/Young's modulus": "1e9",
                "Blocks/foundation/Unit weight": "25e3"}


def plane_point(s, n):
    """The point s along the plane (upslope) and n above it, as the
    Inclined block generator places it (rotated by beta)."""
    return (s * math.cos(BETA) - n * math.sin(BETA), s * math.sin(BETA) + n * math.cos(BETA))


def anchor(T, theta_deg, s=2.0, n=2.0, length=8.0, reduced=False):
    """Settings of one anchor with its head at (s, n) in the block, pulling
    upslope at theta below the plane, its bond point length further on."""
    theta = math.radians(theta_deg)
    head = plane_point(s, n)
    bond = plane_point(s + length * math.cos(theta), n - length * math.sin(theta))
    return {"Reinforcement/Anchor heads": f"{head[0]!r}, {head[1]!r}",
            "Reinforcement/Anchor bond points": f"{bond[0]!r}, {bond[1]!r}",
            "Reinforcement/Anchor forces": repr(T),
            "Reinforcement/Anchor force reduced by K": "true" if reduced else "false"}


def unreduced_K(T, theta):
    return (C * A + (W * math.cos(BETA) + T * math.sin(theta)) * math.tan(PHI)) / \
        (W * math.sin(BETA) - T * math.cos(theta))


def reduced_K(T, theta):
    return (C * A + (W * math.cos(BETA) + T * math.sin(theta)) * math.tan(PHI) + T * math.cos(theta)) / \
        (W * math.sin(BETA))


def reduced_K_star(T, theta, K):
    return (C * A + (W * math.cos(BETA) + T * math.sin(theta)) * math.tan(PHI)) / \
        (W * math.sin(BETA) - T * math.cos(theta) / K)


def check(name, value, expected, tolerance):
    error = abs(value - expected) / abs(expected)
    print(f"{'ok  ' if error <= tolerance else 'FAIL'} {name}: {value!r} against {expected!r} "
          f"({error:.1e}, tolerance {tolerance:g})")
    assert error <= tolerance, name


def run(exe, prm, settings):
    with fdem_run.temporary_run(exe, prm, settings=settings) as result:
        assert result.ok, result.failure()
        rows = list(csv.DictReader(open(result.file("anchors.csv"))))
        return result.summary, result.stdout, rows


# T, theta (degrees), and the head's height above the plane and the
# anchor's length, so that the bond point lies in the foundation slab.
CASES = [(100.0, 20.0, 2.0, 8.0), (200.0, 45.0, 2.0, 8.0), (150.0, 90.0, 2.0, 5.0),
         (50.0, 5.0, 0.5, 8.0)]


def block(exe):
    for reduced in (False, True):
        for T, theta_deg, n, length in CASES:
            theta = math.radians(theta_deg)
            summary, stdout, rows = run(exe, "inclined_block.prm",
                                        {**BASE, **anchor(T, theta_deg, n=n, length=length,
                                                          reduced=reduced)})
            name = f"{'reduced' if reduced else 'unreduced'} T = {T}, theta = {theta_deg}"
            assert summary["converged"], name
            r = summary["reinforcement"]
            assert r["reduced_by_K"] == reduced and len(r["anchors"]) == 1
            a = r["anchors"][0]
            assert a["head_block"] == "block" and a["bond_block"] == "foundation"
            assert a["interface"] == "sliding surface"
            check(f"  {name}: normal component", a["normal_force"], T * math.sin(theta), 1e-12)
            if theta_deg != 90:
                check(f"  {name}: shear component", a["shear_force"], T * math.cos(theta), 1e-12)
            else:
                assert abs(a["shear_force"]) <= 1e-12 * T
            assert len(rows) == 1 and abs(float(rows[0]["force"]) - T) <= 1e-12 * T
            assert "Anchors" in stdout and "1 anchor" in stdout, "the result block names the anchors"
            for step in summary["iterations"]:
                assert step["n_open"] == 0, f"{name}: a pair opened (the closed form assumes none)"
                if step["K_star"] is not None and reduced:
                    check(f"  {name}: K* at K = {step['K']:.12g}", step["K_star"],
                          reduced_K_star(T, theta, step["K"]), 1e-10)
            expected = reduced_K(T, theta) if reduced else unreduced_K(T, theta)
            check(name, summary["safety_factor"], expected, 1e-10)


def invariance(exe):
    for reduced in (False, True):
        settings = {**BASE, **anchor(150.0, 30.0, reduced=reduced)}
        reference, _, _ = run(exe, "inclined_block.prm", settings)
        newton = {**settings, **NEWTON_BLOCK,
                  "Reinforcement/Anchor forces": "150e3"}
        angle = math.radians(25)
        rotated = {**settings, "Geometry/Rotation angle": 25,
                   "Loads/Gravity direction": f"{math.sin(angle)!r}, {-math.cos(angle)!r}"}
        for name, changed in (("N-m-Pa", newton), ("rotated by 25 degrees", rotated)):
            summary, _, _ = run(exe, "inclined_block.prm", changed)
            check(f"{'reduced' if reduced else 'unreduced'}, {name}", summary["safety_factor"],
                  reference["safety_factor"], 1e-10)


PAPER_ANCHOR = {"Reinforcement/Anchor heads": "20, 29.5",
                "Reinforcement/Anchor bond points": f"{20 + 12 * math.cos(math.radians(20))!r}, "
                                                    f"{29.5 - 12 * math.sin(math.radians(20))!r}",
                "Reinforcement/Anchor forces": "100",
                "Safety factor/Stiffness check": "false"}


def paper(exe):
    """The paper's slope with one anchor (T = 100 kN/m, 20 degrees below the
    horizontal, head at (20, 29.5) on the face) against Bishop and Spencer on
    the same circle with the same anchor: the methods differ by their own
    assumptions, so the ratio K_contact / K_LE with the anchor is compared
    with the ratio without it (PAPER_TOLERANCE, from the measured values)."""
    base, _, _ = {}, None, None
    with fdem_run.temporary_run(exe, "paper_slope.prm",
                                settings={"Safety factor/Stiffness check": "false"}) as result:
        assert result.ok, result.failure()
        base = result.summary
    methods = ("bishop_simplified", "spencer")
    ratio0 = {m: base["safety_factor"] / base["limit_equilibrium"]["methods"][m]["K"] for m in methods}
    for reduced in (False, True):
        summary, _, _ = run(exe, "paper_slope.prm",
                            {**PAPER_ANCHOR,
                             "Reinforcement/Anchor force reduced by K": "true" if reduced else "false"})
        assert summary["converged"]
        K = summary["safety_factor"]
        assert K > base["safety_factor"], "the anchor raises K"
        for m in methods:
            le = summary["limit_equilibrium"]["methods"][m]["K"]
            change = (K / le) / ratio0[m] - 1
            print(f"{'reduced' if reduced else 'unreduced'}: K = {K:.6f} (without the anchor "
                  f"{base['safety_factor']:.6f}), {m} {le:.6f} "
                  f"(without {base['limit_equilibrium']['methods'][m]['K']:.6f}); "
                  f"ratio changes by {change:.2e}")
            assert abs(change) <= PAPER_TOLERANCE, m
        assert any("anchors act on the base" in n for n in summary["limit_equilibrium"]["notes"])


# As for kh (PaperSlope.SeismicAgainstLimitEquilibriumAndYieldAcceleration):
# measured 1.6e-3 (Bishop, unreduced), 1.4e-3 (Bishop, reduced), 5e-4 and
# 2.5e-4 (Spencer); with the reduced shear applied at the head instead of
# the crossing it was 8e-3 against Bishop, which this bound catches.
PAPER_TOLERANCE = 5e-3


def mechanism(exe):
    """The mechanism field of the VTU (final state minus the elastic state
    with every pair stuck) with an anchor reduced by K: the all-stick state
    was solved with the anchor's load at K = 1, so its displacements must
    be recovered with that load too. Then u_stick = u - mechanism is the
    all-stick state itself, in which both nodes of every pair of the
    sliding surface move together (no gap, no slip). Recovered with the
    final K's load instead (T_S/K), u_stick carries a spurious elastic
    response to T_S (1 - 1/K) in the sliding mass alone, and its two sides
    part: the difference is checked against 1e-6 of the largest u_stick
    (the two sides' displacements agree to round-off in the stuck state)."""
    import paraview_checks as pv
    import numpy as np
    settings = {**PAPER_ANCHOR, "Reinforcement/Anchor force reduced by K": "true",
                "Output/Write VTU": "true"}
    with fdem_run.temporary_run(exe, "paper_slope.prm", settings=settings) as result:
        assert result.ok, result.failure()
        files = {name: f for _, name, f in pv.datasets(result.file("solution.pvd"))}
        folder = os.path.dirname(result.file("solution.pvd"))
        stuck = {}
        for name in ("sliding mass", "foundation"):
            grid = pv.read(os.path.join(folder, files[name]))
            _, u = pv.point_array(grid, "displacement")
            _, m = pv.point_array(grid, "mechanism_displacement")
            stuck[name] = (pv.points(grid), u - m)
        surface = pv.points(pv.read(os.path.join(folder, files["sliding surface"])))
    scale = max(float(np.max(np.abs(stuck["foundation"][1]))),
                float(np.max(np.abs(stuck["sliding mass"][1]))))
    worst = 0.0
    for x in surface:
        at = {}
        for name, (xyz, u) in stuck.items():
            distance = np.linalg.norm(xyz - x, axis=1)
            at[name] = u[int(np.argmin(distance))]
            assert float(np.min(distance)) <= 1e-9 * 50, f"no node of {name} at {x}"
        worst = max(worst, float(np.max(np.abs(at["sliding mass"] - at["foundation"]))))
    print(f"all-stick state from the VTU: the two sides of the surface differ by "
          f"{worst:.3e}, {worst / scale:.2e} of the largest displacement {scale:.3e}")
    assert worst <= 1e-6 * scale, "the mechanism field mixes the loads of two K"


def main(exe, what):
    {"block": block, "invariance": invariance, "paper": paper,
     "mechanism": mechanism}[what](exe)
    print("passed")


if __name__ == "__main__":
    main(*sys.argv[1:3])
