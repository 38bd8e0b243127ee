#!/usr/bin/python3
"""paraview.screenshots: a screenshot larger than the view equals the view rendered at that size.

    test_screenshots.py PVBATCH_WRAPPER OUTPUT_DIR

ParaView renders a screenshot larger than the view in tiles, one view-sized render each, and the
style after IceT sees only its tile: before, the tiles joined with seams (pixels more than 16
levels from the view rendered at the full size: comic 0.00 to 0.03%, pixel art 3.2 to 28%, sketch
2.5 to 5.2%, crossed bars at every tile border). The view's proxy now renders such a screenshot
in one piece (vtkSMStylizeViewProxy). render_screenshots.py saves each style magnified 2, 3, 4,
5 and 6 x 4 times and as the view resized to the same size. Checked:

- every magnified screenshot equals the direct render: no pixel more than 16 levels apart
  (pixel art at 6 x 4 has non-square art pixels, which the direct render cannot make: not
  compared);
- the view is left as it was: a view-sized screenshot after the magnified ones equals the one
  before exactly.
"""
import os
import sys

from vtkstylize_testing import vtkStylizeImageMetrics as M
from vtkmodules.vtkIOImage import vtkPNGReader
from pvbatch_script import run_render_script

prefix, _ = run_render_script(sys.argv[1], "render_screenshots.py", sys.argv[2], "shot")


def read(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


failures = []
print("| style | screenshot | magnification | pixels > 16 levels from the direct render |")
print("|---|---|---|---:|")
for name in ["comic", "pixel", "sketch"]:
    for target, factor in [("800x600", "2"), ("1200x900", "3"), ("1600x1200", "4"),
                           ("1000x750", "5"), ("1206x904", "6 x 4")]:
        stem = "%s-%s-%s" % (prefix, name, target)
        if not os.path.exists(stem + "-direct.png"):
            continue
        magnified, direct = read(stem + "-magnified.png"), read(stem + "-direct.png")
        if magnified.GetDimensions() != direct.GetDimensions():
            failures.append("%s: %s against %s" % (stem, magnified.GetDimensions(),
                                                   direct.GetDimensions()))
            continue
        differ = M.CountDifferences(magnified, direct, 16.0)
        print("| %s | %s | %s | %d |" % (name, target, factor, differ))
        if differ:
            failures.append("%s %s: %d pixels differ from the direct render" % (name, target,
                                                                                differ))
    before = read("%s-%s-before.png" % (prefix, name))
    after = read("%s-%s-after.png" % (prefix, name))
    if before.GetDimensions() != after.GetDimensions() or \
            M.MaximumDifference(before, after) != 0.0:
        failures.append("%s: the view changed after the magnified screenshots" % name)
if failures:
    sys.exit("FAIL:\n" + "\n".join(failures))
print("OK")
