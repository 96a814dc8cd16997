#!/usr/bin/env pvpython
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Opens an fdem-slope results folder in ParaView, coloured to be read at
once: the blocks by the size of their displacement, the interfaces by their
status as categories (stick, slip, open, no pair, paired elsewhere) drawn
over the blocks, everything warped by the displacement. doc/output.md says
what each field is.

    pvpython tools/open_in_paraview.py RESULTS_FOLDER [--steps] [--mechanism]
        [--scale S] [--screenshot FILE.png]
    FDEM_RESULTS=RESULTS_FOLDER paraview --script=tools/open_in_paraview.py

RESULTS_FOLDER is a run's output folder (the one with solution.pvd).
--steps opens safety_factor_steps.pvd instead (K is the time: step through
the safety-factor iteration; write the steps with Output/Write steps = true).
--mechanism warps by the mechanism displacement (from the all-stick elastic
state to the limit) instead of the displacement under self-weight. --scale
sets the warp factor (default: the largest displacement shown as 5 % of the
model's size). --screenshot saves a picture and exits; otherwise pvpython
opens an interactive window.

The part that reads the folder (plan()) needs no ParaView, so that the tests
can check it with plain Python.
"""
import math
import os
import sys
import tempfile
import xml.etree.ElementTree as ET

# Status values of the interface files (the field data 'status_meaning').
STATUS = [(0, "stick", [0.2, 0.4, 0.9]), (1, "slip", [0.9, 0.15, 0.1]),
          (2, "open", [1.0, 0.75, 0.1]), (3, "no pair", [0.6, 0.6, 0.6]),
          (4, "paired elsewhere", [0.35, 0.35, 0.35])]


def plan(folder, steps=False, mechanism=False):
    """What to open: per block and interface of the folder's .pvd, its name,
    kind ('block' or 'interface'), its (time, absolute file) list, the
    vector to warp by and the field to colour by."""
    pvd = os.path.join(folder, "safety_factor_steps.pvd" if steps else "solution.pvd")
    if not os.path.exists(pvd):
        raise SystemExit(f"open_in_paraview: error: no {os.path.basename(pvd)} in '{folder}' "
                         "(a results folder of fdem-slope with Write VTU = true)")
    parts = {}
    for d in ET.parse(pvd).getroot().iter("DataSet"):
        name, file = d.get("name"), d.get("file")
        entry = parts.setdefault(name, {
            "name": name,
            "kind": "interface" if file.startswith("interface-") else "block",
            "files": []})
        entry["files"].append((float(d.get("timestep")), os.path.join(folder, file)))
    for entry in parts.values():
        entry["warp"] = "mechanism_displacement" if mechanism else "displacement"
        entry["colour"] = "status" if entry["kind"] == "interface" else entry["warp"]
    # Blocks first: the interfaces are drawn over them.
    return sorted(parts.values(), key=lambda e: (e["kind"] != "block", e["name"]))


def collection(entry, directory):
    """A .pvd of one part's files (absolute paths), for ParaView's PVD reader."""
    path = os.path.join(directory, "".join(c if c.isalnum() else "_" for c in entry["name"])
                        + "-" + entry["kind"] + ".pvd")
    with open(path, "w") as f:
        f.write('<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1">\n'
                '  <Collection>\n')
        for time, file in entry["files"]:
            f.write(f'    <DataSet timestep="{time!r}" part="0" file="{file}"/>\n')
        f.write("  </Collection>\n</VTKFile>\n")
    return path


def main(argv):
    args = [a for a in argv if not a.startswith("--")]
    folder = args[0] if args else os.environ.get("FDEM_RESULTS", "")
    if not folder:
        raise SystemExit(__doc__)

    def option(name):
        return argv[argv.index(name) + 1] if name in argv else None

    parts = plan(folder, "--steps" in argv, "--mechanism" in argv)
    from paraview import simple as pv  # only here: plan() runs without ParaView

    directory = tempfile.mkdtemp(prefix="fdem-paraview-")
    view = pv.GetActiveViewOrCreate("RenderView")
    readers = [pv.PVDReader(registrationName=p["name"], FileName=collection(p, directory))
               for p in parts]
    # One warp factor for all parts, so that they stay together.
    bounds, largest = [], 0.0
    for reader in readers:
        reader.UpdatePipeline(max(reader.TimestepValues) if reader.TimestepValues else 0)
        info = reader.GetDataInformation()
        bounds.append(info.GetBounds())
        array = reader.PointData[parts[0]["warp"]] if parts[0]["warp"] in reader.PointData.keys() else None
        if array is not None:
            largest = max(largest, max(abs(v) for v in array.GetRange(-1)))
    size = math.sqrt(sum((max(b[2 * i + 1] for b in bounds) - min(b[2 * i] for b in bounds)) ** 2
                         for i in range(3)))
    scale = float(option("--scale")) if option("--scale") else (
        0.05 * size / largest if largest > 0 else 1.0)
    two_d = all(b[4] == b[5] == 0 for b in bounds)

    for part, reader in zip(parts, readers):
        source = reader
        if part["warp"] in reader.PointData.keys():
            source = pv.WarpByVector(registrationName=part["name"] + " (warped)", Input=reader,
                                     Vectors=["POINTS", part["warp"]], ScaleFactor=scale)
        display = pv.Show(source, view)
        if part["kind"] == "interface":
            pv.ColorBy(display, ("POINTS", "status"))
            lut = pv.GetColorTransferFunction("status")
            lut.InterpretValuesAsCategories = 1
            lut.Annotations = [str(v) for s in STATUS for v in (s[0], s[1])]
            lut.IndexedColors = [c for s in STATUS for c in s[2]]
            display.LineWidth = 5.0
            display.RenderLinesAsTubes = 1
            display.PointSize = 6.0
        else:
            pv.ColorBy(display, ("POINTS", part["colour"], "Magnitude"))
            if not two_d:
                display.Opacity = 0.4  # the interfaces lie on the blocks' faces
        display.SetScalarBarVisibility(view, True)
    scene = pv.GetAnimationScene()
    scene.UpdateAnimationUsingDataTimeSteps()
    scene.AnimationTime = max(t for p in parts for t, _ in p["files"])
    if two_d:
        view.InteractionMode = "2D"
    view.ResetCamera()
    pv.Render(view)
    if option("--screenshot"):
        pv.SaveScreenshot(option("--screenshot"), view, ImageResolution=[1600, 1000])
    elif hasattr(pv, "Interact"):
        pv.Interact(view)


if __name__ == "__main__":
    main(sys.argv[1:])
