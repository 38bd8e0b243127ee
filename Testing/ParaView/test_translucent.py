"""paraview.translucent: translucent surfaces are stylized in ParaView's view (issue 16).

    test_translucent.py PVBATCH_WRAPPER DATA_DIR OUTPUT_DIR

render_translucent.py renders the bunny scan at opacity 0.35 around the pinion gear in each
style (one process: the style draws the translucent layers from the props, the rank's pass
leaves them out of the composited image). Checked per style, against ParaView's own rendering
for where the bunny and the gear are:

- the translucent bunny is stylized: at least 20% of its pixels differ (more than 16 levels)
  from the same view with TranslucentLayers 0, where it is drawn plain, as before;
- the view's depth peeling (on by default) changes no pixel when turned off;
- the gear shows through the translucent bunny (its pixels differ from the picture without the
  gear by more than 8 levels on average) and not at all through the bunny at opacity 1.

With several processes each rank draws its translucent geometry plain and IceT composites it
(a layer of the whole scene would need every rank's props): docs/paraview.md.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Python"))
from pvbatch_script import run_render_script  # noqa: E402
from stylize_png import png_array  # noqa: E402

pvbatch, data, out = sys.argv[1], sys.argv[2], sys.argv[3]
prefix = run_render_script(pvbatch, "render_translucent.py", out, "translucent", data)


def load(name):
    return png_array("%s-%s.png" % (prefix, name))[:, :, :3]


def differs(a, b, tolerance=16):
    return np.abs(a - b).max(axis=2) > tolerance


empty = load("none-empty")
bunny = differs(load("none-bunny"), empty)
gear = differs(load("none-gear"), empty)
inside = gear & bunny
failures = []


def check(cond, message):
    if not cond:
        failures.append(message)
        print("FAIL:", message)


print("bunny %d px, gear %d px, %d of them inside the bunny" % (
    np.count_nonzero(bunny), np.count_nonzero(gear), np.count_nonzero(inside)))
check(np.count_nonzero(gear) > 1000 and np.count_nonzero(inside) == np.count_nonzero(gear),
      "the gear should lie inside the bunny on the screen")
print("| style | differ from plain (of the bunny's) | depth peeling off | gear shows through "
      "(mean levels) | through the opaque bunny |")
print("|---|---:|---:|---:|---:|")
for name in ["comic", "pixel", "sketch"]:
    layers = load(name + "-layers")
    restyled = np.count_nonzero(differs(layers, load(name + "-plain")) & bunny)
    peeling = np.count_nonzero(differs(layers, load(name + "-peeling"), 0))
    shows = float(np.abs(layers - load(name + "-nogear")).max(axis=2)[inside].mean())
    opaque = np.count_nonzero(differs(load(name + "-opaque"), load(name + "-opaque-nogear")))
    print("| %s | %d (%.0f%%) | %d | %.1f | %d |" % (
        name, restyled, 100.0 * restyled / max(1, np.count_nonzero(bunny)), peeling, shows,
        opaque))
    check(restyled > 0.2 * np.count_nonzero(bunny), "%s: the translucent bunny is not stylized"
          % name)
    check(peeling == 0, "%s: depth peeling changed %d pixels" % (name, peeling))
    check(shows > 8.0, "%s: the gear does not show through (%.1f)" % (name, shows))
    check(opaque == 0, "%s: the gear shows through the opaque bunny (%d px)" % (name, opaque))
if failures:
    sys.exit("%d failure(s)" % len(failures))
print("OK")
