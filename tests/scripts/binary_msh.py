#!/usr/bin/python3
# SPDX-License-Identifier: LGPL-2.1-or-later
"""Binary .msh files (format 2.2 and 4.1) with a node tag listed twice at
two different places: each run must fail with the one line of
tests/bad_input/mesh_node_twice.prm (Gmsh itself keeps one of the two
without a word). The files are written here, not committed: two
quadrilaterals on a base line, as tests/bad_input/data/node_twice.msh. The
same files with distinct tags are read by Gmsh (a control: the writer is
right, so the error is about the tags).

  binary_msh.py EXE
"""
import os
import struct
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path[:0] = [HERE]
import run_checks  # noqa: E402

NODES = [(1, 0, 0), (2, 1, 0), (3, 2, 0), (4, 0, 1), (5, 1, 1), (6, 2, 1), (7, 1.5, 1)]
QUADS = [(1, 2, 5, 4), (2, 3, 6, 5)]
LINES = [(1, 2), (2, 3)]
PHYSICAL = b'$PhysicalNames\n2\n1 2 "base"\n2 1 "rock"\n$EndPhysicalNames\n'


def format_2(duplicate):
    tags = [5 if duplicate and n == 7 else n for n in range(1, 8)]
    out = b"$MeshFormat\n2.2 1 8\n" + struct.pack("<i", 1) + b"\n$EndMeshFormat\n" + PHYSICAL
    out += b"$Nodes\n7\n" + b"".join(struct.pack("<i3d", t, x, y, 0.0)
                                    for t, (_, x, y) in zip(tags, NODES))
    out += b"\n$EndNodes\n$Elements\n4\n"
    out += struct.pack("<3i", 1, 2, 2)  # 2 lines with 2 tags each
    out += b"".join(struct.pack("<5i", i + 1, 2, 1, *l) for i, l in enumerate(LINES))
    out += struct.pack("<3i", 3, 2, 2)  # 2 quadrilaterals
    out += b"".join(struct.pack("<7i", i + 3, 1, 1, *q) for i, q in enumerate(QUADS))
    return out + b"\n$EndElements\n"


def format_41(duplicate):
    tags = [5 if duplicate and n == 7 else n for n in range(1, 8)]
    out = b"$MeshFormat\n4.1 1 8\n" + struct.pack("<i", 1) + b"\n$EndMeshFormat\n" + PHYSICAL
    # One curve (the base, physical 2) and one surface (the rock, physical 1).
    out += b"$Entities\n" + struct.pack("<4Q", 0, 1, 1, 0)
    out += struct.pack("<i6dQiQ", 1, 0, 0, 0, 2, 0, 0, 1, 2, 0)
    out += struct.pack("<i6dQiQ", 1, 0, 0, 0, 2, 1, 0, 1, 1, 0)
    out += b"\n$EndEntities\n$Nodes\n" + struct.pack("<4Q", 1, 7, 1, 7)
    out += struct.pack("<3iQ", 2, 1, 0, 7) + struct.pack("<7Q", *tags)
    out += b"".join(struct.pack("<3d", x, y, 0.0) for _, x, y in NODES)
    out += b"\n$EndNodes\n$Elements\n" + struct.pack("<4Q", 2, 4, 1, 4)
    out += struct.pack("<3iQ", 1, 1, 1, 2)
    out += b"".join(struct.pack("<3Q", i + 1, *l) for i, l in enumerate(LINES))
    out += struct.pack("<3iQ", 2, 1, 3, 2)
    out += b"".join(struct.pack("<5Q", i + 3, *q) for i, q in enumerate(QUADS))
    return out + b"\n$EndElements\n"


PRM = """# expect: {expect}
subsection Geometry
  set Source    = mesh file
  set Mesh file = {mesh}
end
subsection Blocks
  set Names = rock
  subsection rock
    set Young's modulus = 1e4
  end
end
subsection Boundaries
  set Names = base
  subsection base
    set Constraint = fixed
  end
end
subsection Interfaces
  set Names =
end
"""


def main(exe):
    with tempfile.TemporaryDirectory() as folder:
        for name, write in (("2.2", format_2), ("4.1", format_41)):
            for duplicate in (False, True):
                mesh = os.path.join(folder, f"binary-{name}-{duplicate}.msh")
                with open(mesh, "wb") as f:
                    f.write(write(duplicate))
                prm = os.path.join(folder, f"binary-{name}-{duplicate}.prm")
                with open(prm, "w") as f:
                    f.write(PRM.format(mesh=mesh, expect="node 5 is listed twice, at two different places"))
                if duplicate:
                    print(f"format {name}, node 5 twice:")
                    run_checks.check_bad_input(exe, prm)
                else:
                    p = subprocess.run([exe, "--validate", prm], capture_output=True, text=True,
                                       timeout=120)
                    print(f"format {name}, distinct tags: exit {p.returncode}",
                          p.stdout.strip().splitlines()[-1:], p.stderr.strip())
                    assert p.returncode == 0, "Gmsh did not read the control file"
    print("passed")


if __name__ == "__main__":
    main(os.path.abspath(sys.argv[1]))
