"""Render the README pictures from the program's VTU output with ParaView.

Run by render.sh as

    xvfb-run -a pvpython render.py OUTPUT_DIR PICTURE_DIR

where OUTPUT_DIR holds the runs wall_stack_bond, wall_running_bond,
wall_laminae, plate_psi3 and masonry_arch, masonry_window, masonry_wall_3d,
masonry_barrel_vault (made from the .prm files beside this script) and
PICTURE_DIR receives wall_*.png, plate_psi3.png and masonry_*.png. Titles
take their numbers (m, g, contact count, ...) from each run's summary.json,
so they always describe the data drawn.
"""
import json
import os
import re
import sys

# The filter and source constructors (Clip, Glyph, PVDReader, ...) are made
# at import time from ParaView's proxy definitions, hence the star import.
from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import (VTK_HEXAHEDRON, VTK_QUAD,
                                           VTK_QUADRATIC_TRIANGLE,
                                           vtkCellArray, vtkPolyData)
import numpy

WIDTH, HEIGHT = 1000, 700

# Displacement magnification per wall. The settlement g = H/2 moves blocks as
# bodies by 0.05 (5 % of the wall), which true scale shows, and a larger
# factor would push the settled blocks through the drawn ground. The laminae
# bridge the settlement instead: they only bend (by about 0.002), so that
# picture is magnified 10 times, still short of the ground at -g.
WALLS = {
    "stack_bond": ("stack bond", 1),
    "running_bond": ("running bond", 1),
    "laminae": ("laminae", 10),
}
# One von Mises range for all walls so that the colours compare, on a log
# scale: the column stress of the settled stack bond is below 0.6, while
# bricks resting on an edge carry singular corner stresses up to ~35.
VON_MISES_RANGE = (0.02, 20.0)

# The plate deflects by less than 0.4 mm on a 100 mm span.
PLATE_MAGNIFICATION = 50

BLACK = [0.0, 0.0, 0.0]


def new_view():
    view = CreateView("RenderView")
    view.ViewSize = [WIDTH, HEIGHT]
    view.OrientationAxesVisibility = 0
    # ParaView 5.11 takes the background from its palette unless told not to.
    view.UseColorPaletteForBackground = 0
    view.Background = [1.0, 1.0, 1.0]
    SetActiveView(view)
    return view


def solid(display, colour):
    """Draw a display in one colour instead of colouring by an array."""
    display.ColorArrayName = ["POINTS", ""]
    display.AmbientColor = display.DiffuseColor = colour


def add_text(view, text, location, size, bold=False):
    source = Text(Text=text)
    display = Show(source, view)
    if isinstance(location, str):
        display.WindowLocation = location
    else:  # a position in the view, (0, 0) lower left to (1, 1)
        display.WindowLocation = "Any Location"
        display.Position = location
    display.FontSize = size
    display.Color = BLACK
    display.Bold = int(bold)
    return display


def add_label(view, text, position, size=14):
    """Text anchored at a point of the scene."""
    source = Text(Text=text)
    display = Show(source, view)
    display.TextPropMode = "Billboard 3D Text"
    display.BillboardPosition = position
    display.FontSize = size
    display.Color = BLACK
    return display


def style_scalar_bar(bar, title, view, position=(0.84, 0.18)):
    bar.Title = title
    bar.ComponentTitle = ""
    bar.TitleColor = BLACK
    bar.LabelColor = BLACK
    bar.TitleFontSize = 16
    bar.LabelFontSize = 14
    bar.HorizontalTitle = 1
    bar.RangeLabelFormat = "%-#.3g"
    bar.WindowLocation = "Any Location"
    bar.Orientation = "Vertical"
    bar.Position = list(position)
    bar.ScalarBarLength = 0.55
    bar.Visibility = 1


def read_parameter(run_dir, name, default=None):
    """A value from the run's copy of its parameter file (default if the
    file does not set it)."""
    with open(os.path.join(run_dir, "parameters.prm")) as prm:
        match = re.search(r"^\s*set\s+" + re.escape(name) + r"\s*=\s*(.+?)\s*$",
                          prm.read(), re.MULTILINE)
    return match.group(1) if match else default


def merged_nodes(reader):
    """The run's grid with its points merged into nodes of the blocks.

    deal.II writes each cell with points of its own; points are merged here
    by (block, position) in the reference configuration, so that two blocks
    meeting in a joint keep nodes of their own. Returns the grid, its cells
    (a row of point indices per cell), their VTK cell type, the node of
    each point and the first point of each node.
    """
    grid = servermanager.Fetch(reader)
    if grid.IsA("vtkMultiBlockDataSet"):
        grid = grid.GetBlock(0)
    points = vtk_to_numpy(grid.GetPoints().GetData()).astype(float)
    block = vtk_to_numpy(grid.GetCellData().GetArray("block_id"))
    cells = vtk_to_numpy(grid.GetCells().GetConnectivityArray())
    types = set(vtk_to_numpy(grid.GetCellTypesArray()).tolist())
    if len(types) != 1:
        raise RuntimeError("unexpected cell types %s" % types)
    cell_type = types.pop()
    cells = cells.reshape(len(block), -1)

    # One id per (block, reference position).
    cell_of_point = numpy.empty(len(points), dtype=numpy.int64)
    cell_of_point[cells.ravel()] = numpy.repeat(numpy.arange(len(cells)),
                                                cells.shape[1])
    keys = numpy.column_stack([block[cell_of_point],
                               numpy.round(points * 1e7).astype(numpy.int64)])
    _, first, node = numpy.unique(keys, axis=0, return_index=True,
                                  return_inverse=True)
    return grid, cells, cell_type, node.ravel(), first


def poly_producer(coordinates, cells, arrays):
    """A ParaView source of a vtkPolyData: points, lines (rows of 2 point
    ids) or quadrilaterals (rows of 4), and named point arrays."""
    poly = vtkPolyData()
    poly.SetPoints(vtkPoints())
    poly.GetPoints().SetData(numpy_to_vtk(numpy.ascontiguousarray(
        coordinates, dtype=float), deep=True))
    connectivity = vtkCellArray()
    for cell in cells:
        connectivity.InsertNextCell(len(cell))
        for point in cell:
            connectivity.InsertCellPoint(int(point))
    if cells.shape[1] == 2:
        poly.SetLines(connectivity)
    else:
        poly.SetPolys(connectivity)
    for name, values in arrays.items():
        array = numpy_to_vtk(numpy.ascontiguousarray(values, dtype=float),
                             deep=True)
        array.SetName(name)
        poly.GetPointData().AddArray(array)
    producer = TrivialProducer()
    producer.GetClientSideObject().SetOutput(poly)
    producer.UpdatePipeline()
    return producer


def block_outlines(reader):
    """The outlines of the blocks of a 2D run as lines carrying the
    displacement.

    A cell edge belongs to a block's outline exactly when no other cell of
    the same block has it. Handles Q2 output (linear quadrilaterals) and
    P2 output (quadratic triangles).
    """
    grid, cells, cell_type, node, first = merged_nodes(reader)
    displacement = vtk_to_numpy(grid.GetPointData().GetArray("displacement"))
    if cell_type == VTK_QUAD:
        edges = [(0, 1), (1, 2), (2, 3), (3, 0)]
    elif cell_type == VTK_QUADRATIC_TRIANGLE:
        edges = [(0, 3), (3, 1), (1, 4), (4, 2), (2, 5), (5, 0)]
    else:
        raise RuntimeError("unexpected cell type %d" % cell_type)
    pairs = numpy.concatenate([numpy.sort(node[cells[:, [a, b]]], axis=1)
                               for a, b in edges])
    unique_pairs, count = numpy.unique(pairs, axis=0, return_counts=True)
    coordinates = vtk_to_numpy(grid.GetPoints().GetData())[first].astype(
        float)
    coordinates[:, 2] = 0.0
    return poly_producer(coordinates, unique_pairs[count == 1],
                         {"displacement": displacement[first]})


# The faces of a VTK hexahedron, each ordered so that its normal points out.
HEXAHEDRON_FACES = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5),
                    (2, 3, 7, 6), (3, 0, 4, 7)]


def block_surfaces(reader, feature_angle=30.0):
    """The blocks of a 3D run as surfaces and edges.

    A cell face belongs to a block's surface exactly when no other cell of
    the same block has it; the block's edges are where two faces of its
    surface meet at more than feature_angle degrees (in the reference
    configuration, so curved voussoirs show only their corners). The points
    carry the displacement and the von Mises stress averaged over the cells
    at a node (the program writes it cell by cell).
    Returns the two sources (surfaces, edges).
    """
    grid, cells, cell_type, node, first = merged_nodes(reader)
    if cell_type != VTK_HEXAHEDRON:
        raise RuntimeError("unexpected cell type %d" % cell_type)
    data = grid.GetPointData()
    displacement = vtk_to_numpy(data.GetArray("displacement"))[first]
    von_mises = (numpy.bincount(node, vtk_to_numpy(data.GetArray("von_mises")))
                 / numpy.bincount(node))
    coordinates = vtk_to_numpy(grid.GetPoints().GetData())[first].astype(
        float)

    faces = numpy.concatenate([node[cells[:, list(f)]]
                               for f in HEXAHEDRON_FACES])
    _, index, count = numpy.unique(numpy.sort(faces, axis=1), axis=0,
                                   return_index=True, return_counts=True)
    faces = faces[index[count == 1]]
    corner = coordinates[faces]
    normal = numpy.cross(corner[:, 2] - corner[:, 0],
                         corner[:, 3] - corner[:, 1])
    normal /= numpy.linalg.norm(normal, axis=1)[:, None]

    # Each edge of a block's closed surface lies on exactly two faces.
    edges = numpy.sort(numpy.concatenate(
        [faces[:, [a, (a + 1) % 4]] for a in range(4)]), axis=1)
    face_of_edge = numpy.tile(numpy.arange(len(faces)), 4)
    _, inverse, count = numpy.unique(edges, axis=0, return_inverse=True,
                                     return_counts=True)
    inverse = inverse.ravel()
    if not numpy.all(count == 2):
        raise RuntimeError("a block's surface is not closed")
    order = numpy.argsort(inverse, kind="stable")
    first_face = face_of_edge[order[0::2]]
    second_face = face_of_edge[order[1::2]]
    cosine = numpy.abs(numpy.sum(normal[first_face] * normal[second_face],
                                 axis=1))
    feature = cosine < numpy.cos(numpy.radians(feature_angle))
    feature_edges = edges[order[0::2]][feature]

    arrays = {"displacement": displacement, "von_mises": von_mises}
    return (poly_producer(coordinates, faces, arrays),
            poly_producer(coordinates, feature_edges, arrays))


def render_wall(output_dir, picture_dir, key):
    geometry, factor = WALLS[key]
    run_dir = os.path.join(output_dir, "wall_" + key)
    summary = json.load(open(os.path.join(run_dir, "summary.json")))
    gap = summary["gap"]
    signorini = float(read_parameter(run_dir, "Signorini part of the base"))

    view = new_view()
    reader = PVDReader(FileName=os.path.join(run_dir, "solution.pvd"))
    warp = WarpByVector(Input=reader, Vectors=["POINTS", "displacement"],
                        ScaleFactor=factor)
    wall = Show(warp, view)
    wall.Representation = "Surface"
    ColorBy(wall, ("POINTS", "von_mises"))
    # Log scale first: the preset's points are then spread in log space.
    lut = GetColorTransferFunction("von_mises")
    lut.AutomaticRescaleRangeMode = "Never"
    lut.UseLogScale = 1
    lut.ApplyPreset("Turbo", True)
    lut.RescaleTransferFunction(*VON_MISES_RANGE)
    style_scalar_bar(GetScalarBar(lut, view), "von Mises stress", view)

    # Block outlines: closed joints show as one line, open joints as a white
    # slit between two lines. Feature Edges alone would outline every cell,
    # since deal.II writes each cell with points of its own.
    outlines = WarpByVector(Input=block_outlines(reader),
                            Vectors=["POINTS", "displacement"],
                            ScaleFactor=factor)
    lines = Show(outlines, view)
    solid(lines, [0.1, 0.1, 0.1])
    lines.LineWidth = 1.5

    # The rigid ground, not magnified: settled by g under the Signorini
    # part [0, s] of the base, at y = 0 under the rest.
    depth = 0.06
    for x0, x1, top in ((0.0, signorini, -gap), (signorini, 1.0, 0.0)):
        ground = Plane(Origin=[x0, top - depth, -0.001],
                       Point1=[x1, top - depth, -0.001],
                       Point2=[x0, top, -0.001])
        display = Show(ground, view)
        solid(display, [0.62, 0.58, 0.52])
    add_label(view, "ground settled by g = %g" % gap,
              [0.02, -gap - 0.045, 0.01], 15)
    add_label(view, "fixed ground", [signorini + 0.02, -0.045, 0.01], 15)

    # (No "|" in texts: ParaView's text actor takes it as a table column.)
    add_text(view, "%s wall, m = %d, on ground sunk by g = %g under x < %g"
             % (geometry.capitalize(), summary["m"], gap, signorini),
             "Upper Center", 22, bold=True)
    add_text(view, "true scale\n(displacement x 1)" if factor == 1 else
             "displacement\nmagnified x %g" % factor,
             (0.80, 0.83), 18, bold=True)
    add_text(view,
             "%d blocks of height H = %g under self-weight, frictionless "
             "joints; g = %gH\n"
             "colour: von Mises stress (log scale); block outlines in black, "
             "open joints as white slits; largest displacement %.3g"
             % (summary["n_blocks"], summary["block_height"],
                summary["relative_gap"], summary["max_displacement"]),
             "Lower Center", 15)

    view.InteractionMode = "2D"
    view.CameraParallelProjection = 1
    view.CameraPosition = [0.52, 0.44, 5.0]
    view.CameraFocalPoint = [0.52, 0.44, 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.CameraParallelScale = 0.66
    Render(view)
    SaveScreenshot(os.path.join(picture_dir, "wall_%s.png" % key), view,
                   ImageResolution=[WIDTH, HEIGHT], CompressionLevel="9")


def render_plate(output_dir, picture_dir):
    run_dir = os.path.join(output_dir, "plate_psi3")
    summary = json.load(open(os.path.join(run_dir, "summary.json")))
    k = PLATE_MAGNIFICATION
    view = new_view()

    plate = PVDReader(FileName=os.path.join(run_dir, "plate.pvd"))
    nodes = PVDReader(FileName=os.path.join(run_dir, "nodes.pvd"))

    # The obstacle, sampled by the program at the same points (plate.vtu's
    # "obstacle"), lifted by the same magnification as the plate.
    obstacle = WarpByScalar(Input=plate, Scalars=["POINTS", "obstacle"],
                            ScaleFactor=k, Normal=[0, 0, 1], UseNormal=1)
    obstacle_display = Show(obstacle, view)
    solid(obstacle_display, [0.72, 0.72, 0.72])

    # The plate's back half only, so the obstacle shows in front of it; the
    # cut at y = 50 gives the plate's profile over the obstacle.
    deflected = WarpByScalar(Input=plate, Scalars=["POINTS", "deflection"],
                             ScaleFactor=k, Normal=[0, 0, 1], UseNormal=1)
    back = Clip(Input=deflected, ClipType="Plane", Invert=0)
    back.ClipType.Origin = [50.0, 50.0, 0.0]
    back.ClipType.Normal = [0.0, 1.0, 0.0]
    back_display = Show(back, view)
    solid(back_display, [0.45, 0.62, 0.85])
    back_display.Specular = 0.3
    profile = Slice(Input=deflected, SliceType="Plane")
    profile.SliceType.Origin = [50.0, 50.0, 0.0]
    profile.SliceType.Normal = [0.0, 1.0, 0.0]
    profile_display = Show(profile, view)
    solid(profile_display, [0.1, 0.2, 0.5])
    profile_display.LineWidth = 3.0

    # The contact set: nodes.vtu has one point per node and cell (merged
    # here); spheres scaled by the 0/1 flag vanish off the contact set.
    merged = CleantoGrid(Input=nodes)
    lifted = WarpByScalar(Input=merged, Scalars=["POINTS", "deflection"],
                          ScaleFactor=k, Normal=[0, 0, 1], UseNormal=1)
    spheres = Glyph(Input=lifted, GlyphType="Sphere",
                    ScaleArray=["POINTS", "contact"], ScaleFactor=1.6,
                    GlyphMode="All Points",
                    OrientationArray=["POINTS", "No orientation array"])
    sphere_display = Show(spheres, view)
    ColorBy(sphere_display, ("POINTS", "contact_force"))
    # The force is zero off the contact set up to round-off (-2e-11 here);
    # the range starts at 0. It peaks on the rim of each contact band.
    lut = GetColorTransferFunction("contact_force")
    lut.AutomaticRescaleRangeMode = "Never"
    lut.ApplyPreset("Inferno (matplotlib)", True)
    force = spheres.PointData["contact_force"].GetRange()
    lut.RescaleTransferFunction(0.0, force[1])
    style_scalar_bar(GetScalarBar(lut, view),
                     "contact force (kg)\nat a contact node", view,
                     position=(0.84, 0.14))

    add_text(view,
             "%s %s plate on the obstacle %s, load %s = %s kg/mm\u00b2"
             % (summary["boundary_condition"].capitalize(),
                summary["material"], summary["obstacle"], summary["force"],
                summary["force_expression"]),
             "Upper Center", 22, bold=True)
    add_text(view, "deflection and\nobstacle\nmagnified x %d" % k,
             (0.80, 0.81), 18, bold=True)
    add_text(view,
             "%g x %g x %g mm, %d x %d Bogner-Fox-Schmit elements: %d of %d "
             "nodes in contact (spheres), smallest deflection %.3f mm\n"
             "plate (blue) cut away in front of y = 50 mm to show the "
             "obstacle (grey); dark blue line: the plate's section there"
             % (summary["length_x"], summary["length_y"], summary["thickness"],
                summary["n1"], summary["n2"], summary["n_contact"],
                summary["n_bounds"], summary["min_deflection"]),
             "Lower Center", 15)

    view.CameraParallelProjection = 0
    view.CameraFocalPoint = [50.0, 50.0, -20.0]
    view.CameraPosition = [50.0 - 100.0, 50.0 - 185.0, 95.0]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.CameraViewAngle = 30
    Render(view)
    SaveScreenshot(os.path.join(picture_dir, "plate_psi3.png"), view,
                   ImageResolution=[WIDTH, HEIGHT], CompressionLevel="9")


# --- the masonry examples of prm/ -------------------------------------------
#
# Each is drawn deformed, its displacement magnified ("factor") so that
# opened joints and settled blocks show, with its obstacles (the ground, the
# lowered centring) moved by their gap along the support's normal, magnified
# by the same factor: a block resting on an obstacle touches it in the
# picture too. The gap is the run's 'Signorini gap' expression, so the drawn
# obstacles follow the parameter file.
#
#   ground    stretches (x0, x1, settled) of the ground under the base,
#             settled by the gap or (rollers) not
#   z         the ground's and the centring's extent along z (3D)
#   centring  the centring under the intrados (the unit circle)
#   depth     the drawn thickness of the ground (2D)
#   range     the von Mises colour range (log scale)
#   camera    2D: (centre, parallel scale); 3D: (focal point, position)
#
# Magnifications: the arch's and the vault's displacements are about 0.02
# on spans of 4, the window wall's 0.03 on 12, hence x 20; the 3D wall's
# settled bricks drop by up to 0.05 on a wall of 1, which x 2 shows without
# pushing them through more than one course.
MASONRY = {
    "masonry_arch": {
        "factor": 20,
        "title": "Arch of 16 voussoirs in its spandrel wall: "
                 "centring lowered, right springing settled",
        "ground": [(-2.0, 0.0, False), (0.0, 2.0, True)],
        "centring": True,
        "depth": 0.25,
        "range": (0.02, 20.0),
        "camera": ((0.42, 0.8), 2.0),
    },
    "masonry_window": {
        "factor": 20,
        "title": "Running-bond wall with a window and a stiff lintel "
                 "on a parabolic settlement",
        "ground": [(0.0, 12.0, True)],
        "centring": False,
        "depth": 0.8,
        "range": (0.2, 40.0),
        "camera": ((6.9, 4.4), 7.0),
    },
    "masonry_wall_3d": {
        "factor": 2,
        "title": "3D running-bond wall of two leaves on a settlement "
                 "varying along and across it",
        "ground": [(0.0, 0.5, True), (0.5, 1.0, False)],
        "z": (-0.1, 0.3),
        "centring": False,
        "range": (0.02, 20.0),
        "camera": ((0.55, 0.4, 0.1), (-1.0, 1.05, 2.85)),
    },
    "masonry_barrel_vault": {
        "factor": 20,
        "title": "Barrel-vault segment of four rings: centring lowered, "
                 "ground settling more towards the back",
        "ground": [(-2.0, 0.0, False), (0.0, 2.0, True)],
        "z": (0.0, 2.0),
        "centring": True,
        "range": (0.02, 20.0),
        "camera": ((0.35, 0.7, 1.0), (6.4, 5.0, 9.2)),
    },
}

GROUND = [0.62, 0.58, 0.52]
CENTRING = [0.80, 0.68, 0.50]


def gap_function(run_dir, summary):
    """The run's 'Signorini gap' as a numpy function of x, y, z.

    muparser's syntax differs from Python's only in '^' and if(c, a, b)
    among what the examples use."""
    expression = read_parameter(run_dir, "Signorini gap")
    python = expression.replace("^", "**").replace("if(", "where(")
    names = {"max": numpy.maximum, "min": numpy.minimum, "where": numpy.where,
             "g": summary["gap"], "H": summary["block_height"]}
    s = read_parameter(run_dir, "Signorini part of the base")
    if s is not None:
        names["s"] = float(s)

    def gap(x, y, z):
        value = eval(python, {"__builtins__": {}},
                     dict(names, x=x, y=y, z=z))
        return numpy.broadcast_to(value, numpy.shape(x)).astype(float)
    return gap


def quad_grid(points):
    """A source of the quadrilaterals of a structured grid of points
    (an array ni x nj x 3)."""
    ni, nj = points.shape[:2]
    ids = numpy.arange(ni * nj).reshape(ni, nj)
    quads = numpy.column_stack([ids[:-1, :-1].ravel(), ids[1:, :-1].ravel(),
                                ids[1:, 1:].ravel(), ids[:-1, 1:].ravel()])
    return poly_producer(points.reshape(-1, 3), quads, {})


def obstacles(spec, gap, dim, factor):
    """The ground and the centring, moved by factor x gap along the
    support's normal. In 2D bands of some depth behind the wall (z < 0), in
    3D sheets."""
    sources = []
    n = 81
    z = numpy.linspace(*spec["z"], 21) if dim == 3 else numpy.zeros(1)
    for x0, x1, settled in spec["ground"]:
        x, zz = numpy.meshgrid(numpy.linspace(x0, x1, n), z, indexing="ij")
        drop = factor * gap(x, 0 * x, zz) if settled else 0 * x
        if dim == 2:
            top = numpy.stack([x[:, 0], -drop[:, 0], -0.002 + 0 * x[:, 0]], 1)
            bottom = top - [0.0, spec["depth"], 0.0]
            points = numpy.stack([top, bottom], axis=1)
        else:
            points = numpy.stack([x, -drop, zz], axis=2)
        sources.append((quad_grid(points), GROUND))
    if spec["centring"]:
        angle = numpy.linspace(0.0, numpy.pi, n)
        ring = numpy.stack([numpy.cos(angle), numpy.sin(angle)], 1)
        if dim == 2:
            drop = factor * gap(ring[:, 0], ring[:, 1], 0 * angle)
            edge = ring * (1.0 - drop)[:, None]
            inner = ring * (1.0 - drop - 0.12)[:, None]
            points = numpy.stack([edge, inner], axis=1)
            points = numpy.concatenate(
                [points, numpy.full(points.shape[:2] + (1,), -0.002)], axis=2)
        else:
            a, zz = numpy.meshgrid(angle, z, indexing="ij")
            x, y = numpy.cos(a), numpy.sin(a)
            drop = factor * gap(x, y, zz)
            points = numpy.stack([x * (1 - drop), y * (1 - drop), zz], axis=2)
        sources.append((quad_grid(points), CENTRING))
    return sources


def von_mises_colours(display, view, stress_range, position=(0.86, 0.2)):
    ColorBy(display, ("POINTS", "von_mises"))
    lut = GetColorTransferFunction("von_mises")
    lut.AutomaticRescaleRangeMode = "Never"
    lut.UseLogScale = 1
    lut.ApplyPreset("Turbo", True)
    lut.RescaleTransferFunction(*stress_range)
    style_scalar_bar(GetScalarBar(lut, view), "von Mises\nstress", view,
                     position=position)


def render_masonry(output_dir, picture_dir, name):
    spec = MASONRY[name]
    factor = spec["factor"]
    run_dir = os.path.join(output_dir, name)
    summary = json.load(open(os.path.join(run_dir, "summary.json")))
    dim = summary["dimension"]
    gap = gap_function(run_dir, summary)

    view = new_view()
    reader = PVDReader(FileName=os.path.join(run_dir, "solution.pvd"))
    if dim == 2:
        warp = WarpByVector(Input=reader, Vectors=["POINTS", "displacement"],
                            ScaleFactor=factor)
        blocks = Show(warp, view)
        outline_source = block_outlines(reader)
    else:
        surface_source, outline_source = block_surfaces(reader)
        warp = WarpByVector(Input=surface_source,
                            Vectors=["POINTS", "displacement"],
                            ScaleFactor=factor)
        blocks = Show(warp, view)
    blocks.Representation = "Surface"
    von_mises_colours(blocks, view, spec["range"])
    outlines = WarpByVector(Input=outline_source,
                            Vectors=["POINTS", "displacement"],
                            ScaleFactor=factor)
    lines = Show(outlines, view)
    solid(lines, [0.1, 0.1, 0.1])
    lines.LineWidth = 1.5
    for source, colour in obstacles(spec, gap, dim, factor):
        display = Show(source, view)
        solid(display, colour)

    add_text(view, spec["title"], "Upper Center", 21,
             bold=True)
    add_text(view, "true scale\n(displacement x 1)" if factor == 1 else
             "displacement\nmagnified x %g" % factor,
             (0.80, 0.83), 18, bold=True)
    add_text(view,
             "%d blocks, frictionless joints: %d of %d contacts closed; "
             "largest displacement %.3g\n"
             "colour: von Mises stress (log scale); block outlines in black; "
             "%s (brown) moved by %s gap x %g"
             % (summary["n_blocks"], summary["n_closed_contacts"],
                summary["n_constraints"], summary["max_displacement"],
                "ground and centring" if spec["centring"] else "ground",
                "their" if spec["centring"] else "its", factor),
             "Lower Center", 15)

    if dim == 2:
        (x, y), scale = spec["camera"]
        view.InteractionMode = "2D"
        view.CameraParallelProjection = 1
        view.CameraPosition = [x, y, 5.0]
        view.CameraFocalPoint = [x, y, 0.0]
        view.CameraViewUp = [0.0, 1.0, 0.0]
        view.CameraParallelScale = scale
    else:
        focus, position = spec["camera"]
        view.CameraParallelProjection = 0
        view.CameraFocalPoint = list(focus)
        view.CameraPosition = list(position)
        view.CameraViewUp = [0.0, 1.0, 0.0]
        view.CameraViewAngle = 30
    Render(view)
    SaveScreenshot(os.path.join(picture_dir, name + ".png"), view,
                   ImageResolution=[WIDTH, HEIGHT], CompressionLevel="9")


def main():
    output_dir, picture_dir = sys.argv[1], sys.argv[2]
    os.makedirs(picture_dir, exist_ok=True)
    for key in WALLS:
        render_wall(output_dir, picture_dir, key)
    render_plate(output_dir, picture_dir)
    for name in MASONRY:
        render_masonry(output_dir, picture_dir, name)


if __name__ == "__main__":
    main()
