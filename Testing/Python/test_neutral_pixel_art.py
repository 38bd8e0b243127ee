"""Pixel art of a gray or white surface stays neutral (issue 40), in VTK and in vtkstylize.

    test_neutral_pixel_art.py VTKSTYLIZE DATA_DIR OUTDIR

The bunny scan, white and mid-gray, under a vtkLightKit (warm key, cool fill and back lights:
ParaView's lights) through vtkPixelArtPass at its defaults, and through vtkstylize --style
pixel: the largest CIELAB chroma over the surface must be at most 10 (the lights' faint tint
used to dither into pink, yellow and teal dots). With ColoredLights on the lights' colours come
back: the same scene then has coloured art pixels (the setting is live, the check can fail).
"""
import math
import os
import subprocess
import sys

import vtkstylize
from stylize_test_scene import check, failures
from vtkmodules.vtkIOImage import vtkPNGReader, vtkPNGWriter
from vtkmodules.vtkIOPLY import vtkPLYReader
from vtkmodules.vtkRenderingCore import (vtkActor, vtkLightKit, vtkPolyDataMapper, vtkRenderer,
                                         vtkRenderWindow, vtkWindowToImageFilter)

exe, data, out = sys.argv[1:4]
os.makedirs(out, exist_ok=True)
BACKGROUND = (0.32, 0.34, 0.43)


def lab_chroma(rgb):
    """CIELAB chroma C*ab of an sRGB colour in [0, 255]."""
    def lin(c):
        c /= 255.0
        return c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4
    r, g, b = (lin(float(c)) for c in rgb)
    x = (0.4124 * r + 0.3576 * g + 0.1805 * b) / 0.95047
    y = 0.2126 * r + 0.7152 * g + 0.0722 * b
    z = (0.0193 * r + 0.1192 * g + 0.9505 * b) / 1.08883

    def f(t):
        return t ** (1.0 / 3.0) if t > 216.0 / 24389.0 else (24389.0 / 27.0 * t + 16.0) / 116.0
    return math.hypot(500.0 * (f(x) - f(y)), 200.0 * (f(y) - f(z)))


def surface_chroma(path, background):
    """The largest chroma of the pixels that are neither the background nor black (the
    outline), and how many there are."""
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    scalars = reader.GetOutput().GetPointData().GetScalars()
    worst, count = 0.0, 0
    for i in range(scalars.GetNumberOfTuples()):
        rgb = [scalars.GetComponent(i, c) for c in range(3)]
        if max(abs(rgb[c] - 255.0 * background[c]) for c in range(3)) <= 2.5 or max(rgb) < 8:
            continue
        count += 1
        worst = max(worst, lab_chroma(rgb))
    return worst, count


def render_vtk(gray, name, **settings):
    reader = vtkPLYReader()
    reader.SetFileName(os.path.join(data, "bunny.ply"))
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(reader.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(gray, gray, gray)
    renderer = vtkRenderer()
    renderer.AddActor(actor)
    renderer.SetBackground(*BACKGROUND)
    kit = vtkLightKit()
    kit.AddLightsToRenderer(renderer)
    renderer.ResetCamera()
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(400, 400)
    window.AddRenderer(renderer)
    vtkstylize.apply_style(renderer, "pixel", **settings)
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.Update()
    path = os.path.join(out, name + ".png")
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    return surface_chroma(path, BACKGROUND)


for gray, name in ((1.0, "white"), (0.5, "gray")):
    worst, count = render_vtk(gray, "vtk-" + name)
    print("VTK, light kit, %s bunny: max chroma %.1f over %d pixels" % (name, worst, count))
    check(count > 1000 and worst <= 10.0,
          "VTK pixel art of a %s surface: max chroma %.1f <= 10" % (name, worst))
worst, count = render_vtk(1.0, "vtk-white-colored-lights", ColoredLights=True)
print("VTK, light kit, ColoredLights: max chroma %.1f" % worst)
check(worst > 10.0, "ColoredLights brings the lights' colours back (max chroma %.1f > 10)" % worst)

path = os.path.join(out, "program-white.png")
subprocess.run([exe, "--style", "pixel", "--size", "400x400", "--no-annotations", "--quiet",
                "--background", ",".join(str(c) for c in BACKGROUND), "--output", path,
                os.path.join(data, "bunny.ply")], check=True)
worst, count = surface_chroma(path, BACKGROUND)
print("vtkstylize, white bunny: max chroma %.1f over %d pixels" % (worst, count))
check(count > 1000 and worst <= 10.0, "vtkstylize pixel art: max chroma %.1f <= 10" % worst)
sys.exit(1 if failures else 0)
