#!/usr/bin/python3
"""paraview.figures: vector figures and orbits from pvbatch, one call each (issue 18).

    test_figures.py PVBATCH_WRAPPER OUTPUT_DIR

render_figures.py writes each style as a PNG screenshot and as SVG and PDF figures
(stylize_paraview.SaveStylizedFigure), and a comic orbit (SaveStylizedOrbit: 3 PNG frames and a
GIF). Checked, as realdata.figures checks vtkstylize's figures: each figure rasterized back at the
view's size (rsvg-convert, pdftocairo) against the screenshot, SSIM >= 0.95 for comic and
sketch, identical for pixel art; the comic SVG holds vector dots or hatch lines and traced
outlines and no embedded image; the orbit's frames differ from each other (the camera turned)
and the GIF holds 3 frames (ffprobe); bad calls are refused with a Python exception. ParaView's
colour legend (vtkContext2DScalarBarActor) is in the comic figure as vectors: SSIM >= 0.95 over
the image and over the legend's corner, no embedded image but the tinted paper's.
"""
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "RealData"))
from figures import SSIM_MIN, rasterize, read_png, vector_content  # noqa: E402
from pvbatch_script import run_render_script  # noqa: E402
from vtkstylize_testing import vtkStylizeImageMetrics as M  # noqa: E402
import vtk  # noqa: E402
from vtk.util.numpy_support import vtk_to_numpy  # noqa: E402

prefix, log = run_render_script(sys.argv[1], "render_figures.py", sys.argv[2], "figure")
failures = []
print("| style | format | bytes | SSIM | pixels that differ |")
print("|---|---|---:|---:|---:|")
for name in ["comic", "pixel", "sketch"]:
    reference = read_png("%s-%s.png" % (prefix, name))
    w, h, _ = reference.GetDimensions()
    for ext in ("svg", "pdf"):
        figure = "%s-%s.%s" % (prefix, name, ext)
        if not os.path.exists(figure):
            failures.append("%s: not written" % figure)
            continue
        png = "%s-%s-%s.png" % (prefix, name, ext)
        rasterize(figure, png, w, h)
        image = read_png(png)
        if image.GetDimensions() != reference.GetDimensions():
            failures.append("%s: rasterized at %s, the screenshot is %s" % (
                figure, image.GetDimensions(), reference.GetDimensions()))
            continue
        ssim = M.SSIM(reference, image, 255.0)
        differ = M.CountDifferences(reference, image, 0.0)
        print("| %s | %s | %d | %.4f | %d |" % (name, ext, os.path.getsize(figure), ssim, differ))
        if name == "pixel" and differ:
            failures.append("%s: %d pixels differ from the screenshot (must be identical)" % (
                figure, differ))
        if name != "pixel" and ssim < SSIM_MIN:
            failures.append("%s: SSIM %.4f < %.2f" % (figure, ssim, SSIM_MIN))
# ParaView's colour legend, painted through vtkContext2D as vectors: the figure matches the
# screenshot over the whole image and over the legend's corner (which holds the legend's colours:
# without it the figure's corner is the background alone).
reference = read_png(prefix + "-bar.png")
w, h, _ = reference.GetDimensions()
corner = [int(0.7 * w), w - 1, 0, int(0.7 * h)]


def crop(image):
    voi = vtk.vtkExtractVOI()
    voi.SetInputData(image)
    voi.SetVOI(corner + [0, 0])
    voi.Update()
    return voi.GetOutput()


reds = vtk_to_numpy(crop(reference).GetPointData().GetScalars())
legend = int(((reds[:, 0].astype(int) - reds[:, 2]) > 60).sum())
if legend < 20:
    failures.append("the screenshot's corner holds no legend (%d red pixels)" % legend)
for ext in ("svg", "pdf"):
    figure = "%s-bar.%s" % (prefix, ext)
    if not os.path.exists(figure):
        failures.append("%s: not written" % figure)
        continue
    png = "%s-bar-%s.png" % (prefix, ext)
    rasterize(figure, png, w, h)
    image = read_png(png)
    ssim = M.SSIM(reference, image, 255.0)
    corner_ssim = M.SSIM(crop(reference), crop(image), 255.0)
    print("| comic + legend | %s | %d | %.4f (legend's corner %.4f) | |" % (
        ext, os.path.getsize(figure), ssim, corner_ssim))
    if ssim < SSIM_MIN or corner_ssim < SSIM_MIN:
        failures.append("%s: SSIM %.4f, legend's corner %.4f (< %.2f)" % (
            figure, ssim, corner_ssim, SSIM_MIN))
# (coloured by an array, the comic's paper takes the colour map's hues: a gradient embedded as
# one image under the vector ink; the legend, drawn after the layers, is vectors)
paths, images = vector_content(prefix + "-bar.svg")
if images > 1:
    failures.append("comic SVG with the legend: %d embedded images (the tinted paper's only "
                    "expected)" % images)
paths, images = vector_content(prefix + "-comic.svg")
if images or paths < 10:
    failures.append("comic SVG: %d paths, %d embedded images (vectors expected)" % (paths, images))
sketch_frames = ["%s-sketch-orbit-%04d.png" % (prefix, f) for f in range(2)]
if not all(os.path.exists(f) for f in sketch_frames):
    failures.append("sketch orbit frames missing: %s" % sketch_frames)
frames = ["%s-orbit-%04d.png" % (prefix, f) for f in range(3)]
if not all(os.path.exists(f) for f in frames):
    failures.append("orbit frames missing: %s" % [f for f in frames if not os.path.exists(f)])
else:
    a, b = read_png(frames[0]), read_png(frames[1])
    if M.CountDifferences(a, b, 16.0) == 0:
        failures.append("orbit frames 0 and 1 are the same: the camera did not turn")
probe = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0",
                        "-show_entries", "stream=nb_read_frames", "-of", "csv=p=0",
                        prefix + "-orbit.gif"], capture_output=True, text=True)
print("orbit GIF frames: %s" % probe.stdout.strip())
if probe.returncode != 0 or probe.stdout.strip() != "3":
    failures.append("orbit GIF: %r frames (3 expected) %s" % (probe.stdout.strip(), probe.stderr))
for line in log.splitlines():
    if line.startswith("refused:"):
        print(line)
for f in failures:
    print("FAIL: " + f)
sys.exit(1 if failures else 0)
