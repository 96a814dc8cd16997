#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""What ParaView reads from a run, read back with VTK's own reader (Debian's
python3-vtk9), as doc/output.md describes it.

  paraview_checks.py EXE CASE.prm [--steps]

Runs the case (with --steps: Output/Write steps = true) and checks:
  - solution.pvd names every dataset after its block or interface, with the
    run's K as the time; each file's field data repeats the name and K, has
    K_star and the units note;
  - interfaces: `status` is an integer array with its meaning in the field
    data; the nodes with a pair status (0-2) are exactly the interface's
    pairs, by status as counted in summary.json; the pair fields are finite
    there and NaN at the nodes that are no pair (3, 4);
  - blocks: `stress` is a 3 x 3 tensor whose zz entry is sigma_zz (in 2D,
    plane strain: nu (sigma_xx + sigma_yy) with the block's Poisson's ratio);
  - warping: every interface node has the displacement (and mechanism
    displacement) of block J's node at the same point, to round-off, so that
    "Warp by vector" moves the interface with its block; and the mechanism
    displacement is written where the safety factor is computed;
  - safety_factor_steps.pvd: the final state alone by default; with --steps
    one set of files per step with a static solution, the step's K as time
    and K and K* in each file as summary.json's iterations give them.
"""
import math
import os
import sys
import xml.etree.ElementTree as ET

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path[:0] = [os.path.join(HERE, "..", "..", "tools")]
import fdem_run  # noqa: E402
import open_in_paraview  # noqa: E402

PAIR_FIELDS = ["normal_force", "tangential_force", "normal_pressure", "shear_stress", "gap",
               "slip", "local_safety_factor"]


def datasets(path):
    """(time, name, file) of each DataSet of a .pvd file."""
    root = ET.parse(path).getroot()
    return [(float(d.get("timestep")), d.get("name"), d.get("file")) for d in root.iter("DataSet")]


def read(path):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    grid = reader.GetOutput()
    assert grid.GetNumberOfPoints() > 0 and grid.GetNumberOfCells() > 0, path
    return grid


def field(grid, name):
    array = grid.GetFieldData().GetAbstractArray(name)
    assert array is not None, f"no field data '{name}'"
    if isinstance(array, vtk.vtkStringArray):
        return array.GetValue(0)
    return array.GetTuple1(0)


def points(grid):
    return vtk_to_numpy(grid.GetPoints().GetData())


def point_array(grid, name):
    array = grid.GetPointData().GetArray(name)
    assert array is not None, f"no point field '{name}'"
    return array, vtk_to_numpy(array)


def same(a, b, rel=1e-12):
    return (math.isnan(a) and math.isnan(b)) or abs(a - b) <= rel * max(1.0, abs(a), abs(b))


def unique_nodes(xyz, values, scale):
    """One row per distinct point (points shared by faces appear once per face)."""
    keys = {}
    for i, x in enumerate(np.round(xyz / scale, 7)):
        keys.setdefault(tuple(x), i)
    return [values[i] for i in keys.values()]


def check_files(run, entries, state_K, state_K_star, dimension, mechanism, materials):
    summary = run.summary
    interfaces = {i["name"]: i for i in summary["interfaces"]}
    blocks = {}
    for time, name, file in entries:
        # The .pvd writes K to 12 digits.
        assert same(time, state_K, 1e-11), f"{file}: time {time} is not K = {state_K}"
        grid = read(run.file(file))
        assert field(grid, "name") == name, f"{file}: field data name {field(grid, 'name')!r}"
        assert same(field(grid, "K"), state_K), f"{file}: K {field(grid, 'K')} != {state_K}"
        assert same(field(grid, "K_star"), state_K_star, 1e-9), \
            f"{file}: K_star {field(grid, 'K_star')} != {state_K_star}"
        units = field(grid, "units")
        assert "F/L^2" in units and "dimensionless" in units, f"{file}: units note {units!r}"
        assert field(grid, "state"), f"{file}: no state description"
        has_mechanism = grid.GetPointData().GetArray("mechanism_displacement") is not None
        assert has_mechanism == mechanism, f"{file}: mechanism_displacement written: {has_mechanism}"
        if file.startswith("block-"):
            blocks[name] = grid
            _, stress = point_array(grid, "stress")
            _, zz = point_array(grid, "stress_zz")
            assert stress.shape[1] == 9, f"{file}: stress has {stress.shape[1]} components"
            assert np.array_equal(stress[:, 8], zz), f"{file}: the tensor's zz is not stress_zz"
            assert np.max(np.abs(zz)) > 0, f"{file}: sigma_zz is zero everywhere"
            if dimension == 2:
                # Plane strain: sigma_zz = nu (sigma_xx + sigma_yy), nu of some material.
                trace = stress[:, 0] + stress[:, 4]
                big = np.abs(trace) > 1e-3 * np.max(np.abs(trace))
                ratios = zz[big] / trace[big]
                nus = np.array(materials)
                closest = np.min(np.abs(ratios[:, None] - nus[None, :]), axis=1)
                assert np.max(closest) < 1e-4, \
                    f"{file}: sigma_zz / (sigma_xx + sigma_yy) is not a Poisson's ratio"
            block_id = grid.GetCellData().GetArray("block_id")
            assert block_id is not None and block_id.GetDataType() == vtk.VTK_INT, \
                f"{file}: block_id is not integer cell data"
            print(f"{file}: {grid.GetNumberOfPoints()} points; stress 3x3, zz = stress_zz")
    for time, name, file in entries:
        if not file.startswith("interface-"):
            continue
        grid = read(run.file(file))
        info = interfaces[name]
        status_array, status = point_array(grid, "status")
        assert status_array.GetDataType() == vtk.VTK_INT, f"{file}: status is not an integer array"
        meaning = field(grid, "status_meaning")
        for text in ("0 stick", "1 slip", "2 open", "3 ", "4 "):
            assert text in meaning, f"{file}: status meaning lacks {text!r}: {meaning!r}"
        assert set(np.unique(status)) <= {0, 1, 2, 3, 4}, f"{file}: status values {np.unique(status)}"
        xyz = points(grid)
        scale = max(1.0, float(np.max(np.abs(xyz))))
        nodes = unique_nodes(xyz, status, scale)
        counts = [sum(1 for s in nodes if s == k) for k in range(5)]
        assert counts[:3] == [info["n_stick"], info["n_slip"], info["n_open"]], \
            f"{file}: stick/slip/open nodes {counts[:3]}, summary " \
            f"{[info['n_stick'], info['n_slip'], info['n_open']]}"
        assert sum(counts[:3]) == info["n_pairs"], f"{file}: {sum(counts[:3])} pair nodes"
        assert counts[4] == info["n_nodes_paired_in_an_earlier_interface"], \
            f"{file}: {counts[4]} nodes marked paired elsewhere, summary " \
            f"{info['n_nodes_paired_in_an_earlier_interface']}"
        is_pair = status <= 2
        for name_field in PAIR_FIELDS:
            _, values = point_array(grid, name_field)
            assert np.all(np.isfinite(values[is_pair])), f"{file}: {name_field} not finite at a pair"
            assert np.all(np.isnan(values[~is_pair])), f"{file}: {name_field} not NaN off the pairs"
        # Warp: the node moves with block J's node at the same point.
        block = blocks[info["block_J"]]
        block_xyz = points(block)
        order = np.lexsort(block_xyz.T[::-1])
        tolerance = 1e-9 * scale
        worst = 0.0
        for vector in ["displacement"] + (["mechanism_displacement"] if mechanism else []):
            _, u_interface = point_array(grid, vector)
            _, u_block = point_array(block, vector)
            u_scale = max(float(np.max(np.abs(u_block))), 1e-300)
            for x, u in zip(xyz, u_interface):
                # The block's points at x (several: every cell has its own).
                distance = np.linalg.norm(block_xyz - x, axis=1)
                matches = np.nonzero(distance <= tolerance)[0]
                assert matches.size > 0, f"{file}: no point of block {info['block_J']} at {x}"
                error = np.max(np.abs(u_block[matches] - u)) / u_scale
                worst = max(worst, error)
        assert worst <= 1e-9, f"{file}: interface and block {info['block_J']} warp apart ({worst:.2e})"
        del order
        print(f"{file}: status counts {counts} (stick, slip, open, no pair, paired elsewhere); "
              f"warps with block {info['block_J']} (largest difference {worst:.1e} of |u|)")


def main():
    exe, prm = sys.argv[1], sys.argv[2]
    steps = "--steps" in sys.argv[3:]
    settings = {"Output/Write steps": "true"} if steps else None
    with fdem_run.temporary_run(exe, prm, settings=settings) as run:
        assert run.returncode == 0, run.stderr
        summary = run.summary
        dimension = summary["dimension"]
        materials = [float(v) for k, v in run.parameters.items()
                     if k.endswith("/Poisson's ratio") or k.endswith("/Poissons ratio")]
        assert materials or dimension == 3, "no Poisson's ratio in parameters.prm"
        sf = "iterations" in summary
        K = summary["model.strength_reduction"]
        K_star = math.nan
        if sf:
            for step in summary["iterations"]:
                if step["K"] == K and step["K_star"] is not None:
                    K_star = step["K_star"]
        final = datasets(run.file("solution.pvd"))
        expected = {b["name"] for b in summary["blocks"]} | {i["name"] for i in summary["interfaces"]}
        assert {name for _, name, _ in final} == expected, f"dataset names {final}"
        check_files(run, final, K, K_star, dimension, sf, materials)
        # tools/open_in_paraview.py opens what is there, warps and colours by
        # fields the files have (its ParaView part is not run here).
        for mechanism in ([False, True] if sf else [False]):
            parts = open_in_paraview.plan(run.output, mechanism=mechanism)
            assert {p["name"] for p in parts} == expected
            for part in parts:
                for _, file in part["files"]:
                    data = read(file).GetPointData()
                    assert data.GetArray(part["warp"]) and data.GetArray(part["colour"]), \
                        f"open_in_paraview.py: {file} lacks {part['warp']} or {part['colour']}"
        if not sf:
            assert not os.path.exists(run.file("safety_factor_steps.pvd"))
            return
        listed = datasets(run.file("safety_factor_steps.pvd"))
        static = [s for s in summary["iterations"] if s["contact_result"] == "converged"]
        if not steps:
            assert listed == final, "safety_factor_steps.pvd is not the final state alone"
            assert not any("-step" in f for f in os.listdir(run.output)), "step files written"
            print(f"safety_factor_steps.pvd: the final state, K = {K}")
            return
        n = len(final)
        assert len(listed) == n * len(static), (len(listed), len(static))
        for k, step in enumerate(static):
            entries = listed[k * n:(k + 1) * n]
            K_step = step["K"]
            K_star_step = math.nan if step["K_star"] is None else step["K_star"]
            for time, name, file in entries:
                assert file.endswith(f"-step{k:03d}.vtu"), file
                grid = read(run.file(file))
                assert same(time, K_step, 1e-11) and same(field(grid, "K"), K_step), \
                    f"{file}: time {time}, K {field(grid, 'K')}, summary {K_step}"
                assert same(field(grid, "K_star"), K_star_step, 1e-9), \
                    f"{file}: K* {field(grid, 'K_star')}, summary {K_star_step}"
                assert field(grid, "name") == name
        print(f"safety_factor_steps.pvd: {len(static)} steps, times "
              f"{[round(s['K'], 6) for s in static]} = the steps' K")


if __name__ == "__main__":
    main()
