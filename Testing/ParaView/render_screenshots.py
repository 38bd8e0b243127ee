"""Renders each style as a screenshot larger than the view and as the view at that size.

    pvbatch-stylize render_screenshots.py OUTPUT_PREFIX

The scene of render_styles.py (a Wavelet contour) in a 400x300 view. For each style and target
size: OUTPUT_PREFIX-<style>-<W>x<H>-magnified.png, SaveScreenshot at the target size (ParaView
magnifies the view by a factor of the target: 2, 3, 4, 5, and 6 x 4 for 1206x904), and
-direct.png, the view resized to the target and saved at its own size (pixel art's
PixelArtPixelSize times the magnification, as the magnified screenshot scales it). Then
-before.png and -after.png, view-sized screenshots before and after the magnified ones.
"""
import sys

from paraview.simple import *  # noqa: F401,F403
from stylize_pv_scene import make_contour, make_view, show_framed

prefix = sys.argv[1]
size = [400, 300]
view = CreateView("StylizeView")
make_view(view, size)
show_framed(make_contour(), view)
TARGETS = [[800, 600], [1200, 900], [1600, 1200], [1000, 750], [1206, 904]]


def magnification(target):
    """ParaView's factor (vtkSMSaveScreenshotProxy): the least one that fits in the view."""
    for m in range(1, 65):
        if target[0] % m == 0 and target[1] % m == 0 and target[0] // m <= size[0] and \
                target[1] // m <= size[1]:
            return m
    return None  # a factor per axis: the direct render cannot make non-square art pixels


for style, name in [(1, "comic"), (2, "pixel"), (3, "sketch")]:
    view.Style = style
    Render(view)
    SaveScreenshot("%s-%s-before.png" % (prefix, name), view, ImageResolution=size)
    for t in TARGETS:
        stem = "%s-%s-%dx%d" % (prefix, name, t[0], t[1])
        SaveScreenshot(stem + "-magnified.png", view, ImageResolution=t)
        m = magnification(t)
        if style == 2 and m is None:
            continue
        view.ViewSize = t
        view.PixelArtPixelSize = 4 * (m or 1)
        Render(view)
        SaveScreenshot(stem + "-direct.png", view, ImageResolution=t)
        view.ViewSize = size
        view.PixelArtPixelSize = 4
    Render(view)
    SaveScreenshot("%s-%s-after.png" % (prefix, name), view, ImageResolution=size)
Delete(view)
print("rendered")
