#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""K must not depend on how the mesh is numbered.

  mesh_numbering.py EXE CASE.prm [PATH=VALUE...]

Runs the case (with the entries PATH set to VALUE), takes the mesh it wrote
(mesh.msh, Gmsh 4.1 ASCII), and writes it again renumbered: node tags and
element tags permuted at random, the nodes and the elements of every entity
block shuffled, the vertices of every quadrilateral and triangle turned by a
random number of places (the same cell, the same orientation) and every line
reversed. The case is then run on the mesh as written and on the renumbered
mesh (Geometry/Source = mesh file). Both must have the same dofs and node
pairs, the same safety-factor steps (stick/slip/open counts of each) and K
within 1e-8 relative, as the unit and stiffness invariance tests ask: the
numbering changes the order of every sum and of the factorisations, so only
round-off may differ. Two seeds are tried.
"""
import os
import random
import shutil
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path[:0] = [HERE, os.path.join(HERE, "..", "..", "tools")]
import fdem_run  # noqa: E402

# Gmsh element types whose vertex list may be turned cyclically without
# changing the cell or its orientation (3-node triangle, 4-node
# quadrilateral), and lines (2-node), which are reversed.
ROTATABLE = {2: 3, 3: 4}
LINE = 1


def sections(lines):
    """The $Name ... $EndName sections of a .msh file: name -> body lines."""
    out, name, body = {}, None, []
    for line in lines:
        if line.startswith("$End"):
            out[name] = body
            name = None
        elif line.startswith("$"):
            name, body = line[1:], []
        elif name is not None:
            body.append(line)
    return out


def renumbered(text, seed):
    """The Gmsh 4.1 ASCII mesh @p text with its nodes and elements
    renumbered and reordered (see the module's text)."""
    rng = random.Random(seed)
    lines = text.splitlines()
    parts = sections(lines)
    assert parts["MeshFormat"][0].split()[0] == "4.1", "a Gmsh 4.1 ASCII mesh is expected"

    # Nodes: entity blocks of tags followed by their coordinates.
    body = parts["Nodes"]
    n_blocks, n_nodes, _, _ = map(int, body[0].split())
    tags = list(range(1, n_nodes + 1))
    rng.shuffle(tags)
    node_map, i, new_nodes, old_tags = {}, 1, [], []
    blocks = []
    for _ in range(n_blocks):
        header = body[i].split()
        count = int(header[3])
        block_tags = [int(t) for t in body[i + 1:i + 1 + count]]
        coords = body[i + 1 + count:i + 1 + 2 * count]
        assert header[2] == "0", "parametric nodes are not handled"
        blocks.append((header, block_tags, coords))
        old_tags += block_tags
        i += 1 + 2 * count
    assert len(old_tags) == n_nodes
    for old, new in zip(old_tags, tags):
        node_map[old] = new
    new_nodes.append(f"{n_blocks} {n_nodes} 1 {n_nodes}")
    for header, block_tags, coords in blocks:
        order = list(range(len(block_tags)))
        rng.shuffle(order)
        new_nodes.append(" ".join(header))
        new_nodes += [str(node_map[block_tags[k]]) for k in order]
        new_nodes += [coords[k] for k in order]

    # Elements: entity blocks of "tag node node ...".
    body = parts["Elements"]
    n_blocks, n_elements, _, _ = map(int, body[0].split())
    element_tags = list(range(1, n_elements + 1))
    rng.shuffle(element_tags)
    next_tag = iter(element_tags)
    new_elements, i = [f"{n_blocks} {n_elements} 1 {n_elements}"], 1
    for _ in range(n_blocks):
        header = body[i].split()
        element_type, count = int(header[2]), int(header[3])
        rows = [row.split()[1:] for row in body[i + 1:i + 1 + count]]
        rng.shuffle(rows)
        new_elements.append(" ".join(header))
        for row in rows:
            nodes = [str(node_map[int(t)]) for t in row]
            if element_type in ROTATABLE:
                assert len(nodes) == ROTATABLE[element_type]
                k = rng.randrange(len(nodes))
                nodes = nodes[k:] + nodes[:k]
            elif element_type == LINE:
                nodes.reverse()
            new_elements.append(" ".join([str(next(next_tag))] + nodes))
        i += 1 + count

    out, skip = [], False
    for line in lines:
        if line in ("$Nodes", "$Elements"):
            out.append(line)
            out += new_nodes if line == "$Nodes" else new_elements
            skip = True
        elif line.startswith("$End"):
            skip = False
            out.append(line)
        elif not skip:
            out.append(line)
    return "\n".join(out) + "\n"


def steps(summary):
    return [(s.get("n_stick"), s.get("n_slip"), s.get("n_open")) for s in summary["iterations"]]


def main(exe, prm, *entries):
    settings = dict(entry.split("=", 1) for entry in entries)
    settings.update({"Output/Write VTU": "false", "Output/Report": "false"})
    with tempfile.TemporaryDirectory(prefix="fdem-numbering-") as folder:
        with fdem_run.temporary_run(exe, prm, settings=settings) as first:
            assert first.ok, first.failure()
            original = os.path.join(folder, "original.msh")
            shutil.copy(first.file("mesh.msh"), original)
        text = open(original).read()
        meshes = {"original": original}
        for seed in (1, 2):
            meshes[f"seed {seed}"] = os.path.join(folder, f"seed_{seed}.msh")
            open(meshes[f"seed {seed}"], "w").write(renumbered(text, seed))
        runs = {}
        for name, path in meshes.items():
            run = fdem_run.run_case(exe, prm, settings=dict(
                settings, **{"Geometry/Source": "mesh file", "Geometry/Mesh file": path}))
            assert run.ok, f"{name}: {run.failure()}"
            s = runs[name] = run.summary
            print(f"{name}: {s['n_dofs']} dofs, K = {s['safety_factor']!r}, "
                  f"{len(s['iterations'])} steps, "
                  f"certificate {s['certificate']['kind']}")
        reference = runs["original"]
        for name, s in runs.items():
            assert s["converged"] and s["certificate"]["holds"], (name, s["certificate"])
            assert s["n_dofs"] == reference["n_dofs"], (name, s["n_dofs"])
            assert steps(s) == steps(reference), (name, steps(s), steps(reference))
            difference = abs(s["safety_factor"] / reference["safety_factor"] - 1)
            print(f"{name}: relative difference of K {difference:.2e}")
            assert difference <= 1e-8, (name, s["safety_factor"], reference["safety_factor"])
    print("passed")


if __name__ == "__main__":
    main(*sys.argv[1:])
