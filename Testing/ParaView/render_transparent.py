"""Renders each style twice, on the view's background and with a transparent background.

    pvbatch-stylize render_transparent.py OUTPUT_PREFIX

Writes OUTPUT_PREFIX-<style>-opaque.png and -<style>-transparent.png (RGBA) for comic, pixel and
sketch, 400x300, the scene of render_styles.py (a Wavelet contour) on a coloured background, and
-sketch-tinted-*.png (the sketch on tinted paper).
"""
import sys

from paraview.simple import *  # noqa: F401,F403
from stylize_pv_scene import make_contour, make_view, show_framed

prefix = sys.argv[1]
size = [400, 300]
view = CreateView("StylizeView")
make_view(view, size)
show_framed(make_contour(), view)
for style, name in [(1, "comic"), (2, "pixel"), (3, "sketch"), (3, "sketch-tinted")]:
    view.Style = style
    view.SketchTint = 2 if name == "sketch-tinted" else 0
    Render(view)
    SaveScreenshot("%s-%s-opaque.png" % (prefix, name), view, ImageResolution=size)
    SaveScreenshot("%s-%s-transparent.png" % (prefix, name), view, ImageResolution=size,
                   TransparentBackground=1)
    # the view is left as it was: the next opaque render is the same as the first
    SaveScreenshot("%s-%s-after.png" % (prefix, name), view, ImageResolution=size)
Delete(view)
print("rendered")
