"""Renders a translucent scan around an opaque CAD part in the stylized view, for
test_translucent.py.

    pvbatch-stylize render_translucent.py OUTPUT_PREFIX DATA_DIR [split]
    mpiexec -n N pvbatch-stylize render_translucent.py OUTPUT_PREFIX DATA_DIR split

The bunny scan at opacity 0.35 (or 1) around the pinion gear (both from the real-data set), a
300x240 view. For each style: OUTPUT_PREFIX-<style>-<case>.png with the cases
  layers      the default (TranslucentLayers 4: the style draws the translucent layers)
  peeling     the same with the view's depth peeling off (on is ParaView's default)
  plain       TranslucentLayers 0 (the translucent surface drawn unstylized, as before)
  nogear      the default without the gear
  opaque      the bunny at opacity 1;  opaque-nogear  the same without the gear
and, for the masks, none-bunny, none-gear and none-empty: ParaView's own rendering (Style None)
of the bunny alone, the gear alone and nothing. With "split" both meshes go through ParaView's
Redistribute DataSet filter, so that on several ranks each rank holds part of the bunny and part
of the gear, and the script prints "pieces BUNNY GEAR": how many ranks hold part of each; it then
renders only the cases the ranks are compared on (layers, peeling, nogear, opaque).
"""
import sys

import paraview.simple as simple
from paraview.simple import (CreateView, Hide, PLYReader, Render, SaveScreenshot, Show,
                             Transform)
from stylize_pv_scene import make_view

prefix, data = sys.argv[1], sys.argv[2]
split = len(sys.argv) > 3 and sys.argv[3] == "split"
view = CreateView("StylizeView")
make_view(view, [300, 240])
view.Background = [1.0, 1.0, 1.0]

bunny = PLYReader(FileNames=[data + "/bunny.ply"])
gear = PLYReader(FileNames=[data + "/pinion.ply"])
bunny.UpdatePipeline()
gear.UpdatePipeline()
b = bunny.GetDataInformation().GetBounds()
g = gear.GetDataInformation().GetBounds()
cb = [(b[2 * i] + b[2 * i + 1]) / 2 for i in range(3)]
cg = [(g[2 * i] + g[2 * i + 1]) / 2 for i in range(3)]
sb = max(b[1] - b[0], b[3] - b[2], b[5] - b[4])
sg = max(g[1] - g[0], g[3] - g[2], g[5] - g[4])
scale = 0.5 * sb / sg  # the gear inside the bunny's body, as in Testing/Python/test_translucent.py
body = [0.1 * sb, -0.12 * sb, 0.0]
placed = Transform(Input=gear)
placed.Transform.Scale = [scale] * 3
placed.Transform.Translate = [cb[i] + body[i] - scale * cg[i] for i in range(3)]

if split:
    counts = []
    for name in ("bunny", "placed"):
        parts = simple.RedistributeDataSet(Input=globals()[name])
        ids = (getattr(simple, "GenerateProcessIds", None) or simple.ProcessIdScalars)(Input=parts)
        ids.UpdatePipeline()
        array = ids.PointData.GetArray("ProcessId")
        low, high = array.GetRange() if array else (0, 0)
        counts.append(int(high - low) + 1)
        globals()[name] = parts
    print("pieces %d %d" % tuple(counts))

bunny_display = Show(bunny, view)
gear_display = Show(placed, view)
for d, colour in ((bunny_display, [0.4, 0.6, 0.9]), (gear_display, [0.85, 0.45, 0.25])):
    d.ColorArrayName = ["POINTS", ""]
    d.AmbientColor = colour
    d.DiffuseColor = colour
bunny_display.Opacity = 0.35
view.CameraFocalPoint = cb
view.CameraPosition = [cb[0], cb[1], cb[2] + 3.0 * sb]
view.CameraViewUp = [0.0, 1.0, 0.0]
view.CameraViewAngle = 30.0


def shot(name, compared_on_ranks=False):
    if split and not compared_on_ranks:
        return  # (the ranks are compared on layers, peeling, nogear and opaque)
    Render(view)
    SaveScreenshot("%s-%s.png" % (prefix, name), view, ImageResolution=[300, 240])


view.Style = 0
Hide(placed, view)
shot("none-bunny")
Show(placed, view)
Hide(bunny, view)
shot("none-gear")
Hide(placed, view)
shot("none-empty")
Show(bunny, view)
Show(placed, view)
for style, name in [(1, "comic"), (2, "pixel"), (3, "sketch")]:
    view.Style = style
    shot(name + "-layers", True)
    peeling = view.DepthPeeling
    view.DepthPeeling = 0
    shot(name + "-peeling", True)
    view.DepthPeeling = peeling
    layers = {1: "Comic", 2: "PixelArt", 3: "Sketch"}[style] + "TranslucentLayers"
    setattr(view, layers, 0)
    shot(name + "-plain")
    setattr(view, layers, 4)
    Hide(placed, view)
    shot(name + "-nogear", True)
    bunny_display.Opacity = 1.0
    shot(name + "-opaque-nogear")
    Show(placed, view)
    shot(name + "-opaque", True)
    bunny_display.Opacity = 0.35
print("rendered")
