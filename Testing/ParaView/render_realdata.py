"""Renders real data in the stylized view, split across the ranks, for test_realdata_mpi.py.

    mpiexec -n N pvbatch-stylize render_realdata.py OUTPUT_PREFIX DATA_DIR

Two datasets of the real-data set (the bunny read by the plugin's Stylize Checked Reader), each
through ParaView's Redistribute DataSet filter so that on
several ranks every rank holds part of it (the script prints "pieces NAME K": how many ranks hold
part of NAME):
  bunny   the Stanford bunny scan (PLY, a scanned triangle mesh)
  vessel  the outer surface of an Exodus II hexahedral mesh (simulation output)
(Extract Surface after the split, as a ParaView user would show them.)
For each dataset and style it writes OUTPUT_PREFIX-<dataset>-<style>.png (none, comic, pixel,
sketch), and for the bunny also -bunny-sketch-model.png: the sketch along the Principal
Curvatures filter's directions (Direction Source Model), the filter run on each rank's piece,
and -bunny-lines.svg: the line art's vector figure (SaveStylizedFigure) of the split bunny.
"""
import sys

import paraview.simple as simple
from paraview.simple import (CreateView, Delete, ExtractSurface, Hide, IOSSReader, Render,
                             SaveScreenshot, Show)
from stylize_pv_scene import make_view
import stylize_paraview as stylize

prefix, data = sys.argv[1], sys.argv[2]
SIZE = [360, 300]
view = CreateView("StylizeView")
make_view(view, SIZE)


def split(source, name):
    """The source redistributed across the ranks; prints how many ranks hold part of it."""
    parts = simple.RedistributeDataSet(Input=source)
    # one layer of ghost cells: filters that look at neighbours (surface normals, curvatures)
    # see across the cut, and the surface leaves out the faces between the pieces
    parts = simple.GhostCellsGenerator(Input=parts)
    parts.BuildIfRequired = 0
    ids = (getattr(simple, "GenerateProcessIds", None) or simple.ProcessIdScalars)(Input=parts)
    ids.UpdatePipeline()
    array = ids.PointData.GetArray("ProcessId")
    low, high = array.GetRange() if array else (0, 0)
    print("pieces %s %d" % (name, int(high - low) + 1))
    return parts


def frame(direction, up):
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraPosition = direction
    view.CameraViewUp = up
    view.ResetCamera()


def shots(source, name, direction, up):
    display = Show(source, view)
    display.ColorArrayName = ["POINTS", ""]
    frame(direction, up)
    for style, label in enumerate(["none", "comic", "pixel", "sketch"]):
        view.Style = style
        Render(view)
        SaveScreenshot("%s-%s-%s.png" % (prefix, name, label), view, ImageResolution=SIZE)
    view.Style = 0
    Hide(source, view)
    return display


# (the redistributed pieces are unstructured grids: Extract Surface makes them polygonal data again,
# which the Principal Curvatures filter takes)
# (the bunny through the plugin's checked reader: its helper reads on the rank that needs the
# data, which test_ranks.py counts)
bunny = ExtractSurface(Input=split(simple.StylizeCheckedReader(FileName=data + "/bunny.ply"),
                                   "bunny"))
shots(bunny, "bunny", [0.0, 0.0, 1.0], [0.0, 1.0, 0.0])
# the sketch along the scan's principal directions, computed per rank on its piece
curvatures = simple.PrincipalCurvatures(Input=bunny)
display = Show(curvatures, view)
display.ColorArrayName = ["POINTS", ""]
frame([0.0, 0.0, 1.0], [0.0, 1.0, 0.0])
view.Style = 3
view.SketchDirectionSource = 1
Render(view)
SaveScreenshot("%s-bunny-sketch-model.png" % prefix, view, ImageResolution=SIZE)
view.SketchDirectionSource = 0
view.Style = 0
Hide(curvatures, view)

# the line art's vector figure of the split bunny (every rank's lines, no line along the cut)
display = Show(bunny, view)
display.ColorArrayName = ["POINTS", ""]
frame([0.0, 0.0, 1.0], [0.0, 1.0, 0.0])
view.Style = "Line art"
background = list(view.Background)
view.Background = [1.0, 1.0, 1.0]  # (white paper: the lines are the figure's dark pixels)
Render(view)
stylize.SaveStylizedFigure("%s-bunny-lines.svg" % prefix, view)
view.Background = background
view.Style = 0
Hide(bunny, view)

reader = IOSSReader(FileName=[data + "/vessel.ex2"])
# smooth point normals, as a user gives a curved simulation surface (Generate Surface Normals),
# computed before the split: the filter makes no use of ghost cells, and on a piece it bends the
# normals along the cut
smooth = simple.GenerateSurfaceNormals(Input=ExtractSurface(Input=reader))
vessel = ExtractSurface(Input=split(smooth, "vessel"))
shots(vessel, "vessel", [1.0, -1.0, 0.6], [0.0, 0.0, 1.0])
Delete(view)
print("rendered")
