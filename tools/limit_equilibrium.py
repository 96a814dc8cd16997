# SPDX-License-Identifier: LGPL-2.1-or-later
"""Limit equilibrium by the method of slices: Spencer's method on any
polyline (or circular) sliding surface, and Bishop's simplified method on a
circle. It is the program's independent yardstick for non-circular surfaces
(doc/limit_equilibrium.md): written from the textbook equations, sharing no
code with fdem-slope. Runs under /usr/bin/python3 (numpy, scipy).

A section (2D, lengths in the model's unit, x to the right, y up) is:
  ground      the ground surface, points from left to right;
  layers      a list of Layer, top down: each layer lies below its top line
              (the ground for the first one) down to the next layer's top;
  piezometric the piezometric line (points from left to right) or None;
  gamma_w     the unit weight of water.
Below the piezometric line a layer weighs gamma_sat and the base carries
the hydrostatic pore pressure gamma_w (y_piezometric - y), as in the
program's 'piezometric' pore pressure. A layer may have a piezometric line
of its own (Layer.piezometric, a perched water table): its wet part and a
base in it use that line instead.

The sliding surface runs from where it leaves the ground on one side to
where it enters it on the other; its end points lie on the ground. The mass
above it moves down the slope, to the left or to the right: the program
finds out which from the ground's elevations at the two ends. A vertical
tension crack closes the surface at its upper end (crack_depth > 0): the
surface then starts at the crack's bottom, and water in the crack
(crack_water_depth) pushes the mass down the slope with gamma_w d^2 / 2.

The slices' boundaries include every vertex of every line and every point
where two lines cross, so that every line is straight inside a slice: the
weights and pore-pressure forces of the slices are then exact for the
polyline geometry, and only the interslice assumption (Spencer's constant
inclination) and the base forces' points of action remain as the method's
own approximations.
"""
import math
from dataclasses import dataclass, field

import numpy as np
from scipy.optimize import brentq


@dataclass
class Layer:
    """One soil layer: its top line (None: the ground surface), unit weights
    and Mohr-Coulomb strength (c, phi in degrees)."""
    top: list = None
    gamma: float = 20.0
    gamma_sat: float = None
    c: float = 0.0
    phi: float = 30.0
    # The layer's own piezometric line (points from left to right), or None
    # for the section's.
    piezometric: list = None

    def weight_below_water(self):
        return self.gamma if self.gamma_sat is None else self.gamma_sat


@dataclass
class Section:
    ground: list
    layers: list = field(default_factory=lambda: [Layer()])
    piezometric: list = None
    gamma_w: float = 9.81
    # Pseudo-static seismic coefficients: kh W' horizontal at each slice's
    # centroid towards the way the mass slides (kh_direction 0; +1 or -1:
    # along +x or -x), kv W' upwards; W' with the unit weight below the
    # piezometric line unless seismic_on_pore_water (then the saturated one).
    kh: float = 0.0
    kv: float = 0.0
    seismic_on_pore_water: bool = False
    kh_direction: int = 0


def elevation(line, x):
    """The elevation of a polyline (points with increasing x) at x; constant
    beyond its ends."""
    xs = [p[0] for p in line]
    ys = [p[1] for p in line]
    return float(np.interp(x, xs, ys))


def _crossings(line_a, line_b, x0, x1):
    """The x where two polylines cross inside (x0, x1)."""
    xs = sorted({p[0] for p in line_a} | {p[0] for p in line_b} | {x0, x1})
    xs = [x for x in xs if x0 <= x <= x1]
    found = []
    for a, b in zip(xs[:-1], xs[1:]):
        da = elevation(line_a, a) - elevation(line_b, a)
        db = elevation(line_a, b) - elevation(line_b, b)
        if da * db < 0:
            found.append(a + (b - a) * da / (da - db))
    return found


def circle_surface(ground, centre, radius, n_points=2001):
    """The arc of a circle below the ground, as a polyline from left to
    right whose end points lie on the ground (found by bisection)."""
    xc, yc = centre

    def circle(x):  # the lower half
        return yc - math.sqrt(max(radius**2 - (x - xc) ** 2, 0.0))

    def depth(x):  # ground minus circle at x
        return elevation(ground, x) - circle(x)

    xs = np.linspace(xc - radius, xc + radius, 20001)
    # The ground's elevations in one np.interp call (the same values as
    # elevation() point by point, 20000 calls fewer); the circle's as before.
    grounds = np.interp(xs, [p[0] for p in ground], [p[1] for p in ground])
    inside = [g - circle(x) > 0 for g, x in zip(grounds, xs)]
    first = inside.index(True)
    last = len(inside) - 1 - inside[::-1].index(True)
    x0 = brentq(depth, xs[max(first - 1, 0)], xs[first], xtol=1e-13) if first > 0 else xs[0]
    x1 = brentq(depth, xs[last], xs[min(last + 1, len(xs) - 1)], xtol=1e-13) \
        if last < len(xs) - 1 else xs[-1]
    return [(x, yc - math.sqrt(max(radius**2 - (x - xc) ** 2, 0.0)))
            for x in np.linspace(x0, x1, n_points)]


class SlicedMass:
    """The sliding mass cut into slices, in a frame where it moves to the
    left (a mass that moves to the right is mirrored first)."""

    def __init__(self, section, surface, n_slices=400, crack_depth=0.0,
                 crack_water_depth=0.0):
        surface = sorted((float(x), float(y)) for x, y in surface)
        self.mirrored = elevation(section.ground, surface[0][0]) > \
            elevation(section.ground, surface[-1][0])
        flip = (lambda line: [(-x, y) for x, y in line][::-1]) if self.mirrored \
            else (lambda line: list(line))
        self.ground = flip(section.ground)
        self.surface = flip(surface)
        self.layers = [Layer(None if l.top is None else flip(l.top), l.gamma, l.gamma_sat,
                             l.c, l.phi,
                             None if l.piezometric is None else flip(l.piezometric))
                       for l in section.layers]
        self.piezometric = None if section.piezometric is None else flip(section.piezometric)
        self.gamma_w = section.gamma_w
        self.kh, self.kv = getattr(section, "kh", 0.0), getattr(section, "kv", 0.0)
        self.seismic_on_pore_water = getattr(section, "seismic_on_pore_water", False)
        # The frame's mass moves to the left: a kh along +x or -x of the
        # section pushes it forwards or back.
        if getattr(section, "kh_direction", 0):
            self.kh *= -section.kh_direction * (-1.0 if self.mirrored else 1.0)
        self.crack_force = 0.0
        self.crack_point = None
        if crack_depth > 0:
            self._cut_at_crack(crack_depth, crack_water_depth)
        self._make_slices(n_slices)

    def _cut_at_crack(self, depth, water_depth):
        # The crack is at the upper (right) end: the surface ends where it
        # is depth below the ground.
        x1 = self.surface[-1][0]
        x0 = self.surface[0][0]
        gap = lambda x: elevation(self.ground, x) - elevation(self.surface, x) - depth
        if gap(x1 - 1e-12 * (x1 - x0)) > 0:
            raise ValueError("tension crack: the surface is not that deep at its upper end")
        xs = np.linspace(x0, x1, 4001)
        values = [gap(x) for x in xs]
        k = max(i for i, v in enumerate(values[:-1]) if v >= 0)
        xc = brentq(gap, xs[k], xs[k + 1], xtol=1e-14)
        self.surface = [p for p in self.surface if p[0] < xc] + \
            [(xc, elevation(self.surface, xc))]
        bottom = self.surface[-1][1]
        self.crack_force = 0.5 * self.gamma_w * water_depth**2
        # Pushes to the left, at a third of the water depth above the bottom.
        self.crack_point = (xc, bottom + water_depth / 3.0)

    def _top(self, k):
        return self.ground if k == 0 or self.layers[k].top is None else self.layers[k].top

    def _make_slices(self, n_slices):
        x0, x1 = self.surface[0][0], self.surface[-1][0]
        lines = [self.ground, self.surface] + [self._top(k) for k in range(1, len(self.layers))]
        if self.piezometric is not None:
            lines.append(self.piezometric)
        lines += [l.piezometric for l in self.layers if l.piezometric is not None]
        breaks = {x0, x1}
        for line in lines:
            breaks |= {p[0] for p in line if x0 < p[0] < x1}
        for i in range(len(lines)):
            for j in range(i + 1, len(lines)):
                breaks |= set(_crossings(lines[i], lines[j], x0, x1))
        breaks = sorted(breaks)
        xs = []
        width = (x1 - x0) / n_slices
        for a, b in zip(breaks[:-1], breaks[1:]):
            m = max(1, int(math.ceil((b - a) / width - 1e-9)))
            xs.extend(np.linspace(a, b, m + 1)[:-1])
        xs.append(x1)
        self.x = np.array(xs)

    def _water_level(self, k, x):
        """The elevation of layer k's water table at x (its own line or the
        section's), -inf if it is dry."""
        line = self.layers[k].piezometric if self.layers[k].piezometric is not None \
            else self.piezometric
        return -math.inf if line is None else elevation(line, x)

    def _column(self, x):
        """Per layer, the (dry, saturated) thickness of the column above the
        surface at x; with the surface's elevation."""
        yb, yg = elevation(self.surface, x), elevation(self.ground, x)
        parts = []
        for k in range(len(self.layers)):
            top = min(elevation(self._top(k), x), yg)
            bottom = elevation(self._top(k + 1), x) if k + 1 < len(self.layers) else -math.inf
            bottom = max(bottom, yb)
            h = max(top - bottom, 0.0)
            wet = max(min(top, self._water_level(k, x)) - bottom, 0.0) if h > 0 else 0.0
            parts.append((h - wet, wet))
        return parts, yb

    def _layer_at(self, x, y):
        for k in range(len(self.layers)):
            below = elevation(self._top(k + 1), x) if k + 1 < len(self.layers) else -math.inf
            if y >= below:
                return k
        return len(self.layers) - 1

    def slices(self):
        """Per slice: weight W, x of its line of action, base angle alpha
        (positive where the base rises to the right), base length l, base
        midpoint, pore force U, c, tan(phi)."""
        out = []
        for a, b in zip(self.x[:-1], self.x[1:]):
            wa, wb = 0.0, 0.0  # weight per unit width at a and b
            ca, cb = self._column(a), self._column(b)
            for (dry_a, wet_a), (dry_b, wet_b), layer in zip(ca[0], cb[0], self.layers):
                wa += layer.gamma * dry_a + layer.weight_below_water() * wet_a
                wb += layer.gamma * dry_b + layer.weight_below_water() * wet_b
            # A linear load w(x) on [a, b]: its resultant and centroid.
            W = 0.5 * (wa + wb) * (b - a)
            xg = a + (b - a) * (wa + 2 * wb) / (3 * (wa + wb)) if wa + wb > 0 else 0.5 * (a + b)
            ya, yb = ca[1], cb[1]
            l = math.hypot(b - a, yb - ya)
            alpha = math.atan2(yb - ya, b - a)
            xm, ym = 0.5 * (a + b), 0.5 * (ya + yb)
            # The base lies in one layer: its strength and its water table.
            k = self._layer_at(xm, ym + 1e-9 * (1 + abs(ym)))
            layer = self.layers[k]
            ua = self.gamma_w * max(self._water_level(k, a) - ya, 0.0)
            ub = self.gamma_w * max(self._water_level(k, b) - yb, 0.0)
            U = 0.5 * (ua + ub) * l
            Q, V, y_g = 0.0, 0.0, 0.0
            if self.kh != 0 or self.kv != 0:
                # The seismic weight W' per unit width at a and b and its
                # first moment about y = 0, the column stacked from its base.
                def seismic_weight(column):
                    parts, y = column
                    w = m = 0.0
                    for (dry, wet), lay in reversed(list(zip(parts, self.layers))):
                        wet_weight = lay.weight_below_water() if self.seismic_on_pore_water \
                            else lay.gamma
                        w += wet_weight * wet + lay.gamma * dry
                        m += wet_weight * wet * (y + wet / 2) + lay.gamma * dry * (y + wet + dry / 2)
                        y += wet + dry
                    return w, m
                (w_a, m_a), (w_b, m_b) = seismic_weight(ca), seismic_weight(cb)
                W_seismic = 0.5 * (w_a + w_b) * (b - a)
                y_g = (m_a + m_b) / (w_a + w_b) if w_a + w_b > 0 else 0.5 * (ya + yb)
                Q, V = self.kh * W_seismic, self.kv * W_seismic
            out.append(dict(W=W, xg=xg, alpha=alpha, l=l, xm=xm, ym=ym, U=U,
                            c=layer.c, tan_phi=math.tan(math.radians(layer.phi)),
                            Q=Q, V=V, yg=y_g))
        return out


def _spencer_thrusts(slices, F, lam, crack_force):
    """The effective base normal forces N of the slices and the interslice
    thrusts E at their right-hand boundaries (E = 0 at the toe), for the
    mass moving to the left. @p slices is the dict of arrays of
    slice_arrays(). @p F may be a column of factors (shape (m, 1)): a row
    per factor then, each the same operations as for that F alone (the
    cumulative sum runs along the slices in order either way)."""
    s = slices
    sa, ca = s["sin"], s["cos"]
    a, b = s["c"] * s["l"] / F, s["tan_phi"] / F
    # The crack's water force acts on the last (upper) slice, to the left.
    # The seismic force Q on every slice, to the left, and V upwards.
    Px = -s["Q"].copy()
    Px[-1] -= crack_force
    num = (s["U"] * ca + a * sa - (s["W"] - s["V"])) - lam * (a * ca - s["U"] * sa + Px)
    den = lam * (b * ca - sa) - (ca + b * sa)
    N = num / den
    return N, np.cumsum(N * (b * ca - sa) + (a * ca - s["U"] * sa + Px), axis=-1)


def _spencer_residuals(slices, F, lam, crack_force, crack_point):
    """E at the last boundary (force equilibrium) and the total moment about
    the origin (moment equilibrium), for the mass moving to the left.
    @p slices is the dict of arrays of slice_arrays(); @p F a factor or a
    column of them, as for _spencer_thrusts()."""
    s = slices
    sa, ca = s["sin"], s["cos"]
    a, b = s["c"] * s["l"] / F, s["tan_phi"] / F
    N, thrusts = _spencer_thrusts(slices, F, lam, crack_force)
    E = thrusts[..., -1]
    S = a + b * N
    # Moment about the origin of the weights, the base forces and the
    # crack's water force; interslice forces cancel in the sum.
    fx = -(N + s["U"]) * sa + S * ca
    fy = (N + s["U"]) * ca + S * sa
    moment = np.sum(s["xm"] * fy - s["ym"] * fx - s["xg"] * (s["W"] - s["V"]) + s["yg"] * s["Q"],
                    axis=-1)
    if crack_force:
        moment += crack_point[1] * crack_force  # r x F with F = (-P, 0)
    return E, moment


def slice_arrays(slices):
    """The slices as a dict of numpy arrays (sin and cos of alpha added)."""
    arrays = {k: np.array([s[k] for s in slices]) for k in slices[0]}
    arrays["sin"], arrays["cos"] = np.sin(arrays["alpha"]), np.cos(arrays["alpha"])
    return arrays


def spencer(section, surface, n_slices=400, crack_depth=0.0, crack_water_depth=0.0):
    """Spencer's factor of safety and the tangent of the interslice force
    inclination, (F, lambda), on a polyline surface."""
    mass = SlicedMass(section, surface, n_slices, crack_depth, crack_water_depth)
    slices = slice_arrays(mass.slices())

    def force_F(lam):
        f = lambda F: _spencer_residuals(slices, F, lam, mass.crack_force, mass.crack_point)[0]
        return _root_in_F(f, slices, lambda Fs: f(Fs[:, np.newaxis]))

    def moment_gap(lam):
        F = force_F(lam)
        return _spencer_residuals(slices, F, lam, mass.crack_force, mass.crack_point)[1]

    return _root_in_lambda(moment_gap, np.linspace(-0.6, 1.2, 37), force_F,
                           np.sum(slices["W"]) * (mass.x[-1] - mass.x[0]))


def _largest_root(f, low, high, n, f_many=None):
    """The largest root of @p f in [low, high]: a sign change over n
    geometrically spaced factors, refined by Brent. @p f_many, if given,
    evaluates f on an array of factors at once (the same values as f one by
    one: the scan is most of the work, and one array pass costs what a few
    single calls do)."""
    Fs = np.geomspace(low, high, n)
    values = f_many(Fs) if f_many is not None else [f(F) for F in Fs]
    for i in reversed(range(len(Fs) - 1)):
        if np.isfinite(values[i]) and np.isfinite(values[i + 1]) and values[i] * values[i + 1] <= 0:
            return brentq(f, Fs[i], Fs[i + 1], xtol=1e-14, rtol=1e-14)
    return None


def _root_in_F(f, slices, f_many=None):
    """The largest root of f in [0.05, 50] (@p f_many: f on an array of
    factors, see _largest_root()). Small spurious roots exist where
    a slice's normal-force denominator (Bishop's m_alpha = cos(alpha) +
    sin(alpha) tan(phi) / F) changes sign at a small F; the physical root is
    the one above them. A root at which some m_alpha of @p slices (arrays
    'alpha' and 'tan_phi') is not positive is such a spurious root (Whitman
    and Bailey 1967): the physical one is then looked for up to 1e4, and
    without it there is no factor."""
    def admissible(F):
        return F is not None and bool(np.all(
            np.cos(slices["alpha"]) + np.sin(slices["alpha"]) * slices["tan_phi"] / F > 0))

    F = _largest_root(f, 0.05, 50, 200, f_many)
    if admissible(F):
        return F
    F = _largest_root(f, 50, 1e4, 100, f_many)
    if admissible(F):
        return F
    raise ValueError("no factor of safety in [0.05, 1e4] with every m_alpha positive")


def bishop(section, centre, radius, n_slices=400):
    """Bishop's simplified factor of safety on a circle (moments about its
    centre, interslice shear neglected)."""
    surface = circle_surface(section.ground, centre, radius, n_points=n_slices + 1)
    mass = SlicedMass(section, surface, n_slices)
    slices = mass.slices()
    xc = -centre[0] if mass.mirrored else centre[0]

    # What does not depend on F, once: per slice cos(alpha), sin(alpha)
    # tan(phi) and the numerator of its resisting term; the driving moment.
    cos_alpha, sin_tan_phi, numerator = [], [], []
    driving = 0.0
    for s in slices:
        sa, ca = math.sin(s["alpha"]), math.cos(s["alpha"])
        width = s["l"] * ca
        cos_alpha.append(ca)
        sin_tan_phi.append(sa * s["tan_phi"])
        numerator.append(s["c"] * width + (s["W"] - s["V"] - s["U"] * ca) * s["tan_phi"])
        # The weight's moment about the centre, for a mass moving left, and
        # the seismic force's (Q to the left at yg).
        driving += (s["W"] - s["V"]) * (s["xg"] - xc) + s["Q"] * (centre[1] - s["yg"])
    cos_alpha, sin_tan_phi, numerator = map(np.array, (cos_alpha, sin_tan_phi, numerator))

    def g(F):
        """@p F a factor or an array of them. The resisting terms are summed
        slice after slice (cumsum adds in the order of a loop), so that each
        F gets the value it would alone."""
        m = cos_alpha + sin_tan_phi / np.expand_dims(F, -1)
        resisting = np.cumsum(numerator / m, axis=-1)[..., -1]
        return F - radius * resisting / driving

    return _root_in_F(g, slice_arrays(slices), g)


def _section_strength(mass, x):
    """Along the vertical section at @p x from the surface up to the ground:
    the integral of c over its height, the height-weighted mean tan(phi),
    its height, and the water force on it (hydrostatic below each layer's
    piezometric line over that layer's part of the section, the line taken
    no higher than the ground)."""
    parts, yb = mass._column(x)
    C = sum(layer.c * (dry + wet) for (dry, wet), layer in zip(parts, mass.layers))
    h = sum(dry + wet for dry, wet in parts)
    T = sum(math.tan(math.radians(layer.phi)) * (dry + wet)
            for (dry, wet), layer in zip(parts, mass.layers)) / h
    yg = elevation(mass.ground, x)
    water, y = 0.0, yb
    for k in reversed(range(len(mass.layers))):
        low, high = y, y + parts[k][0] + parts[k][1]
        yw = min(mass._water_level(k, x), yg)
        if min(yw, high) > low:
            water += 0.5 * mass.gamma_w * ((yw - low) ** 2 - (yw - min(yw, high)) ** 2)
        y = high
    return C, T, h, water


def vertical_wedges(section, surface, n_slices=400, crack_depth=0.0, crack_water_depth=0.0):
    """The multi-wedge factor of safety (the wedge method of the limit-state
    multi-block mechanism): the mass cut into blocks by vertical interslices
    at the interior vertices of the polyline @p surface, each block sliding
    rigidly on its segment, and every surface, interslices included, at its
    limit with c/K and tan(phi)/K. It is what fdem-slope computes with
    `Interslice surfaces = vertical` and interslices `Reduced by K`.

    Each block translates along its base; the vertical interslices make the
    horizontal velocities equal, so a block moves with (-1, -tan(alpha)) in
    the frame where the mass moves left, and block j+1 slides down past
    block j where tan(alpha_{j+1}) > tan(alpha_j): the interslice shear on
    it acts upwards then. Force equilibrium block by block from the toe
    (two unknowns each: the base's effective normal force and the thrust
    on the next interslice) leaves one residual at the crest block; K is
    its root. Moments are not needed: a block's normal forces act where its
    moment balance puts them. Within a block's base, c is integrated along
    it and tan(phi) is its length-weighted mean (exact for one material per
    base); along an interslice both are integrated over the layers it cuts.
    Returns (K, the interslice thrusts E)."""
    mass = SlicedMass(section, surface, n_slices, crack_depth, crack_water_depth)
    if mass.kh != 0 or mass.kv != 0:
        raise ValueError("the wedge method here takes no seismic coefficients")
    slices = mass.slices()
    vertices = mass.surface
    cuts = [p[0] for p in vertices[1:-1]]
    n = len(cuts) + 1
    blocks = [dict(W=0.0, U=0.0, cL=0.0, tL=0.0, L=0.0) for _ in range(n)]
    for s in slices:
        i = sum(1 for x in cuts if s["xm"] > x)
        b = blocks[i]
        b["W"] += s["W"]
        b["U"] += s["U"]
        b["cL"] += s["c"] * s["l"]
        b["tL"] += s["tan_phi"] * s["l"]
        b["L"] += s["l"]
    for i, b in enumerate(blocks):
        (x0, y0), (x1, y1) = vertices[i], vertices[i + 1]
        b["alpha"] = math.atan2(y1 - y0, x1 - x0)
        b["tan_phi"] = b["tL"] / b["L"]
    interslices = []
    for j, x in enumerate(cuts):
        C, T, _, U = _section_strength(mass, x)
        sense = math.copysign(1.0, math.tan(blocks[j + 1]["alpha"]) - math.tan(blocks[j]["alpha"])) \
            if blocks[j + 1]["alpha"] != blocks[j]["alpha"] else 0.0
        interslices.append(dict(C=C, tan_phi=T, U=U, sense=sense))

    def march(K):
        E_left, U_left, T_left = 0.0, 0.0, 0.0
        thrusts = []
        for i, b in enumerate(blocks):
            sa, ca = math.sin(b["alpha"]), math.cos(b["alpha"])
            a, t = b["cL"] / K, b["tan_phi"] / K
            Px = -mass.crack_force if i == n - 1 else 0.0
            # x: N (t ca - sa) - E_right = -(-U sa + a ca + E_left + U_left - U_right + Px)
            # y: N (ca + t sa) - sense t_is/K E_right = -(U ca + a sa - W + T_left - sense C/K)
            if i < n - 1:
                j = interslices[i]
                bx = -(-b["U"] * sa + a * ca + E_left + U_left - j["U"] + Px)
                by = -(b["U"] * ca + a * sa - b["W"] + T_left - j["sense"] * j["C"] / K)
                m = np.array([[t * ca - sa, -1.0], [ca + t * sa, -j["sense"] * j["tan_phi"] / K]])
                N, E = np.linalg.solve(m, [bx, by])
                T_right = j["sense"] * (j["C"] + E * j["tan_phi"]) / K
                thrusts.append(E)
                E_left, U_left, T_left = E, j["U"], T_right
            else:
                N = -(b["U"] * ca + a * sa - b["W"] + T_left) / (ca + t * sa)
                return N * (t * ca - sa) + (-b["U"] * sa + a * ca + E_left + U_left + Px), thrusts

    K = _root_in_F(lambda K: march(K)[0],
                   {k: np.array([b[k] for b in blocks]) for k in ("alpha", "tan_phi")})
    return K, march(K)[1]


def spencer_interslice_use(section, surface, xs, n_slices=800, crack_depth=0.0,
                           crack_water_depth=0.0):
    """Spencer's interslice shear X = lambda E at the vertical sections @p xs
    over the shear strength there at Spencer's F, (C + E tan(phi)) / F, with
    C and tan(phi) integrated over the height as vertical_wedges() does.
    Above 1 Spencer's answer breaks Mohr-Coulomb across that section: a
    mechanism of blocks cut there is weaker than Spencer's F says."""
    F, lam = spencer(section, surface, n_slices, crack_depth, crack_water_depth)
    mass = SlicedMass(section, surface, n_slices, crack_depth, crack_water_depth)
    _, E = _spencer_thrusts(slice_arrays(mass.slices()), F, lam, mass.crack_force)
    uses = []
    for x in xs:
        x = -x if mass.mirrored else x
        k = int(np.argmin(abs(mass.x[1:] - x)))
        C, T, _, _ = _section_strength(mass, x)
        uses.append(abs(lam * E[k]) / ((C + E[k] * T) / F))
    return uses


def _root_in_lambda(gap, lams, F_of, scale):
    """(F, lambda) where moment equilibrium also holds: a sign change of
    @p gap over @p lams, refined; on one plane without cohesion (the gap the
    same for every lambda) F from force equilibrium alone and NaN. @p scale:
    the size of the moments (the weight times the mass's width)."""
    gaps = []
    for lam in lams:
        try:
            gaps.append(gap(lam))
        except ValueError:
            gaps.append(math.nan)
    # Every sign change is refined; one where the F of force equilibrium
    # jumps (its largest root in [0.05, 50] passes from a spurious branch to
    # the physical one, as at strongly negative lambda) leaves a gap that
    # does not vanish and is no solution. Of the solutions, the one nearest
    # lambda = 0.
    roots = []
    for i in range(len(lams) - 1):
        if np.isfinite(gaps[i]) and np.isfinite(gaps[i + 1]) and gaps[i] * gaps[i + 1] <= 0:
            lam = brentq(gap, lams[i], lams[i + 1], xtol=1e-13)
            if abs(gap(lam)) <= 1e-6 * scale:
                roots.append((abs(lam), lam))
    if roots:
        lam = min(roots)[1]
        return F_of(lam), lam
    # A plane without cohesion: every slice's forces are proportional to its
    # weight whatever lambda, so moment equilibrium does not fix lambda (the
    # gap left is the midpoint rule's, relative to the weights' moments).
    finite = [(abs(g), lam) for g, lam in zip(gaps, lams) if np.isfinite(g)]
    if finite and max(g for g, _ in finite) - min(g for g, _ in finite) < 1e-9 * scale \
            and min(finite)[0] < 1e-4 * scale:
        return F_of(min(finite)[1]), math.nan
    raise ValueError("no interslice force scale satisfies both equilibria")


class _InterSliceMarch:
    """Morgenstern-Price's march: X = lam f E on each vertical boundary
    (f at the boundaries, E = 0 at the toe), each slice's effective normal
    force from its vertical equilibrium and the thrust on its right from its
    horizontal one. residuals() returns the thrust left at the crest end and
    the moment about the origin of the weights, base forces and the crack's
    water (the interslice forces cancel in it). With f = 1 it is Spencer's.

    The root finders evaluate the march thousands of times, and it
    is sequential (a slice's N needs the thrust on its left), so its speed
    is a Python loop's: what depends on neither F nor lambda is worked out
    once, and the loop runs on Python floats (several times faster than
    numpy scalars, and rounded the same). Every sum and product is the one
    of the textbook march, in the same order."""

    def __init__(self, s, f, crack_force, crack_point):
        """@p s: the dict of arrays of slice_arrays(); @p f: the interslice
        function at the slices' boundaries."""
        self.crack_force, self.crack_point = crack_force, crack_point
        n = len(s["W"])
        s = {k: v.tolist() for k, v in s.items()}
        f = [float(v) for v in f]
        self.rows = []
        for i in range(n):
            sa, ca, U, W_V = s["sin"][i], s["cos"][i], s["U"][i], s["W"][i] - s["V"][i]
            # The crack's water on the upper slice and the seismic force Q
            # on every slice push to the left.
            Px = (-crack_force if i == n - 1 else 0.0) - s["Q"][i]
            self.rows.append((sa, ca, s["c"][i] * s["l"][i], s["tan_phi"][i], U, U * ca, U * sa,
                              W_V, Px, f[i] - f[i + 1], f[i + 1],
                              s["xm"][i], s["ym"][i], s["xg"][i] * W_V, s["yg"][i] * s["Q"][i]))

    def residuals(self, F, lam, moment=True):
        """(E at the crest, moment) at the factor @p F and scale @p lam; the
        moment is None unless asked for. @p F may also be an array of
        factors: the same operations element by element, so the same
        values, for the scan of _largest_root() in one pass."""
        lam = float(lam)  # a numpy scalar from a scan would slow the loop down
        try:
            return self._march(F, lam, moment)
        except ZeroDivisionError:
            # A denominator exactly zero: numpy's inf or nan (as an array
            # of F gives), not an exception.
            return self._march(np.float64(F), lam, moment)

    def _march(self, F, lam, moment):
        E, M = 0.0, 0.0
        for sa, ca, cl, tan_phi, U, U_ca, U_sa, W_V, Px, df, f_right, xm, ym, xg_W, yg_Q \
                in self.rows:
            a, b = cl / F, tan_phi / F
            g = a * ca - U_sa + Px
            h = b * ca - sa
            # y: N (ca + b sa) + U ca + a sa - W + lam f_L E_L - lam f_R E_R = 0,
            # with E_R = E_L + N h + g.
            N = ((U_ca + a * sa - W_V) + lam * df * E - lam * f_right * g) \
                / (lam * f_right * h - (ca + b * sa))
            E += N * h + g
            if moment:
                S = a + b * N
                fx = -(N + U) * sa + S * ca
                fy = (N + U) * ca + S * sa
                M += xm * fy - ym * fx - xg_W + yg_Q
        if not moment:
            return E, None
        if self.crack_force:
            M += self.crack_point[1] * self.crack_force
        return E, M


def morgenstern_price(section, surface, n_slices=400, function="half-sine", crack_depth=0.0,
                      crack_water_depth=0.0):
    """Morgenstern and Price's factor of safety with the interslice function
    f = 1 ('constant', Spencer's assumption) or f = sin(pi (x - x_toe) /
    (x_crest - x_toe)) ('half-sine'): (F, lambda)."""
    mass = SlicedMass(section, surface, n_slices, crack_depth, crack_water_depth)
    s = slice_arrays(mass.slices())
    x = mass.x
    if function == "constant":
        f, lams = np.ones(len(x)), np.linspace(-0.6, 1.2, 37)
    else:
        f, lams = np.sin(math.pi * (x - x[0]) / (x[-1] - x[0])), np.linspace(-1.2, 2.4, 73)

    march = _InterSliceMarch(s, f, mass.crack_force, mass.crack_point)

    def force_F(lam):
        thrust = lambda F: march.residuals(F, lam, moment=False)[0]
        return _root_in_F(thrust, s, thrust)

    def gap(lam):
        return march.residuals(force_F(lam), lam)[1]

    return _root_in_lambda(gap, lams, force_F, np.sum(s["W"]) * (x[-1] - x[0]))


def ordinary(section, surface, n_slices=400, crack_depth=0.0, crack_water_depth=0.0):
    """The ordinary method of slices (Fellenius): interslice forces
    neglected, N' = W cos(alpha) - U - P sin(alpha), F = sum(c l + N'
    tan(phi)) / sum(W sin(alpha) + P cos(alpha)), P the crack's water force
    on the upper slice."""
    mass = SlicedMass(section, surface, n_slices, crack_depth, crack_water_depth)
    s = slice_arrays(mass.slices())
    # The seismic force Q pushes left like the crack's water; V upwards.
    P = s["Q"].copy()
    P[-1] += mass.crack_force
    W = s["W"] - s["V"]
    resisting = s["c"] * s["l"] + (W * s["cos"] - s["U"] - P * s["sin"]) * s["tan_phi"]
    return np.sum(resisting) / np.sum(W * s["sin"] + P * s["cos"])


def janbu(section, surface, n_slices=400, crack_depth=0.0, crack_water_depth=0.0):
    """Janbu's simplified method: force equilibrium without interslice
    shear, F0; and the corrected F0 f0 with f0 = 1 + b1 (d/L - 1.4 (d/L)^2),
    d the largest depth of the surface below the chord of length L between
    its ends, b1 = 0.69 (c only), 0.31 (phi only), 0.50 (both). Returns
    (F0, f0)."""
    mass = SlicedMass(section, surface, n_slices, crack_depth, crack_water_depth)
    s = slice_arrays(mass.slices())
    f = np.ones(len(mass.x))
    march = _InterSliceMarch(s, f, mass.crack_force, mass.crack_point)
    thrust = lambda F: march.residuals(F, 0.0, moment=False)[0]
    F0 = _root_in_F(thrust, s, thrust)
    (x0, y0), (x1, y1) = mass.surface[0], mass.surface[-1]
    L = math.hypot(x1 - x0, y1 - y0)
    d = max(max(((x1 - x0) * (y0 - y) - (y1 - y0) * (x0 - x)) / L for x, y in mass.surface), 0.0)
    cohesion, friction = np.any(s["c"] > 0), np.any(s["tan_phi"] > 0)
    b1 = 0.50 if cohesion and friction else 0.69 if cohesion else 0.31
    return F0, 1 + b1 * (d / L - 1.4 * (d / L) ** 2)
