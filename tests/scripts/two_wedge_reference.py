#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Limit equilibrium of a slide on a bilinear sliding surface cut into two
rigid wedges by one straight interslice (the two-wedge method), written for
the tests independently of the program; doc/theory.md ("Multi-block
mechanisms") has the derivation.

Wedge 1 rests on the segment A-B of the sliding surface, wedge 2 on B-C; the
interslice runs from the kink B up to the ground at T. Every surface slips,
with c and tan(phi) of all three divided by the same K. Wedge i moves along
its base, v_i parallel to s_i (unit, towards the lower end of its segment);
the interslice stays closed, so v_1 - v_2 lies along it (m, unit, B to T):
v_2 = b s_2 with b = (s_1.n_m)/(s_2.n_m) > 0 for v_1 = s_1, and the sign
sigma of (v_1 - v_2).m says which way wedge 1 slides past wedge 2. With
mu = 1/K, n_i the base normals (into the wedges), n_21 the interslice normal
into wedge 1, the forces on wedge 1 and 2 are

  F_1 + N_1 n_1 - mu (c_1 L_1 + t_1 N_1) s_1 + (E a + b_v) = 0
  F_2 + N_2 n_2 - mu (c_2 L_2 + t_2 N_2) s_2 - (E a + b_v) = 0
  a = n_21 - mu sigma t_12 m,   b_v = U_12 n_21 - mu sigma c_12 L_12 m

(F_i the weight plus the water forces, N_i and E the effective normal
forces, t = tan(phi), U the water force on a surface). Projecting each on
n_i gives N_i; on s_i then E = -P_i(mu)/Q_i(mu) with quadratics P_i, Q_i,
and K follows from P_1 Q_2 - P_2 Q_1 = 0, a quartic in mu: the one root with
N_1, N_2, E >= 0 and mu > 0.

    two_wedge_reference.py two-wedge EXE PRM TOLERANCE
    two_wedge_reference.py planar EXE PRM TOLERANCE

run the case PRM (Geometry/Source = slope, a polyline sliding surface with
interslices) and compare its safety factor with the two-wedge K (three
polyline points, one interslice), or with the single-block planar K (every
polyline point on one line, any number of interslices).
"""
import math
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path[:0] = [HERE, os.path.join(HERE, "..", "..", "tools")]
import fdem_run  # noqa: E402


def points(text):
    return [tuple(float(v) for v in p.split(",")) for p in text.split(";") if p.strip()]


def ground_at(ground, x):
    for (x0, y0), (x1, y1) in zip(ground, ground[1:]):
        if x <= x1:
            return y0 + (x - x0) / (x1 - x0) * (y1 - y0)
    return ground[-1][1]


def area(polygon):
    return 0.5 * abs(sum(x0 * y1 - x1 * y0 for (x0, y0), (x1, y1)
                         in zip(polygon, polygon[1:] + polygon[:1])))


def unit(v):
    return np.asarray(v, float) / math.hypot(*v)


def upward_normal(d):
    n = np.array([-d[1], d[0]])
    return n if n[1] > 0 else -n


def water_force(pressure, p, q):
    """The resultant of a pressure linear along the segment p-q: exact."""
    return math.dist(p, q) * 0.5 * (pressure(*p) + pressure(*q))


def pressure_function(expression):
    if expression.strip() in ("", "0"):
        return lambda x, y: 0.0
    assert "piezometric" not in expression, "give the pore pressure as a function of x, y"
    return lambda x, y: eval(expression, {"max": max, "min": min}, {"x": x, "y": y})


def ground_between(ground, x_from, x_to):
    """Ground vertices strictly between x_from and x_to, from x_from to x_to."""
    inner = [p for p in ground if min(x_from, x_to) < p[0] < max(x_from, x_to)]
    return inner if x_from < x_to else inner[::-1]


def two_wedge_K(A, B, C, T, ground, gamma, strength, water, crack=0.0):
    """K of the two-wedge mechanism; strength[s] = (tan phi, c) and
    water[s] = pore pressure function for s in 'base 1', 'base 2',
    'interslice'. @p crack: the water force in a vertical tension crack that
    closes wedge 2 above C (a crest on the right). Returns (K, N_1, N_2, E)."""
    wedge_1 = [A, B, T] + ground_between(ground, T[0], A[0])
    top = [(C[0], ground_at(ground, C[0]))] if ground_at(ground, C[0]) > C[1] else []
    wedge_2 = [B, C] + top + ground_between(ground, C[0], T[0]) + [T]
    A, B, C, T = (np.asarray(p, float) for p in (A, B, C, T))
    s1, s2 = unit(A - B), unit(B - C)  # the motion, towards the toe
    if s1[0] > 0:  # a slope facing right: the toe is at C
        s1, s2 = unit(B - A), unit(C - B)
    n1, n2 = upward_normal(s1), upward_normal(s2)
    m = unit(T - B)
    n_m = np.array([-m[1], m[0]])
    centre_1 = np.mean(np.asarray(wedge_1, float), axis=0)
    n21 = n_m if (centre_1 - B) @ n_m > 0 else -n_m  # into wedge 1
    b = (s1 @ n21) / (s2 @ n21)
    assert b > 0, "the two wedges cannot both move down their bases"
    sigma = math.copysign(1, (s1 - b * s2) @ m)
    L1, L2, L12 = (float(np.linalg.norm(v)) for v in (B - A, C - B, T - B))
    (t1, c1), (t2, c2), (t12, c12) = (strength[k] for k in ("base 1", "base 2", "interslice"))
    U1 = water_force(water["base 1"], A, B)
    U2 = water_force(water["base 2"], B, C)
    U12 = water_force(water["interslice"], B, T)
    F1 = np.array([0, -gamma * area(wedge_1)]) + U1 * n1
    F2 = np.array([0, -gamma * area(wedge_2)]) + U2 * n2 + np.array([-crack, 0])
    # Vectors affine in mu as (constant, coefficient of mu); products of two
    # such scalars as numpy polynomials (highest power first).
    a = (n21, -sigma * t12 * m)
    bv = (U12 * n21, -sigma * c12 * L12 * m)
    P = np.polynomial.Polynomial

    def dot(u, affine):
        return P([u @ affine[0], u @ affine[1]])

    mu = P([0, 1])
    P1 = s1 @ F1 - mu * c1 * L1 + mu * t1 * (n1 @ F1 + dot(n1, bv)) + dot(s1, bv)
    Q1 = dot(s1, a) + mu * t1 * dot(n1, a)
    P2 = s2 @ F2 - mu * c2 * L2 + mu * t2 * (n2 @ F2 - dot(n2, bv)) - dot(s2, bv)
    Q2 = -(dot(s2, a) + mu * t2 * dot(n2, a))
    quartic = P1 * Q2 - P2 * Q1
    answers = []
    for root in quartic.roots():
        if abs(root.imag) > 1e-9 * abs(root) or root.real <= 0:
            continue
        x = root.real
        for _ in range(3):  # Newton polishes the root to round-off
            d = quartic.deriv()(x)
            if d != 0:
                x -= quartic(x) / d
        E = -P1(x) / Q1(x)
        N1 = -(n1 @ F1 + E * (n1 @ (a[0] + x * a[1])) + n1 @ (bv[0] + x * bv[1]))
        N2 = -(n2 @ F2 - E * (n2 @ (a[0] + x * a[1])) - n2 @ (bv[0] + x * bv[1]))
        if min(N1, N2, E) >= 0:
            answers.append((1 / x, N1, N2, E))
    assert len(answers) == 1, f"admissible roots: {answers}"
    return answers[0]


def planar_K(A, C, ground, gamma, tan_phi, c, pressure):
    """K of one rigid block on the plane A-C (the mass above it)."""
    mass = [A, C] + ground_between(ground, C[0], A[0])
    W = gamma * area(mass)
    d = unit(np.subtract(A, C)) if A[1] < C[1] else unit(np.subtract(C, A))
    n = upward_normal(d)
    U = water_force(pressure, A, C)
    weight = np.array([0, -W])
    N = -(weight @ n) - U
    return (c * math.dist(A, C) + tan_phi * N) / (weight @ d)


def case_data(run):
    p = run.parameters
    slope = "Geometry/Slope/"
    ground = points(p[slope + "Ground surface"])
    line = points(p[slope + "Sliding surface polyline"])
    gammas = {float(p[k]) for k in p if k.startswith("Blocks/") and k.endswith("/Unit weight")}
    assert len(gammas) == 1, "one unit weight for all blocks"

    def interface(name):
        key = "Interfaces/" + name + "/"
        return ((math.tan(math.radians(float(p.get(key + "Friction angle", 30)))),
                 float(p.get(key + "Cohesion", 0))),
                pressure_function(p.get(key + "Pore pressure", "0")))

    return ground, line, gammas.pop(), interface


def check_two_wedge(exe, prm, tolerance):
    run = fdem_run.run_case(exe, prm)
    assert run.ok, run.failure()
    summary = run.summary
    ground, line, gamma, interface = case_data(run)
    assert len(line) == 3, "a bilinear surface: three polyline points"
    assert run.parameters["Geometry/Slope/Interslice surfaces"] in ("vertical", "bisector",
                                                                    "inclination")
    # The top of the interslice: the program's block corners are not
    # reported, so it is computed here from the direction the case asks for.
    A, B, C = line
    kind = run.parameters["Geometry/Slope/Interslice surfaces"]
    if kind == "vertical":
        d = (0.0, 1.0)
    elif kind == "inclination":
        angle = math.radians(float(run.parameters["Geometry/Slope/Interslice inclinations"]))
        d = (math.cos(angle), math.sin(angle))
    else:
        u, w = unit(np.subtract(A, B)), unit(np.subtract(C, B))
        d = u + w if (u + w)[1] > 0 else -(u + w)
    # The ray B + s d meets the ground: bisection on the height above it.
    lo, hi = 0.0, 1.0
    while B[1] + hi * d[1] < ground_at(ground, B[0] + hi * d[0]):
        hi *= 2
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        below = B[1] + mid * d[1] < ground_at(ground, B[0] + mid * d[0])
        lo, hi = (mid, hi) if below else (lo, mid)
    T = (B[0] + hi * d[0], B[1] + hi * d[1])
    # A tension crack: the point C' of B-C that lies its depth below the
    # ground (bisection), and the force of its pressure (each part linear
    # in y: trapezoids either side of the water level are exact).
    depth = float(run.parameters.get("Geometry/Slope/Tension crack depth", 0))
    crack = 0.0
    if depth > 0:
        lo, hi = 0.0, 1.0  # C' = C + t (B - C)
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            x, y = C[0] + mid * (B[0] - C[0]), C[1] + mid * (B[1] - C[1])
            lo, hi = (mid, hi) if ground_at(ground, x) - y < depth else (lo, mid)
        C = (C[0] + hi * (B[0] - C[0]), C[1] + hi * (B[1] - C[1]))
        level = C[1] + float(run.parameters["Geometry/Slope/Tension crack water depth"])
        # The generator fills the crack to that level (Water/Unit weight
        # of water, 9.81 unless set).
        gamma_w = float(run.parameters.get("Water/Unit weight of water", 9.81))
        p = lambda x, y: gamma_w * max(0.0, level - y)
        for y0, y1 in ((C[1], level), (level, C[1] + depth)):
            crack += 0.5 * (y1 - y0) * (p(C[0], y0) + p(C[0], y1))
    names = {"base 1": "sliding surface 1", "base 2": "sliding surface 2",
             "interslice": "interslice 1"}
    strength = {k: interface(v)[0] for k, v in names.items()}
    water = {k: interface(v)[1] for k, v in names.items()}
    K, N1, N2, E = two_wedge_K(A, B, C, T, ground, gamma, strength, water, crack)
    K_program = summary["safety_factor"]
    error = (K_program - K) / K
    print(f"two-wedge K = {K:.15g} (N1 = {N1:.6g}, N2 = {N2:.6g}, E = {E:.6g}); program "
          f"K = {K_program:.15g} ({summary['certificate']['kind']}); relative {error:.3e}")
    assert summary["converged"], summary["certificate"]
    assert abs(error) <= float(tolerance), (K_program, K)


def check_planar(exe, prm, tolerance):
    run = fdem_run.run_case(exe, prm)
    assert run.ok, run.failure()
    summary = run.summary
    ground, line, gamma, interface = case_data(run)
    A, C = line[0], line[-1]
    for p in line[1:-1]:  # every vertex on the line A-C
        assert abs(np.cross(np.subtract(C, A), np.subtract(p, A))) < 1e-12 * math.dist(A, C) ** 2
    n_blocks = sum(1 for b in summary["blocks"] if b["name"].startswith("sliding mass"))
    names = [f"sliding surface {i + 1}" for i in range(n_blocks)] if n_blocks > 1 else \
            ["sliding surface"]
    strengths = {interface(n)[0] for n in names}
    assert len(strengths) == 1, "one strength on the whole plane"
    tan_phi, c = strengths.pop()
    K = planar_K(A, C, ground, gamma, tan_phi, c, interface(names[0])[1])
    K_program = summary["safety_factor"]
    error = (K_program - K) / K
    print(f"{n_blocks} blocks: planar K = {K:.15g}; program K = {K_program:.15g} "
          f"({summary['certificate']['kind']}); relative {error:.3e}")
    assert summary["converged"], summary["certificate"]
    assert abs(error) <= float(tolerance), (K_program, K)


if __name__ == "__main__":
    command, exe, prm, tolerance = sys.argv[1:5]
    {"two-wedge": check_two_wedge, "planar": check_planar}[command](exe, prm, tolerance)
