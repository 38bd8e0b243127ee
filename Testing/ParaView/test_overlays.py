#!/usr/bin/python3
"""paraview.figure_overlays: every overlay in a vector figure as on the screen (issue 40).

    test_overlays.py PVBATCH_WRAPPER OUTPUT_DIR

render_overlays.py writes the comic and the sketch with each overlay alone (orientation axes,
data axes grid, a Text source, the colour legend) as a screenshot and as SVG and PDF figures.
Each figure is rasterized back at the view's size (rsvg-convert, pdftocairo) and compared with
the screenshot: SSIM >= 0.95 over the image and over the overlay's box (the pixels where the
screenshot with the overlay differs from the one without, grown by 4 pixels), there after a
Gaussian blur of 1 pixel: vector text and lines land within a pixel of VTK's raster, whose
hinting and anti-aliasing differ (a thin glyph one pixel off scores an SSIM near 0 unblurred),
while a missing, moved or recoloured overlay still fails. Text is held to its pixels instead
(SSIM is near 0 over thin glyphs that FreeType hints and cairo does not, and FreeType rounds
each glyph's advance to a whole pixel): at least 90% of the text's pixels in each image lie
within 2 pixels of the text's pixels in the other (a text moved by 3 pixels or more fails). The orientation
axes render in a renderer of their own over the style's: the figures used to read their pixels
as the style's layers (the X axis lost, the Z axis black in the comic).
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "RealData"))
from figures import SSIM_MIN, rasterize, read_png  # noqa: E402
from pvbatch_script import run_render_script  # noqa: E402
from vtkstylize_testing import vtkStylizeImageMetrics as M  # noqa: E402
import numpy  # noqa: E402
import vtk  # noqa: E402
from vtk.util.numpy_support import vtk_to_numpy  # noqa: E402

prefix, log = run_render_script(sys.argv[1], "render_overlays.py", sys.argv[2], "overlay")
failures = []


def pixels(image):
    w, h, _ = image.GetDimensions()
    return vtk_to_numpy(image.GetPointData().GetScalars()).reshape(h, w, -1)[:, :, :3].astype(int)


def crop(image, box):
    """The box of the image, blurred by a Gaussian of 1 pixel."""
    voi = vtk.vtkExtractVOI()
    voi.SetInputData(image)
    voi.SetVOI(box[0], box[1], box[2], box[3], 0, 0)
    cast = vtk.vtkImageCast()
    cast.SetInputConnection(voi.GetOutputPort())
    cast.SetOutputScalarTypeToFloat()
    blur = vtk.vtkImageGaussianSmooth()
    blur.SetInputConnection(cast.GetOutputPort())
    blur.SetDimensionality(2)
    blur.SetStandardDeviations(1.0, 1.0)
    blur.SetRadiusFactors(3.0, 3.0)
    blur.Update()
    return blur.GetOutput()


def ink_agreement(reference, figure, base, box):
    """Text: the share of the overlay's pixels in one image that lie within 2 pixels of the
    overlay's pixels in the other, the smaller of the two ways (an overlay's pixels: those that
    differ from the screenshot without it by more than 40 of 255)."""
    x0, x1, y0, y1 = box
    b = base[y0:y1 + 1, x0:x1 + 1]
    a = abs(pixels(reference)[y0:y1 + 1, x0:x1 + 1] - b).max(axis=2) > 40
    f = abs(pixels(figure)[y0:y1 + 1, x0:x1 + 1] - b).max(axis=2) > 40

    def near(m):
        grown = m.copy()
        for dy in range(-2, 3):
            for dx in range(-2, 3):
                grown |= numpy.roll(numpy.roll(m, dy, axis=0), dx, axis=1)
        return grown
    if not a.any() or not f.any():
        return 0.0
    return min(float((a & near(f)).sum()) / a.sum(), float((f & near(a)).sum()) / f.sum())


print("| style | overlay | format | SSIM | overlay's box | box SSIM | text's pixels within 2 px |")
print("|---|---|---|---:|---|---:|---:|")
for style in ("comic", "sketch"):
    base = pixels(read_png("%s-%s-none.png" % (prefix, style)))
    for overlay in ("axes", "grid", "text", "legend"):
        stem = "%s-%s-%s" % (prefix, style, overlay)
        reference = read_png(stem + ".png")
        w, h, _ = reference.GetDimensions()
        rows, cols = (abs(pixels(reference) - base).max(axis=2) > 0).nonzero()
        if len(rows) == 0:
            failures.append("%s: the screenshot shows no %s" % (stem, overlay))
            continue
        box = [max(0, int(cols.min()) - 4), min(w - 1, int(cols.max()) + 4),
               max(0, int(rows.min()) - 4), min(h - 1, int(rows.max()) + 4)]
        for ext in ("svg", "pdf"):
            figure = "%s.%s" % (stem, ext)
            if not os.path.exists(figure):
                failures.append("%s: not written" % figure)
                continue
            png = "%s-%s.png" % (stem, ext)
            rasterize(figure, png, w, h)
            image = read_png(png)
            ssim = M.SSIM(reference, image, 255.0)
            local = M.SSIM(crop(reference, box), crop(image, box), 255.0)
            ink = ink_agreement(reference, image, base, box)
            print("| %s | %s | %s | %.4f | %d-%d x %d-%d | %.4f | %.3f |"
                  % (style, overlay, ext, ssim, box[0], box[1], box[2], box[3], local, ink))
            if ssim < SSIM_MIN:
                failures.append("%s: SSIM %.4f (< %.2f)" % (figure, ssim, SSIM_MIN))
            if overlay != "text" and local < SSIM_MIN:
                failures.append("%s: SSIM over the %s %.4f (< %.2f)"
                                % (figure, overlay, local, SSIM_MIN))
            if overlay == "text" and ink < 0.9:
                failures.append("%s: %.3f of the text's pixels within 2 pixels (< 0.9)"
                                % (figure, ink))
for f in failures:
    print("FAIL: " + f)
sys.exit(1 if failures else 0)
