#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""The safety factor of a rigid mass on a spherical sliding surface in
undrained (phi = 0) soil, by quadrature, independent of the program.

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
by tilting e by 5 degrees in eight directions: K rises in each). On the
sphere, with psi the angle about the y axis, dA = R dpsi dy and
|y x r| = rho(y) = sqrt(R^2 - (y - y_c)^2), so

    K = c * integral rho(y) R psi_below(y) dy / (gamma * integral (x - x_c) dV).

The slope is the section of tests/three_d/slope_3d.prm (the paper's:
ground z = 25 for x <= 10, rising to 35 at x = 30, flat beyond) extruded
along y. Gauss-Legendre quadrature on the pieces between the ground's kinks
and its crossings of each section circle, and in y with the substitution
y = y_c -/+ (y_c - y_0) cos t that softens the ends: 80 and 160 points in
y agree to 3e-7 (40 points: 1.1e-5 lower).

    /usr/bin/python3 tests/scripts/undrained_sphere.py XC YC ZC R C GAMMA
"""
import sys

import numpy as np
from numpy.polynomial.legendre import leggauss

X_TOE, X_CREST, Z_TOE, HEIGHT = 10.0, 30.0, 25.0, 10.0


def ground(x):
    return np.where(x <= X_TOE, Z_TOE,
                    np.where(x >= X_CREST, Z_TOE + HEIGHT, Z_TOE + HEIGHT * (x - X_TOE) / (X_CREST - X_TOE)))


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


def section(centre, R, y):
    """The surface integral of rho R over psi below the ground and the
    first moment (x - x_c) of the mass's section, at y."""
    xc, yc, zc = centre
    rho = np.sqrt(R * R - (y - yc) ** 2)
    below = lambda psi: ground(xc + rho * np.sin(psi)) - (zc - rho * np.cos(psi))
    kinks = [np.arcsin((x - xc) / rho) for x in (X_TOE, X_CREST) if abs(x - xc) < rho]
    area = piecewise_gauss(lambda psi: np.where(below(psi) > 0, rho * R, 0.0), -np.pi, np.pi,
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


def undrained_sphere_factor(centre, R, c, gamma, n=80):
    xc, yc, zc = centre

    def depth(y):
        rho = np.sqrt(max(R * R - (y - yc) ** 2, 0.0))
        xs = np.linspace(xc - rho, xc + rho, 2001)
        return np.max(ground(xs) - (zc - np.sqrt(np.maximum(rho ** 2 - (xs - xc) ** 2, 0))))

    # y_0: where the section circles first dip below the ground.
    ys = np.linspace(yc - R, yc, 4001)
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
            total += 0.25 * np.pi * wi * (yc - y0) * np.sin(t) * section(centre, R, yc + sense * (yc - y0) * np.cos(t))
    return c * total[0] / (gamma * total[1])


if __name__ == "__main__":
    xc, yc, zc, R, c, gamma = map(float, sys.argv[1:7])
    print(repr(undrained_sphere_factor((xc, yc, zc), R, c, gamma)))
