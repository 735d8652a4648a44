#!/usr/bin/env python3
"""Blocks to Gmsh meshes for the masonry scene (`Geometry = mesh file`).

A small library (and no more): a structure is a list of blocks, each a
quadrilateral given by its four corners counter-clockwise, cut into
`cells` x `cells` (or a pair) quadrilateral cells; its boundary segments
are named by a function of the segment. `write_geo` writes a Gmsh .geo
script in which every block is a surface of its own (blocks that touch
share points and lines, so their meshes share nodes, which the masonry
scene splits again: each surface is a body) and `mesh` runs Debian's gmsh
on it. In 3D each block is extruded through the given layers of z, each
layer a volume of its own.

Boundary names become physical curves (2D) or physical surfaces (3D) of
the same name; every block's cells are the physical group `material`
unless the block names its own.
"""
import math
import os
import subprocess


class Block:
    def __init__(self, corners, cells=(1, 1), material="masonry"):
        """corners: four (x, y), counter-clockwise; cells: along the edges
        corner 0 -> 1 and 1 -> 2."""
        self.corners = [tuple(float(c) for c in p) for p in corners]
        self.cells = cells
        self.material = material


def _key(p):
    return tuple(round(c, 12) for c in p)


def write_geo(path, blocks, name_segment, layers=None, name_face=None):
    """Write the .geo script.

    name_segment(p, q): the boundary name of the straight segment p-q of a
    block's edge that lies on no other block (or None): in 2D a physical
    curve, in 3D the physical surface of its extrusion.
    layers: None (2D) or a list of (z0, z1, cells) for 3D extrusion, one
    volume per block and layer.
    name_face(z): in 3D, the name of the block faces at z (front, back,
    collar) or None.
    """
    points, lines = {}, {}
    out = ["// Written by prm/meshes/blocks_to_gmsh.py", "SetFactory(\"Built-in\");"]

    def point(p):
        k = _key(p)
        if k not in points:
            points[k] = len(points) + 1
            out.append(f"Point({points[k]}) = {{{p[0]!r}, {p[1]!r}, 0}};")
        return points[k]

    def line(a, b, n):
        if (a, b) in lines:
            return lines[(a, b)]
        if (b, a) in lines:
            return -lines[(b, a)]
        tag = len(lines) + 1
        lines[(a, b)] = tag
        out.append(f"Line({tag}) = {{{a}, {b}}};")
        out.append(f"Transfinite Curve{{{tag}}} = {n + 1};")
        return tag

    uses = {}
    for block in blocks:
        c = block.corners
        for i in range(4):
            e = frozenset((_key(c[i]), _key(c[(i + 1) % 4])))
            uses[e] = uses.get(e, 0) + 1
    surfaces = []
    boundary = {}  # name -> line tags
    for b, block in enumerate(blocks):
        c = block.corners
        ids = [point(p) for p in c]
        n = [block.cells[0], block.cells[1], block.cells[0], block.cells[1]]
        loop = [line(ids[i], ids[(i + 1) % 4], n[i]) for i in range(4)]
        for i in range(4):
            if uses[frozenset((_key(c[i]), _key(c[(i + 1) % 4])))] == 1:
                name = name_segment(c[i], c[(i + 1) % 4])
                if name:
                    boundary.setdefault(name, []).append(abs(loop[i]))
        tag = b + 1
        out.append(f"Curve Loop({tag}) = {{{', '.join(map(str, loop))}}};")
        out.append(f"Plane Surface({tag}) = {{{tag}}};")
        out.append(f"Transfinite Surface{{{tag}}};")
        out.append(f"Recombine Surface{{{tag}}};")
        surfaces.append(tag)
    materials = {}
    if layers is None:
        for b, block in enumerate(blocks):
            materials.setdefault(block.material, []).append(b + 1)
        for name, tags in boundary.items():
            out.append(f"Physical Curve(\"{name}\") = {{{', '.join(map(str, tags))}}};")
        for name, tags in materials.items():
            out.append(f"Physical Surface(\"{name}\") = {{{', '.join(map(str, tags))}}};")
    else:
        # Extrude each block layer by layer: ext[0] is the top surface,
        # ext[1] the volume, ext[2..5] the sides (in the loop's order).
        faces = {}
        sides = {}
        for b, block in enumerate(blocks):
            bottom = f"{b + 1}"
            out.append(f"bottom = {bottom};")
            for l, (z0, z1, nz) in enumerate(layers):
                if l == 0 and z0 != 0:
                    out.append(f"Translate {{0, 0, {z0!r}}} {{ Surface{{bottom}}; }}")
                out.append(f"ext[] = Extrude {{0, 0, {z1 - z0!r}}} "
                           f"{{ Surface{{bottom}}; Layers{{{nz}}}; Recombine; }};")
                materials.setdefault(block.material, []).append(f"ext[1]")
                out[-1] += (f" vol_{b}_{l} = ext[1];")
                materials[block.material][-1] = f"vol_{b}_{l}"
                if name_face is not None:
                    if l == 0 and name_face(z0):
                        faces.setdefault(name_face(z0), []).append("bottom")
                        out[-1] += f" face_{b}_{l}_0 = bottom;"
                        faces[name_face(z0)][-1] = f"face_{b}_{l}_0"
                    if name_face(z1):
                        out[-1] += f" face_{b}_{l}_1 = ext[0];"
                        faces.setdefault(name_face(z1), []).append(f"face_{b}_{l}_1")
                c = block.corners
                for i in range(4):
                    if uses[frozenset((_key(c[i]), _key(c[(i + 1) % 4])))] == 1:
                        name = name_segment(c[i], c[(i + 1) % 4])
                        if name:
                            out[-1] += f" side_{b}_{l}_{i} = ext[{2 + i}];"
                            sides.setdefault(name, []).append(f"side_{b}_{l}_{i}")
                out.append("bottom = ext[0];")
        for name, tags in list(sides.items()) + list(faces.items()):
            out.append(f"Physical Surface(\"{name}\") = {{{', '.join(tags)}}};")
        for name, tags in materials.items():
            out.append(f"Physical Volume(\"{name}\") = {{{', '.join(tags)}}};")
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")


def mesh(geo, msh, dim, version="2.2"):
    """Run gmsh: first-order quadrilaterals (hexahedra in 3D), ASCII."""
    subprocess.run(["gmsh", "-" + str(dim), "-order", "1", "-format",
                    "msh22" if version == "2.2" else "msh41", "-o", msh,
                    geo], check=True, stdout=subprocess.DEVNULL)


def wall(bond, m):
    """The paper's walls on the unit square as blocks (H = 1/m, one cell
    per H), as the built-in generator lays them out."""
    H = 1.0 / m
    blocks = []
    if bond == "stack bond":
        for j in range(m):
            for i in range(m):
                blocks.append(Block([(i * H, j * H), ((i + 1) * H, j * H),
                                     ((i + 1) * H, (j + 1) * H),
                                     (i * H, (j + 1) * H)], (1, 1)))
    elif bond == "running bond":
        for j in range(m):
            x = -H * (j % 2)
            while x < 1 - 1e-12:
                x0, x1 = max(x, 0.0), min(x + 2 * H, 1.0)
                n = round((x1 - x0) / H)
                blocks.append(Block([(x0, j * H), (x1, j * H),
                                     (x1, (j + 1) * H), (x0, (j + 1) * H)],
                                    (n, 1)))
                x += 2 * H
    else:
        for j in range(m):
            blocks.append(Block([(0, j * H), (1, j * H), (1, (j + 1) * H),
                                 (0, (j + 1) * H)], (m, 1)))
    return blocks


def wall_sides(p, q, width=1.0, height=1.0):
    """The built-in walls' boundary names for a segment p-q."""
    if abs(p[0]) < 1e-12 and abs(q[0]) < 1e-12:
        return "left"
    if abs(p[0] - width) < 1e-12 and abs(q[0] - width) < 1e-12:
        return "right"
    if abs(p[1]) < 1e-12 and abs(q[1]) < 1e-12:
        return "base"
    if abs(p[1] - height) < 1e-12 and abs(q[1] - height) < 1e-12:
        return "top"
    return None
