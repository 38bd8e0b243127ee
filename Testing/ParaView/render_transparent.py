"""Renders each style twice, on the view's background and with a transparent background.

    pvbatch-stylize render_transparent.py OUTPUT_PREFIX

Writes OUTPUT_PREFIX-<style>-opaque.png and -<style>-transparent.png (RGBA) for comic, pixel and
sketch, 400x300, the scene of render_styles.py (a Wavelet contour) on a coloured background, and
-sketch-tinted-*.png (the sketch on tinted paper).
"""
import sys

from paraview.simple import *  # noqa: F401,F403

prefix = sys.argv[1]
size = [400, 300]
view = CreateView("StylizeView")
view.ViewSize = size
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0
view.Background = [0.32, 0.34, 0.43]
contour = Contour(Input=Wavelet(), ContourBy=["POINTS", "RTData"], Isosurfaces=[157.0])
display = Show(contour, view)
ColorBy(display, None)
view.CameraPosition = [30.0, -45.0, 25.0]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
view.ResetCamera()
for style, name in [(1, "comic"), (2, "pixel"), (3, "sketch"), (3, "sketch-tinted")]:
    view.Style = style
    view.SketchTinted = 1 if name == "sketch-tinted" else 0
    Render(view)
    SaveScreenshot("%s-%s-opaque.png" % (prefix, name), view, ImageResolution=size)
    SaveScreenshot("%s-%s-transparent.png" % (prefix, name), view, ImageResolution=size,
                   TransparentBackground=1)
    # the view is left as it was: the next opaque render is the same as the first
    SaveScreenshot("%s-%s-after.png" % (prefix, name), view, ImageResolution=size)
Delete(view)
print("rendered")
