#!/usr/bin/python3
"""Read a plate run's VTU/PVD files with VTK's own XML reader (what ParaView
sees) and check them against summary.json. Prints one verdict per line.

Usage: /usr/bin/python3 read_plate_vtu.py RUN_DIRECTORY
(Debian's python3-vtk9 lives under /usr/bin/python3.)
"""
import json
import math
import os
import sys
import xml.etree.ElementTree as ElementTree

import vtk
from vtk.util.numpy_support import vtk_to_numpy
import numpy


def verdict(text, condition):
    print(f"{text}: {'yes' if condition else 'no'}")
    return condition


def read_vtu(file_name):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(file_name)
    reader.Update()
    grid = reader.GetOutput()
    points = vtk_to_numpy(grid.GetPoints().GetData()).astype(float)
    data = grid.GetPointData()
    fields = {
        data.GetArrayName(i): vtk_to_numpy(data.GetArray(i)).astype(float)
        for i in range(data.GetNumberOfArrays())
    }
    return grid, points, fields


def pvd_references(pvd_file, vtu_name):
    tree = ElementTree.parse(pvd_file)
    files = [d.get("file") for d in tree.iter("DataSet")]
    return files == [vtu_name]


def main(run_directory):
    summary = json.load(open(os.path.join(run_directory, "summary.json")))
    n1, n2 = summary["n1"], summary["n2"]
    L1, L2 = summary["length_x"], summary["length_y"]
    D, nu = summary["flexural_rigidity"], summary["poisson_ratio"]
    h1, h2 = L1 / n1, L2 / n2
    scale = max(abs(summary["min_deflection"]), 1e-300)

    for name in ("plate", "nodes"):
        verdict(f"{name}.pvd references {name}.vtu",
                pvd_references(os.path.join(run_directory, name + ".pvd"),
                               name + ".vtu"))

    # plate.vtu: the bicubic field sampled with subdivisions.
    grid, points, fields = read_vtu(os.path.join(run_directory, "plate.vtu"))
    expected = {"deflection": 1, "slope": 3, "obstacle": 1, "gap": 1,
                "bending_moment_xx": 1, "bending_moment_yy": 1,
                "bending_moment_xy": 1}
    verdict("plate.vtu has deflection, slope (3 components), obstacle, gap, "
            "bending_moment_xx/yy/xy",
            all(name in fields and
                (fields[name].ndim == 1 if size == 1 else
                 fields[name].shape[1] == size)
                for name, size in expected.items()))
    subdivisions = round(math.sqrt(grid.GetNumberOfCells() / (n1 * n2)))
    verdict("plate.vtu has one patch of s x s cells per element",
            grid.GetNumberOfCells() == n1 * n2 * subdivisions ** 2 and
            subdivisions > 1)
    verdict("all plate.vtu values are finite",
            all(numpy.isfinite(values).all() for values in fields.values()))

    x, y = points[:, 0], points[:, 1]
    centre = (numpy.abs(x - L1 / 2) < 1e-9 * L1) & (numpy.abs(y - L2 / 2) < 1e-9 * L2)
    verdict("plate.vtu: deflection at the centre equals the solver's "
            "(summary.json), relative 1e-6 (Float32)",
            centre.any() and numpy.all(
                numpy.abs(fields["deflection"][centre] -
                          summary["centre_deflection"]) <= 1e-6 * scale))
    verdict("plate.vtu: gap = deflection - obstacle at every point",
            numpy.all(numpy.abs(fields["gap"] - (fields["deflection"] -
                                                  fields["obstacle"]))
                      <= 1e-6 * scale))
    on_node = (numpy.abs(x / h1 - numpy.round(x / h1)) < 1e-6) & \
              (numpy.abs(y / h2 - numpy.round(y / h2)) < 1e-6)
    verdict("plate.vtu: gap >= -1e-12 at the mesh nodes",
            numpy.all(fields["gap"][on_node] >= -1e-12))
    edge = (numpy.abs(x) < 1e-9 * L1) & (numpy.abs(y - L2 / 2) < 1e-9 * L2)
    # Under a downward load the plate leaves a clamped edge curving downwards
    # (w_xx < 0, w_yy = 0 along the edge), so M_xx = -D w_xx > 0 there.
    verdict("plate.vtu: M_xx > 0 at the middle of the clamped edge x = 0 "
            "(the plate curves downwards there; M = -D (w_xx + nu w_yy))",
            edge.any() and numpy.all(fields["bending_moment_xx"][edge] > 0))

    # nodes.vtu: the LCP at the mesh nodes.
    grid_n, points_n, nodes = read_vtu(os.path.join(run_directory, "nodes.vtu"))
    verdict("nodes.vtu has deflection, slope_x, slope_y, twist, obstacle, gap, "
            "contact, contact_force",
            all(name in nodes for name in ("deflection", "slope_x", "slope_y",
                                           "twist", "obstacle", "gap",
                                           "contact", "contact_force")))
    keys = numpy.round(points_n[:, :2] / [h1, h2]).astype(int)
    _, unique = numpy.unique(keys, axis=0, return_index=True)
    # Each node once (a review: a point per node and cell repeated the
    # contact force four times in ParaView's sums), as a vertex cell.
    verdict("nodes.vtu: its points are the (n1+1)(n2+1) mesh nodes, each once, "
            "each a vertex cell",
            len(unique) == (n1 + 1) * (n2 + 1) and
            len(points_n) == len(unique) and
            grid_n.GetNumberOfCells() == len(unique) and
            all(grid_n.GetCellType(c) == vtk.VTK_VERTEX
                for c in range(grid_n.GetNumberOfCells())) and
            numpy.all(numpy.abs(points_n[:, :2] - keys * [h1, h2]) < 1e-9 * L1))
    contact = nodes["contact"][unique]
    gap = nodes["gap"][unique]
    force = nodes["contact_force"][unique]
    verdict("nodes.vtu: contact is 0 or 1 everywhere",
            numpy.all((nodes["contact"] == 0) | (nodes["contact"] == 1)))
    verdict("nodes.vtu: number of nodes in contact = n_contact of summary.json",
            int(contact.sum()) == summary["n_contact"])
    verdict("nodes.vtu: gap >= -1e-12 at every node",
            numpy.all(nodes["gap"] >= -1e-12))
    verdict("nodes.vtu: gap = 0 where contact = 1",
            numpy.all(numpy.abs(gap[contact == 1]) <= 1e-12))
    largest_force = max(numpy.abs(force).max(), 1e-300)
    verdict("nodes.vtu: contact force > 0 where contact = 1, ~0 elsewhere",
            numpy.all(force[contact == 1] > 0) and
            numpy.all(numpy.abs(force[contact == 0]) <= 1e-8 * largest_force))
    verdict("nodes.vtu: smallest deflection = min_deflection of summary.json",
            abs(nodes["deflection"].min() - summary["min_deflection"])
            <= 1e-6 * scale)
    node_centre = (numpy.abs(points_n[:, 0] - L1 / 2) < 1e-9 * L1) & \
                  (numpy.abs(points_n[:, 1] - L2 / 2) < 1e-9 * L2)
    verdict("nodes.vtu: deflection at the centre node equals the solver's",
            node_centre.any() and numpy.all(
                numpy.abs(nodes["deflection"][node_centre] -
                          summary["centre_deflection"]) <= 1e-6 * scale))
    boundary = (numpy.abs(points_n[:, 0]) < 1e-9) | \
               (numpy.abs(points_n[:, 0] - L1) < 1e-9 * L1) | \
               (numpy.abs(points_n[:, 1]) < 1e-9) | \
               (numpy.abs(points_n[:, 1] - L2) < 1e-9 * L2)
    verdict("nodes.vtu: w = w_x = w_y = 0 at boundary nodes (clamped)",
            numpy.all(nodes["deflection"][boundary] == 0) and
            numpy.all(nodes["slope_x"][boundary] == 0) and
            numpy.all(nodes["slope_y"][boundary] == 0))

    # The two files agree at the nodes: deflection, and M_xy = -D (1 - nu) w_xy
    # (w_xy is a nodal DOF, so every cell has the same value there).
    node_of = {tuple(k): i for i, k in enumerate(keys)}
    plate_keys = numpy.round(points[on_node, :2] / [h1, h2]).astype(int)
    matched = [node_of[tuple(k)] for k in plate_keys]
    twist_scale = max(numpy.abs(nodes["twist"]).max() * D * (1 - nu), 1e-300)
    verdict("deflection in plate.vtu equals nodes.vtu at every node",
            numpy.all(numpy.abs(fields["deflection"][on_node] -
                                nodes["deflection"][matched]) <= 1e-6 * scale))
    slope_scale = max(numpy.abs(nodes["slope_x"]).max(),
                      numpy.abs(nodes["slope_y"]).max(), 1e-300)
    verdict("slope in plate.vtu equals (slope_x, slope_y) of nodes.vtu at "
            "every node (the FE_Q(3) field has the BFS nodal derivatives)",
            numpy.all(numpy.abs(fields["slope"][on_node, 0] -
                                nodes["slope_x"][matched]) <= 1e-5 * slope_scale)
            and numpy.all(numpy.abs(fields["slope"][on_node, 1] -
                                    nodes["slope_y"][matched])
                          <= 1e-5 * slope_scale))
    verdict("bending_moment_xy in plate.vtu equals -D (1 - nu) twist of "
            "nodes.vtu at every node",
            numpy.all(numpy.abs(fields["bending_moment_xy"][on_node] +
                                D * (1 - nu) * nodes["twist"][matched])
                      <= 1e-5 * twist_scale))


if __name__ == "__main__":
    main(sys.argv[1])
