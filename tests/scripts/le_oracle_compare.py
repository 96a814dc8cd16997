#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""The C++ limit equilibrium (summary.json's "limit_equilibrium") against
the Python yardstick tools/limit_equilibrium.py on the same case:

    le_oracle_compare.py EXE CASE.prm [TOLERANCE] [Sub/Section/Entry=value ...]

Runs the case, builds the section from the parameters the run used (its
parameters.prm, read here independently of the C++ translation), and
checks every method's K (and lambda), with 100 slices and twice as many, to TOLERANCE relative (default 1e-11: both find the
roots to 1e-14 by the same Brent iteration on the same slices; what
remains is the order of floating-point sums). Entries given as
Sub/Section/Entry=value are set in the run (e.g. the seismic coefficients
of Loads, which the section then takes from the run's parameters too).
"""
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path[:0] = [HERE, os.path.join(HERE, "..", "..", "tools"),
                os.path.join(HERE, "..", "..", "benchmarks")]
import fdem_run  # noqa: E402
import limit_equilibrium as le  # noqa: E402
from le_comparison import surface_in_ground  # noqa: E402


def points(text):
    return [tuple(float(v) for v in p.split(",")) for p in text.split(";") if p.strip()]


def section_and_surface(prm):
    """The Python section, sliding surface and crack of the run's
    parameters @p prm (a dict 'Sub/Section/Entry' -> text)."""
    slope = "Geometry/Slope/"
    ground = points(prm[slope + "Ground surface"])
    g = float(prm["Loads/Gravitational acceleration"])
    names = [n.strip() for n in prm["Interfaces/Names"].split(",") if n.strip()]
    sliding = [n for n in names if prm[f"Interfaces/{n}/Sliding surface"] == "true"]
    first = f"Interfaces/{sliding[0]}/"
    from_material = prm[first + "Strength"] == "material"

    def layer(path, top):
        gamma = float(prm[path + "Unit weight"]) + float(prm[path + "Density"]) * g
        saturated = float(prm[path + "Saturated unit weight"]) or gamma
        if from_material:
            c, phi = float(prm[path + "Cohesion"]), float(prm[path + "Friction angle"])
        else:
            c, phi = float(prm[first + "Cohesion"]), float(prm[first + "Friction angle"])
        # A perched water table: the material's own piezometric line.
        own = points(prm.get(path + "Piezometric line", "")) or None
        return le.Layer(top, gamma, saturated, c, phi, own)

    layer_names = [n.strip() for n in prm.get(slope + "Layers", "").split(",") if n.strip()]
    if layer_names:
        tops = [None] + [points(t) for t in prm[slope + "Layer boundaries"].split("|")]
        layers = [layer(f"Materials/{n}/", top) for n, top in zip(layer_names, tops)]
    else:
        blocks = [n.strip() for n in prm["Blocks/Names"].split(",")]
        layers = [layer(f"Blocks/{[b for b in blocks if b.startswith('sliding mass')][0]}/", None)]
    piezometric = points(prm.get("Water/Piezometric line", "")) or None
    if prm[first + "Pore pressure"] != "piezometric" and piezometric:
        raise SystemExit("this script compares cases whose surface carries the piezometric "
                         "pore pressure, or that have no water")
    section = le.Section(ground, layers, piezometric, float(prm["Water/Unit weight of water"]))
    # The pseudo-static seismic load of the run (Loads/...).
    section.kh = float(prm.get("Loads/Horizontal seismic coefficient", "0"))
    section.kv = float(prm.get("Loads/Vertical seismic coefficient", "0"))
    section.seismic_on_pore_water = prm.get("Loads/Seismic force on pore water", "false") == "true"
    direction = prm.get("Loads/Seismic direction", "towards free face").strip()
    if direction != "towards free face":
        section.kh_direction = 1 if float(direction.split(",")[0]) > 0 else -1
    crack = dict(crack_depth=float(prm[slope + "Tension crack depth"]),
                 crack_water_depth=float(prm[slope + "Tension crack water depth"]))
    if prm[slope + "Sliding surface"] == "circular":
        circle = (tuple(float(v) for v in prm[slope + "Circle centre"].split(",")),
                  float(prm[slope + "Circle radius"]))
        return section, None, circle, crack
    polyline = surface_in_ground(ground, points(prm[slope + "Sliding surface polyline"]))
    return section, polyline, None, crack


def python_values(section, polyline, circle, crack, n):
    """Method key -> (K, lambda) of the yardstick with @p n slices."""
    surface = polyline if circle is None else le.circle_surface(section.ground, *circle, n + 1)
    F0, f0 = le.janbu(section, surface, n, **crack)
    values = {"ordinary": (le.ordinary(section, surface, n, **crack), None),
              "janbu_simplified": (F0, None), "janbu_corrected": (F0 * f0, None),
              "spencer": le.spencer(section, surface, n, **crack),
              "morgenstern_price_constant": le.morgenstern_price(section, surface, n, "constant", **crack),
              "morgenstern_price_half_sine": le.morgenstern_price(section, surface, n, "half-sine", **crack)}
    if circle is not None:
        values["bishop_simplified"] = (le.bishop(section, *circle, n), None)
    return values


def main():
    exe, prm = sys.argv[1:3]
    extra = dict(a.split("=", 1) for a in sys.argv[3:] if "=" in a)
    rest = [a for a in sys.argv[3:] if "=" not in a]
    tolerance = float(rest[0]) if rest else 1e-11
    # Only the limit equilibrium is compared: no safety factor, no VTU, no
    # report.html (its pictures took half the run's time; report_checks.py
    # tests it); 100 slices (and 200), as the Python yardstick's loops take
    # seconds per method at the default 400.
    run = fdem_run.run_case(exe, prm, settings={"Output/Write VTU": "false",
                                                "Output/Report": "false",
                                                "Safety factor/Compute": "false",
                                                "Limit equilibrium/Number of slices": "100",
                                                **extra})
    assert run.returncode == 0 and run.summary is not None, run.stderr
    results = run.summary["limit_equilibrium"]
    assert results["computed"], results["not_computed"]
    section, polyline, circle, crack = section_and_surface(run.parameters)
    n = int(run.parameters["Limit equilibrium/Number of slices"])
    worst = 0.0
    for slices, key in ((n, "K"), (2 * n, "K_doubled_slices")):
        for method, (K, lam) in python_values(section, polyline, circle, crack, slices).items():
            cpp = results["methods"][method]
            error = abs(cpp[key] - K) / K
            worst = max(worst, error)
            line = f"{method:28s} {slices:5d} slices: C++ {cpp[key]:.15f}  Python {K:.15f}  ({error:.1e})"
            if lam is not None and key == "K" and not math.isnan(lam):
                lam_error = abs(cpp["lambda"] - lam) / max(abs(lam), 1e-3)
                worst = max(worst, lam_error)
                line += f"; lambda {cpp['lambda']:.12f} against {lam:.12f} ({lam_error:.1e})"
            print(line)
            assert error <= tolerance, f"{method}: {error:.2e} > {tolerance:g}"
            assert lam is None or key != "K" or math.isnan(lam) or lam_error <= tolerance * 100, \
                f"{method} lambda"
    if circle is None:
        assert results["methods"]["bishop_simplified"]["K"] is None, "Bishop on a polyline"
    print(f"largest relative difference {worst:.1e} (tolerance {tolerance:g})")


if __name__ == "__main__":
    main()
