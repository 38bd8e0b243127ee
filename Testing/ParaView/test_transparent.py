#!/usr/bin/python3
"""paraview.transparent_background: a transparent-background screenshot keeps the style.

    test_transparent.py PVBATCH_WRAPPER OUTPUT_DIR

render_transparent.py saves each style (comic, pixel art, sketch, sketch on tinted paper) on a
coloured background and with TransparentBackground=1 (ParaView renders over white and over
black and makes transparent what differs). Checked per style:

- the transparent image composited over the view's background is the opaque image: at most
  0.05% of the pixels more than 16 levels apart (measured: 0, 0, 5 and 5 pixels of 120,000);
- what became transparent is the background: the transparent pixels number the opaque image's
  background-coloured pixels within 0.05%, and no background-coloured pixel is partly
  transparent beyond that (a partly transparent pixel is ink over the background: the sketch's
  feature lines reach half their width beyond the silhouette, anti-aliased);
- the view is left as it was: an opaque screenshot after it equals the first exactly.

Before (ParaView 5.11 renders the style over white and over black, and the style's ink followed
the background): the sketch's paper turned transparent inside the objects and the pixel-art
outlines thickened (2,480 pixels, as the issue measured it).
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Python"))
from pvbatch_script import run_render_script  # noqa: E402
from stylize_png import png_array as load  # noqa: E402

prefix, _ = run_render_script(sys.argv[1], "render_transparent.py", sys.argv[2], "transparent")


background = np.array([0.32, 0.34, 0.43]) * 255.0  # stylize_pv_scene.BACKGROUND
failures = []
print("| style | composited vs opaque, pixels > 16 levels | transparent | background in the opaque image | partly transparent |")
print("|---|---:|---:|---:|---:|")
for name in ["comic", "pixel", "sketch", "sketch-tinted"]:
    opaque = load("%s-%s-opaque.png" % (prefix, name))[:, :, :3]
    transparent = load("%s-%s-transparent.png" % (prefix, name))
    after = load("%s-%s-after.png" % (prefix, name))[:, :, :3]
    if transparent.shape[2] != 4:
        failures.append("%s: the transparent screenshot has no alpha" % name)
        continue
    pixels = opaque.shape[0] * opaque.shape[1]
    alpha = transparent[:, :, 3:4] / 255.0
    composited = transparent[:, :, :3] * alpha + background * (1.0 - alpha)
    far = int((np.abs(composited - opaque).max(axis=2) > 16).sum())
    clear = int((alpha[:, :, 0] == 0).sum())
    ground_mask = np.abs(opaque - background).max(axis=2) <= 1
    partial_mask = (alpha[:, :, 0] > 0) & (alpha[:, :, 0] < 1)
    partial = int(partial_mask.sum())
    partial_ground = int((partial_mask & ground_mask).sum())
    ground = int(ground_mask.sum())
    print("| %s | %d | %d | %d | %d |" % (name, far, clear, ground, partial))
    if far > 0.0005 * pixels:
        failures.append("%s: %d pixels differ from the opaque screenshot" % (name, far))
    if abs(clear - ground) > 0.0005 * pixels or partial_ground > 0.0005 * pixels:
        failures.append("%s: %d transparent and %d partly transparent background pixels for %d "
                        "background" % (name, clear, partial_ground, ground))
    if np.abs(after - opaque).max() > 0:
        failures.append("%s: the view did not come back to its opaque picture" % name)
for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
