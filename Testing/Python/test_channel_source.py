"""realdata.channel_source: a style after a compositor reads the processes' own G-buffers.

    test_channel_source.py DATADIR

ParaView's path, in one process: the style stylizes its delegate's image (a camera pass around a
per-process vtkStylizeGBufferPass, the "channel source"), as it does after IceT compositing.
Without the source the G-buffer is rebuilt from the image's depth (facet normals, no model
directions); with it the style reads the true channels. For each style on a scanned mesh, a CAD
part, a coarse isosurface and simulation output (the surface of an Exodus II hexahedral mesh),
and for the sketch's model-space directions on the scan, the image is compared with the geometry
path (the style rendering the geometry itself), same camera and lights: with the source at most
0.5% of the pixels may be more than 16 levels apart. The image path without the source is
measured beside it (not asserted: it is what the source replaces).

Composite data (ParaView's mapper, vtkCompositePolyDataMapper2, uploads no mapped array): the
sketch's model directions are the point data's tangents, which vtkStylizePrincipalCurvatures
sets. On the CAD part, the composite mapper's model sketch (geometry path and channel source)
must be the plain mapper's within 0.5%, and differ from the screen estimate (the option acts: 25
times the paths' own difference);
with no tangents (TangentDirection NONE) model mode warns and draws the screen estimate.
"""
import os
import sys
import time

import numpy as np
import vtkstylize
from vtkmodules.vtkFiltersCore import vtkContourFilter, vtkPolyDataNormals
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkFiltersGeometry import vtkCompositeDataGeometryFilter
from vtkmodules.vtkIOExodus import vtkExodusIIReader
from vtkmodules.vtkCommonCore import VTK_STRING, vtkCommand
from vtkmodules.vtkCommonDataModel import vtkMultiBlockDataSet
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderer,
                                         vtkWindowToImageFilter)
from vtkmodules.vtkRenderingOpenGL2 import vtkCompositePolyDataMapper2
from vtkmodules.vtkRenderingOpenGL2 import vtkCameraPass
from vtkmodules.util.numpy_support import vtk_to_numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from stylize_test_scene import (check, failures, offscreen_window, ply_mesh,  # noqa: E402
                                style_maker)

data = sys.argv[1]
SIZE = (480, 360)


def ply(name):
    return ply_mesh(data, name)


def exodus(name):
    # Simulation output: the outer surface of an Exodus II hexahedral mesh, with normals.
    reader = vtkExodusIIReader()
    reader.SetFileName(os.path.join(data, name + ".ex2"))
    reader.UpdateInformation()
    reader.SetAllArrayStatus(vtkExodusIIReader.ELEM_BLOCK, 1)
    surface = vtkCompositeDataGeometryFilter()
    surface.SetInputConnection(reader.GetOutputPort())
    normals = vtkPolyDataNormals()
    normals.SetInputConnection(surface.GetOutputPort())
    normals.Update()
    return normals.GetOutput()


def coarse_contour():
    # A coarse isosurface of VTK's wavelet (about 3,000 triangles), as ParaView's Contour makes.
    wavelet = vtkRTAnalyticSource()
    wavelet.SetWholeExtent(-10, 10, -10, 10, -10, 10)
    contour = vtkContourFilter()
    contour.SetInputConnection(wavelet.GetOutputPort())
    contour.SetValue(0, 157.0)
    contour.ComputeNormalsOn()
    contour.Update()
    return contour.GetOutput()


def with_directions(poly, tangents=1):
    curvatures = vtkstylize.vtkStylizePrincipalCurvatures()
    curvatures.SetInputData(poly)
    curvatures.SetTangentDirection(tangents)
    curvatures.Update()
    return curvatures.GetOutput()


def render(poly, make_style, path, composite=False, warnings=None):
    """The frame of `path` ('geometry', 'image' or 'source') and the style; a fresh window.
    composite: the data as the one block of a multiblock, drawn by VTK's composite mapper."""
    window = offscreen_window(*SIZE)
    renderer = vtkRenderer()
    renderer.SetBackground(0.32, 0.34, 0.43)
    window.AddRenderer(renderer)
    if composite:
        blocks = vtkMultiBlockDataSet()
        blocks.SetBlock(0, poly)
        mapper = vtkCompositePolyDataMapper2()
        mapper.SetInputDataObject(blocks)
    else:
        mapper = vtkPolyDataMapper()
        mapper.SetInputData(poly)
    mapper.ScalarVisibilityOff()
    actor = vtkActor()
    actor.SetMapper(mapper)
    renderer.AddActor(actor)
    renderer.ResetCamera()
    renderer.GetActiveCamera().Azimuth(30.0)
    renderer.GetActiveCamera().Elevation(20.0)
    renderer.ResetCameraClippingRange()
    style = make_style()
    keep = [style]
    if warnings is not None:
        def warned(caller, event, text):
            warnings.append(text)
        warned.CallDataType = VTK_STRING
        style.AddObserver(vtkCommand.WarningEvent, warned)
    if path != "geometry":
        camera = vtkCameraPass()
        if path == "source":
            source = vtkstylize.vtkStylizeGBufferPass()
            source.SetLightingPass(style.GetLightingPass())
            camera.SetDelegatePass(source)
            style.GetGBufferPass().SetChannelSource(source)
            keep.append(source)
        else:
            camera.SetDelegatePass(style.GetLightingPass())
        style.SetDelegatePass(camera)
        keep.append(camera)
    renderer.SetPass(style)
    window.Render()
    times = []
    for _ in range(3):
        start = time.perf_counter()
        window.Render()
        window.WaitForCompletion()
        times.append(1000.0 * (time.perf_counter() - start))
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    image = grab.GetOutput()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars())[:, :3].astype(int)
    used = style.GetGBufferPass().GetChannelSourceUsed()
    renderer.SetPass(None)
    style.ReleaseGraphicsResources(window)
    window.Finalize()
    return pixels, sorted(times)[1], used


def beyond16(a, b):
    return 100.0 * float((np.abs(a - b).max(axis=1) > 16).sum()) / len(a)


scenes = [("bunny (scan)", ply("bunny")), ("fandisk (CAD)", ply("fandisk")),
          ("wavelet contour (coarse)", coarse_contour()),
          ("vessel (Exodus, simulation)", exodus("vessel"))]
styles = [("comic", style_maker("vtkComicPass")), ("pixel art", style_maker("vtkPixelArtPass")),
          ("sketch", style_maker("vtkSketchPass"))]
cases = [(scene, poly, name, make) for scene, poly in scenes for name, make in styles]
cases.append(("bunny (scan)", with_directions(scenes[0][1]), "sketch, model directions",
              style_maker("vtkSketchPass", DirectionSource=1)))

print("| scene | style | image path: pixels > 16 levels | with channel source | ms geometry "
      "/ image / source |")
print("|---|---|---:|---:|---|")
for scene, poly, name, make in cases:
    geometry, t_geometry, _ = render(poly, make, "geometry")
    image, t_image, _ = render(poly, make, "image")
    source, t_source, used = render(poly, make, "source")
    d_image, d_source = beyond16(geometry, image), beyond16(geometry, source)
    print("| %s | %s | %.2f%% | %.2f%% | %.0f / %.0f / %.0f |" % (
        scene, name, d_image, d_source, t_geometry, t_image, t_source))
    check(used, "%s, %s: the channel source was not used" % (scene, name))
    check(d_source <= 0.5, "%s, %s: %.2f%% of the pixels differ from the geometry path "
          "(at most 0.5%%)" % (scene, name, d_source))

# Composite data: the model directions are the tangents.
fandisk = scenes[1][1]
model = style_maker("vtkSketchPass", DirectionSource=1)
screen = style_maker("vtkSketchPass")
plain, _, _ = render(with_directions(fandisk), model, "geometry")
comp_geometry, _, _ = render(with_directions(fandisk), model, "geometry", composite=True)
comp_source, _, _ = render(with_directions(fandisk), model, "source", composite=True)
comp_screen, _, _ = render(with_directions(fandisk), screen, "source", composite=True)
warned = []
inert, _, _ = render(with_directions(fandisk, 0), model, "source", composite=True, warnings=warned)
rows = [("composite, geometry path", beyond16(plain, comp_geometry)),
        ("composite, channel source", beyond16(plain, comp_source)),
        ("composite, screen estimate", beyond16(plain, comp_screen)),
        ("composite, no tangents", beyond16(plain, inert))]
print("")
print("| fandisk (CAD), sketch, model directions, against the plain mapper | pixels > 16 levels |")
print("|---|---:|")
for name, value in rows:
    print("| %s | %.2f%% |" % (name, value))
check(rows[0][1] <= 0.5, "composite geometry path: %.2f%% differ (at most 0.5%%)" % rows[0][1])
check(rows[1][1] <= 0.5, "composite channel source: %.2f%% differ (at most 0.5%%)" % rows[1][1])
# The model directions act: the sketch along them is not the screen estimate's. On this CAD part
# the two estimate the same principal directions and mostly agree (measured 1.2%, against 0.02%
# between paths that draw the same directions; 4.7% before the G-buffer stopped blending the
# direction channel with what lay behind; 0.40% since the bright faces are paper, which no
# direction changes): at least 25 times the paths' own difference, and 0.2%.
required = max(0.2, 25.0 * max(rows[0][1], rows[1][1]))
check(rows[2][1] >= required, "model directions change the composite sketch: %.2f%% differ from "
      "the screen estimate (at least %.2f%%)" % (rows[2][1], required))
d_inert = beyond16(comp_screen, inert)
check(d_inert == 0.0, "model mode with no tangents draws the screen estimate (%.3f%% differ)"
      % d_inert)
check(len(warned) == 1 and "DirectionSource is MODEL" in warned[0],
      "model mode with no tangents warns once (%d warnings)" % len(warned))
sys.exit(1 if failures else 0)
