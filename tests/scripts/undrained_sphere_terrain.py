#!/usr/bin/env python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""The safety factor of a rigid mass on a spherical sliding surface in
undrained (phi = 0) soil under a terrain given on a grid, by quadrature,
independent of the program.

As in undrained_sphere.py (Baligh & Azzouz 1975's moment balance): with
phi = 0 the normal stresses on a sphere pass through its centre, and a
rigid mass turning about an axis e through the centre at the limit gives

    K(e) = c * integral |e x r| dA / (e . M_w),   K = min over e,

r from the centre, M_w = integral r x (0, 0, -gamma) dV the moment of the
weight about the centre, (-gamma (y - y_c), gamma (x - x_c), 0) per unit
volume. Under a terrain that is not symmetric about a plane through the
centre M_w has a component along x too, and the axis of the minimum tilts
from y: it is found by a compass search over the directions of e (steps
halved down to 1e-7 rad).

The ground is the grid's bilinear surface, as in the program
(TerrainGrid::elevation). Both integrals are taken over slices y =
const: on a sphere dA = R dpsi dy (Archimedes), psi the angle about the y
axis, and the volume's column heights integrate over x. Gauss-Legendre
quadrature between the breaks where the integrands kink: in y the grid
lines and the ends of the range where the sphere dips below the ground
and where its rim crosses a grid line in x (with y = lo + (hi - lo)(1 -
cos t)/2 on each piece, which softens the square-root ends), along each
circle and in x the grid lines and the crossings of the ground
with the sphere. For the terrain equal to the straight slope of
tests/three_d/slope_3d.prm this reproduces undrained_sphere.py's
1.0315274 (the minimum on e = y); see tests/CMakeLists.txt for the
convergence measured on the terrains tested.

With a water table (a grid file WATER, bilinear as the terrain) the unit
weight below it is GAMMA_SAT: the weight's moment takes each column's
saturated part at GAMMA_SAT. The pore pressure on the sphere is normal to
it and passes through the centre, so it adds no moment: K is that of the
heavier mass.

    /usr/bin/python3 tests/scripts/undrained_sphere_terrain.py TERRAIN XC YC ZC R C GAMMA [N [WATER GAMMA_SAT]]
"""
import bisect
import functools
import sys

import numpy as np
from numpy.polynomial.legendre import leggauss as numpy_leggauss

from undrained_sphere import sign_changes as roots  # the sign changes of f on [a, b]


@functools.lru_cache(maxsize=None)
def leggauss(n):
    """numpy's Gauss-Legendre points and weights, computed once per n (an
    eigenvalue problem each time otherwise: most of the time of a run)."""
    return numpy_leggauss(n)


class Terrain:
    def __init__(self, path):
        rows = []
        for line in open(path):
            line = line.split('#')[0].replace(',', ' ').replace(';', ' ').split()
            if not line:
                continue
            try:
                rows.append([float(v) for v in line])
            except ValueError:
                continue  # the header
        rows = np.array(rows)
        self.x = np.unique(rows[:, 0])
        self.y = np.unique(rows[:, 1])
        self.z = np.zeros((len(self.y), len(self.x)))
        for x, y, z in rows:
            self.z[np.searchsorted(self.y, y), np.searchsorted(self.x, x)] = z

    def __call__(self, x, y):
        if isinstance(x, float) and isinstance(y, float):
            return self.at_point(x, y)
        x = np.clip(np.asarray(x, dtype=float), self.x[0], self.x[-1])
        y = np.clip(np.asarray(y, dtype=float), self.y[0], self.y[-1])
        i = np.clip(np.searchsorted(self.x, x, side='right') - 1, 0, len(self.x) - 2)
        j = np.clip(np.searchsorted(self.y, y, side='right') - 1, 0, len(self.y) - 2)
        s = (x - self.x[i]) / (self.x[i + 1] - self.x[i])
        t = (y - self.y[j]) / (self.y[j + 1] - self.y[j])
        z = self.z
        return ((1 - s) * (1 - t) * z[j, i] + s * (1 - t) * z[j, i + 1] + (1 - s) * t * z[j + 1, i]
                + s * t * z[j + 1, i + 1])

    def at_point(self, x, y):
        """__call__ at one point, the same operations on Python floats (the
        same numbers, far fewer calls into numpy)."""
        if not hasattr(self, "_lists"):
            self._lists = (self.x.tolist(), self.y.tolist(), self.z.tolist())
        xs, ys, z = self._lists
        x = min(max(x, xs[0]), xs[-1])
        y = min(max(y, ys[0]), ys[-1])
        i = min(max(bisect.bisect_right(xs, x) - 1, 0), len(xs) - 2)
        j = min(max(bisect.bisect_right(ys, y) - 1, 0), len(ys) - 2)
        s = (x - xs[i]) / (xs[i + 1] - xs[i])
        t = (y - ys[j]) / (ys[j + 1] - ys[j])
        return ((1 - s) * (1 - t) * z[j][i] + s * (1 - t) * z[j][i + 1] + (1 - s) * t * z[j + 1][i]
                + s * t * z[j + 1][i + 1])


def pieces(a, b, breaks, n):
    """Gauss points and weights on [a, b] split at the breaks."""
    g, w = leggauss(n)
    points = sorted([a, b] + [t for t in breaks if a < t < b])
    xs, ws = [], []
    for lo, hi in zip(points[:-1], points[1:]):
        xs.append(0.5 * (hi - lo) * g + 0.5 * (hi + lo))
        ws.append(0.5 * (hi - lo) * w)
    return np.concatenate(xs), np.concatenate(ws)


def plane_of(grid):
    """(a, b, c) if the grid's surface is the plane z = a + b x + c y, else
    None."""
    X, Y = np.meshgrid(grid.x, grid.y)
    A = np.stack([np.ones(X.size), X.ravel(), Y.ravel()], axis=1)
    coefficients = np.linalg.lstsq(A, grid.z.ravel(), rcond=None)[0]
    scale = 1 + np.max(np.abs(grid.z))
    return coefficients if np.max(np.abs(A @ coefficients - grid.z.ravel())) < 1e-12 * scale else None


def sphere_quadrature(ground, centre, R, n, gamma, water=None, gamma_sat=None):
    """The nodes r (from the centre) and weights of dA on the sphere below
    the ground, and the moment M_w of the mass's weight: gamma, or below
    the grid @p water gamma_sat."""
    xc, yc, zc = centre
    excess = 0.0 if water is None else gamma_sat - gamma

    def circle(y):
        rho = np.sqrt(max(R * R - (y - yc) ** 2, 0.0))
        return rho, (lambda psi: ground(xc + rho * np.sin(psi), y) - (zc - rho * np.cos(psi)))

    def depth(y):
        rho, below = circle(y)
        return np.max(below(np.linspace(-np.pi, np.pi, 4001))) if rho > 0 else -1.0

    # The range of y where the circle dips below the ground: an interval
    # around the deepest section (checked: one interval on a fine scan).
    ys = np.linspace(yc - R, yc + R, 4001)
    dips = np.array([depth(y) > 0 for y in ys])
    assert dips.any() and np.count_nonzero(np.diff(dips.astype(int))) == 2, 'expected one range in y'
    ends = []
    for k in np.nonzero(np.diff(dips.astype(int)))[0]:
        lo, hi = ys[k], ys[k + 1]
        for _ in range(80):
            mid = 0.5 * (lo + hi)
            lo, hi = (lo, mid) if (depth(mid) > 0) == dips[k + 1] else (mid, hi)
        ends.append(0.5 * (lo + hi))
    y_a, y_b = ends
    # The integrands in y kink at the grid lines y = y_j and where the
    # sphere's rim on the ground crosses a grid line x = x_i.
    crossings = []
    for xg in ground.x:
        half = np.sqrt(max(R * R - (xg - xc) ** 2, 0.0))
        for sense in (-1, 1):
            sheet = lambda y: ground(xg, y) - (zc + sense * np.sqrt(np.maximum(half * half - (y - yc) ** 2, 0)))
            crossings += roots(sheet, yc - half, yc + half) if half > 0 else []
    # Below a water table the weight kinks at its grid lines, and where
    # the water enters a section: for a plane z = a + b x + c y its line in
    # the section touches the circle, (a + b x_c + c y - z_c) / sqrt(1 +
    # b^2) = -rho(y) (other water surfaces: see the convergence in n).
    if water is not None:
        crossings += list(water.y)
        plane = plane_of(water)
        if plane is not None:
            a, b, c = plane
            crossings += roots(lambda y: (a + b * xc + c * y - zc) / np.sqrt(1 + b * b)
                               + np.sqrt(np.maximum(R * R - (y - yc) ** 2, 0)), yc - R, yc + R)
    breaks = sorted(set([y_a, y_b] + [y for y in list(ground.y) + crossings if y_a < y < y_b]))
    g, w = leggauss(n)
    nodes, weights = [], []
    moment = np.zeros(3)
    for lo, hi in zip(breaks[:-1], breaks[1:]):
        t = 0.5 * np.pi * (g + 1)
        for ti, wi in zip(t, w):
            y = lo + 0.5 * (hi - lo) * (1 - np.cos(ti))
            wy = wi * 0.5 * np.pi * 0.5 * (hi - lo) * np.sin(ti)
            rho, below = circle(y)
            # The surface: psi over the circle below the ground.
            kinks = []
            for xg in ground.x:
                if abs(xg - xc) < rho:
                    a = np.arcsin((xg - xc) / rho)
                    kinks += [a, np.pi - a if a > 0 else -np.pi - a]
            psi, wpsi = pieces(-np.pi, np.pi, roots(below, -np.pi, np.pi) + kinks, n)
            inside = below(psi) > 0
            psi, wpsi = psi[inside], wpsi[inside]
            nodes.append(np.stack([rho * np.sin(psi), np.full(psi.shape, y - yc), -rho * np.cos(psi)], axis=1))
            weights.append(R * wpsi * wy)
            # The volume: columns over x between the sphere's sheets.

            def weight(x):
                s = np.sqrt(np.maximum(rho * rho - (x - xc) ** 2, 0))
                top = np.minimum(ground(x, y), zc + s)
                total = gamma * np.maximum(0, top - (zc - s))
                if water is not None:
                    total += excess * np.maximum(0, np.minimum(water(x, y), top) - (zc - s))
                return total

            xbreaks = [xg for xg in ground.x]
            sheets = [lambda x, sense=sense: zc + sense * np.sqrt(np.maximum(rho * rho - (x - xc) ** 2, 0))
                      for sense in (-1, 1)]
            for sheet in sheets:
                xbreaks += roots(lambda x: ground(x, y) - sheet(x), xc - rho, xc + rho)
            if water is not None:
                xbreaks += list(water.x)
                for surface in sheets + [lambda x: ground(x, y)]:
                    xbreaks += roots(lambda x: water(x, y) - surface(x), xc - rho, xc + rho)
            x, wx = pieces(xc - rho, xc + rho, xbreaks, n)
            h = weight(x) * wx * wy
            moment += np.array([-(y - yc) * np.sum(h), np.sum((x - xc) * h), 0.0])
    return np.concatenate(nodes), np.concatenate(weights), moment


def factor_and_axis(nodes, weights, moment, c):
    def K(a, b):
        e = np.array([np.cos(a) * np.sin(b), np.cos(a) * np.cos(b), np.sin(a)])
        em = e @ moment
        return (c * np.sum(weights * np.linalg.norm(np.cross(e, nodes), axis=1)) / em if em > 0 else np.inf), e

    a, b = 0.0, 0.0  # e = y
    best, _ = K(a, b)
    step = 0.1
    while step > 1e-7:
        moved = False
        for da, db in ((step, 0), (-step, 0), (0, step), (0, -step)):
            value, _ = K(a + da, b + db)
            if value < best:
                best, a, b, moved = value, a + da, b + db, True
                break
        if not moved:
            step /= 2
    return best, K(a, b)[1]


def undrained_sphere_terrain_factor(path, centre, R, c, gamma, n=40, water=None, gamma_sat=None):
    """K and the axis of the turn; with @p water (a grid file of the water
    table) the unit weight is @p gamma_sat below it."""
    nodes, weights, moment = sphere_quadrature(Terrain(path), centre, R, n, gamma,
                                               Terrain(water) if water else None, gamma_sat)
    return factor_and_axis(nodes, weights, moment, c)


if __name__ == '__main__':
    path = sys.argv[1]
    xc, yc, zc, R, c, gamma = map(float, sys.argv[2:8])
    n = int(sys.argv[8]) if len(sys.argv) > 8 else 40
    water, gamma_sat = (sys.argv[9], float(sys.argv[10])) if len(sys.argv) > 10 else (None, None)
    K, e = undrained_sphere_terrain_factor(path, (xc, yc, zc), R, c, gamma, n, water, gamma_sat)
    print(repr(K), ' '.join(f'{v:.6f}' for v in e))
