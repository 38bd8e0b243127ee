"""Writes the view with each kind of overlay, as a screenshot and as vector figures (issue 40).

    pvbatch-stylize render_overlays.py OUTPUT_PREFIX

The contour of render_styles.py in a 400x300 view, for the comic and the sketch, once without
overlays (OUTPUT_PREFIX-<style>-none.png) and once with each overlay alone: the orientation axes
(axes), the data axes grid (cube axes: grid), a Text source (text) and the colour legend of the
contour coloured by its normals' z (legend): OUTPUT_PREFIX-<style>-<overlay>.png, .svg and .pdf
(SaveScreenshot, SaveStylizedFigure). test_overlays.py compares them.
"""
import sys

from paraview.simple import (ColorBy, CreateView, Delete, GetDisplayProperties, Render,
                             SaveScreenshot, Show, Text)
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
contour = make_contour()
show_framed(contour, view)
display = GetDisplayProperties(contour, view)
label = Text(Text="Pressure 2 bar")
label_display = Show(label, view)
label_display.WindowLocation = "Upper Left Corner"
label_display.FontSize = 20
label_display.Color = [0.0, 0.0, 0.0]
label_display.Visibility = 0


def overlay(name, on):
    if name == "axes":
        view.OrientationAxesVisibility = on
    elif name == "grid":
        display.DataAxesGrid.GridAxesVisibility = on
    elif name == "text":
        label_display.Visibility = on
    elif name == "legend":
        if on:
            ColorBy(display, ("POINTS", "Normals", "Z"))
        display.SetScalarBarVisibility(view, bool(on))
        if not on:
            ColorBy(display, None)


for style in ("Comic", "Sketch"):
    view.Style = style
    stem = "%s-%s" % (prefix, style.lower())
    Render(view)
    SaveScreenshot(stem + "-none.png", view, ImageResolution=size)
    for name in ("axes", "grid", "text", "legend"):
        overlay(name, 1)
        Render(view)
        SaveScreenshot("%s-%s.png" % (stem, name), view, ImageResolution=size)
        for ext in ("svg", "pdf"):
            stylize.SaveStylizedFigure("%s-%s.%s" % (stem, name, ext), view)
        overlay(name, 0)
print("rendered")
Delete(view)  # (before exiting: see test_styles.py)
