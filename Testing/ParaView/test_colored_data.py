"""Coloured data in the stylized view at the defaults, as a ParaView user shows it (issue 40).

    pvbatch-stylize test_colored_data.py OUTDIR DATA_DIR [EXTRA.ex2:ARRAY ...]

Simulation output coloured by a field that varies over the surface, with ParaView's default
colour map (Cool to Warm, a diverging map whose luminance is not monotonic in the data) and
light kit: the real-data set's vessel.ex2 by its temperature and plate.ex2 (a plate with a hole
under tension) by its stress, each drawn plain (Style None), comic and sketch. Measured over the
surface's pixels of images blurred by a Gaussian (sigma 4 pixels, the patterns' scale):
  luminance  the stylized image's luminance against the plain render's (correlation >= 0.8):
             the light and the colour map both still read;
  red-blue   the stylized image's red minus blue against the plain render's (>= 0.8): the
             data's colours are there;
  ink        the share of surface pixels whose largest channel is below 0.5, inked more than
             half (a mid-luminance map must not be drawn as shadow all over: at most 0.5).
Iso-lines (LineArtIsoLines) on the plate's stress add ink to at least 1% of its surface and to
at most 0.1% of the background. The data axes grid off the surface is drawn where ParaView draws it in every style
(recall and precision of its pixels at least 0.9).
Colour legends: shown over the comic and the sketch of coloured data, left out over black and
white (Tint Black and white, line art), as vtkstylize does. Pixel art of the uncoloured bunny
scan under the same light kit must stay neutral (max CIELAB chroma <= 10 over the surface). Further files (EXTRA.ex2:ARRAY, e.g. ParaView's
disk_out_ref.ex2:Pres) are measured and printed, not checked: the held-out data.
Writes OUTDIR/<name>-<style>.png; prints one line per measure and FAIL lines.
"""
import math
import os
import sys

import numpy
from paraview.simple import (ColorBy, CreateView, Delete, ExtractSurface,
                             GetColorTransferFunction, Hide, IOSSReader, PLYReader,
                             SaveScreenshot, Show)
from paraview.vtk.util.numpy_support import vtk_to_numpy
from paraview.vtk.vtkIOImage import vtkPNGReader
from stylize_pv_scene import BACKGROUND, check, failures, make_view

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Python"))
from stylize_png import near, overlay_match  # noqa: E402

out, data = sys.argv[1], sys.argv[2]
extra = sys.argv[3:]
os.makedirs(out, exist_ok=True)
SIZE = [480, 360]
view = CreateView("StylizeView")
make_view(view, SIZE)


def image(path):
    """The PNG as a float array (rows, columns, 3) in [0, 1]."""
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    img = reader.GetOutput()
    w, h, _ = img.GetDimensions()
    a = vtk_to_numpy(img.GetPointData().GetScalars()).reshape(h, w, -1)[:, :, :3]
    return a.astype(numpy.float64) / 255.0


def blur(a, mask, sigma=4.0):
    """Gaussian blur of a (rows, columns[, channels]) over the mask alone (normalised), so that
    the background does not bleed into the surface's edge."""
    r = int(3 * sigma)
    k = numpy.exp(-0.5 * (numpy.arange(-r, r + 1) / sigma) ** 2)
    k /= k.sum()

    def smooth(x):
        for axis in (0, 1):
            x = numpy.apply_along_axis(lambda v: numpy.convolve(v, k, mode="same"), axis, x)
        return x
    m = mask.astype(numpy.float64)
    if a.ndim == 3:
        return numpy.stack([smooth(a[:, :, c] * m) for c in range(3)], axis=2) / \
            numpy.maximum(smooth(m), 1e-6)[:, :, None]
    return smooth(a * m) / numpy.maximum(smooth(m), 1e-6)


def luminance(a):
    return a @ numpy.array([0.2126, 0.7152, 0.0722])


def correlation(x, y):
    x, y = x - x.mean(), y - y.mean()
    d = math.sqrt((x * x).sum() * (y * y).sum())
    return float((x * y).sum() / d) if d > 0 else 0.0


def chroma(a):
    """CIELAB chroma C*ab of sRGB colours (rows, columns, 3) in [0, 1]."""
    lin = numpy.where(a <= 0.04045, a / 12.92, ((a + 0.055) / 1.055) ** 2.4)
    m = numpy.array([[0.4124, 0.3576, 0.1805], [0.2126, 0.7152, 0.0722],
                     [0.0193, 0.1192, 0.9505]])
    xyz = lin @ m.T / numpy.array([0.95047, 1.0, 1.08883])
    f = numpy.where(xyz > 216 / 24389, numpy.cbrt(xyz), (24389 / 27 * xyz + 16) / 116)
    return numpy.hypot(500 * (f[..., 0] - f[..., 1]), 200 * (f[..., 1] - f[..., 2]))


def shoot(name, styles):
    paths = {}
    for style, label in styles:
        view.Style = style
        paths[label] = os.path.join(out, "%s-%s.png" % (name, label))
        SaveScreenshot(paths[label], view, ImageResolution=SIZE)
    return {label: image(p) for label, p in paths.items()}


def measure(name, path, array, checked):
    source = ExtractSurface(Input=IOSSReader(FileName=path))
    display = Show(source, view)
    ColorBy(display, ("POINTS", array))
    display.RescaleTransferFunctionToDataRange(True, False)
    GetColorTransferFunction(array).ApplyPreset("Cool to Warm", True)
    view.CameraPosition = [6.0, -9.0, 12.0]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.ResetCamera()
    images = shoot(name, [(0, "plain"), (1, "comic"), (3, "sketch")])
    plain = images["plain"]
    surface = numpy.abs(plain - numpy.array(BACKGROUND)).max(axis=2) > 2.5 / 255.0
    bp = blur(plain, surface)
    for label in ("comic", "sketch"):
        b = blur(images[label], surface)
        lum = correlation(luminance(bp)[surface], luminance(b)[surface])
        rb = correlation((bp[..., 0] - bp[..., 2])[surface], (b[..., 0] - b[..., 2])[surface])
        ink = float((images[label].max(axis=2)[surface] < 0.5).mean())
        print("%-8s %-7s luminance %.3f  red-blue %.3f  ink %.3f  (%d surface pixels)"
              % (name, label, lum, rb, ink, int(surface.sum())), flush=True)
        if checked:
            check(lum >= 0.8, "%s %s: luminance correlation %.3f >= 0.8" % (name, label, lum))
            check(rb >= 0.8, "%s %s: red-blue correlation %.3f >= 0.8" % (name, label, rb))
            check(ink <= 0.5, "%s %s: ink share %.3f <= 0.5" % (name, label, ink))
    Hide(source, view)


measure("vessel", os.path.join(data, "vessel.ex2"), "Temp", True)
measure("plate", os.path.join(data, "plate.ex2"), "StressXX", True)
for item in extra:
    path, array = item.rsplit(":", 1)
    measure(os.path.splitext(os.path.basename(path))[0], path, array, False)

# Iso-lines of the coloured data (issue 55) through ParaView's representation and colour map:
# the line art of the plate by its von Mises stress, with and without LineArtIsoLines 10 (round
# levels of the map's range, 0.5 to 2.5: five lines across the plate and around its hole); the
# lines add ink on the surface, and none off it.
plate = ExtractSurface(Input=IOSSReader(FileName=os.path.join(data, "plate.ex2")))
display = Show(plate, view)
ColorBy(display, ("POINTS", "VonMises"))
display.RescaleTransferFunctionToDataRange(True, False)
view.ResetCamera()
view.LineArtIsoLines = 0
bare = shoot("plate-isolines-off", [(4, "lines")])["lines"]
view.LineArtIsoLines = 10
lined = shoot("plate-isolines-on", [(4, "lines")])["lines"]
view.LineArtIsoLines = 0
surface = numpy.abs(bare - numpy.array(BACKGROUND)).max(axis=2) > 2.5 / 255.0
new_ink = (lined.max(axis=2) < 0.5) & ~(bare.max(axis=2) < 0.5)
added, astray = float(new_ink[surface].mean()), float(new_ink[~surface].mean())
print("plate    lines   iso-lines add ink to %.4f of the surface, %.4f of the background"
      % (added, astray), flush=True)
check(added >= 0.01, "plate lines: iso-lines add ink to %.4f >= 0.01 of the surface" % added)
check(astray <= 0.001, "plate lines: iso-lines add ink to %.4f <= 0.001 of the background"
      % astray)

# The data axes grid (issue 55) drawn where ParaView draws it in every style on one process, off
# the surface (more than 4 pixels away): its pixels (where the plain picture with the grid
# differs from the one without) drawn (recall: at least 90% of them within a pixel of what the
# grid changes in the style's picture) and nothing else (precision: at least 90% of what it
# changes within a pixel of them). Its labels were thickened by the comic's edges and pixelated by the
# pixel art, and the line art left the grid out; the text's anti-aliasing differs (ParaView's
# FXAA in the plain view), its place does not.
display.DataAxesGrid.GridAxesVisibility = 0
no_grid = shoot("plate-grid-off", [(0, "plain")])["plain"]
display.DataAxesGrid.GridAxesVisibility = 1
grid = shoot("plate-grid-on", [(0, "plain"), (1, "comic"), (2, "pixel"), (3, "sketch"),
                               (4, "lines")])
display.DataAxesGrid.GridAxesVisibility = 0


# (the styles' outlines reach past the surface, along the grid's edges)
on_surface = numpy.abs(no_grid - numpy.array(BACKGROUND)).max(axis=2) > 2.5 / 255.0
off_surface = ~near(on_surface, 4)
for label in ("comic", "pixel", "sketch", "lines"):
    recall, precision, count = overlay_match(grid["plain"], no_grid, grid[label], off_surface,
                                             24 / 255.0)
    print("plate    %-7s data axes grid: recall %.3f, precision %.3f (%d pixels)"
          % (label, recall, precision, count), flush=True)
    check(recall >= 0.9 and precision >= 0.9, "plate %s: data axes grid where ParaView draws it: "
          "recall %.3f, precision %.3f >= 0.9" % (label, recall, precision))
Hide(plate, view)

# One rule for colour legends: shown where the style shows the colours (as vtkstylize draws
# them), left out over black and white (Tint Black and white; line art).
vessel = ExtractSurface(Input=IOSSReader(FileName=os.path.join(data, "vessel.ex2")))
display = Show(vessel, view)
ColorBy(display, ("POINTS", "Temp"))
view.ResetCamera()
for style, tint, legend in [(1, 1, True), (1, 0, False), (3, 1, True), (4, 1, False)]:
    view.Style = style
    view.ComicTint = tint
    shots = []
    for visible in (True, False):  # the legend's pixels: what its visibility changes
        display.SetScalarBarVisibility(view, visible)
        path = os.path.join(out, "legend-%d-%d-%d.png" % (style, tint, visible))
        SaveScreenshot(path, view, ImageResolution=SIZE)
        shots.append(image(path))
    changed = int((numpy.abs(shots[0] - shots[1]).max(axis=2) > 0).sum())
    print("legend   style %d tint %d: %d pixels" % (style, tint, changed))
    check((changed > 100) == legend, "style %d, tint %d: the legend is %s (%d pixels)" % (
        style, tint, "shown" if legend else "left out", changed))
view.ComicTint = 1
display.SetScalarBarVisibility(view, False)
Hide(vessel, view)

# Pixel art of a neutral surface under ParaView's light kit stays neutral.
bunny = PLYReader(FileNames=[os.path.join(data, "bunny.ply")])
display = Show(bunny, view)
display.ColorArrayName = [None, ""]
view.CameraPosition = [0.0, 0.0, 1.0]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 1.0, 0.0]
view.ResetCamera()
images = shoot("bunny", [(0, "plain"), (2, "pixel")])
surface = numpy.abs(images["plain"] - numpy.array(BACKGROUND)).max(axis=2) > 2.5 / 255.0
pixel = images["pixel"]
# (the outline is black; the background around the pixelated silhouette is left out)
inside = surface & (numpy.abs(pixel - numpy.array(BACKGROUND)).max(axis=2) > 2.5 / 255.0)
c = chroma(pixel)[inside]
print("bunny    pixel   max chroma %.1f  mean %.2f  (plain render: max %.1f)"
      % (float(c.max()), float(c.mean()), float(chroma(images["plain"])[surface].max())))
check(c.max() <= 10.0, "bunny pixel art: max chroma %.1f <= 10" % c.max())
Hide(bunny, view)

print("%d failures" % len(failures))
Delete(view)  # (before exiting: see test_styles.py)

sys.exit(1 if failures else 0)
