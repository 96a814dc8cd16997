# SPDX-License-Identifier: LGPL-2.1-or-later
"""The report of one fdem-slope run: turns a results folder into
report.html, a self-contained page (its pictures embedded as data URIs),
with the pictures also written beside it as PNG files:

  model.png       the model: blocks, material regions, water table, the
                  sliding surfaces coloured by pair status, and the local
                  safety factor along each surface
  stresses.png    normal and shear stress along each surface against the
                  Mohr-Coulomb strength (full and divided by K)
  iterations.png  K and K* per safety-factor step, with the pairs' statuses

Usage: /usr/bin/python3 fdem_report.py RESULTS_FOLDER

The program runs it at the end of a run (Output/Report = true). It reads
summary.json, parameters.prm, interfaces.csv (absent when the run found no
equilibrium), mesh.msh (material regions) and the blocks' VTU files (their
cells, through python3-vtk9; without vtk the blocks are left out of the
model picture and the report says so). Exit code 3: a module it needs
(numpy, matplotlib) is missing, named on the last line of its output.
"""
import base64
import csv
import html
import json
import math
import os
import re
import sys
import time

try:
    import numpy as np
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.collections import LineCollection, PolyCollection
except ImportError as error:
    print(f"fdem_report.py: {error.name} is not installed for {sys.executable} "
          f"(Debian: apt-get install python3-numpy python3-matplotlib)")
    sys.exit(3)

STATUS_COLOURS = {"stick": "#2b83ba", "slip": "#d7191c", "open": "#9e9e9e"}
BLOCK_COLOURS = ["#f4e3c1", "#d9d9d9", "#e0ecd4", "#f2d4d4", "#d4e4f2", "#efe0f5"]
LAYER_COLOURS = ["#e6c98f", "#a6bddb", "#c2a5cf", "#b8e186", "#fdb863", "#d1a6c4"]
DPI = 110


# --------------------------------------------------------------------------
# Reading the results folder.

def read_prm(path):
    """Entries of parameters.prm as a dict 'Sub/Section/Entry' -> text."""
    values, sections = {}, []
    if not os.path.exists(path):
        return values
    for raw in open(path):
        line = raw.split("#", 1)[0].strip()
        if line.startswith("subsection "):
            sections.append(line[len("subsection "):].strip())
        elif line == "end":
            sections.pop()
        elif line.startswith("set ") and "=" in line:
            key, value = line[4:].split("=", 1)
            values["/".join(sections + [key.strip()])] = value.strip()
    return values


def read_interfaces(path):
    """interfaces.csv as {interface name: list of rows (dicts of floats and
    strings)}, in the file's order (along the surface)."""
    interfaces = {}
    if not os.path.exists(path):
        return interfaces
    for row in csv.DictReader(open(path)):
        parsed = {}
        for key, value in row.items():
            try:
                parsed[key] = float(value)
            except (TypeError, ValueError):
                parsed[key] = value
        interfaces.setdefault(row["interface"], []).append(parsed)
    return interfaces


def final_block_files(folder):
    """The VTU files of the blocks at the end of the run: those that
    solution.pvd lists, else block-*.vtu without a step number, else for each
    block the step file with the highest step number."""
    pvd = os.path.join(folder, "solution.pvd")
    if os.path.exists(pvd):
        files = re.findall(r'file="([^"]+)"', open(pvd).read())
        blocks = [f for f in files if os.path.basename(f).startswith("block-")]
        if blocks:
            return [os.path.join(folder, f) for f in blocks]
    names = sorted(os.listdir(folder))
    plain = [n for n in names if n.startswith("block-") and n.endswith(".vtu")
             and not re.search(r"-step\d+\.vtu$", n)]
    if plain:
        return [os.path.join(folder, n) for n in plain]
    latest = {}
    for n in names:
        match = re.match(r"(block-.*)-step(\d+)\.vtu$", n)
        if match and int(match.group(2)) >= latest.get(match.group(1), (-1, ""))[0]:
            latest[match.group(1)] = (int(match.group(2)), n)
    return [os.path.join(folder, n) for _, n in sorted(latest.values(), key=lambda v: v[1])]


def read_block_geometry(folder):
    """The blocks' cells from their final-state VTU files: a list of
    (block file stem, points (n x 3 array), cells (list of point-index
    lists in boundary order)), and a note if they could not be read. The
    one place that knows the VTU files' layout."""
    try:
        # The one reader, not the whole of vtk (seconds to import).
        from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
        from vtkmodules.util.numpy_support import vtk_to_numpy
    except ImportError:
        return [], "python3-vtk9 is not installed: the blocks are not drawn"
    blocks = []
    for path in final_block_files(folder):
        reader = vtkXMLUnstructuredGridReader()
        reader.SetFileName(path)
        reader.Update()
        grid = reader.GetOutput()
        if grid is None or grid.GetNumberOfPoints() == 0:
            continue
        points = vtk_to_numpy(grid.GetPoints().GetData()).astype(float)
        cells = []
        for c in range(grid.GetNumberOfCells()):
            cell = grid.GetCell(c)
            ids = [cell.GetPointId(i) for i in range(cell.GetNumberOfPoints())]
            # deal.II's patches are VTK_QUAD/VTK_TRIANGLE (or higher-order
            # Lagrange cells, whose first corners come first).
            corners = {9: 4, 5: 3, 70: 4, 69: 3, 28: 4, 22: 3, 23: 4}.get(cell.GetCellType())
            if corners:
                ids = ids[:corners]
            cells.append(ids)
        stem = os.path.basename(path)[len("block-"):-len(".vtu")]
        blocks.append((re.sub(r"-step\d+$", "", stem), points, cells))
    if not blocks:
        return [], "no block VTU files in the folder (Output/Write VTU = false?): the blocks are not drawn"
    return blocks, ""


def boundary_edges(points, cells):
    """The edges of a 2D block that belong to one cell only: its outline."""
    # The VTU files repeat the points of each patch: edges are matched by
    # their ends' coordinates (rounded far below the mesh size).
    scale = 1e-9 * max(1.0, float(np.abs(points).max()))
    key_of = [tuple(np.round(p[:2] / scale).astype(np.int64)) for p in points]
    count = {}
    for cell in cells:
        for a, b in zip(cell, cell[1:] + cell[:1]):
            key = tuple(sorted((key_of[a], key_of[b])))
            count.setdefault(key, [0, a, b])[0] += 1
    return [[points[a, :2], points[b, :2]] for n, a, b in count.values() if n == 1]


def read_msh_regions(path, material_names):
    """Material regions of a 2D mesh.msh (ASCII, format 4): {material name:
    list of cells, each an (n x 2) array of corner coordinates}."""
    if not material_names or not os.path.exists(path):
        return {}
    try:
        text = open(path).read()
    except UnicodeDecodeError:
        return {}
    section = lambda name: text.split(f"${name}\n", 1)[1].split(f"$End{name}", 1)[0].split("\n")
    if "$MeshFormat\n4" not in text:
        return {}
    names = {}
    for line in section("PhysicalNames")[1:]:
        parts = line.split(maxsplit=2)
        if len(parts) == 3 and parts[0] == "2":
            names[int(parts[1])] = parts[2].strip('"')
    entities = section("Entities")
    n_points, n_curves, n_surfaces = (int(v) for v in entities[0].split()[:3])
    surface_material = {}
    for line in entities[1 + n_points + n_curves: 1 + n_points + n_curves + n_surfaces]:
        values = line.split()
        tag, n_tags = int(values[0]), int(values[7])
        for t in values[8: 8 + n_tags]:
            if names.get(int(t)) in material_names:
                surface_material[tag] = names[int(t)]
    nodes, lines, i = {}, section("Nodes"), 1
    while i < len(lines) and lines[i].strip():
        _, _, _, n = (int(v) for v in lines[i].split())
        tags = [int(v) for v in lines[i + 1: i + 1 + n]]
        for k, tag in enumerate(tags):
            nodes[tag] = [float(v) for v in lines[i + 1 + n + k].split()[:2]]
        i += 1 + 2 * n
    regions, lines, i = {}, section("Elements"), 1
    while i < len(lines) and lines[i].strip():
        dim, entity, element_type, n = (int(v) for v in lines[i].split())
        material = surface_material.get(entity) if dim == 2 else None
        corners = {2: 3, 3: 4, 9: 3, 10: 4, 16: 4}.get(element_type, 0)
        if material:
            for line in lines[i + 1: i + 1 + n]:
                tags = [int(v) for v in line.split()[1: 1 + corners]]
                regions.setdefault(material, []).append(np.array([nodes[t] for t in tags]))
        i += 1 + n
    return regions


def polyline(text):
    """'x,y; x,y; ...' as an (n x 2) array (None if empty or not 2D)."""
    try:
        points = [[float(v) for v in p.split(",")] for p in text.split(";") if p.strip()]
    except ValueError:
        return None
    return np.array(points) if points and all(len(p) == 2 for p in points) else None


def along(rows):
    """The coordinate along the surface of each row: the CSV's arc_length
    (2D) or down_dip_distance (3D) column."""
    for key in ("arc_length", "down_dip_distance"):
        if rows and key in rows[0]:
            return np.array([r[key] for r in rows]), key.replace("_", " ")
    return np.arange(len(rows), dtype=float), "pair"


# --------------------------------------------------------------------------
# Pictures.

def model_picture(folder, summary, prm, interfaces, path):
    """model.png: the model with the sliding surfaces coloured by status,
    and the local safety factor along each surface. Returns notes."""
    notes = []
    dim = summary.get("dimension", 2)
    blocks, note = read_block_geometry(folder)
    if note:
        notes.append(note)
    fig = plt.figure(figsize=(9, 7.5))
    grid = fig.add_gridspec(2, 1, height_ratios=[2.2, 1])
    if dim == 2:
        ax = fig.add_subplot(grid[0])
        outlines = []
        for b, (name, points, cells) in enumerate(blocks):
            polygons = [points[c, :2] for c in cells]
            ax.add_collection(PolyCollection(polygons, facecolors=BLOCK_COLOURS[b % len(BLOCK_COLOURS)],
                                             edgecolors="#00000022", linewidths=0.3))
            outlines.append((name, boundary_edges(points, cells)))
        materials = [m.strip() for m in prm.get("Materials/Names", "").split(",") if m.strip()]
        regions = read_msh_regions(os.path.join(folder, "mesh.msh"), materials)
        for m, name in enumerate(materials):
            if name in regions:
                ax.add_collection(PolyCollection(regions[name], facecolors=LAYER_COLOURS[m % len(LAYER_COLOURS)],
                                                 edgecolors="none", alpha=0.75, label=f"material {name}"))
        if materials and not regions:
            notes.append("the material regions could not be read from mesh.msh")
        for b, (name, edges) in enumerate(outlines):
            ax.add_collection(LineCollection(edges, colors="k", linewidths=0.9, zorder=2))
            centre = np.mean(blocks[b][1][:, :2], axis=0)
            ax.annotate(f"block {name}", centre, fontsize=8, ha="center", zorder=4,
                        bbox=dict(boxstyle="round", fc="white", alpha=0.7, lw=0))
        water = polyline(prm.get("Water/Piezometric line", ""))
        if water is not None:
            ax.plot(water[:, 0], water[:, 1], color="#1f78b4", lw=1.6, ls="--", label="piezometric line")
        for name, rows in interfaces.items():
            x = np.array([r["x"] for r in rows])
            y = np.array([r["y"] for r in rows])
            segments = [[(x[k], y[k]), (x[k + 1], y[k + 1])] for k in range(len(rows) - 1)]
            colours = [STATUS_COLOURS.get(rows[k]["status"], "k") for k in range(len(rows) - 1)]
            ax.add_collection(LineCollection(segments, colors=colours, linewidths=3))
            ax.annotate(name, (x[0], y[0]), textcoords="offset points", xytext=(4, 6), fontsize=8)
        reinforcement = summary.get("reinforcement", {})
        for k, a in enumerate(reinforcement.get("anchors", [])):
            ax.plot([a["head"][0], a["bond_point"][0]], [a["head"][1], a["bond_point"][1]],
                    color="#6a3d9a", lw=1.8, label="anchor" if k == 0 else None, zorder=3)
        for k, b in enumerate(reinforcement.get("passive_bars", {}).get("bars", [])):
            ax.plot([b["head"][0], b["end"][0]], [b["head"][1], b["end"][1]],
                    color="#b15928", lw=1.8, ls="-" if b["status"] == "elastic" else "--",
                    label=("passive bar (dashed: yielded)" if k == 0 else None), zorder=3)
        for status, colour in STATUS_COLOURS.items():
            ax.plot([], [], color=colour, lw=3, label=status)
        ax.autoscale()
        ax.set_aspect("equal")
        ax.set_xlabel("x (length unit)")
        ax.set_ylabel("y (length unit)")
        ax.legend(fontsize=7, loc="best", framealpha=0.85)
    else:
        ax = fig.add_subplot(grid[0], projection="3d")
        for b, (name, points, cells) in enumerate(blocks):
            step = max(1, len(points) // 3000)
            ax.scatter(points[::step, 0], points[::step, 1], points[::step, 2], s=1,
                       color=BLOCK_COLOURS[b % len(BLOCK_COLOURS)], alpha=0.3)
        for name, rows in interfaces.items():
            ax.scatter([r["x"] for r in rows], [r["y"] for r in rows], [r["z"] for r in rows], s=8,
                       c=[STATUS_COLOURS.get(r["status"], "k") for r in rows])
        for status, colour in STATUS_COLOURS.items():
            ax.scatter([], [], [], color=colour, label=status)
        ax.set_xlabel("x")
        ax.set_ylabel("y")
        ax.set_zlabel("z")
        ax.legend(fontsize=7)
    ax.set_title(f"{summary.get('case', '')}: the model and the state of the sliding surface at the limit",
                 fontsize=10)
    ax2 = fig.add_subplot(grid[1])
    for name, rows in interfaces.items():
        s, label = along(rows)
        local = np.array([r["local_safety_factor"] for r in rows])
        closed = np.array([r["status"] != "open" for r in rows])
        if label == "arc length":
            ax2.plot(s[closed], np.minimum(local[closed], 10), lw=1, label=name)
        ax2.scatter(s, np.minimum(local, 10), s=10, c=[STATUS_COLOURS.get(r["status"], "k") for r in rows],
                    zorder=3)
        ax2.set_xlabel(f"{label} along the surface (length unit)")
    if summary.get("safety_factor"):
        ax2.axhline(summary["safety_factor"], color="k", lw=0.8, ls=":", label="K")
    top = max([2.0 * (summary.get("safety_factor") or 1.0)] +
              [min(r["local_safety_factor"], 10) * 1.05 for rows in interfaces.values() for r in rows])
    ax2.set_ylim(0, top)
    ax2.ticklabel_format(axis="y", useOffset=False)
    ax2.set_ylabel("local safety factor\n(full strength / shear; cut at 10)")
    ax2.grid(alpha=0.3)
    if interfaces:
        ax2.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=DPI)
    plt.close(fig)
    return notes


def stress_picture(summary, interfaces, path):
    """stresses.png: normal pressure and shear stress along each surface,
    with the Mohr-Coulomb strength c + sigma_n tan(phi) and its share 1/K."""
    K = summary.get("safety_factor") or 1.0
    n = max(1, len(interfaces))
    fig, axes = plt.subplots(n, 1, figsize=(9, 3.6 * n), squeeze=False)
    for ax, (name, rows) in zip(axes[:, 0], interfaces.items()):
        s, label = along(rows)
        sigma = np.array([r["normal_pressure"] for r in rows])
        tau = np.array([r["shear_stress"] for r in rows])
        c = np.array([r["cohesion"] for r in rows])
        phi = np.radians([r["friction_angle"] for r in rows])
        limit = c + np.maximum(sigma, 0) * np.tan(phi)
        # A surface (3D) has no order along which lines mean anything: points.
        line = {"lw": 1.4} if label == "arc length" else {"ls": "none", "marker": ".", "ms": 4}
        limit_line = {"lw": 1} if label == "arc length" else {"ls": "none", "marker": "_", "ms": 5}
        ax.plot(s, sigma, color="#377eb8", label="normal stress σn (compression > 0)", **line)
        ax.plot(s, tau, color="#e41a1c", label="shear stress τ", **line)
        ax.plot(s, limit, color="k", ls="--" if label == "arc length" else "none",
                label="Mohr–Coulomb strength c + σn tan φ", **{k: v for k, v in limit_line.items() if k != "ls"})
        ax.plot(s, limit / K, color="#4daf4a", ls=":" if label == "arc length" else "none",
                label=f"strength / K (K = {K:.3f})", **{k: v for k, v in limit_line.items() if k != "ls"})
        ax.set_title(f"interface {name}", fontsize=10)
        ax.set_xlabel(f"{label} along the surface (length unit)")
        ax.set_ylabel("stress (force / length²)")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    if not interfaces:
        axes[0, 0].text(0.5, 0.5, "no interfaces.csv (no equilibrium)", ha="center",
                        transform=axes[0, 0].transAxes)
    fig.tight_layout()
    fig.savefig(path, dpi=DPI)
    plt.close(fig)


def iteration_picture(summary, path):
    """iterations.png: K and K* of each step, and the statuses of its pairs."""
    steps = summary.get("iterations", [])
    fig, (ax, ax2) = plt.subplots(2, 1, figsize=(9, 6), sharex=True)
    i = np.arange(1, len(steps) + 1)
    K = [s["K"] for s in steps]
    K_star = [s["K_star"] if s.get("K_star") is not None else np.nan for s in steps]
    ax.plot(i, K, "o-", label="K (the step's strength reduction)")
    ax.plot(i, K_star, "s--", label="K* = K F_R / F_τ")
    if summary.get("safety_factor"):
        ax.axhline(summary["safety_factor"], color="k", lw=0.8, ls=":",
                   label=f"safety factor {summary['safety_factor']:.4f}")
    ax.set_ylabel("factor")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    ax.set_title("safety-factor iteration", fontsize=10)
    bottom = np.zeros(len(steps))
    for status in ("stick", "slip", "open"):
        counts = np.array([s.get(f"n_{status}", 0) for s in steps], dtype=float)
        ax2.bar(i, counts, bottom=bottom, color=STATUS_COLOURS[status], label=status)
        bottom += counts
    ax2.set_xlabel("step")
    ax2.set_ylabel("node pairs")
    ax2.set_xticks(i)
    ax2.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=DPI)
    plt.close(fig)


def seismic_section(folder, summary):
    """The seismic load, the yield acceleration's K(kh) curve and the
    Newmark displacement (summary.json's "seismic"): HTML, or "" without it."""
    seismic = summary.get("seismic")
    if not seismic:
        return ""
    out = ["<h2>Seismic load, yield acceleration, Newmark displacement</h2>"]
    rows = [("kh (towards " + html.escape(str(seismic.get("direction_from", ""))) + ")",
             number(seismic.get("kh"))),
            ("kv (positive upwards)", number(seismic.get("kv"))),
            ("direction of a positive kh", ", ".join(number(h, 4) for h in seismic.get("direction", []))),
            ("seismic force on the pore water", number(seismic.get("on_pore_water")))]
    y = seismic.get("yield_acceleration")
    if y:
        rows.append(("yield coefficient k_y (K = 1)",
                     f"<b>{number(y.get('k_y'), 6)}</b>" if y.get("found")
                     else html.escape("none: " + y.get("not_found", ""))))
        if y.get("k_y_backward") is not None:
            rows.append(("k_y backwards", number(y.get("k_y_backward"), 6)))
    n = seismic.get("newmark")
    if n and n.get("computed"):
        rows.append((f"largest Newmark displacement ({html.escape(n.get('sliding', ''))})",
                     f"<b>{number(n.get('max_displacement_m'), 4)} m</b> at {number(n.get('time_of_max_s'), 4)} s"))
    out.append(table(rows))
    curve = [p for p in (y or {}).get("curve", []) if p.get("K") is not None]
    newmark_csv = os.path.join(folder, "newmark.csv")
    has_newmark = bool(n and n.get("computed") and os.path.exists(newmark_csv))
    if curve or has_newmark:
        panels = (1 if curve else 0) + (2 if has_newmark else 0)
        fig, axes = plt.subplots(panels, 1, figsize=(9, 3.2 * panels), squeeze=False)
        axes = list(axes[:, 0])
        if curve:
            ax = axes.pop(0)
            ax.plot([p["kh"] for p in curve], [p["K"] for p in curve], "o-", label="K(kh)")
            ax.axhline(1, color="k", lw=0.8, ls=":")
            if y.get("found"):
                ax.axvline(y["k_y"], color="C3", lw=0.8, label=f"k_y = {y['k_y']:.4f}")
            ax.set_xlabel("horizontal seismic coefficient kh")
            ax.set_ylabel("safety factor K")
            ax.grid(alpha=0.3)
            ax.legend(fontsize=8)
        if has_newmark:
            data = np.genfromtxt(newmark_csv, delimiter=",", names=True)
            ax, ax2 = axes
            ax.plot(data["time_s"], data["acceleration_m_s2"], lw=0.8, label="record")
            if y and y.get("found"):
                ax.axhline(y["k_y"] * 9.80665, color="C3", lw=0.8, label="k_y g")
            ax.set_ylabel("acceleration (m/s²)")
            ax.grid(alpha=0.3)
            ax.legend(fontsize=8)
            ax2.plot(data["time_s"], data["displacement_m"], color="C2")
            ax2.set_xlabel("time (s)")
            ax2.set_ylabel("sliding displacement (m)")
            ax2.grid(alpha=0.3)
        fig.tight_layout()
        path = os.path.join(folder, "seismic.png")
        fig.savefig(path, dpi=DPI)
        plt.close(fig)
        out.append(f"<p>{image(path, 'K(kh) and the Newmark displacement')}</p>")
    return "\n".join(out)
def probabilistic_section(folder, summary):
    """The probabilistic safety factor (summary.json "probabilistic"): its
    numbers, and probabilistic.png: the histogram of K, its empirical CDF
    with P(K < 1), and the fragility curve if there is one."""
    p = summary["probabilistic"]
    K = []
    samples = os.path.join(folder, "samples.csv")
    if os.path.exists(samples):
        with open(samples) as f:
            K = [float(r["K"]) for r in csv.DictReader(f) if r["status"] == "certified"]
    fragility = p.get("fragility")
    fig, axes = plt.subplots(1, 3 if fragility else 2, figsize=(13 if fragility else 9, 3.8))
    ax, ax2 = axes[0], axes[1]
    if K:
        ax.hist(K, bins=min(40, max(5, int(len(K) ** 0.5))), color="#4a7ebb")
        ax2.plot(np.sort(K), np.arange(1, len(K) + 1) / len(K), color="#4a7ebb")
    for a in (ax, ax2):
        a.axvline(1.0, color="#a00", lw=0.8, ls="--")
        a.set_xlabel("safety factor K")
        a.grid(alpha=0.3)
    ax.set_ylabel("samples")
    ax.set_title("histogram of K (certified samples)", fontsize=10)
    ax2.set_ylabel("P(K ≤ k)")
    ax2.set_title("empirical CDF of K", fontsize=10)
    if fragility:
        bins = fragility["bins"]
        x = [b["x_mean"] for b in bins]
        ax3 = axes[2]
        ax3.errorbar(x, [b["P_failure"] for b in bins],
                     yerr=[[b["P_failure"] - b["lower"] for b in bins],
                           [b["upper"] - b["P_failure"] for b in bins]], fmt="o-", capsize=3)
        target = p["variables"][fragility["variable"] - 1]["target"]
        ax3.set_xlabel(target)
        ax3.set_ylabel("P(K < 1) in the bin")
        ax3.set_title("fragility curve (95 % Wilson intervals)", fontsize=10)
        ax3.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(folder, "probabilistic.png"), dpi=DPI)
    plt.close(fig)
    interval = p["P_failure_interval"]
    rows = [("samples", f"{p['n_samples']} ({html.escape(p['sampling'])}, seed {p['seed']})"),
            ("certified / no equilibrium / not certified / nonphysical",
             f"{p['n_certified']} / {p['n_no_equilibrium']} / {p['n_not_certified']} / "
             f"{p['n_nonphysical']}"),
            ("mean K, standard deviation", f"{number(p['K_mean'], 4)}, {number(p['K_std'], 4)}"),
            ("P(K < 1)", f"<b>{number(p['P_failure'], 4)}</b> (95 % Wilson interval "
                         f"{number(interval['lower'], 4)} – {number(interval['upper'], 4)})"),
            ("reliability index β (normal, lognormal)",
             f"{number(p['beta_normal'], 4)}, {number(p['beta_lognormal'], 4)}"),
            ("K at the variables' means", number(p["K_at_means"], 6))]
    for key, name in (("fosm", "FOSM"), ("point_estimate", "Rosenblueth's point estimates")):
        e = p.get(key)
        if e and e.get("computed"):
            rows.append((f"{name}: mean K, standard deviation",
                         f"{number(e['K_mean'], 4)}, {number(e['K_std'], 4)}"))
    cost = p["cost"]
    rows.append(("cost", f"{number(cost['seconds_per_sample'], 3)} s per sample, "
                         f"{number(cost['mean_steps_per_sample'], 3)} steps per sample, "
                         f"{cost['n_ranks']} rank(s)"))
    variables = table([(html.escape(v["target"]), html.escape(v["distribution"]), number(v["mean"], 6),
                        number(v["std"], 6)) for v in p["variables"]],
                      ["random variable", "distribution", "mean", "standard deviation"])
    return ("<h2>Probabilistic safety factor</h2>\n" + variables + table(rows) +
            f"<p>{image(os.path.join(folder, 'probabilistic.png'), 'probabilistic safety factor')}</p>"
            "<p>Samples whose contact problem has no static equilibrium, or whose K is not certified, "
            "count as failures; every sample is in samples.csv.</p>")


def reinforcement_section(summary):
    """The anchors' and passive bars' forces (summary.json's
    "reinforcement"), or "" without any."""
    r = summary.get("reinforcement")
    if not r:
        return ""
    out = ["<h2>Reinforcement</h2>"]
    if r.get("anchors"):
        out.append(f"<p>Active anchors ({html.escape(r['convention'])}), in the state at "
                   f"K = {number(r['K_of_state'], 8)}; anchors.csv has the same.</p>")
        out.append(table([(k + 1, html.escape(a["interface"]), number(a["force"]),
                           number(a["normal_force"]), number(a["shear_force"]),
                           number(a["applied_shear_force"]))
                          for k, a in enumerate(r["anchors"])],
                         ["anchor", "surface crossed", "T", "normal part", "shear part",
                          "shear applied"]))
    bars = r.get("passive_bars")
    if bars:
        out.append(f"<p>Passive bars (capacities {'reduced' if bars['capacity_reduced_by_K'] else 'not reduced'} "
                   f"by K), in the state at K = {number(bars['K_of_state'], 8)}: axial force N "
                   "(tension positive) against the capacity applied; bars.csv has the same.</p>")
        out.append(table([(k + 1, html.escape(b["interface"]), number(b["tensile_capacity"]),
                           number(b["pullout_in_mass"]), number(b["pullout_in_ground"]),
                           number(b["applied_axial_capacity"]), number(b["axial_force"]),
                           number(b["axial_utilisation"], 4), number(b["shear_force"]),
                           html.escape(b["status"]))
                          for k, b in enumerate(bars["bars"])],
                         ["bar", "surface crossed", "steel capacity", "pull-out in the mass",
                          "pull-out in the ground", "capacity applied", "N", "N / capacity", "shear",
                          "status"]))
    return "\n".join(out)


# --------------------------------------------------------------------------
# The page.

def number(x, digits=6):
    if x is None:
        return "—"
    if isinstance(x, bool) or not isinstance(x, (int, float)):
        return html.escape(str(x))
    return f"{x:.{digits}g}"


def table(rows, header=None):
    out = ["<table>"]
    if header:
        out.append("<tr>" + "".join(f"<th>{html.escape(h)}</th>" for h in header) + "</tr>")
    for row in rows:
        out.append("<tr>" + "".join(f"<td>{c}</td>" for c in row) + "</tr>")
    out.append("</table>")
    return "\n".join(out)


def image(path, alt):
    data = base64.b64encode(open(path, "rb").read()).decode("ascii")
    return f'<img src="data:image/png;base64,{data}" alt="{html.escape(alt)}">'


def results_table(summary):
    rows = [("case", html.escape(str(summary.get("case", "")))),
            ("status", html.escape(summary.get("status", "")))]
    if "safety_factor" in summary:
        rows.append(("safety factor K", f"<b>{number(summary['safety_factor'], 4)}</b>"))
        cert = summary.get("certificate", {})
        rows.append(("certificate", html.escape(f"{cert.get('kind', '')}: "
                                                f"{'holds' if cert.get('holds') else 'does not hold'}"
                                                f"{' (conservative)' if cert.get('conservative') else ''}")))
        rows.append(("certificate details", html.escape(cert.get("reason", ""))))
        bracket = summary.get("safety_factor_bracket", [None, None])
        rows.append(("bracket", f"{number(bracket[0])} – {number(bracket[1])}"))
        fe = summary.get("fe_stress_factor", {})
        if fe.get("computed"):
            rows.append(("factor from the finite-element stresses", number(fe.get("factor"), 4)))
        stiff = summary.get("stiffness_sensitivity", {})
        if stiff.get("computed"):
            rows.append((f"K with the moving blocks {number(stiff.get('factor'))} times stiffer / softer",
                         f"{number(stiff.get('K_stiffer'), 4)} / {number(stiff.get('K_softer'), 4)} "
                         f"(relative change {number(stiff.get('relative_change'), 3)})"))
    rows.append(("dimension, element degree", f"{summary.get('dimension')}D, degree {summary.get('fe_degree')}"))
    rows.append(("unknowns (dofs)", number(summary.get("n_dofs"))))
    return table(rows)


def surface_search_picture(folder, search, path):
    """search.png: the screening factor over the grid of centres (each
    centre's lowest over its radii), the refinement's circles and the
    centres evaluated by the contact method, with the critical centre."""
    rows = list(csv.DictReader(open(os.path.join(folder, "search.csv"))))
    lowest = {}
    for r in rows:
        if r["stage"] == "grid" and r["le_K"]:
            key = (float(r["centre_x"]), float(r["centre_y"]))
            lowest[key] = min(lowest.get(key, np.inf), float(r["le_K"]))
    fig, ax = plt.subplots(figsize=(8, 6))
    if lowest:
        xy = np.array(list(lowest.keys()))
        K = np.array(list(lowest.values()))
        xs, ys = np.unique(xy[:, 0]), np.unique(xy[:, 1])
        if len(xs) > 1 and len(ys) > 1 and len(K) == len(xs) * len(ys):
            grid = np.full((len(ys), len(xs)), np.nan)
            for (x, y), k in lowest.items():
                grid[np.searchsorted(ys, y), np.searchsorted(xs, x)] = k
            shown = ax.contourf(xs, ys, grid, levels=20, cmap="viridis")
        else:
            shown = ax.scatter(xy[:, 0], xy[:, 1], c=K, cmap="viridis", s=40)
        fig.colorbar(shown, ax=ax, label=f"lowest {search['method']} factor at the centre")
    refined = np.array([(float(r["centre_x"]), float(r["centre_y"])) for r in rows
                        if r["stage"] == "refinement" and r["le_K"]]).reshape(-1, 2)
    ax.plot(refined[:, 0], refined[:, 1], ".", color="0.7", ms=3,
            label="refinement (limit equilibrium)")
    contact = np.array([(float(r["centre_x"]), float(r["centre_y"])) for r in rows
                        if r["stage"].startswith("contact")]).reshape(-1, 2)
    ax.plot(contact[:, 0], contact[:, 1], "o", mfc="none", color="tab:red",
            label="contact evaluations")
    c = search["critical"]["centre"]
    if c is not None:  # a critical polyline has no centre
        ax.plot([c[0]], [c[1]], "*", color="w", mec="k", ms=16, label="critical circle's centre")
    ax.set_xlabel("x of the centre (length unit)")
    ax.set_ylabel("y of the centre (length unit)")
    ax.set_aspect("equal")
    ax.legend(fontsize=8)
    ax.set_title("surface search: factor of safety over the grid of centres", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=DPI)
    plt.close(fig)


def surface_search_section(folder, summary):
    """The report's section on the surface search (summary.json's
    surface_search): the critical circle, its factors, the counts and the
    picture of K over the grid."""
    search = summary["surface_search"]
    critical, counts = search["critical"], search["counts"]
    if critical.get("shape") == "polyline":
        surface = ("critical polyline", "; ".join(f"({number(x)}, {number(y)})"
                                                  for x, y in critical["polyline"]))
    else:
        surface = ("critical circle", f"centre ({number(critical['centre'][0])}, "
                                      f"{number(critical['centre'][1])}), radius "
                                      f"{number(critical['radius'])}")
    rows = [surface,
            ("chosen by", html.escape(critical["chosen_by"])),
            ("contact K (the run's, at the model's mesh size)", number(critical["K"], 4)),
            ("contact K during the search (screening mesh size "
             f"{number(critical['screening_mesh_size'])})", number(critical["contact_K"], 4))]
    for method, K in critical["limit_equilibrium"].items():
        rows.append((f"limit equilibrium, {html.escape(method)}", number(K, 4)))
    rows.append(("circles screened (grid, refinement)",
                 f"{counts['grid']} ({counts['valid']} valid), {counts['refinement']}"))
    rows.append(("contact evaluations (certified)",
                 f"{counts['contact_evaluations']} ({counts['contact_certified']})"))
    polylines = search.get("non_circular")
    if polylines:
        p, minimum = polylines["counts"], polylines.get("minimum")
        rows.append((f"polylines of {polylines['n_vertices']} vertices screened by "
                     f"{html.escape(polylines['method'])} (from circles)",
                     f"{p['screened']} ({p['valid']} valid) from {p['starts']}, "
                     f"{number(polylines['timings']['screening'], 3)} s"))
        rows.append(("lowest polyline factor",
                     number(minimum["le_K"], 4) if minimum else "none"))
        if p.get("snapped"):
            rows.append(("optima snapped onto layer lines (within)",
                         f"{p['snapped']} ({number(polylines['snap_distance'], 3)})"))
        rows.append(("polylines evaluated by the contact method (certified)",
                     f"{p['contact_evaluations']} ({p['contact_certified']})"))
        refinement = polylines.get("contact_refinement", {})
        if refinement.get("performed"):
            r = refinement["counts"]
            rows.append(("best polyline refined by its contact K (moves kept of "
                         "evaluations)",
                         f"{number(refinement['from']['contact_K'], 4)} to "
                         f"{number(refinement['best']['contact_K'], 4)} "
                         f"({r['moves']} of {r['contact_evaluations']})"))
    out = ["<h2>Surface search</h2>", table(rows)]
    if search.get("minimum_on_grid_edge"):
        out.append('<p class="warning">The screening minimum lies on the edge of the search '
                   "region: a lower one may lie beyond it.</p>")
    if os.path.exists(os.path.join(folder, "search.csv")):
        surface_search_picture(folder, search, os.path.join(folder, "search.png"))
        out.append("<p>" + image(os.path.join(folder, "search.png"),
                                 "Factor of safety over the grid of centres") + "</p>")
    out.append("<p>Every circle evaluated: search.csv; the critical circle's entries to rerun "
               "it: critical_surface.prm.</p>")
    return out


def main(folder):
    start = time.perf_counter()
    summary = json.load(open(os.path.join(folder, "summary.json")))
    prm = read_prm(os.path.join(folder, "parameters.prm"))
    interfaces = read_interfaces(os.path.join(folder, "interfaces.csv"))
    pictures = [("model.png", "The model and its sliding surfaces"),
                ("stresses.png", "Stresses along the sliding surfaces"),
                ("iterations.png", "Safety-factor iteration")]
    notes = model_picture(folder, summary, prm, interfaces, os.path.join(folder, pictures[0][0]))
    stress_picture(summary, interfaces, os.path.join(folder, pictures[1][0]))
    if summary.get("iterations"):
        iteration_picture(summary, os.path.join(folder, pictures[2][0]))
    else:
        pictures.pop()
    if not interfaces:
        notes.append("no interfaces.csv: the run found no equilibrium, so there are no stresses to show")

    page = [f"""<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8">
<title>fdem-slope report: {html.escape(str(summary.get('case', '')))}</title>
<style>
body {{ font-family: sans-serif; max-width: 1000px; margin: 2em auto; color: #222; }}
table {{ border-collapse: collapse; margin: 0.5em 0 1.5em; }}
td, th {{ border: 1px solid #ccc; padding: 3px 8px; text-align: left; font-size: 90%; }}
th {{ background: #f0f0f0; }}
img {{ max-width: 100%; border: 1px solid #ddd; }}
pre {{ background: #f7f7f7; padding: 1em; font-size: 80%; overflow-x: auto; }}
.warning {{ color: #a00; }}
</style></head><body>
<h1>fdem-slope report: {html.escape(str(summary.get('case', '')))}</h1>
<p>Units are those of the input (doc/units.md): lengths in the model's length unit,
stresses in force per length squared.</p>
<h2>Results</h2>
{results_table(summary)}
<h2>Warnings</h2>"""]
    warnings = summary.get("warnings", [])
    page.append("<ul>" + "".join(f'<li class="warning">{html.escape(w)}</li>' for w in warnings) + "</ul>"
                if warnings else "<p>None.</p>")
    if "surface_search" in summary:
        page += surface_search_section(folder, summary)
    page.append("<h2>Sliding surfaces</h2>")
    page.append(table([(html.escape(i["name"]), html.escape(i["block_I"]), html.escape(i["block_J"]),
                        i["n_pairs"], i["n_stick"], i["n_slip"], i["n_open"],
                        number(i["max_normal_pressure"]), number(i["total_normal_force"]),
                        number(i["total_tangential_force"]))
                       for i in summary.get("interfaces", [])],
                      ["interface", "block I", "block J", "pairs", "stick", "slip", "open",
                       "max normal stress", "total normal force", "total tangential force"]))
    for name, alt in pictures:
        page.append(f"<h2>{html.escape(alt)}</h2>\n<p>{image(os.path.join(folder, name), alt)}</p>")
    reinforcement = reinforcement_section(summary)
    if reinforcement:
        page.append(reinforcement)
    seismic = seismic_section(folder, summary)
    if seismic:
        page.append(seismic)
    if notes:
        page.append("<p>Notes: " + "; ".join(html.escape(n) for n in notes) + ".</p>")
    steps = summary.get("iterations", [])
    if steps:
        page.append("<h2>Safety-factor steps</h2>")
        page.append(table([(k + 1, number(s["K"], 8), number(s.get("K_star"), 8), number(s["F_R"]),
                            number(s["F_tau"]), s["n_stick"], s["n_slip"], s["n_open"],
                            html.escape(str(s["contact_result"])))
                           for k, s in enumerate(steps)],
                          ["step", "K", "K*", "F_R", "F_τ", "stick", "slip", "open", "contact problem"]))
    if "probabilistic" in summary:
        page.append(probabilistic_section(folder, summary))
    page.append("<h2>Input parameters (parameters.prm)</h2>")
    if os.path.exists(os.path.join(folder, "parameters.prm")):
        # The entries the case set (marked '# default:' by the program) first.
        text = open(os.path.join(folder, "parameters.prm")).read()
        page.append("<pre>" + html.escape(text) + "</pre>")
    page.append("</body></html>\n")
    with open(os.path.join(folder, "report.html.tmp"), "w") as f:
        f.write("\n".join(page))
    os.replace(os.path.join(folder, "report.html.tmp"), os.path.join(folder, "report.html"))
    print(f"report.html made in {time.perf_counter() - start:.2f} s")


if __name__ == "__main__":
    if len(sys.argv) != 2 or not os.path.isdir(sys.argv[1]):
        print("usage: fdem_report.py RESULTS_FOLDER")
        sys.exit(2)
    main(sys.argv[1])
