#!/usr/bin/env python3
"""Flicker of the styles' patterns in an orbit animation: screen against surface anchors.

For each mesh, style and anchor it renders a 1 degree per frame orbit (the camera's azimuth,
perspective, the headlight; the sketch with the SPARSE noise that animations use) and measures, between consecutive frames, the share of surface
points whose ink changes: every surface pixel of a frame is reprojected, from its object-space
position (the G-buffer's), into the previous frame; the previous frame's gray is interpolated
bilinearly there and both are thresholded at half (comic, sketch), or the art pixel's colour is
compared (pixel art, nearest pixel); points hidden in the previous frame (their position there
more than two pixels' size away) are left out. It also measures the pattern's screen scale with
the surface anchor: the median over surface pixels of focal distance / depth, the factor by
which an object-space pattern sized at the focal point differs from the still frame's screen
spacing.

With --margin M (a fraction of full ink, default 0) a gray pixel counts as changed only when it is
a clear change of ink: both frames at least M away from half gray, on opposite sides. The strict
count (0) also counts the anti-aliased rim of a dot or line whose gray crosses half by a few
levels when the pixel grid moves a fraction of a pixel over it. For pixel art (hard edges, no
gray to threshold) a margin above 0 counts a clear change of colour: the point's colour is none
of the colours of the four pixels around its reprojected position in the previous frame. The
strict count (nearest pixel) also counts a point within half a pixel of a colour edge that the
edge's rasterization put on the other side: an edge fixed to the surface can be drawn only to the
nearest pixel, so about a quarter pixel in every texel's width flips by the pixel grid alone.

With --check it fails unless, for the styles named by --require, the surface anchor's share is
at most --max-ratio (default 1/3, the target; or per style, e.g. comic=0.45,pixel=0.6) of the
screen anchor's and the scale stays within
20% of the still frame's.

With --sampling K (default 1) the frames are rendered at K times --size in one piece with the
style's WindowScale K: the picture of a K-times magnified screenshot (vtkstylize --magnify K), the
same picture at higher detail, so that every pixel of --size is measured at K x K surface points.
At 1 the count is of pixels, and it includes a rasterization floor that no pattern fixed to the
surface escapes: its dots, lines and texel edges are redrawn on a pixel grid that moves under
them, so the pixels along every edge flip as the grid shifts by a fraction of a pixel (an
anti-aliased rim crossing half gray, a hard edge drawn to the nearest pixel). That floor falls
as K grows, while what the screen anchor's pattern does (it slides over the surface) does not: the
share of surface points, what the target is about, is measured at K = 3 or more.
--control draws the pattern alone (no outlines, a light fixed in the world): with the surface
anchor the comic's and pixel art's pictures are then a function of the surface point, and what
their count measures is the rasterization floor alone.

--degrees sets the turn per frame (1, the target's), --light scene fixes the light in the world
where the first frame's headlight is (the shading then stays on the surface, so what changes is
the pattern's own doing). Both anchors' counts grow with the motion per frame in pixels, the
screen anchor's in proportion while the surface anchor's residue (pattern features redrawn on a
moved pixel grid) grows less, so the ratio falls as the image grows or the turn per frame does.

--measure NAME:K:M:LIMITS (repeatable) computes several counts in one run and checks each: K the
sampling, M the margin, LIMITS the largest ratio (one number for every style, or per style, e.g.
comic=0.45,pixel=0.6). The frames of one sampling are rendered once and every margin counted on
them; the G-buffer's positions of a frame are rendered once for every style and anchor (the
camera's path is the same). realdata.orbit checks its three counts so (surface points at K = 3;
pixels; clear changes on the same pixels).

usage: orbit.py DATADIR [--meshes bunny,fandisk] [--styles comic,pixel,sketch] [--frames 7]
                [--size 400x300] [--degrees 1] [--light head|scene] [--margin 0] [--sampling 1]
                [--control] [--check]
                [--require comic] [--max-ratio 0.333]
                [--measure NAME:K:M:LIMITS ...]
"""
import argparse
import math
import os
import sys

import numpy as np
import vtk
from vtk.util.numpy_support import vtk_to_numpy

import vtkstylize

import realdata

ANCHORS = {
    "comic": ("Anchor", vtkstylize.vtkComicPass.SCREEN, vtkstylize.vtkComicPass.OBJECT),
    "pixel": ("DitherAnchor", vtkstylize.vtkPixelArtPass.SCREEN, vtkstylize.vtkPixelArtPass.SURFACE),
    "sketch": ("NoiseSpace", vtkstylize.vtkSketchPass.SCREEN_SPACE, vtkstylize.vtkSketchPass.OBJECT),
}


def scene(path, width, height, light="head"):
    reader = vtkstylize.vtkStylizeReader()
    reader.SetFileName(path)
    reader.Update()
    if reader.GetErrorMessage():
        sys.exit("orbit.py: " + reader.GetErrorMessage())
    surface = vtk.vtkGeometryFilter()
    surface.SetInputData(reader.GetOutputDataObject(0))
    normals = vtk.vtkPolyDataNormals()
    normals.SetInputConnection(surface.GetOutputPort())
    normals.SplittingOff()
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputConnection(normals.GetOutputPort())
    mapper.ScalarVisibilityOff()
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    renderer = vtk.vtkRenderer()
    renderer.AddActor(actor)
    renderer.SetBackground(1, 1, 1)
    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(width, height)
    window.AddRenderer(renderer)
    renderer.ResetCamera()
    camera = renderer.GetActiveCamera()
    camera.Azimuth(30)
    camera.Elevation(20)
    camera.OrthogonalizeViewUp()
    renderer.ResetCamera()
    if light == "scene":
        # a light fixed in the world where the first frame's headlight is: the shading stays on
        # the surface, so what changes is the pattern's own doing
        fixed = vtk.vtkLight()
        fixed.SetLightTypeToSceneLight()
        fixed.SetPosition(camera.GetPosition())
        fixed.SetFocalPoint(camera.GetFocalPoint())
        renderer.AddLight(fixed)
    return window, renderer


def capture(window):
    """The frame the window has just rendered (not rendered again: ShouldRerender off)."""
    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.SetInputBufferTypeToRGB()
    grab.ReadFrontBufferOff()
    grab.ShouldRerenderOff()
    grab.Update()
    w, h, _ = grab.GetOutput().GetDimensions()
    return vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars()).reshape(h, w, 3).astype(float)


def positions(renderer, window):
    gbuffer = vtkstylize.vtkStylizeGBufferPass()
    gbuffer.SetChannels(vtkstylize.vtkStylizeGBufferPass.POSITION)
    gbuffer.SetPositionSpace(vtkstylize.vtkStylizeGBufferPass.OBJECT)
    style = renderer.GetPass()
    renderer.SetPass(gbuffer)
    window.Render()
    out = vtk.vtkFloatArray()
    gbuffer.DownloadChannel(vtkstylize.vtkStylizeGBufferPass.POSITION_BUFFER, out)
    gbuffer.ReleaseGraphicsResources(window)
    renderer.SetPass(style)
    w, h = window.GetSize()
    return vtk_to_numpy(out).reshape(h, w, 4).copy()


def measure(window, renderer, style, anchor, frames, margins=(0.0,), degrees=1.0, sampling=1,
            control=False, cache=None):
    """The orbit's counts for one style and anchor: a list with, per margin of margins, the share
    of surface points whose ink changes, then the pattern scale's minimum and maximum over the
    frames (relative to the first) and the first frame's scale. cache (a dict) keeps each frame's
    G-buffer positions, which depend on the camera alone, for the next style and anchor."""
    w, h = window.GetSize()
    setting, screen, surface = ANCHORS[style]
    styled = vtkstylize.create_pass(style)
    getattr(styled, "Set" + setting)(screen if anchor == "screen" else surface)
    # the window is sampling times the size: the lengths the style gives in pixels grow with it
    styled.SetWindowScale(sampling, sampling)
    if control:
        # the pattern alone: no outlines (the sketch draws none)
        if style == "comic":
            styled.SetEdges(False)
        elif style == "pixel":
            styled.SetEdgeDetector(vtkstylize.vtkPixelArtPass.NO_EDGES)
            styled.SetDepthEdges(False)
            styled.SetNormalEdges(False)
    if style == "sketch":
        # the noise animations use (vtkstylize --orbit, vtkstylize.orbit, SaveStylizedOrbit),
        # fixed to the screen or to the surface
        styled.SetNoise(vtkstylize.vtkSketchPass.SPARSE)
    renderer.SetPass(styled)
    camera = renderer.GetActiveCamera()
    start = [camera.GetPosition(), camera.GetFocalPoint(), camera.GetViewUp()]
    changed = [0] * len(margins)
    counted = 0
    scales = []
    previous = None
    if cache is None:
        cache = {}
    for f in range(frames):
        if f:
            camera.Azimuth(degrees)
            camera.OrthogonalizeViewUp()
        renderer.ResetCameraClippingRange()
        window.Render()
        image = capture(window)
        gray = image.mean(axis=2) if style != "pixel" else None
        if f not in cache:
            cache[f] = positions(renderer, window)
        pos = cache[f]
        matrix = camera.GetCompositeProjectionTransformMatrix(w / h, -1, 1)
        m = np.array([[matrix.GetElement(i, j) for j in range(4)] for i in range(4)])
        on = pos[..., 3] > 0.5
        # the pattern's screen scale with an object-space pattern: focal distance / depth
        eye = np.array(camera.GetPosition())
        view = np.array(camera.GetDirectionOfProjection())
        depth = (pos[..., :3] - eye) @ view
        scales.append(float(np.median(camera.GetDistance() / depth[on])))
        pixel_world = 2 * camera.GetDistance() * math.tan(math.radians(camera.GetViewAngle() / 2)) / h
        if previous is not None:
            p_image, p_gray, p_pos, p_m, p_on = previous
            ys, xs = np.nonzero(on)
            q = np.c_[pos[ys, xs, :3], np.ones(len(ys))] @ p_m.T
            ok = q[:, 3] > 0
            x = (q[:, 0] / q[:, 3] * 0.5 + 0.5) * w - 0.5
            y = (q[:, 1] / q[:, 3] * 0.5 + 0.5) * h - 0.5
            x0 = np.floor(x).astype(int)
            y0 = np.floor(y).astype(int)
            ok &= (x0 >= 0) & (y0 >= 0) & (x0 + 1 < w) & (y0 + 1 < h)
            x0, y0, x, y, ys, xs = x0[ok], y0[ok], x[ok], y[ok], ys[ok], xs[ok]
            # the four neighbours on the surface, and the nearest one the same point (visible)
            near_x = np.clip(np.rint(x).astype(int), 0, w - 1)
            near_y = np.clip(np.rint(y).astype(int), 0, h - 1)
            seen = p_on[y0, x0] & p_on[y0, x0 + 1] & p_on[y0 + 1, x0] & p_on[y0 + 1, x0 + 1]
            gap = np.linalg.norm(p_pos[near_y, near_x, :3] - pos[ys, xs, :3], axis=1)
            seen &= gap < 2.0 * pixel_world * np.maximum(1.0, depth[ys, xs] / camera.GetDistance())
            counted += int(np.count_nonzero(seen))
            for k, margin in enumerate(margins):
                diff = changes(style, margin, (image, gray), (p_image, p_gray), ys, xs, x, y, x0,
                               y0, near_x, near_y)
                changed[k] += int(np.count_nonzero(diff & seen))
        previous = (image, gray, pos, m, on)
    camera.SetPosition(start[0])
    camera.SetFocalPoint(start[1])
    camera.SetViewUp(start[2])
    styled.ReleaseGraphicsResources(window)
    return ([c / max(1, counted) for c in changed], min(scales) / scales[0],
            max(scales) / scales[0], scales[0])


def changes(style, margin, frame, p_frame, ys, xs, x, y, x0, y0, near_x, near_y):
    """Which reprojected surface points changed their ink (see the module's docstring); frame and
    p_frame: this and the previous frame's colours and grays."""
    (image, gray), (p_image, p_gray) = frame, p_frame
    if style == "pixel":
        now = image[ys, xs]
        if margin > 0:
            # a clear change of colour: none of the four pixels around the point had it
            diff = np.ones(len(ys), bool)
            for dy in (0, 1):
                for dx in (0, 1):
                    diff &= np.any(p_image[y0 + dy, x0 + dx] != now, axis=1)
            return diff
        return np.any(now != p_image[near_y, near_x], axis=1)
    tx, ty = x - x0, y - y0
    bilinear = (p_gray[y0, x0] * (1 - tx) * (1 - ty) + p_gray[y0, x0 + 1] * tx * (1 - ty) +
                p_gray[y0 + 1, x0] * (1 - tx) * ty + p_gray[y0 + 1, x0 + 1] * tx * ty)
    now, before = gray[ys, xs], bilinear
    diff = (now < 128) != (before < 128)
    if margin > 0:
        # a clear change of ink: both frames away from half gray by the margin
        band = 255.0 * margin
        diff &= (np.abs(now - 127.5) > band) & (np.abs(before - 127.5) > band)
    return diff


def parse_limits(text, styles):
    """'0.333' (every style) or 'comic=0.45,pixel=0.6': the largest ratio per style."""
    if "=" in text:
        return {k: float(v) for k, v in (item.split("=") for item in text.split(","))}
    return {style: float(text) for style in styles}


def parse_measures(args, styles):
    """The counts to compute: [(name, sampling, margin, limits or None)]. --measure gives them;
    without it, the one count of --sampling and --margin, checked (--check) for --require."""
    if not args.measure:
        limits = None
        if args.check:
            every = parse_limits(args.max_ratio, styles)
            limits = {s: every.get(s, 1.0 / 3.0) for s in args.require.split(",")}
        return [("", args.sampling, args.margin, limits)]
    measures = []
    for spec in args.measure:
        parts = spec.split(":")
        if len(parts) != 4:
            sys.exit("orbit.py: --measure NAME:K:M:LIMITS, not %r" % spec)
        name, sampling, margin, limits = parts
        measures.append((name, int(sampling), float(margin), parse_limits(limits, styles)))
    return measures


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("datadir")
    parser.add_argument("--meshes", default="bunny,fandisk")
    parser.add_argument("--styles", default="comic,pixel,sketch")
    parser.add_argument("--frames", type=int, default=7)
    parser.add_argument("--size", default="400x300")
    parser.add_argument("--margin", type=float, default=0.0,
                        help="count only clear changes of ink: both grays this far from half")
    parser.add_argument("--degrees", type=float, default=1.0,
                        help="the camera's turn per frame (the target is stated for 1 degree)")
    parser.add_argument("--light", choices=("head", "scene"), default="head",
                        help="head: the camera's headlight (the shading turns with the camera); "
                        "scene: a light fixed in the world (the shading stays on the surface)")
    parser.add_argument("--sampling", type=int, default=1, choices=range(1, 9), metavar="K",
                        help="measure the K-times magnified picture: K x K surface points per "
                        "pixel of --size (1: pixels, rasterization floor included)")
    parser.add_argument("--control", action="store_true",
                        help="the pattern alone: no outlines, a light fixed in the world (the "
                        "count of a pattern fixed to the surface: the rasterization floor)")
    parser.add_argument("--check", action="store_true")
    parser.add_argument("--require", default="comic")
    parser.add_argument("--max-ratio", default=str(1.0 / 3.0),
                        help="the largest surface/screen share --check accepts (the target: 1/3)")
    parser.add_argument("--measure", action="append", metavar="NAME:K:M:LIMITS",
                        help="a count of sampling K and margin M checked against LIMITS "
                        "(repeatable; the frames of one K are shared)")
    args = parser.parse_args()
    width, height = (int(v) for v in args.size.split("x"))
    styles = args.styles.split(",")
    measures = parse_measures(args, styles)
    failures = []
    light = "scene" if args.control else args.light
    if args.control:
        print("control: the pattern alone (no outlines, a light fixed in the world)")
    for sampling in sorted({m[1] for m in measures}):
        group = [m for m in measures if m[1] == sampling]
        margins = [m[2] for m in group]
        for name, _, margin, _ in group:
            label = ("%s: " % name) if name else ""
            if sampling > 1:
                print("%sthe %d-times magnified picture (%dx%d): %d x %d surface points per pixel"
                      % (label, sampling, width * sampling, height * sampling, sampling, sampling))
            elif name:
                print("%sthe %dx%d pixels" % (label, width, height))
            if margin > 0:
                print("%sclear changes of ink only: both grays at least %.0f%% of full ink from "
                      "half; pixel art: a colour none of the four pixels around the point had"
                      % (label, 100 * margin))
        rows = {m[0]: [] for m in group}
        for mesh in args.meshes.split(","):
            path = os.path.join(args.datadir, mesh + ".ply")
            cache = {}  # the frames' positions, shared by every style and anchor
            for style in styles:
                window, renderer = scene(path, width * sampling, height * sampling, light)
                screen = measure(window, renderer, style, "screen", args.frames, margins,
                                 args.degrees, sampling, args.control, cache)
                surface = measure(window, renderer, style, "surface", args.frames, margins,
                                  args.degrees, sampling, args.control, cache)
                window.Finalize()
                scale = (surface[1] * surface[3], surface[2] * surface[3])
                for k, (name, _, _, limits) in enumerate(group):
                    ratio = surface[0][k] / max(1e-9, screen[0][k])
                    rows[name].append("%-8s %-6s %10.2f %10.2f %7.2f %11.3f .. %.3f" % (
                        mesh, style, 100 * screen[0][k], 100 * surface[0][k], ratio, scale[0],
                        scale[1]))
                    if limits is None or style not in limits:
                        continue
                    label = ("%s: " % name) if name else ""
                    if ratio > limits[style]:
                        failures.append("%s%s %s: surface/screen ratio %.2f > %.2f" % (
                            label, mesh, style, ratio, limits[style]))
                    if not (0.8 <= scale[0] and scale[1] <= 1.2):
                        failures.append("%s%s %s: pattern scale outside 20%% of the still "
                                        "frame's" % (label, mesh, style))
        for name, _, _, _ in group:
            if name:
                print("%s:" % name)
            print("%-8s %-6s %10s %10s %7s %22s" % ("mesh", "style", "screen %", "surface %",
                                                      "ratio", "scale vs still (range)"))
            print("\n".join(rows[name]))
            sys.stdout.flush()
    return realdata.exit_status(failures, args.check or bool(args.measure))


if __name__ == "__main__":
    sys.exit(main())
