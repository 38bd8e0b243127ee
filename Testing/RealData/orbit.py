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

usage: orbit.py DATADIR [--meshes bunny,fandisk] [--styles comic,pixel,sketch] [--frames 7]
                [--size 400x300] [--degrees 1] [--light head|scene] [--margin 0] [--sampling 1]
                [--control] [--check]
                [--require comic] [--max-ratio 0.333]
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
    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.SetInputBufferTypeToRGB()
    grab.ReadFrontBufferOff()
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


def measure(window, renderer, style, anchor, frames, margin=0.0, degrees=1.0, sampling=1,
            control=False):
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
    changed = counted = 0
    scales = []
    previous = None
    for f in range(frames):
        if f:
            camera.Azimuth(degrees)
            camera.OrthogonalizeViewUp()
        renderer.ResetCameraClippingRange()
        window.Render()
        image = capture(window)
        pos = positions(renderer, window)
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
            p_image, p_pos, p_m, p_on = previous
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
            if style == "pixel":
                now = image[ys, xs]
                if margin > 0:
                    # a clear change of colour: none of the four pixels around the point had it
                    diff = np.ones(len(ys), bool)
                    for dy in (0, 1):
                        for dx in (0, 1):
                            diff &= np.any(p_image[y0 + dy, x0 + dx] != now, axis=1)
                else:
                    diff = np.any(now != p_image[near_y, near_x], axis=1)
            else:
                gray = image.mean(axis=2)
                p_gray = p_image.mean(axis=2)
                tx, ty = x - x0, y - y0
                bilinear = (p_gray[y0, x0] * (1 - tx) * (1 - ty) + p_gray[y0, x0 + 1] * tx * (1 - ty) +
                            p_gray[y0 + 1, x0] * (1 - tx) * ty + p_gray[y0 + 1, x0 + 1] * tx * ty)
                now, before = gray[ys, xs], bilinear
                diff = (now < 128) != (before < 128)
                if margin > 0:
                    # a clear change of ink: both frames away from half gray by the margin
                    band = 255.0 * margin
                    diff &= (np.abs(now - 127.5) > band) & (np.abs(before - 127.5) > band)
            changed += int(np.count_nonzero(diff & seen))
            counted += int(np.count_nonzero(seen))
        previous = (image, pos, m, on)
    camera.SetPosition(start[0])
    camera.SetFocalPoint(start[1])
    camera.SetViewUp(start[2])
    styled.ReleaseGraphicsResources(window)
    return changed / max(1, counted), min(scales) / scales[0], max(scales) / scales[0], scales[0]


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
    args = parser.parse_args()
    width, height = (int(v) for v in args.size.split("x"))
    if "=" in args.max_ratio:
        limits = {k: float(v) for k, v in (item.split("=") for item in args.max_ratio.split(","))}
    else:
        limits = {style: float(args.max_ratio) for style in args.styles.split(",")}
    failures = []
    light = "scene" if args.control else args.light
    if args.sampling > 1:
        print("the %d-times magnified picture (%dx%d): %d x %d surface points per pixel" % (
            args.sampling, width * args.sampling, height * args.sampling, args.sampling,
            args.sampling))
    if args.control:
        print("control: the pattern alone (no outlines, a light fixed in the world)")
    if args.margin > 0:
        print("clear changes of ink only: both grays at least %.0f%% of full ink from half; pixel "
              "art: a colour none of the four pixels around the point had" % (100 * args.margin))
    print("%-8s %-6s %10s %10s %7s %22s" % ("mesh", "style", "screen %", "surface %", "ratio",
                                              "scale vs still (range)"))
    for mesh in args.meshes.split(","):
        path = os.path.join(args.datadir, mesh + ".ply")
        for style in args.styles.split(","):
            window, renderer = scene(path, width * args.sampling, height * args.sampling, light)
            screen = measure(window, renderer, style, "screen", args.frames, args.margin,
                             args.degrees, args.sampling, args.control)
            surface = measure(window, renderer, style, "surface", args.frames, args.margin,
                              args.degrees, args.sampling, args.control)
            ratio = surface[0] / max(1e-9, screen[0])
            print("%-8s %-6s %10.2f %10.2f %7.2f %11.3f .. %.3f" % (
                mesh, style, 100 * screen[0], 100 * surface[0], ratio, surface[1] * surface[3],
                surface[2] * surface[3]))
            sys.stdout.flush()
            if style in args.require.split(","):
                limit = limits.get(style, 1.0 / 3.0)
                if ratio > limit:
                    failures.append("%s %s: surface/screen ratio %.2f > %.2f" % (
                        mesh, style, ratio, limit))
                if not (0.8 <= surface[1] * surface[3] and surface[2] * surface[3] <= 1.2):
                    failures.append("%s %s: pattern scale outside 20%% of the still frame's" % (mesh, style))
            window.Finalize()
    return realdata.exit_status(failures, args.check)


if __name__ == "__main__":
    sys.exit(main())
