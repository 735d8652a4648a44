#!/usr/bin/env python3
"""Writes the meshes of the masonry examples in prm/ (needs Debian's gmsh;
the .msh files are committed, so running the examples does not):

  arch.msh          a semicircular arch of 16 voussoirs set in a wall of
                    spandrel blocks, its intrados a named boundary for the
                    centring (prm/masonry_arch.prm)
  window_wall.msh   a running-bond wall with a window and its lintel
                    (prm/masonry_window.prm)
  barrel_vault.msh  the arch and its spandrels extruded into four rings: a
                    segment of a barrel vault (prm/masonry_barrel_vault.prm)

  python3 prm/meshes/make_examples.py
"""
import math
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, here)
import blocks_to_gmsh as g  # noqa: E402


def arch_in_wall(voussoirs=16, inner=1.0, outer=1.25, half_width=2.0,
                 height=2.0):
    """Voussoirs between the radii `inner` and `outer` with radial joints,
    and outside each voussoir a spandrel block between the same rays, out
    to the wall's edge (the rectangle [-half_width, half_width] x
    [0, height]). `voussoirs` must be a multiple of 4 so that a ray runs
    into each top corner of the wall."""
    assert voussoirs % 4 == 0
    def on_circle(r, t):
        return (r * math.cos(t), r * math.sin(t))

    def on_edge(t):
        # Where the ray at angle t leaves the rectangle.
        c, s = math.cos(t), math.sin(t)
        if abs(c) > 1e-12 and abs(half_width / c * s) <= height + 1e-12:
            x = math.copysign(half_width, c)
            return (x, x / c * s if abs(s) > 1e-12 else 0.0)
        return (height / s * c, height)

    blocks = []
    for k in range(voussoirs):
        t0, t1 = math.pi * k / voussoirs, math.pi * (k + 1) / voussoirs
        blocks.append(g.Block([on_circle(inner, t0), on_circle(outer, t0),
                               on_circle(outer, t1), on_circle(inner, t1)],
                              (2, 2), "voussoir"))
        blocks.append(g.Block([on_circle(outer, t0), on_edge(t0),
                               on_edge(t1), on_circle(outer, t1)],
                              (3, 2), "spandrel"))

    def sides(p, q):
        if all(abs(math.hypot(*r) - inner) < 1e-9 for r in (p, q)):
            return "intrados"
        return g.wall_sides((p[0] + half_width, p[1]),
                            (q[0] + half_width, q[1]),
                            2 * half_width, height)
    return blocks, sides


def window_wall(length=12, courses=10, window=(4, 8), sill=3, lintel=7):
    """A running-bond wall of blocks 2 x 1 (H = 1), `length` long and
    `courses` high, with a window x in window, y in [sill, lintel) and a
    lintel course y in [lintel, lintel + 1) whose block spans the opening
    and one unit on each side."""
    blocks = []
    for j in range(courses):
        cuts = {0, length}
        cuts |= {x for x in range(j % 2, length, 2) if 0 < x < length}
        if sill <= j < lintel:
            cuts |= set(window)
        if j == lintel:
            cuts = {x for x in cuts
                    if not window[0] - 1 < x < window[1] + 1}
            cuts |= {window[0] - 1, window[1] + 1}
        xs = sorted(cuts)
        for x0, x1 in zip(xs, xs[1:]):
            if sill <= j < lintel and window[0] <= x0 and x1 <= window[1]:
                continue  # the opening
            blocks.append(g.Block([(x0, j), (x1, j), (x1, j + 1), (x0, j + 1)],
                                  (x1 - x0, 1),
                                  "lintel" if j == lintel and
                                  x1 - x0 > 2 else "brick"))
    return blocks, lambda p, q: g.wall_sides(p, q, length, courses)


def build(name, blocks, sides, dim, **extrusion):
    geo = os.path.join(here, name + ".geo")
    g.write_geo(geo, blocks, sides, **extrusion)
    g.mesh(geo, os.path.join(here, name + ".msh"), dim, "4.1")
    os.remove(geo)


if __name__ == "__main__":
    blocks, sides = arch_in_wall()
    build("arch", blocks, sides, 2)
    build("window_wall", *window_wall(), 2)
    rings = [(0.5 * k, 0.5 * (k + 1), 1) for k in range(4)]
    build("barrel_vault", blocks, sides, 3, layers=rings,
          name_face=lambda z: {0.0: "front", 2.0: "back"}.get(z))
