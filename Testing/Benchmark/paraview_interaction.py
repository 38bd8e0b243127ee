"""Interaction in ParaView: frame times of the VTK Stylize view while the camera turns, against
ParaView's own Render View with the same LOD settings, through the views' interactive render
path (issue 41, item 4). Run with the plugin's pvbatch (not a test: it prints medians):

    build/paraview/bin/pvbatch-stylize Testing/Benchmark/paraview_interaction.py \
        [--bunny build/Testing/RealData/data/bunny.ply] [--size 1280x720] [--frames 7]
        [--markdown FILE]

Scenes: the scanned bunny and a contour of ParaView's Wavelet source at about a million
triangles (extent [-120, 120]^3, RTData 160, as the benchmark's iso970k). Views: ParaView's
Render View and the Render View (Stylize) with each style at its defaults, all at the same size
and LOD settings (ParaView's defaults: LOD Threshold 20 MB, LOD Resolution 0.5), one light
(the light kit off, the headlight on, as in vtkStylizeBenchmark).

How an interactive frame is measured: what ParaView's interactor does while the mouse drags,
done from a script. The view's render window is asked for ParaView's interactive rate
(SetDesiredUpdateRate(5), which is what makes a style draw its interactive variant), the camera
turns by 2 degrees, the view's InteractiveRender() renders (with ParaView's LOD geometry when
the data exceed the LOD threshold) and glFinish waits for it (WaitForCompletion); the clock
reads before the render and after the finish. A still frame is the same with the update rate
0.002 and StillRender(). First a drag (the interactive frames), then the still frames; within
each, frames are interleaved across views (one frame of each view per round) so that the
machine's drift affects all alike; the first two rounds of each are warm-up.
"""
import argparse
import os
import statistics
import sys
import time

from paraview.simple import Contour, CreateView, Delete, PLYReader, Render, Show, Wavelet

STYLES = ["None", "Comic", "Pixel art", "Sketch", "Line art"]


def parse():
    here = os.path.dirname(os.path.abspath(__file__))
    default_bunny = os.path.join(here, "..", "..", "build", "Testing", "RealData", "data",
                                 "bunny.ply")
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--bunny", default=os.path.normpath(default_bunny))
    parser.add_argument("--size", default="1280x720")
    parser.add_argument("--frames", type=int, default=7, help="timed rounds (after 2 warm-up)")
    parser.add_argument("--scenes", default="bunny,contour1M")
    parser.add_argument("--markdown", default="")
    return parser.parse_args()


def make_views(source, size):
    """ParaView's Render View and one Stylize view per style, showing `source` alike."""
    views = []
    for style in [None] + STYLES:
        view = CreateView("RenderView") if style is None else CreateView("StylizeView")
        if style is not None:
            view.Style = style
        view.ViewSize = size
        view.OrientationAxesVisibility = 0
        view.UseColorPaletteForBackground = 0
        view.Background = [1.0, 1.0, 1.0]
        view.UseLight = 0  # the light kit off: one headlight, as the benchmark
        view.KeyLightIntensity = 0.0
        view.LODThreshold = 20.0
        view.LODResolution = 0.5
        Show(source, view)
        view.CameraPosition = [30.0, -45.0, 25.0]
        view.CameraFocalPoint = [0.0, 0.0, 0.0]
        view.CameraViewUp = [0.0, 0.0, 1.0]
        view.ResetCamera()
        Render(view)
        views.append(("ParaView Render View" if style is None else style, view))
    return views


def frame(view, interactive):
    window = view.GetRenderWindow()
    window.SetDesiredUpdateRate(5.0 if interactive else 0.002)
    camera = view.GetActiveCamera()
    camera.Azimuth(2.0)
    start = time.perf_counter()
    if interactive:
        view.SMProxy.InteractiveRender()
    else:
        view.SMProxy.StillRender()
    window.WaitForCompletion()
    return 1000.0 * (time.perf_counter() - start)


def measure(views, rounds):
    """A drag (interactive frames), then still frames; within each, one frame of every view per
    round. (Alternating interactive and still frames of one view would make a style that caches
    per variant recompute at every frame, which no drag does.)"""
    times = {(name, mode): [] for name, _ in views for mode in ("interactive", "still")}
    for mode in ("interactive", "still"):
        for r in range(rounds + 2):
            for name, view in views:
                ms = frame(view, mode == "interactive")
                if r >= 2:
                    times[(name, mode)].append(ms)
    return {key: statistics.median(values) for key, values in times.items()}


def main():
    args = parse()
    size = [int(v) for v in args.size.lower().split("x")]
    rows = []
    for scene in args.scenes.split(","):
        if scene == "bunny":
            if not os.path.exists(args.bunny):
                sys.exit("no bunny at %s (run ctest -R realdata.setup, or give --bunny)"
                         % args.bunny)
            source = PLYReader(FileNames=[args.bunny])
        else:
            wavelet = Wavelet(WholeExtent=[-120, 120, -120, 120, -120, 120])
            source = Contour(Input=wavelet, ContourBy=["POINTS", "RTData"], Isosurfaces=[160.0],
                             ComputeScalars=0)
        source.UpdatePipeline()
        triangles = source.GetDataInformation().GetNumberOfCells()
        views = make_views(source, size)
        medians = measure(views, args.frames)
        base = medians[("ParaView Render View", "interactive")]
        for name, _ in views:
            inter, still = medians[(name, "interactive")], medians[(name, "still")]
            rows.append((scene, triangles, name, inter, still, inter / base))
            print("%-10s %9d  %-22s interactive %8.1f ms  still %8.1f ms  ratio %.2f"
                  % (scene, triangles, name, inter, still, inter / base), flush=True)
        for _, view in views:
            Delete(view)
        del views
    table = ["| scene | triangles | view | interactive (ms) | still (ms) | interactive / "
             "Render View's interactive (<= 2) |", "| --- | ---: | --- | ---: | ---: | ---: |"]
    table += ["| %s | %s | %s | %.1f | %.1f | %.2f |" % (s, format(t, ","), n, i, st, q)
              for s, t, n, i, st, q in rows]
    print("\n".join(table))
    if args.markdown:
        with open(args.markdown, "w") as f:
            f.write("\n".join(table) + "\n")


main()
