"""The styles' interactive variant (issue 15).

While the render window asks for an interactive update rate (VTK's interactors set 15 frames per
second while the user drags, ParaView's interactive renders 5), each style renders a cheaper
variant; the still frame after it is the full-quality image. For each style this test requires:

- an interactive frame (desired update rate 15) differs from the still frame of the same view
  (the variant was taken), and its picture is of the same scene (a similar share of dark ink);
- the still frame rendered after interactive frames is identical to a still frame rendered by a
  fresh pass (nothing of the variant lingers);
- with InteractiveUpdateRate 0 an interactive frame is identical to the still frame (the setting
  turns the variant off), and at ParaView's still rate (0.002) nothing changes either.

Run with the build's python folder on PYTHONPATH and a display (the suite does both).
"""
import sys

import vtkstylize
from vtkmodules.vtkCommonCore import vtkUnsignedCharArray
from vtkmodules.vtkRenderingCore import vtkRenderer

from stylize_test_scene import check, failures, offscreen_window, style_maker, torus_actor


def make_window():
    win = offscreen_window(300, 200)
    ren = vtkRenderer()
    ren.SetBackground(1.0, 1.0, 1.0)
    win.AddRenderer(ren)
    ren.AddActor(torus_actor(0.4, 55.0))
    ren.ResetCamera()
    ren.GetActiveCamera().Azimuth(20.0)
    return win, ren


def frame(win, rate):
    win.SetDesiredUpdateRate(rate)
    win.Render()
    rgba = vtkUnsignedCharArray()
    w, h = win.GetSize()
    win.GetRGBACharPixelData(0, 0, w - 1, h - 1, 0, rgba)
    return [rgba.GetValue(i) for i in range(rgba.GetNumberOfTuples() * 4)]


def ink(values):
    """Share of pixels darker than mid-grey."""
    n = len(values) // 4
    dark = sum(1 for i in range(n) if sum(values[4 * i:4 * i + 3]) < 3 * 128)
    return dark / n


STYLES = (
    ("comic", style_maker("vtkComicPass")),
    ("comic-principal",
     style_maker("vtkComicPass", HatchOrientation=vtkstylize.vtkComicPass.PRINCIPAL)),
    ("sketch", style_maker("vtkSketchPass")),
    ("pixel-faithful", style_maker("vtkPixelArtPass", Mode=vtkstylize.vtkPixelArtPass.FAITHFUL)),
)

STILL, INTERACTIVE, PARAVIEW_STILL = 0.0001, 15.0, 0.002

for name, make in STYLES:
    win, ren = make_window()
    style = make()
    ren.SetPass(style)
    still = frame(win, STILL)
    interactive = frame(win, INTERACTIVE)
    frame(win, INTERACTIVE)
    after = frame(win, STILL)
    paraview_still = frame(win, PARAVIEW_STILL)
    style.SetInteractiveUpdateRate(0.0)
    off = frame(win, INTERACTIVE)
    ren.SetPass(None)
    win.Finalize()

    win2, ren2 = make_window()
    fresh_style = make()
    ren2.SetPass(fresh_style)
    fresh = frame(win2, STILL)
    ren2.SetPass(None)
    win2.Finalize()

    changed = sum(1 for a, b in zip(still, interactive) if a != b)
    print("%-16s interactive frame differs at %d values; ink %.3f still, %.3f interactive" %
          (name, changed, ink(still), ink(interactive)))
    check(changed > 0, name + ": the interactive frame is the still one (no variant)")
    check(abs(ink(still) - ink(interactive)) < 0.5 * ink(still) + 0.01,
          name + ": the interactive variant draws another picture")
    check(after == fresh, name + ": the still frame after interaction differs from a fresh one")
    check(after == still, name + ": the still frame after interaction differs from the first")
    check(paraview_still == still, name + ": ParaView's still rate took the variant")
    check(off == still, name + ": InteractiveUpdateRate 0 did not turn the variant off")

if failures:
    print("%d failure(s)" % len(failures))
    sys.exit(1)
print("interactive: every style's variant is taken while interacting, and only then")
