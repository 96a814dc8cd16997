#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Writes the .prm files of the invariance tests (run once; the files are
committed, run_checks.py invariance runs them).

Each file includes a case of prm/ and overrides only what its units or a
common Young's modulus change; all files of a case share a coarse mesh and
write no VTU, so that the runs are quick and compare the same discrete model.

Unit sets, from the cases' kN, m, kPa:
  N_m_Pa     forces x 1e3, lengths x 1, stresses x 1e3, unit weights x 1e3
  N_mm_MPa   forces x 1e3, lengths x 1e3 (Geometry/Scale factor),
             stresses x 1e-3, unit weights x 1e-6
  lbf_ft_psf forces / 4.4482216152605e-3 (lbf = 4.4482216152605 N exactly),
             lengths / 0.3048 (ft = 0.3048 m exactly), stresses and unit
             weights from those
Common E: both blocks' Young's modulus set to 1e-8, 1e-2, 1e8 and 1e14 (kPa)
(with materials: all scaled by one factor that gives the first that value),
the rest as in kN, m, kPa. K must be the same in all of them: every decision
of the program is taken on dimensionless numbers (doc/theory.md,
"Scale-free decisions").

Usage: tests/invariance/make_cases.py   (writes next to itself)
"""
import os

HERE = os.path.dirname(os.path.abspath(__file__))

FOOT = 0.3048  # m
POUND_FORCE = 4.4482216152605e-3  # kN

# name: (force factor, length factor) from kN and m
UNITS = {
    "N_m_Pa": (1e3, 1.0),
    "N_mm_MPa": (1e3, 1e3),
    "lbf_ft_psf": (1 / POUND_FORCE, 1 / FOOT),
}
COMMON_E = ["1e-8", "1e-2", "1e8", "1e14"]


def num(x):
    return repr(float(x))


# prm/layered_slope.prm's layers: Young's modulus, unit weight, saturated
# unit weight, cohesion (kPa, kN/m^3).
LAYERS = {"fill": (1.0e4, 19, 20.5, 5), "clay": (5.0e3, 18, 19.5, 10),
          "sand": (3.0e4, 20, 21, 0)}


def layered_water(F, L):
    """The layered slope's water: its unit weight in the new units; the
    piezometric line stays as it is, in the input's coordinates, which
    Geometry/Scale factor scales with the mesh (as the layers)."""
    return ["subsection Water",
            f"  set Unit weight of water = {num(9.81 * F / L**3)}",
            "end"]


# Each case: the prm/ file, the blocks, the entries of the reference
# (kN, m, kPa) that make it quick, and a function giving the
# units-dependent entries for a force factor F and a length factor L
# (stress factor F / L^2, unit weight factor F / L^3).
CASES = {
    "paper_slope": {
        "prm": "paper_slope.prm",
        "blocks": {"sliding mass": (1.0e4, 20), "foundation": (1.0e4, 20)},
        "quick": ["subsection Geometry", "  subsection Slope",
                  "    set Mesh size = 2.0", "  end", "end"],
        "interfaces": lambda F, L: [("sliding surface", "Cohesion", 3.0 * F / L**2)],
        "extra": lambda F, L: [],
    },
    "priest_plane_failure": {
        "prm": "priest_plane_failure.prm",
        "blocks": {"block": (1e6, 25), "rock": (1e6, 25)},
        # The mesh is the .geo's (relative to prm/): named absolutely here.
        "quick": ["subsection Geometry",
                  "  set Mesh file = @PRM_DIR@/priest_plane_failure.geo", "end"],
        "interfaces": lambda F, L: [("failure plane", "Cohesion", 20 * F / L**2)],
        # Water in the crack and on the plane, x and y in the new length
        # unit (x / L in m), pressures in the new stress unit.
        "extra": lambda F, L: [
            "subsection Boundaries", "  subsection tension crack",
            f"    set Pressure = {num(F / L**2)} * 9.81 * max(0, 18.75 - y / {num(L)})",
            "  end", "end",
            "subsection Interfaces", "  subsection failure plane",
            f"    set Pore pressure = {num(F / L**2)} * 9.81 * 3.75 * (x / {num(L)})"
            " / 25.980762113533160",
            "  end", "end"],
    },
    "rock_wedge": {
        "prm": "rock_wedge.prm",
        "blocks": {"wedge": (1e7, 26), "rock": (1e7, 26)},
        # A coarser mesh and tolerance: the comparison is between unit
        # systems on the same mesh, not with the limit equilibrium.
        "quick": ["subsection Geometry", "  subsection Wedge",
                  "    set Mesh size = 6", "  end", "end",
                  "subsection Safety factor", "  set Tolerance = 1e-4", "end"],
        "interfaces": lambda F, L: [],
        "extra": lambda F, L: [],
    },
    "layered_slope": {
        "prm": "layered_slope.prm",
        "blocks": {},
        "materials": LAYERS,
        "quick": ["subsection Geometry", "  subsection Slope",
                  "    set Mesh size = 2.0", "  end", "end"],
        "interfaces": lambda F, L: [],
        "extra": layered_water,
    },
    # The layered slope on a named weak layer (Materials/seam/Weak layer,
    # in the input's coordinates: scaled with the mesh by Scale factor).
    "weak_layer_slope": {
        "prm": "weak_layer_slope.prm",
        "blocks": {},
        "materials": LAYERS,
        "quick": ["subsection Geometry", "  subsection Slope",
                  "    set Mesh size = 2.0", "  end", "end"],
        "interfaces": lambda F, L: [],
        "extra": lambda F, L: [
            "subsection Materials", "  subsection seam",
            f"    set Cohesion = {num(1 * F / L**2)}", "  end", "end"] + layered_water(F, L),
    },
    "block_on_plane_3d": {
        "prm": "block_on_plane_3d.prm",
        "blocks": {"block": (1e6, 25), "foundation": (1e6, 25)},
        "quick": [],
        "interfaces": lambda F, L: [("sliding surface", "Cohesion", 15 * F / L**2),
                                    ("sliding surface", "Tensile strength", 1e3 * F / L**2)],
        "extra": lambda F, L: [],
    },
    "two_wedge_slope": {
        "prm": "two_wedge_slope.prm",
        "blocks": {"sliding mass 1": (1e5, 20), "sliding mass 2": (1e5, 20),
                   "foundation": (1e5, 20)},
        "quick": [],
        "interfaces": lambda F, L: [(f"sliding surface {i}", entry, 10 * F / L**2)
                                    for i in (1, 2) for entry in ("Cohesion",
                                                                  "Tensile strength")],
        # The water in the tension crack: the generator's, from the unit
        # weight of water in the new units.
        "extra": lambda F, L: [
            "subsection Water", f"  set Unit weight of water = {num(9.81 * F / L**3)}", "end"],
    },
    # The 3D slope generator's sphere: its pairs take the sphere's exact
    # normal, moved with the mesh by Geometry/Scale factor.
    "slope_3d": {
        "prm": "slope_3d.prm",
        "blocks": {"sliding mass": (1.0e4, 20), "foundation": (1.0e4, 20)},
        "quick": ["subsection Geometry", "  subsection Slope 3D",
                  "    set Mesh size = 3", "  end", "end",
                  "subsection Safety factor", "  set Stiffness check = false", "end"],
        "interfaces": lambda F, L: [("sliding surface", "Cohesion", 3.0 * F / L**2)],
        "extra": lambda F, L: [],
    },
}
# The 3D slope under a water table surface (Water/Piezometric surface file,
# in the input's coordinates: scaled with the mesh by Scale factor) with
# saturated weights and the pore pressure on the sliding surface
# (tests/three_d/sloping_water.prm, kN and m; the units' variants override
# the weights).
def water_3d_lines(F, L):
    return (["subsection Water", f"  set Unit weight of water = {num(9.81 * F / L**3)}", "end",
             "subsection Blocks"]
            + sum(([f"  subsection {name}", f"    set Saturated unit weight = {num(22 * F / L**3)}",
                    "  end"] for name in ("sliding mass", "foundation")), [])
            + ["end"])


CASES["slope_3d_water"] = {
    **CASES["slope_3d"],
    "quick": CASES["slope_3d"]["quick"]
    + ["include @PRM_DIR@/../tests/three_d/sloping_water.prm"],
    "extra": water_3d_lines,
}
# The layered slope with a perched water table in the fill
# (Materials/fill/Piezometric line, in the input's coordinates like the
# slope's line): the layered slope's entries.
CASES["perched_water_slope"] = {**CASES["layered_slope"], "prm": "perched_water_slope.prm"}

# The paper's slope with three rows of soil nails: their capacities are
# forces per unit width (F / L), the bond a force per length per width and
# the stiffness a force per displacement per width (both F / L^2); a common
# Young's modulus scales the nails' stiffness with the soil's (relative to
# the slope's 1e4 kPa), so that every stiffness ratio stays.
def nail_lines(capacity, pullout, stiffness):
    return ["subsection Reinforcement",
            f"  set Bar tensile capacities = {', '.join([num(capacity)] * 3)}",
            f"  set Bar pull-out resistances = {', '.join([num(pullout)] * 3)}",
            f"  set Bar axial stiffnesses = {', '.join([num(stiffness)] * 3)}",
            "end"]


CASES["nailed_slope"] = {
    **CASES["paper_slope"], "prm": "nailed_slope.prm",
    "extra": lambda F, L: nail_lines(137 * F / L, 21 * F / L**2, 33000 * F / L**2),
    "modulus_extra": lambda factor: nail_lines(137, 21, 33000 * factor),
    "reference_modulus": 1.0e4}


def write(case, variant, lines, description):
    data = CASES[case]
    text = [f"# Invariance test ({description}): {data['prm']} of prm/ with",
            "# only the entries that depend on the units or on a common Young's",
            "# modulus changed; written by tests/invariance/make_cases.py.",
            f"include @PRM_DIR@/{data['prm']}",
            "subsection Output", "  set Write VTU = false", "end"]
    text += data["quick"] + lines
    path = os.path.join(HERE, f"{case}.{variant}.prm")
    with open(path, "w") as f:
        f.write("\n".join(text) + "\n")


def unit_lines(case, F, L):
    data = CASES[case]
    lines = []
    if L != 1.0:
        lines += ["subsection Geometry", f"  set Scale factor = {num(L)}", "end"]
    lines.append("subsection Blocks")
    for name, (modulus, unit_weight) in data["blocks"].items():
        lines += [f"  subsection {name}",
                  f"    set Young's modulus = {num(modulus * F / L**2)}",
                  f"    set Unit weight     = {num(unit_weight * F / L**3)}",
                  "  end"]
    lines.append("end")
    if data.get("materials"):
        lines.append("subsection Materials")
        for name, (modulus, unit_weight, saturated, cohesion) in data["materials"].items():
            lines += [f"  subsection {name}",
                      f"    set Young's modulus       = {num(modulus * F / L**2)}",
                      f"    set Unit weight           = {num(unit_weight * F / L**3)}",
                      f"    set Saturated unit weight = {num(saturated * F / L**3)}",
                      f"    set Cohesion              = {num(cohesion * F / L**2)}",
                      "  end"]
        lines.append("end")
    entries = data["interfaces"](F, L)
    if entries:
        lines.append("subsection Interfaces")
        for name, entry, value in entries:
            lines += [f"  subsection {name}", f"    set {entry} = {num(value)}", "  end"]
        lines.append("end")
    return lines + data["extra"](F, L)


def modulus_lines(case, E):
    lines = ["subsection Blocks"]
    for name in CASES[case]["blocks"]:
        lines += [f"  subsection {name}", f"    set Young's modulus = {E}", "  end"]
    lines.append("end")
    if CASES[case].get("materials"):
        lines.append("subsection Materials")
        # All scaled by one factor, which makes the first material's E:
        # the ratios between the layers stay.
        reference = next(iter(CASES[case]["materials"].values()))[0]
        for name, values in CASES[case]["materials"].items():
            modulus = num(values[0] * float(E) / reference)
            lines += [f"  subsection {name}", f"    set Young's modulus = {modulus}", "  end"]
        lines.append("end")
    if CASES[case].get("modulus_extra"):
        lines += CASES[case]["modulus_extra"](float(E) / CASES[case]["reference_modulus"])
    return lines


if __name__ == "__main__":
    for case in CASES:
        write(case, "kN_m_kPa", [], "the reference: kN, m, kPa")
        for variant, (F, L) in UNITS.items():
            write(case, variant, unit_lines(case, F, L), variant.replace("_", ", "))
        for E in COMMON_E:
            write(case, f"E_{E}", modulus_lines(case, E),
                  f"kN, m, kPa, Young's modulus {E} kPa in both blocks")
