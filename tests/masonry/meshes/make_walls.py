#!/usr/bin/env python3
"""The paper's three walls (m = 5) as Gmsh files, in formats 2.2 and 4.1,
for tests/masonry/mesh_file_walls: each block a surface of its own (so
neighbouring blocks share nodes in the file), boundaries named left, right,
base, top like the built-in walls'. Needs Debian's gmsh; the .msh files are
committed, so the tests do not.

  python3 tests/masonry/meshes/make_walls.py
"""
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(here, "..", "..", "..", "prm", "meshes"))
import blocks_to_gmsh as g  # noqa: E402

for bond in ("stack bond", "running bond", "laminae"):
    name = bond.replace(" ", "_") + "_5"
    geo = os.path.join(here, name + ".geo")
    g.write_geo(geo, g.wall(bond, 5), g.wall_sides)
    for version in ("2.2", "4.1"):
        g.mesh(geo, os.path.join(here, f"{name}_v{version[0]}.msh"), 2, version)
    os.remove(geo)
