"""The line art's vector-figure strokes behind translucent surfaces are greyed as the frame greys
them (StrokeInk, vtkStylizeRayOccluder::Transmittance; issue 55).

    test_figure_ink.py

An opaque torus (tilted 30 degrees) seen through a translucent sphere (opacity 0.6) that covers its left
half, 480x360: the figure's strokes (vtkLineArtPass::ComputeFigureStrokes) carry a StrokeInk per
point; where a stroke lies behind the sphere, the light the sphere lets through, (1 - 0.6)^2 =
0.16 (its front and its back crossed), elsewhere 1. Each stroke point's ink must be within 0.01 of
the one its place predicts (inside the sphere's silhouette: 0.16, outside it: 1, a 3 px band along
the silhouette left out), and both kinds must be there. Without the sphere, the strokes carry no
StrokeInk (all at full ink).
"""
import sys

import numpy as np
import vtkstylize
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderer

from stylize_test_scene import check, failures, offscreen_window, torus_actor

W, H = 480, 360
win = offscreen_window(W, H)
ren = vtkRenderer()
ren.SetBackground(1.0, 1.0, 1.0)
win.AddRenderer(ren)
ring = torus_actor(0.35, 30.0)
ren.AddActor(ring)
ren.ResetCamera()
camera = ren.GetActiveCamera()
style = vtkstylize.vtkLineArtPass()
ren.SetPass(style)
win.Render()
plain = style.ComputeFigureStrokes(W, H, 1)
check(plain.GetNumberOfPoints() > 100 and plain.GetPointData().GetArray("StrokeInk") is None,
      "without translucent surfaces: %d points, StrokeInk %s"
      % (plain.GetNumberOfPoints(), plain.GetPointData().GetArray("StrokeInk")))

# the sphere over the torus's left half, between it and the camera
b = ring.GetBounds()
centre = (b[0] + 0.25 * (b[1] - b[0]), 0.5 * (b[2] + b[3]), b[5] + 0.05 * (b[1] - b[0]))
radius = 0.3 * (b[1] - b[0])
sphere = vtkSphereSource()
sphere.SetCenter(centre)
sphere.SetRadius(radius)
sphere.SetThetaResolution(96)
sphere.SetPhiResolution(96)
veil = vtkActor()
veil.SetMapper(vtkPolyDataMapper())
veil.GetMapper().SetInputConnection(sphere.GetOutputPort())
veil.GetProperty().SetOpacity(0.6)
ren.AddActor(veil)
win.Render()
strokes = style.ComputeFigureStrokes(W, H, 1)
ink = strokes.GetPointData().GetArray("StrokeInk")
check(ink is not None, "behind a translucent sphere: no StrokeInk")
if ink is not None:
    ink = vtk_to_numpy(ink)
    xy = vtk_to_numpy(strokes.GetPoints().GetData())[:, :2]
    # the sphere's silhouette on the figure's page (pixels, y up): its centre and radius there
    ren.SetWorldPoint(*centre, 1.0)
    ren.WorldToDisplay()
    cx, cy, _ = ren.GetDisplayPoint()
    ren.SetWorldPoint(centre[0] + radius, centre[1], centre[2], 1.0)
    ren.WorldToDisplay()
    rx = abs(ren.GetDisplayPoint()[0] - cx)
    distance = np.hypot(xy[:, 0] - cx, xy[:, 1] - cy)
    inside, outside = distance < rx - 3.0, distance > rx + 3.0
    print("%d stroke points: %d behind the sphere (ink %.3f to %.3f), %d beside it (%.3f to %.3f)"
          % (len(ink), inside.sum(), ink[inside].min(initial=1), ink[inside].max(initial=0),
             outside.sum(), ink[outside].min(initial=1), ink[outside].max(initial=0)))
    check(inside.sum() > 50 and outside.sum() > 50, "both kinds of stroke points: %d, %d"
          % (inside.sum(), outside.sum()))
    check(np.all(np.abs(ink[inside] - 0.16) < 0.01), "behind the sphere: ink %s"
          % np.unique(ink[inside].round(3))[:8])
    check(np.all(np.abs(ink[outside] - 1.0) < 0.01), "beside the sphere: ink %s"
          % np.unique(ink[outside].round(3))[:8])
if failures:
    print("%d failure(s)" % len(failures))
    sys.exit(1)
print("OK")
