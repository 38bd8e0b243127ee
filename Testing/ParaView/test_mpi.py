#!/usr/bin/python3
"""paraview.mpi: the same scene on 1 and on 2 ranks (mpiexec -n N pvbatch), each style compared.

    test_mpi.py RANKS_DIR OUTPUT_DIR [BASELINE_DIR]

RANKS_DIR holds the renders of the Wavelet contour (render_styles.py) on 1 and on 2 ranks, made by
paraview.ranks (test_ranks.py, render_ranks.py: one pvbatch per rank count for every test that
compares ranks).

With 2 ranks the data is split (each rank holds a piece: checked), each rank lights its piece
(the lighting pass, before IceT compositing) and the style runs once on the composited colour
and depth. With 1 rank there is no compositing. Tolerances, from what differs and why:

- none (ParaView's own rendering): at most 2 levels apart (IceT's blending over the background
  rounds differently by one level).
- comic-subject: comic with a Stylized Surface's own subject factor 1 (per-representation
  lighting, applied by each rank to its piece): as for the comic below, and it must change
  the 2-rank image (at least 2000 pixels beyond 16 levels from the comic image).
- sketch-model: the sketch along the Principal Curvatures filter's directions (the point data's
  tangents, composited by depth like the normals): as for the sketch below, and it must change
  the sketch on 1 and on 2 ranks (at least 1000 pixels beyond 16 levels). (It differed by 1.6%
  while the G-buffer blended its direction channel with what the pixel held before: a rank's piece
  is drawn in another order than the whole contour; measured 0.02% since.)
- comic (and comic-subject), pixel art, sketch, line art: at most 0.5% of the pixels more than 16
  levels apart, SSIM >= 0.99. The feature lines (line art, the comic's and the sketch's line
  phase) of each rank's pieces are tested against the composited depth, with the whole data's
  thresholds, and their ink combined on rank 0. The ranks' normals reach the style composited by depth
  (vtkStylizeGBufferPass::SetChannelSource), and IceT's transparent background is taken as the
  view's background by the stages that read colour across a silhouette (Canny, the sketch's
  tone blur; vtkStylizeGBufferPass::SetImageBackground), so the picture is the one rank's
  (measured: comic 0, pixel art 0.03%, sketch 0.03%, from the odd pixel along a boundary
  between the ranks' pieces; before the background: pixel art 0.95%, sketch 0.55%).

On both rank counts ParaView's progress bar must be told the line art's progress while it finds
its lines (render_styles.py's "progress lines" line: a value below 100%).

With BASELINE_DIR, the 1-rank images are also regression images: each must match
BASELINE_DIR/paraview.<style>.png with at most 0.2% of the pixels more than 2 levels apart and
none more than 32 (llvmpipe renders the same image byte for byte; the margin is for another
Mesa). A missing baseline fails and names the image to copy there.
"""
import os
import shutil
import sys

from vtkstylize_testing import vtkStylizeImageMetrics
from vtkmodules.vtkIOImage import vtkPNGReader

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from pvbatch_script import ranks_run  # noqa: E402

ranks_dir, out = sys.argv[1], sys.argv[2]
baselines = sys.argv[3] if len(sys.argv) > 3 else None
os.makedirs(out, exist_ok=True)
failures = []


def run(ranks):
    """The contour's renders on `ranks` ranks: their prefix and the "ranks ..." line's fields."""
    prefix, log = ranks_run(ranks_dir, ranks, "contour")
    sys.stdout.write(log + "\n")
    pieces = [line for line in log.splitlines() if line.startswith("ranks")]
    # ParaView's progress bar was given the line art's progress while it found its lines (the
    # handler drops events closer than its interval: the last, 100%, may not come)
    reports = [line.split()[2:] for line in log.splitlines() if line.startswith("progress lines")]
    values = [int(v) for v in reports[-1]] if reports else []
    if not values or min(values) >= 100:
        failures.append("%d ranks: the line art's progress reached ParaView as %s" % (ranks, values))
    return prefix, pieces[-1].split() if pieces else []


def read(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


one, info1 = run(1)
two, info2 = run(2)
if len(info2) < 4 or int(info2[3]) != 2:
    failures.append("the data is not split across the 2 ranks: %s" % " ".join(info2))

M = vtkStylizeImageMetrics
print("| style | SSIM | max difference | pixels > 16 levels | PSNR dB |")
print("|---|---:|---:|---:|---:|")
for name in ["none", "comic", "pixel", "sketch", "lines", "comic-subject", "sketch-model"]:
    a = read("%s-%s.png" % (one, name))
    b = read("%s-%s.png" % (two, name))
    dims = a.GetDimensions()
    pixels = dims[0] * dims[1]
    ssim = M.SSIM(a, b, 255.0)
    worst = M.MaximumDifference(a, b)
    far = M.CountDifferences(a, b, 16.0)
    psnr = M.PSNR(a, b, 255.0)
    print("| %s | %.4f | %.0f | %d (%.2f%%) | %.1f |" % (name, ssim, worst, far,
          100.0 * far / pixels, psnr))
    if name == "none":
        if worst > 2:
            failures.append("none: 1 and 2 ranks differ (max %g)" % worst)
    elif far > 0.005 * pixels or ssim < 0.99:
        failures.append("%s: SSIM %.4f, %d pixels beyond 16 levels (at most 0.5%%)"
                        % (name, ssim, far))
    # each style must differ from ParaView's own image (the style ran after compositing)
    if name != "none" and M.SSIM(read("%s-none.png" % two), b, 255.0) > 0.9:
        failures.append("%s: the 2-rank image looks unstylized" % name)

# per-representation lighting reached every rank: the subject factor changes the 2-rank image
# (everywhere: a rank without the setting would leave its piece as in the comic image)
subject_change = M.CountDifferences(read("%s-comic.png" % two), read("%s-comic-subject.png" % two), 16.0)
print("comic-subject vs comic on 2 ranks: %d pixels beyond 16 levels" % subject_change)
if subject_change < 2000:
    failures.append("the Stylized Surface subject factor barely changes the 2-rank image")

# model directions reached the style on every rank count: the Principal Curvatures filter's
# tangents change the sketch
for prefix, ranks in [(one, 1), (two, 2)]:
    model_change = M.CountDifferences(read("%s-sketch.png" % prefix),
                                      read("%s-sketch-model.png" % prefix), 16.0)
    print("sketch-model vs sketch on %d rank(s): %d pixels beyond 16 levels" % (ranks, model_change))
    if model_change < 1000:
        failures.append("model directions barely change the %d-rank sketch (%d pixels)"
                        % (ranks, model_change))

if baselines:
    for name in ["none", "comic", "pixel", "sketch", "lines"]:
        image = "%s-%s.png" % (one, name)
        baseline = os.path.join(baselines, "paraview.%s.png" % name)
        if not os.path.exists(baseline):
            failures.append("no baseline %s: copy %s there if it is right" % (baseline, image))
            continue
        a, b = read(image), read(baseline)
        if a.GetDimensions() != b.GetDimensions():
            failures.append("%s: size %s, baseline %s" % (name, a.GetDimensions(), b.GetDimensions()))
            continue
        dims = a.GetDimensions()
        worst = M.MaximumDifference(a, b)
        far = M.CountDifferences(a, b, 2.0)
        print("baseline %s: max difference %g levels, %d pixels beyond 2 levels" % (name, worst, far))
        if worst > 32 or far > 0.002 * dims[0] * dims[1]:
            shutil.copy(image, os.path.join(out, "paraview.%s.failed.png" % name))
            failures.append("%s differs from its baseline (max %g, %d pixels beyond 2 levels)"
                            % (name, worst, far))

for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
