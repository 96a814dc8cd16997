#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Limit-equilibrium safety factor of a rock wedge on two planes, by vectors
(Hoek & Bray, Rock Slope Engineering, wedge analysis; written here for the
tests, independent of the program).

A plane with dip psi and dip direction alpha (x east, y north, z up) has the
upward unit normal n = (sin psi sin alpha, sin psi cos alpha, cos psi). The
wedge rests on planes A and B, so the rock pushes it along n_A and n_B. With
the weight W (a vector) and the line of intersection i (unit, pointing down
the line), equilibrium perpendicular to i gives the normal reactions

    N_A + m N_B = -W.n_A,   m N_A + N_B = -W.n_B,   m = n_A.n_B,

and K = (N_A tan phi_A + N_B tan phi_B + c_A A_A + c_B A_B) / (W.i).
If a reaction comes out tensile, that plane lifts off and the wedge slides
on the other plane alone, down its dip: K = (N tan phi + c A) / |W_t| with
N = -W.n and W_t the part of W in that plane.

    wedge_reference.py DIP_A DIR_A DIP_B DIR_B WEIGHT AREA_A AREA_B \\
                       PHI_A PHI_B C_A C_B
prints K and the mode (both planes, plane A only, plane B only).
"""
import math
import sys


def normal(dip, direction):
    d, a = math.radians(dip), math.radians(direction)
    return (math.sin(d) * math.sin(a), math.sin(d) * math.cos(a), math.cos(d))


def dot(u, v):
    return sum(a * b for a, b in zip(u, v))


def cross(u, v):
    return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])


def safety_factor(dip_a, dir_a, dip_b, dir_b, weight, area_a, area_b, phi_a, phi_b, c_a, c_b):
    n_a, n_b = normal(dip_a, dir_a), normal(dip_b, dir_b)
    W = (0.0, 0.0, -weight)
    m = dot(n_a, n_b)
    N_a = (-dot(W, n_a) + m * dot(W, n_b)) / (1 - m * m)
    N_b = (-dot(W, n_b) + m * dot(W, n_a)) / (1 - m * m)
    tan_a, tan_b = math.tan(math.radians(phi_a)), math.tan(math.radians(phi_b))
    if N_a >= 0 and N_b >= 0:
        i = cross(n_a, n_b)
        length = math.sqrt(dot(i, i))
        i = tuple(x / length for x in i)
        if dot(W, i) < 0:
            i = tuple(-x for x in i)
        return (N_a * tan_a + N_b * tan_b + c_a * area_a + c_b * area_b) / dot(W, i), "both planes"
    # One plane lifts off: sliding on the other alone.
    n, tan_phi, c, area, mode = (n_b, tan_b, c_b, area_b, "plane B only") if N_a < 0 else \
                                (n_a, tan_a, c_a, area_a, "plane A only")
    N = -dot(W, n)
    W_t = tuple(w - dot(W, n) * x for w, x in zip(W, n))
    return (N * tan_phi + c * area) / math.sqrt(dot(W_t, W_t)), mode


def safety_factor_of_run(parameters, summary):
    """safety_factor() for a run of fdem-slope on Geometry/Source = wedge:
    the planes and strengths from its @p parameters (parameters.prm as a
    dict, see tools/fdem_run.py), the wedge's weight (unit weight times the
    volume of the block with six free rigid modes) and the plane areas from
    its @p summary."""
    wedge = next(b for b in summary["blocks"] if b["free_rigid_modes"] == 6)
    weight = float(parameters[f"Blocks/{wedge['name']}/Unit weight"]) * wedge["volume"]
    area = {i["name"]: i["area"] for i in summary["interfaces"]}
    args = []
    for plane in "AB":
        args += [float(x) for x in parameters[f"Geometry/Wedge/Plane {plane}"].split(",")]
    strength = {key: [float(parameters.get(f"Interfaces/plane {plane}/{key}", 0)) for plane in "AB"]
                for key in ("Friction angle", "Cohesion")}
    return safety_factor(*args, weight, area["plane A"], area["plane B"],
                         *strength["Friction angle"], *strength["Cohesion"])


if __name__ == "__main__":
    args = [float(a) for a in sys.argv[1:12]]
    K, mode = safety_factor(*args)
    print(f"{K:.12g} {mode}")
