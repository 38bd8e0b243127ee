"""Background culling changes no pixel (issue 15).

The styles skip the background two ways (vtkStylizeStylePass): surface-only stages (the direction
field) run under an early depth test against the G-buffer, and the final stage runs only inside
the scene's screen rectangle, the base writing the background around it. This test renders the
same frames with culling on and off and requires identical colour, alpha and depth, in scenes
that reach the rectangle's edges: a curved surface with an anisotropic field (a torus), wide
lines and large points near the frame's border, a gradient background (written by a program
around the scene), a flat one (a clear), a layered renderer (the background discarded), parallel
projection, a camera inside the scene's bounds (no rectangle), a scene outside the view (an empty
rectangle). It also requires that culling took effect where
it should (the timed stages show the base's BACKGROUND stage), so that it cannot pass vacuously.

Run with the build's python folder on PYTHONPATH and a display (the suite does both).
"""
import sys

import vtkstylize
from vtkmodules.vtkCommonCore import vtkFloatArray, vtkPoints, vtkUnsignedCharArray
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderer

from stylize_test_scene import check, failures, offscreen_window, style_maker, torus_actor


def polyline_and_points():
    """A zigzag polyline and a row of points, offset to the side of the torus."""
    pts = vtkPoints()
    for i in range(12):
        pts.InsertNextPoint(2.2 + 0.15 * (i % 2), -1.2 + 0.22 * i, 0.3)
    lines = vtkCellArray()
    lines.InsertNextCell(12)
    for i in range(12):
        lines.InsertCellPoint(i)
    verts = vtkCellArray()
    for i in range(0, 12, 3):
        verts.InsertNextCell(1)
        verts.InsertCellPoint(i)
    pd = vtkPolyData()
    pd.SetPoints(pts)
    pd.SetLines(lines)
    pd.SetVerts(verts)
    return pd


def build(case):
    win = offscreen_window(320, 200)
    layers = case.get("layered", False)
    if layers:
        win.SetNumberOfLayers(2)
    ren = vtkRenderer()
    win.AddRenderer(ren)
    if case.get("flat"):
        # a flat background, written by a clear around the scene (0.1: 25.5 levels, snapped)
        ren.SetBackground(0.1, 0.5, 0.3)
    else:
        ren.GradientBackgroundOn()
        ren.SetBackground(0.9, 0.9, 0.85)
        ren.SetBackground2(0.4, 0.5, 0.7)

    actor = torus_actor(0.35, 60.0)
    ren.AddActor(actor)

    extra_mapper = vtkPolyDataMapper()
    extra_mapper.SetInputData(polyline_and_points())
    extra = vtkActor()
    extra.SetMapper(extra_mapper)
    extra.GetProperty().SetLineWidth(5.0)
    extra.GetProperty().SetPointSize(11.0)
    extra.GetProperty().SetColor(0.8, 0.2, 0.1)
    ren.AddActor(extra)

    if layers:
        # the stylized renderer over an opaque one: its background is discarded
        base = vtkRenderer()
        base.SetBackground(0.2, 0.6, 0.3)
        win.AddRenderer(base)
        base.SetLayer(0)
        ren.SetLayer(1)

    camera = ren.GetActiveCamera()
    camera.SetParallelProjection(1 if case.get("parallel") else 0)
    ren.ResetCamera()
    camera.Azimuth(25.0)
    camera.Zoom(case.get("zoom", 1.0))
    if case.get("inside"):
        camera.SetPosition(0.0, 0.0, 0.0)
        camera.SetFocalPoint(1.0, 0.0, 0.0)
    if case.get("away"):
        # in front of the eye, beside the view
        actor.AddPosition(8.0, 0.0, 0.0)
        extra.AddPosition(8.0, 0.0, 0.0)
    ren.ResetCameraClippingRange()
    return win, ren


def read(win):
    rgba = vtkUnsignedCharArray()
    w, h = win.GetSize()
    win.GetRGBACharPixelData(0, 0, w - 1, h - 1, 0, rgba)
    depth = vtkFloatArray()
    win.GetZbufferData(0, 0, w - 1, h - 1, depth)
    return rgba, depth


def differing(a, b):
    n = a.GetNumberOfTuples() * a.GetNumberOfComponents()
    return sum(1 for i in range(n) if a.GetValue(i) != b.GetValue(i))


def render(case, make_pass, culling):
    win, ren = build(case)
    style = make_pass()
    if culling:
        style.BackgroundCullingOn()
    else:
        style.BackgroundCullingOff()
    style.StageTimingOn()
    ren.SetPass(style)
    win.Render()
    ren.GetActiveCamera().Azimuth(1.0)  # a second frame: the textures hold the last frame
    win.Render()
    out = read(win)
    if len(sys.argv) > 1:  # a folder: keep the images to look at
        from vtkmodules.vtkIOImage import vtkPNGWriter
        from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter
        grab = vtkWindowToImageFilter()
        grab.SetInput(win)
        grab.ReadFrontBufferOff()
        png = vtkPNGWriter()
        png.SetInputConnection(grab.GetOutputPort())
        png.SetFileName("%s/%s-%s.png" % (sys.argv[1], case["name"], "on" if culling else "off"))
        png.Write()
    stages = [style.GetTimedStageName(i) for i in range(style.GetNumberOfTimedStages())]
    ren.SetPass(None)
    win.Finalize()
    return out, stages


STYLES = {
    "comic": style_maker("vtkComicPass"),
    "comic-principal-tinted": style_maker(
        "vtkComicPass", HatchOrientation=vtkstylize.vtkComicPass.PRINCIPAL,
        Tint=vtkstylize.vtkComicPass.ALL_COLORS),
    "comic-color-edges": style_maker("vtkComicPass", EdgeWeights=(0.3, 0.3, 0.4)),
    "sketch": style_maker("vtkSketchPass"),
    "sketch-directions": style_maker("vtkSketchPass", Layer=vtkstylize.vtkSketchPass.DIRECTIONS),
}

# case name -> (scene, whether the final stage is split around the scene's rectangle)
CASES = {
    "small": ({"zoom": 0.6}, True),
    "flat": ({"zoom": 0.7, "flat": True}, True),
    "parallel": ({"zoom": 0.8, "parallel": True}, True),
    "border": ({"zoom": 1.6}, True),  # the scene crosses the frame's border
    "layered": ({"zoom": 0.7, "layered": True}, True),
    "inside": ({"inside": True}, False),  # the eye inside the bounds: no rectangle
    "away": ({"away": True}, True),  # nothing in view: an empty rectangle, all background
}

for style_name, make in STYLES.items():
    for case_name, (case, split) in CASES.items():
        case = dict(case, name=style_name + "-" + case_name)
        (on_rgba, on_depth), stages = render(case, make, True)
        (off_rgba, off_depth), off_stages = render(case, make, False)
        label = "%s / %s" % (style_name, case_name)
        rgba_diff = differing(on_rgba, off_rgba)
        depth_diff = differing(on_depth, off_depth)
        print("%-36s colour differs at %d values, depth at %d; culled stages: %s" %
              (label, rgba_diff, depth_diff, "BACKGROUND" in stages))
        check(rgba_diff == 0, label + ": colour and alpha differ with culling")
        check(depth_diff == 0, label + ": depth differs with culling")
        check("BACKGROUND" not in off_stages, label + ": culling off still split the frame")
        expect = split and style_name != "comic-color-edges"
        check(("BACKGROUND" in stages) == expect,
              label + ": the final stage was %s around the scene" %
              ("not split" if expect else "split"))

if failures:
    print("%d failure(s)" % len(failures))
    sys.exit(1)
print("culling: every frame identical with and without culling")
