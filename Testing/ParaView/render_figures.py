"""Writes each style as a PNG screenshot and as a vector figure, and an orbit, from pvbatch.

    pvbatch-stylize render_figures.py OUTPUT_PREFIX

The scene of render_styles.py (a Wavelet contour) in a 400x300 view, with the plugin's Python
module (stylize_paraview, embedded in the plugin): OUTPUT_PREFIX-<style>.png (SaveScreenshot),
-<style>.svg and .pdf (SaveStylizedFigure, one call each); the comic with ParaView's colour
legend (the contour coloured by its normals' z): OUTPUT_PREFIX-bar.png, .svg, .pdf; then a
3-frame comic orbit,
OUTPUT_PREFIX-orbit.gif with its frames OUTPUT_PREFIX-orbit-0000.png ... (SaveStylizedOrbit, one
call), the view's anchor as it was after the orbit, and a 2-frame sketch orbit after which the
view's noise settings are as they were; then the failures: a figure of the style None and an
orbit to a .txt are refused with RuntimeError/ValueError.
"""
import sys

from paraview.simple import *  # noqa: F401,F403
from stylize_pv_scene import make_contour, make_view, show_framed

import stylize_paraview as stylize

prefix = sys.argv[1]
size = [400, 300]
view = CreateView("StylizeView")
make_view(view, size)
# 1 point = 1 pixel: the comic's 8-point cells are 8 pixels, which the screenshot draws as the
# figure does (at the default 1080-line reference they are 2.2 pixels of this view: the
# screenshot fades them to the tone, the vector figure keeps them)
view.ComicReferenceHeight = size[1]
show_framed(make_contour(), view)
for style, name in [("Comic", "comic"), ("Pixel art", "pixel"), ("Sketch", "sketch")]:
    view.Style = style
    Render(view)
    SaveScreenshot("%s-%s.png" % (prefix, name), view, ImageResolution=size)
    for ext in ("svg", "pdf"):
        stylize.SaveStylizedFigure("%s-%s.%s" % (prefix, name, ext), view)
# ParaView's colour legend (a vtkContext2DScalarBarActor, not a vtkScalarBarActor) painted into
# the figure as vectors: the contour coloured by its normals' z, the legend shown.
view.Style = "Comic"
contour = FindSource("Contour1")
display = GetDisplayProperties(contour, view)
ColorBy(display, ("POINTS", "Normals", "Z"))
display.SetScalarBarVisibility(view, True)
Render(view)
SaveScreenshot(prefix + "-bar.png", view, ImageResolution=size)
for ext in ("svg", "pdf"):
    stylize.SaveStylizedFigure("%s-bar.%s" % (prefix, ext), view)
display.SetScalarBarVisibility(view, False)
ColorBy(display, None)
anchor = str(view.ComicAnchor)
written = stylize.SaveStylizedOrbit(prefix + "-orbit.gif", view, frames=3, degrees=30)
print("orbit: " + " ".join(written))
if str(view.ComicAnchor) != anchor:
    sys.exit("the orbit left ComicAnchor at %s (was %s)" % (view.ComicAnchor, anchor))
# The sketch's orbit uses the object-space SPARSE noise and gives the view's noise back.
view.Style = "Sketch"
noise = (str(view.SketchNoise), str(view.SketchNoiseSpace))
written = stylize.SaveStylizedOrbit(prefix + "-sketch-orbit.png", view, frames=2, degrees=2)
print("sketch orbit: " + " ".join(written))
if (str(view.SketchNoise), str(view.SketchNoiseSpace)) != noise:
    sys.exit("the orbit left the sketch's noise at %s, %s (was %s)" % (
        view.SketchNoise, view.SketchNoiseSpace, noise))
refused = 0
bad_calls = [  # (style, call, the exception it must raise)
    ("None", lambda: stylize.SaveStylizedFigure(prefix + "-none.svg", view), RuntimeError),
    ("Comic", lambda: stylize.SaveStylizedOrbit(prefix + "-orbit.txt", view, frames=2), ValueError),
    ("Sketch", lambda: stylize.SaveStylizedFigure(prefix + "-figure.png", view), RuntimeError),
    # outside ORBIT_OPTIONS' ranges (those of vtkstylize --orbit and --orbit-elevation)
    ("Comic", lambda: stylize.SaveStylizedOrbit(prefix + "-orbit.gif", view, frames=3601),
     ValueError),
    ("Comic", lambda: stylize.SaveStylizedOrbit(prefix + "-orbit.gif", view, elevation=90),
     ValueError),
]
for style, call, expected in bad_calls:
    view.Style = style
    try:
        call()
    except expected as error:
        print("refused: %s" % error)
        refused += 1
if refused != len(bad_calls):
    sys.exit("%d of %d bad calls refused" % (refused, len(bad_calls)))
Delete(view)
print("rendered")
