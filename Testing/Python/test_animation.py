"""The Python package's figure and animation calls (issue 18): vtkstylize.save_figure,
vtkstylize.orbit and vtkstylize.encode.

For each style, on a torus in a 200x150 offscreen window: an orbit of 3 frames over 6 degrees
writes 3 PNGs that differ (the camera turned), renders them with the surface anchor (checked from
inside the orbit, on the pass, at every frame) and gives the style's own settings back
afterwards (comic Anchor, pixel art DitherAnchor, sketch NoiseSpace and Noise), and the camera
too; with surface_anchor=False the settings stay as they are. The frames encode to a GIF when
ffmpeg is on the PATH (a bad pattern is refused with RuntimeError). A comic figure is written as
SVG and PDF; a figure to a .txt is refused with RuntimeError.
"""
import os
import shutil
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import vtkstylize  # noqa: E402
from stylize_test_scene import check, failures, offscreen_window, torus_actor  # noqa: E402
from vtkmodules.vtkIOImage import vtkPNGReader  # noqa: E402
from vtkmodules.vtkRenderingCore import vtkRenderer  # noqa: E402

S = vtkstylize
# style: (settings before the orbit, the getters and the surface values the orbit must use)
CASES = {
    "comic": ({"Anchor": S.vtkComicPass.SCREEN}, {"Anchor": S.vtkComicPass.OBJECT}),
    "pixel": ({"DitherAnchor": S.vtkPixelArtPass.SCREEN},
              {"DitherAnchor": S.vtkPixelArtPass.SURFACE}),
    "sketch": ({"NoiseSpace": S.vtkSketchPass.SCREEN_SPACE, "Noise": S.vtkSketchPass.PERLIN},
               {"NoiseSpace": S.vtkSketchPass.OBJECT, "Noise": S.vtkSketchPass.SPARSE}),
}


def read_png(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput().GetPointData().GetScalars()


def differs(a, b):
    return any(a.GetValue(i) != b.GetValue(i) for i in range(0, a.GetNumberOfValues(), 7))


def values(style_pass, names):
    return {name: getattr(style_pass, "Get" + name)() for name in names}


folder = tempfile.mkdtemp(prefix="vtkstylize-animation-")
try:
    for style, (before, during) in CASES.items():
        window = offscreen_window(200, 150)
        renderer = vtkRenderer()
        renderer.AddActor(torus_actor(0.35, 50))
        renderer.SetBackground(1, 1, 1)
        window.AddRenderer(renderer)
        renderer.ResetCamera()
        style_pass = vtkstylize.create_pass(style, **before)
        renderer.SetPass(style_pass)
        camera = renderer.GetActiveCamera()
        start = camera.GetPosition()
        seen = []
        window.AddObserver("StartEvent", lambda *_: seen.append(values(style_pass, during)))
        pattern = os.path.join(folder, style + "-%04d.png")
        written = vtkstylize.orbit(window, 3, pattern, degrees=6.0)
        check(written == [pattern % i for i in range(3)] and all(map(os.path.exists, written)),
              "%s: orbit wrote %s" % (style, written))
        frames = [read_png(p) for p in written]
        check(differs(frames[0], frames[1]), "%s: frames 0 and 1 are the same" % style)
        check(len(seen) >= 3 and all(v == during for v in seen),
              "%s: the orbit rendered with %s, expected %s" % (style, seen, during))
        check(values(style_pass, before) == before,
              "%s: after the orbit %s, expected %s" % (style, values(style_pass, before), before))
        check(camera.GetPosition() == start, "%s: the camera was not restored" % style)
        seen.clear()
        vtkstylize.orbit(window, 1, os.path.join(folder, style + "-fixed-%04d.png"),
                         surface_anchor=False)
        check(seen and all(v == before for v in seen),
              "%s: surface_anchor=False rendered with %s" % (style, seen))
        if shutil.which("ffmpeg"):
            gif = vtkstylize.encode(pattern, os.path.join(folder, style + ".gif"), fps=10)
            check(os.path.getsize(gif) > 0, "%s: empty GIF" % style)
        if style == "comic":
            window.Render()
            for ext in ("svg", "pdf"):
                path = os.path.join(folder, "figure." + ext)
                vtkstylize.save_figure(window, path)
                with open(path, "rb") as f:
                    head = f.read(5)
                check(head in (b"<?xml", b"<svg ") if ext == "svg" else head == b"%PDF-",
                      "figure.%s starts with %r" % (ext, head))
            try:
                vtkstylize.save_figure(window, os.path.join(folder, "figure.txt"))
                check(False, "a figure to a .txt was written")
            except RuntimeError as error:
                print("refused: %s" % error)
        window.Finalize()
    if shutil.which("ffmpeg"):
        try:
            vtkstylize.encode(os.path.join(folder, "missing-%04d.png"),
                              os.path.join(folder, "missing.gif"))
            check(False, "encoding frames that do not exist succeeded")
        except RuntimeError as error:
            print("refused: %s" % error)
finally:
    shutil.rmtree(folder, ignore_errors=True)
print("%d failures" % len(failures))
sys.exit(1 if failures else 0)
