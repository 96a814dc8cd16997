#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""The safety factor of a rigid mass on a spherical, or spheroidal,
sliding surface in undrained (phi = 0) soil, by quadrature, independent of
the program.

With phi = 0 the strength c does not depend on the normal stress, and the
normal stresses on a sphere pass through its centre: they have no moment
about it. A rigid mass turning about an axis e through the centre slips
along circles about e with speed omega |e x r| (r from the centre); moment
equilibrium about e at the limit (every point at its strength c / K along
its slip) gives

    K(e) = c * integral |e x r| dA / (e . M_w),

M_w the moment of the mass's weight about the centre, and K = min over e
(Baligh & Azzouz 1975, J. Geotech. Eng. Div. 101(GT11), for cylinders with
ends; the same moment balance on a sphere). For a mass symmetric about the
plane y = y_c, M_w lies along y and the axis e = y is the minimum (checked
by tilting e by 5 degrees in eight directions: K rises in each).

A spheroid with semi-axes R in x and z and b along y is a surface of
revolution about the axis along y through its centre: its normal
((x - x_c)/R^2, (y - y_c)/b^2, (z - z_c)/R^2) has no moment about that axis
((z - z_c) n_x - (x - x_c) n_z = 0), and turning about it is its only
rigid motion, so K = K(y) there. With psi the angle about the y axis and
rho(y) = R sqrt(1 - ((y - y_c)/b)^2) the radius of the section circle,
dA = J dpsi dy with J = rho sqrt(1 + rho'^2) = sqrt(rho^2 + R^4 s^2 / b^2),
s = (y - y_c)/b (J = R on the sphere), and |y x r| = rho, so

    K = c * integral rho(y) J(y) psi_below(y) dy / (gamma * integral (x - x_c) dV).

The slope is the section of tests/three_d/slope_3d.prm (the paper's:
ground z = 25 for x <= 10, rising to 35 at x = 30, flat beyond) extruded
along y. Gauss-Legendre quadrature on the pieces between the ground's kinks
and its crossings of each section circle, and in y with the substitution
y = y_c -/+ (y_c - y_0) cos t that softens the ends. The sphere (R = 21.32
m): 1.0315274 with 80 points in y, 1.0315297, 1.0315304 with 160, 320
(40 points: 8.6e-6 lower). The spheroid of tests/three_d/slope_3d.prm
(b = 15 m, c = 20 kPa): 1.0956209, 1.0956218, 1.0956214 with 160, 320, 640
points, within 8.3e-7 (a crude independent sum, 4000 x 8000 facets of the
spheroid and 3000 x 3000 columns of the mass, gives 1.0956047, -1.5e-5).

A capsule (a cylinder of radius R along y over a straight length L,
closed by the two halves of the spheroid: Baligh & Azzouz's cylinder with
ends) is a surface of revolution about the same axis: its K adds L times
the central section's integrals to the spheroid's.

    /usr/bin/python3 tests/scripts/undrained_sphere.py XC YC ZC R C GAMMA [B [N [L]]]
"""
import functools
import sys

import numpy as np
from numpy.polynomial.legendre import leggauss as numpy_leggauss

X_TOE, X_CREST, Z_TOE, HEIGHT = 10.0, 30.0, 25.0, 10.0


def ground(x):
    return np.where(x <= X_TOE, Z_TOE,
                    np.where(x >= X_CREST, Z_TOE + HEIGHT, Z_TOE + HEIGHT * (x - X_TOE) / (X_CREST - X_TOE)))


@functools.lru_cache(maxsize=None)
def leggauss(n):
    """numpy's Gauss-Legendre points and weights, computed once per n (an
    eigenvalue problem each time otherwise: most of the time of a run)."""
    return numpy_leggauss(n)


def sign_changes(f, a, b, n=400):
    """The roots of f on [a, b] where it changes sign, by bisection."""
    xs = np.linspace(a, b, n + 1)
    fs = f(xs)
    roots = []
    for i in range(n):
        if fs[i] * fs[i + 1] < 0:
            lo, hi = xs[i], xs[i + 1]
            for _ in range(100):
                mid = 0.5 * (lo + hi)
                lo, hi = (lo, mid) if f(lo) * f(mid) <= 0 else (mid, hi)
            roots.append(0.5 * (lo + hi))
    return roots


def piecewise_gauss(f, a, b, breaks, n=40):
    points = sorted([a, b] + [t for t in breaks if a < t < b])
    g, w = leggauss(n)
    total = 0.0
    for lo, hi in zip(points[:-1], points[1:]):
        x = 0.5 * (hi - lo) * g + 0.5 * (hi + lo)
        total += 0.5 * (hi - lo) * np.sum(w * f(x))
    return total


def section(centre, R, b, y):
    """The surface integral of rho J over psi below the ground and the
    first moment (x - x_c) of the mass's section, at y."""
    xc, yc, zc = centre
    s = (y - yc) / b
    rho = R * np.sqrt(1 - s * s)
    # dA = J dpsi dy with J = rho sqrt(1 + rho'(y)^2) = sqrt(rho^2 + R^4 s^2 / b^2)
    # (R on a sphere).
    J = np.sqrt(rho * rho + (R * R * s / b) ** 2)
    below = lambda psi: ground(xc + rho * np.sin(psi)) - (zc - rho * np.cos(psi))
    kinks = [np.arcsin((x - xc) / rho) for x in (X_TOE, X_CREST) if abs(x - xc) < rho]
    area = piecewise_gauss(lambda psi: np.where(below(psi) > 0, rho * J, 0.0), -np.pi, np.pi,
                           sign_changes(below, -np.pi, np.pi) + kinks)

    def height(x):
        s = np.sqrt(np.maximum(rho ** 2 - (x - xc) ** 2, 0))
        return np.maximum(0, np.minimum(ground(x), zc + s) - (zc - s))

    breaks = [X_TOE, X_CREST]
    for sense in (-1, 1):
        breaks += sign_changes(lambda x: ground(x) - (zc + sense * np.sqrt(np.maximum(rho ** 2 - (x - xc) ** 2, 0))),
                               xc - rho, xc + rho)
    moment = piecewise_gauss(lambda x: (x - xc) * height(x), xc - rho, xc + rho, breaks)
    return np.array([area, moment])


def undrained_sphere_factor(centre, R, c, gamma, n=80, b=None, straight=0.0):
    """K of the sphere of radius R, or of the spheroid with semi-axes R in
    x and z and b along y (its axis of revolution), or of the capsule: a
    cylinder of radius R along y over the length @p straight, closed by the
    spheroid's halves (its two ends, the spheroid's halves moved apart;
    between them every section is the central one)."""
    totals = spheroid_totals(centre, R, n, b)
    totals += straight * section(centre, R, R if b is None else b, centre[1])
    return c * totals[0] / (gamma * totals[1])


def spheroid_totals(centre, R, n, b):
    """The integrals over y of section() on the spheroid (the sphere if b
    is None)."""
    xc, yc, zc = centre
    b = R if b is None else b

    def depth(y):
        rho = R * np.sqrt(max(1 - ((y - yc) / b) ** 2, 0.0))
        xs = np.linspace(xc - rho, xc + rho, 2001)
        return np.max(ground(xs) - (zc - np.sqrt(np.maximum(rho ** 2 - (xs - xc) ** 2, 0))))

    # y_0: where the section circles first dip below the ground.
    ys = np.linspace(yc - b, yc, 4001)
    i = int(np.argmax([depth(y) > 0 for y in ys]))
    lo, hi = ys[i - 1], ys[i]
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        lo, hi = (lo, mid) if depth(mid) > 0 else (mid, hi)
    y0 = 0.5 * (lo + hi)
    g, w = leggauss(n)
    total = np.zeros(2)
    for sense in (-1, 1):
        for gi, wi in zip(g, w):
            t = 0.25 * np.pi * (gi + 1)
            total += 0.25 * np.pi * wi * (yc - y0) * np.sin(t) * section(centre, R, b, yc + sense * (yc - y0) * np.cos(t))
    return total


if __name__ == "__main__":
    xc, yc, zc, R, c, gamma = map(float, sys.argv[1:7])
    b = float(sys.argv[7]) if len(sys.argv) > 7 else None
    n = int(sys.argv[8]) if len(sys.argv) > 8 else 80
    straight = float(sys.argv[9]) if len(sys.argv) > 9 else 0.0
    print(repr(undrained_sphere_factor((xc, yc, zc), R, c, gamma, n, b, straight)))
