#!/usr/bin/python3
"""Write synthetic LCPs in unilateral's exchange format (lcp_A.mtx, lcp_b.txt,
lcp_constraints.txt; see include/unilateral/lcp/io.h).

  laplacian  the obstacle problem for a membrane: the 5-point Laplacian on the
             m x m interior nodes of the unit square (Dirichlet boundary),
             every node constrained, u >= psi with a dome-shaped obstacle
             psi(x, y) = 0.3 - 2 |(x, y) - (0.5, 0.5)|^2 and a downward load
             f = -10 (about a third of the nodes end up in contact).
             A is positive definite.
  mixed      the shape of masonry's LCP: a constrained part, unconstrained
             unknowns and a singular positive semidefinite A. Two membranes
             with free (Neumann) edges, m x m nodes each:
               - the first rests on a dome-shaped support under a downward load
                 (u >= psi on its left half only, the right half is free);
                 its rigid vertical translation is held by the contacts alone;
               - the second floats: no constraint at all and a self-balanced
                 load, so A_EE (the unconstrained block) is singular and u is
                 unique only up to that membrane's translation, like a wall
                 that can slide frictionlessly.

Only the standard library, so it runs with any python3.
"""
import argparse
import math
import os


def laplacian_neumann(m, h2_scale=1.0):
    """Entries (i, j, value), i >= j, of the graph Laplacian of an m x m grid
    (free edges: each node's diagonal is its number of neighbours)."""
    entries = []
    for r in range(m):
        for c in range(m):
            k = r * m + c
            neighbours = 0
            for dr, dc in ((-1, 0), (1, 0), (0, -1), (0, 1)):
                rr, cc = r + dr, c + dc
                if 0 <= rr < m and 0 <= cc < m:
                    neighbours += 1
                    kk = rr * m + cc
                    if kk < k:
                        entries.append((k, kk, -h2_scale))
            entries.append((k, k, neighbours * h2_scale))
    return entries


def laplacian_dirichlet(m):
    entries = []
    for r in range(m):
        for c in range(m):
            k = r * m + c
            if c > 0:
                entries.append((k, k - 1, -1.0))
            if r > 0:
                entries.append((k, k - m, -1.0))
            entries.append((k, k, 4.0))
    return entries


def write(directory, n, entries, b, constraints):
    os.makedirs(directory, exist_ok=True)
    with open(os.path.join(directory, "lcp_A.mtx"), "w") as f:
        f.write("%%MatrixMarket matrix coordinate real symmetric\n")
        f.write("%d %d %d\n" % (n, n, len(entries)))
        for i, j, v in sorted(entries, key=lambda e: (e[1], e[0])):
            f.write("%d %d %.17g\n" % (i + 1, j + 1, v))
    with open(os.path.join(directory, "lcp_b.txt"), "w") as f:
        for v in b:
            f.write("%.17g\n" % v)
    with open(os.path.join(directory, "lcp_constraints.txt"), "w") as f:
        for i, lower in constraints:
            f.write("%d %.17g\n" % (i + 1, lower))


def laplacian(m, directory):
    h = 1.0 / (m + 1)
    n = m * m
    b = [-10.0 * h * h] * n
    constraints = []
    for r in range(m):
        for c in range(m):
            x, y = (c + 1) * h, (r + 1) * h
            psi = 0.3 - 2.0 * ((x - 0.5) ** 2 + (y - 0.5) ** 2)
            constraints.append((r * m + c, psi))
    write(directory, n, laplacian_dirichlet(m), b, constraints)


def mixed(m, directory):
    h = 1.0 / (m - 1)
    block = m * m
    n = 2 * block
    entries = laplacian_neumann(m)
    entries += [(i + block, j + block, v) for i, j, v in laplacian_neumann(m)]
    b = [0.0] * n
    constraints = []
    for r in range(m):
        for c in range(m):
            x, y = c * h, r * h
            k = r * m + c
            # Membrane 1: weight plus a bump load; contacts on the left half,
            # on a dome-shaped support, so that only part of it touches.
            b[k] = -h * h * (1.0 + 4.0 * math.exp(-20.0 * ((x - 0.3) ** 2 +
                                                          (y - 0.5) ** 2)))
            if x < 0.5:
                constraints.append((k, -0.5 * ((x - 0.25) ** 2 + (y - 0.5) ** 2)))
            # Membrane 2: self-balanced load, no constraint. Mirror-
            # antisymmetric in x, so that it sums to zero exactly and b is in
            # the range of A (otherwise the energy is unbounded below).
            if 2 * c < m - 1:
                value = h * h * math.cos(math.pi * x) * math.cos(math.pi * y)
                b[block + k] = value
                b[block + r * m + (m - 1 - c)] = -value
    write(directory, n, entries, b, constraints)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("kind", choices=["laplacian", "mixed"])
    parser.add_argument("m", type=int, help="nodes per side")
    parser.add_argument("directory")
    args = parser.parse_args()
    if args.m < 2:
        parser.error("m must be at least 2")
    {"laplacian": laplacian, "mixed": mixed}[args.kind](args.m, args.directory)


if __name__ == "__main__":
    main()
