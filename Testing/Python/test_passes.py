"""Python test: the wrapped modules import as one package and the passes render.

Run with the build's python folder on PYTHONPATH and a display (the suite does both).
"""
import sys

import vtkstylize
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderer,
                                         vtkRenderWindow, vtkWindowToImageFilter)
from vtkmodules.vtkCommonCore import vtkFloatArray

failures = []


def check(cond, message):
    if not cond:
        failures.append(message)
        print("FAIL:", message)


def render(model, gbuffer):
    win = vtkRenderWindow()
    win.SetSize(160, 120)
    win.SetMultiSamples(0)
    win.OffScreenRenderingOn()
    ren = vtkRenderer()
    win.AddRenderer(ren)
    sphere = vtkSphereSource()
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(sphere.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    ren.AddActor(actor)
    lighting = vtkstylize.vtkStylizeLightingPass()
    lighting.SetModel(model)
    vtkstylize.vtkStylizeLightingPass.SetActorSubjectFactor(actor, 0.7)
    if gbuffer:
        gb = vtkstylize.vtkStylizeGBufferPass()
        gb.SetLightingPass(lighting)
        gb.SetChannels(vtkstylize.vtkStylizeGBufferPass.NORMAL)
        ren.SetPass(gb)
    else:
        ren.SetPass(lighting)
    ren.ResetCamera()
    win.Render()
    normals = None
    if gbuffer:
        normals = vtkFloatArray()
        check(gb.DownloadChannel(vtkstylize.vtkStylizeGBufferPass.NORMAL_BUFFER, normals),
              "normal download")
    w2i = vtkWindowToImageFilter()
    w2i.SetInput(win)
    w2i.ReadFrontBufferOff()
    w2i.Update()
    image = w2i.GetOutput()
    win.Finalize()
    return image, normals


plain = None
for name in ("standard", "comic", "pixelart"):
    model = vtkstylize.vtkStylizeLightingPass.GetModelFromName(name)
    check(model >= 0, "model name %s" % name)
    for gbuffer in (False, True):
        image, normals = render(model, gbuffer)
        scalars = image.GetPointData().GetScalars()
        lo, hi = scalars.GetRange(0)
        check(hi > lo, "%s%s: the image is flat" % (name, " (G-buffer)" if gbuffer else ""))
        if normals is not None:
            check(vtkstylize.vtkStylizeImageMetrics.CountNonFinite(normals) == 0,
                  "%s: non-finite normals" % name)
        if name == "standard" and not gbuffer:
            plain = image
        print("%-9s %-9s ok, range %g..%g" % (name, "gbuffer" if gbuffer else "lighting", lo, hi))
comic, _ = render(1, False)
check(vtkstylize.vtkStylizeImageMetrics.MaximumDifference(plain, comic) > 10,
      "comic looks like standard")

sys.exit(1 if failures else 0)
