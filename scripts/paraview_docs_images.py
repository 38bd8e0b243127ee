"""Re-renders docs/paraview.md's gallery: data as ParaView shows it at the defaults, every style.

    pvbatch-stylize scripts/paraview_docs_images.py OUTDIR EXODUS CT_MHD SCAN_PLY

EXODUS is simulation output shown coloured by its temperature (ParaView's disk_out_ref.ex2,
from its examples, by `Temp`), CT_MHD a CT volume contoured at the skin as ParaView's Contour
filter leaves it (VTK's headsq quarter-resolution head, iso-value 500, coloured by the contoured
array as ParaView colours a new contour), SCAN_PLY a surface scan shown in ParaView's solid
colour (the real-data set's bunny.ply). Writes OUTDIR/paraview-<exodus|ct|scan>-<style>.png,
400x300, for the styles None, Comic, Pixel art, Sketch and Line art, ParaView's light kit and
background, no orientation axes.
"""
import os
import sys

from paraview.simple import (ColorBy, Contour, CreateView, Delete, ExtractSurface, Hide,
                             IOSSReader, OpenDataFile, PLYReader, SaveScreenshot, Show)

out, exodus, ct, scan = sys.argv[1:5]
os.makedirs(out, exist_ok=True)
SIZE = [400, 300]
STYLES = ["none", "comic", "pixel", "sketch", "lines"]
view = CreateView("StylizeView")
view.ViewSize = SIZE
view.OrientationAxesVisibility = 0


def shoot(name, source, colour, position, up):
    display = Show(source, view)
    if colour:
        ColorBy(display, ("POINTS", colour))
        display.RescaleTransferFunctionToDataRange(True, False)
        display.SetScalarBarVisibility(view, True)
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraPosition = position
    view.CameraViewUp = up
    view.ResetCamera()
    for index, style in enumerate(STYLES):
        view.Style = index
        SaveScreenshot(os.path.join(out, "paraview-%s-%s.png" % (name, style)), view,
                       ImageResolution=SIZE)
    if colour:
        display.SetScalarBarVisibility(view, False)
    Hide(source, view)


shoot("exodus", ExtractSurface(Input=IOSSReader(FileName=exodus)), "Temp",
      [10.0, 20.0, 30.0], [0.0, 1.0, 0.0])
volume = OpenDataFile(ct)
volume.UpdatePipeline()
scalars = volume.PointData.keys()[0]
head = Contour(Input=volume, ContourBy=["POINTS", scalars], Isosurfaces=[500.0],
               ComputeScalars=1)
shoot("ct", head, scalars, [-0.6, 1.0, -0.1], [0.0, 0.0, -1.0])
shoot("scan", PLYReader(FileNames=[scan]), None, [0.0, 0.0, 1.0], [0.0, 1.0, 0.0])
print("rendered")
Delete(view)
