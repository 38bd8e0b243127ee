#!/usr/bin/python3
"""paraview.realdata_mpi: real data split across 2 ranks against 1 rank, every style.

    test_realdata_mpi.py RANKS_DIR

render_realdata.py (run on 1 and on 2 ranks by paraview.ranks: test_ranks.py, render_ranks.py, one
pvbatch per rank count for every test that compares ranks; its images in RANKS_DIR) shows a scanned mesh (the bunny) and simulation output (the surface of an
Exodus II hexahedral mesh, the vessel), each split by Redistribute DataSet with a layer of ghost
cells (checked: on 2 ranks each rank holds part of each), in each style, and the sketch along the
Principal Curvatures filter's directions (computed per rank) on the bunny. After IceT compositing
each style reads the ranks' own normals, positions and directions composited by depth (issue 16),
so the 2-rank picture must be the 1-rank one: at most 0.5% of the pixels more than 16 levels
apart and SSIM >= 0.99, for ParaView's own image (Style None) as for each style. (The paraview.mpi
test does the same on the Wavelet contour.) The line art's SVG figure of the split bunny,
rasterized, has its line pixels within 1 px of the 1-rank figure's, both ways (>= 0.99).
"""
import os
import sys

from vtkstylize_testing import vtkStylizeImageMetrics as M
from vtkmodules.vtkIOImage import vtkPNGReader

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from pvbatch_script import ranks_run  # noqa: E402

ranks_dir = sys.argv[1]
failures = []


def read(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


prefixes = {}
for ranks in (1, 2):
    prefixes[ranks], log = ranks_run(ranks_dir, ranks, "realdata")
    pieces = dict(line.split()[1:3] for line in log.splitlines() if line.startswith("pieces "))
    print("%d rank(s): ranks holding part of each dataset: %s" % (ranks, pieces))
    for name in ("bunny", "vessel"):
        if pieces.get(name) != str(ranks):
            failures.append("%d rank(s): %s is not split across the ranks (%s)"
                            % (ranks, name, pieces.get(name)))

images = ["%s-%s" % (d, s) for d in ("bunny", "vessel") for s in ("none", "comic", "pixel", "sketch")]
images.insert(4, "bunny-sketch-model")
print("| image | SSIM | max difference | pixels > 16 levels |")
print("|---|---:|---:|---:|")
for name in images:
    a = read("%s-%s.png" % (prefixes[1], name))
    b = read("%s-%s.png" % (prefixes[2], name))
    dims = a.GetDimensions()
    pixels = dims[0] * dims[1]
    ssim = M.SSIM(a, b, 255.0)
    far = M.CountDifferences(a, b, 16.0)
    print("| %s | %.4f | %.0f | %d (%.2f%%) |" % (name, ssim, M.MaximumDifference(a, b), far,
                                                  100.0 * far / pixels))
    if far > 0.005 * pixels or ssim < 0.99:
        failures.append("%s: SSIM %.4f, %d pixels beyond 16 levels (at most 0.5%%)"
                        % (name, ssim, far))
    # each style ran after compositing: its picture is not ParaView's own
    dataset = name.split("-")[0]
    if not name.endswith("-none") and M.SSIM(read("%s-%s-none.png" % (prefixes[2], dataset)),
                                             b, 255.0) > 0.9:
        failures.append("%s: the 2-rank image looks unstylized" % name)

# the model directions act on 2 ranks: the sketch along them is not the screen estimate
change = M.CountDifferences(read("%s-bunny-sketch.png" % prefixes[2]),
                            read("%s-bunny-sketch-model.png" % prefixes[2]), 16.0)
print("bunny sketch-model vs sketch on 2 ranks: %d pixels beyond 16 levels" % change)
if change < 1000:
    failures.append("model directions barely change the 2-rank sketch (%d pixels)" % change)

# The line art's vector figure of the split bunny: every rank's lines, as on 1 rank (issue 53: it
# held rank 0's half and drew the cut). Rasterized, the line pixels (darker than mid-grey) of each
# within 1 px of the other's, both ways.
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "RealData"))
from figures import rasterize  # noqa: E402
import numpy  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402


def line_pixels(svg):
    png = svg[:-4] + "-svg.png"
    rasterize(svg, png, 360, 300)
    image = read(png)
    w, h, _ = image.GetDimensions()
    rgb = vtk_to_numpy(image.GetPointData().GetScalars()).reshape(h, w, -1)[:, :, :3]
    return rgb.astype(float).mean(axis=2) < 128.0


def within_one_pixel(a, b):
    """The share of a's pixels with one of b's within 1 px (b dilated by a 3 x 3 square)."""
    grown = numpy.zeros_like(b)
    padded = numpy.pad(b, 1)
    for dy in range(3):
        for dx in range(3):
            grown |= padded[dy:dy + b.shape[0], dx:dx + b.shape[1]]
    return float((a & grown).sum()) / max(1, int(a.sum()))


one, two = (line_pixels("%s-bunny-lines.svg" % prefixes[r]) for r in (1, 2))
recall, precision = within_one_pixel(one, two), within_one_pixel(two, one)
print("line-art SVG, 2 ranks against 1: %d / %d line pixels; 1-rank lines within 1 px of the "
      "2-rank figure's: %.4f, 2-rank within 1 px of 1-rank: %.4f"
      % (two.sum(), one.sum(), recall, precision))
if one.sum() < 300 or min(recall, precision) < 0.99:
    failures.append("the 2-rank line-art figure is not the 1-rank one: %.4f / %.4f (at least "
                    "0.99 both ways)" % (recall, precision))

for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
