"""Renders a scene in the VTK Stylize view, once per style, with pvbatch (one or more ranks).

    pvbatch-stylize render_styles.py OUTPUT_PREFIX [WIDTH HEIGHT]
    pvpython-stylize render_styles.py OUTPUT_PREFIX WIDTH HEIGHT HOST:PORT remote|local

With HOST:PORT it connects to a pvserver (pvserver-stylize) first: "remote" forces remote
rendering (the server renders and composites, the client receives the image), "local" makes
the client render the delivered geometry itself.

Writes OUTPUT_PREFIX-none.png, -comic.png, -pixel.png, -sketch.png and -lines.png, then -comic-subject.png
(comic with the display as a Stylized Surface whose own subject factor is 1: per-representation
lighting, which every rank must apply to its piece) and -sketch-model.png (the sketch along the
Principal Curvatures filter's directions, DirectionSource Model), and prints one line
"ranks N pieces P points M" (P: how many ranks hold part of the data) and one line "progress
lines ..." (the percentages ParaView's progress bar was given while the line art rendered) for
the caller to check.
The data is a contour of ParaView's Wavelet source, which ParaView splits across ranks.
"""
import sys

from paraview.simple import *  # noqa: F401,F403
from stylize_pv_scene import make_contour, make_view, show_framed

prefix = sys.argv[1]
size = [int(sys.argv[2]), int(sys.argv[3])] if len(sys.argv) > 3 else [400, 300]
server = sys.argv[4] if len(sys.argv) > 4 else None
if server:
    host, port = server.rsplit(":", 1)
    Connect(host, int(port))

view = CreateView("StylizeView")
make_view(view, size)
if server:
    # threshold in MB of geometry: 0 always renders on the server, a huge one never does
    view.RemoteRenderThreshold = 0.0 if sys.argv[5] == "remote" else 1.0e9

contour = make_contour()
ids = (globals().get("GenerateProcessIds") or globals().get("ProcessIdScalars"))(Input=contour)
ids.UpdatePipeline()
array = ids.PointData.GetArray("ProcessId")
low, high = array.GetRange() if array else (0, 0)
print("ranks %d pieces %d points %d" % (servermanager.ActiveConnection.GetNumberOfDataPartitions(),
      int(high - low) + 1, ids.GetDataInformation().GetNumberOfPoints()))

display = show_framed(contour, view)

# What ParaView's progress bar is told while the styles find their lines: the session's
# progress handler (every event passed on: the interval at its floor).
handler = servermanager.ActiveConnection.Session.GetProgressHandler()
handler.SetProgressInterval(0.01)
progress = {}


def on_progress(caller, event):
    text = caller.GetLastProgressText() or ""
    if "Stylize" in text:
        progress.setdefault(current, []).append(caller.GetLastProgress())


handler.AddObserver("ProgressEvent", on_progress)
for style, name in enumerate(["none", "comic", "pixel", "sketch", "lines"]):
    view.Style = style
    current = name
    Render(view)
    SaveScreenshot("%s-%s.png" % (prefix, name), view, ImageResolution=size)
# the line art's first frame found the lines; its later frames kept them (no report)
print("progress lines %s" % " ".join(str(p) for p in progress.get("lines", [])))
view.Style = 1
display.SetRepresentationType("Stylized Surface")
display.StylizeOverrideLighting = 1
display.StylizeSubjectFactor = 1.0
Render(view)
SaveScreenshot("%s-comic-subject.png" % prefix, view, ImageResolution=size)
# the sketch along model directions: the Principal Curvatures filter's tangents, per rank
display.SetRepresentationType("Surface")
curvatures = PrincipalCurvatures(Input=contour)
Hide(contour, view)
show_framed(curvatures, view)
view.Style = 3
view.SketchDirectionSource = 1
Render(view)
SaveScreenshot("%s-sketch-model.png" % prefix, view, ImageResolution=size)
Delete(view)
print("rendered")
