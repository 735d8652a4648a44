"""Render the README pictures from the program's VTU output with ParaView.

Run by render.sh as

    xvfb-run -a pvpython render.py OUTPUT_DIR PICTURE_DIR

where OUTPUT_DIR holds the runs wall_stack_bond, wall_running_bond,
wall_laminae and plate_psi3 (made from the .prm files beside this script)
and PICTURE_DIR receives wall_*.png and plate_psi3.png. Titles take their
numbers (m, g, contact count, ...) from each run's summary.json, so they
always describe the data drawn.
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
from vtkmodules.vtkCommonDataModel import (VTK_QUAD, VTK_QUADRATIC_TRIANGLE,
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


def read_parameter(run_dir, name):
    """A value from the run's copy of its parameter file."""
    with open(os.path.join(run_dir, "parameters.prm")) as prm:
        match = re.search(r"^\s*set\s+" + re.escape(name) + r"\s*=\s*(.+?)\s*$",
                          prm.read(), re.MULTILINE)
    return match.group(1)


def block_outlines(reader):
    """The outlines of the blocks as lines carrying the displacement.

    Points are merged by (block, position) in the reference configuration,
    so a cell edge belongs to a block's outline exactly when no other cell
    of the same block has it. Handles Q2 output (linear quadrilaterals) and
    P2 output (quadratic triangles).
    """
    grid = servermanager.Fetch(reader)
    if grid.IsA("vtkMultiBlockDataSet"):
        grid = grid.GetBlock(0)
    points = vtk_to_numpy(grid.GetPoints().GetData())[:, :2].astype(float)
    displacement = vtk_to_numpy(grid.GetPointData().GetArray("displacement"))
    block = vtk_to_numpy(grid.GetCellData().GetArray("block_id"))
    cells = vtk_to_numpy(grid.GetCells().GetConnectivityArray())
    types = set(vtk_to_numpy(grid.GetCellTypesArray()).tolist())
    if types == {VTK_QUAD}:
        cells = cells.reshape(-1, 4)
        edges = [(0, 1), (1, 2), (2, 3), (3, 0)]
    elif types == {VTK_QUADRATIC_TRIANGLE}:
        cells = cells.reshape(-1, 6)
        edges = [(0, 3), (3, 1), (1, 4), (4, 2), (2, 5), (5, 0)]
    else:
        raise RuntimeError("unexpected cell types %s" % types)

    # One id per (block, reference position).
    cell_of_point = numpy.empty(len(points), dtype=numpy.int64)
    cell_of_point[cells.ravel()] = numpy.repeat(numpy.arange(len(cells)),
                                                cells.shape[1])
    keys = numpy.column_stack([block[cell_of_point],
                               numpy.round(points * 1e7).astype(numpy.int64)])
    _, first, node = numpy.unique(keys, axis=0, return_index=True,
                                  return_inverse=True)
    node = node.ravel()
    pairs = numpy.concatenate([numpy.sort(node[cells[:, [a, b]]], axis=1)
                               for a, b in edges])
    unique_pairs, count = numpy.unique(pairs, axis=0, return_counts=True)
    outline = unique_pairs[count == 1]

    poly = vtkPolyData()
    coordinates = numpy.zeros((len(first), 3))
    coordinates[:, :2] = points[first]
    poly.SetPoints(vtkPoints())
    poly.GetPoints().SetData(numpy_to_vtk(coordinates, deep=True))
    lines = vtkCellArray()
    for a, b in outline:
        lines.InsertNextCell(2)
        lines.InsertCellPoint(int(a))
        lines.InsertCellPoint(int(b))
    poly.SetLines(lines)
    vector = numpy_to_vtk(displacement[first].astype(float), deep=True)
    vector.SetName("displacement")
    poly.GetPointData().AddArray(vector)

    producer = TrivialProducer()
    producer.GetClientSideObject().SetOutput(poly)
    producer.UpdatePipeline()
    return producer


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


def main():
    output_dir, picture_dir = sys.argv[1], sys.argv[2]
    os.makedirs(picture_dir, exist_ok=True)
    for key in WALLS:
        render_wall(output_dir, picture_dir, key)
    render_plate(output_dir, picture_dir)


if __name__ == "__main__":
    main()
