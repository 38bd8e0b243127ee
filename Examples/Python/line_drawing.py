#!/usr/bin/env python3
"""A vector line drawing of a dataset (or the built-in scene), hidden lines removed, as SVG.

Usage (as stylize_dataset.py: the build tree's Python package, /usr/bin/python3, a display)::

    PYTHONPATH=build/python /usr/bin/python3 Examples/Python/line_drawing.py \\
        [FILE] [-o OUT.svg] [--size WxH] [--azimuth DEG] [--elevation DEG]

FILE is read and turned into surfaces as stylize_dataset.py does (vtkStylizeReader, checked).
The surfaces are rendered once, offscreen, for the scene's depth; each surface's feature lines
(vtkStylizeFeatureLines: contours, boundaries, creases, ridges, valleys, suggestive contours)
are tested against that depth (vtkStylizeLineVisibility: every surface hides every other), and
the visible runs are written as SVG paths: projected to the image, simplified to 0.1 px
(Douglas-Peucker), round caps and joins, widths by kind (contours and boundaries 2 px, creases
1.2 px, the interior lines 0.8 px, faded by their strength). It prints the output's path and a
line of counts. Errors print one line on stderr and exit 1 (2 for command-line syntax); no file
is written then, and a file is written whole or not at all.
"""

import argparse
import math
import os
import sys

from stylize_dataset import Failure, load_parts, parse_size

import vtkstylize
from vtkmodules.vtkCommonCore import vtkFloatArray, vtkIdList
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderWindow, vtkRenderer
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL render window)

KINDS = ["contour", "boundary", "crease", "ridge", "valley", "suggestive", "isoline"]
WIDTH = {"contour": 2.0, "boundary": 2.0, "crease": 1.2, "ridge": 0.8, "valley": 0.8,
         "suggestive": 0.8, "isoline": 0.8}
TOLERANCE = 0.1  # simplification, pixels


def simplify(points, tolerance):
    """Douglas-Peucker: the points of the polyline within `tolerance` of it."""
    if len(points) < 3:
        return points
    keep = [False] * len(points)
    keep[0] = keep[-1] = True
    stack = [(0, len(points) - 1)]
    while stack:
        first, last = stack.pop()
        (ax, ay), (bx, by) = points[first], points[last]
        length = math.hypot(bx - ax, by - ay)
        worst, index = -1.0, None
        for i in range(first + 1, last):
            px, py = points[i]
            if length > 0.0:
                d = abs((bx - ax) * (ay - py) - (ax - px) * (by - ay)) / length
            else:
                d = math.hypot(px - ax, py - ay)
            if d > worst:
                worst, index = d, i
        if index is not None and worst > tolerance:
            keep[index] = True
            stack += [(first, index), (index, last)]
    return [p for p, k in zip(points, keep) if k]


def render(parts, size, azimuth, elevation):
    """The window, its camera and the scene's depth (every part drawn)."""
    renderer = vtkRenderer()
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)
    window.SetSize(*size)
    window.AddRenderer(renderer)
    for _, surface in parts:
        mapper = vtkPolyDataMapper()
        mapper.SetInputData(surface)
        actor = vtkActor()
        actor.SetMapper(mapper)
        renderer.AddActor(actor)
    renderer.ResetCamera()
    camera = renderer.GetActiveCamera()
    camera.Azimuth(azimuth)
    camera.Elevation(elevation)
    camera.OrthogonalizeViewUp()
    renderer.ResetCamera()
    window.Render()
    z = vtkFloatArray()
    window.GetZbufferData(0, 0, size[0] - 1, size[1] - 1, z)
    depth = vtkImageData()
    depth.SetDimensions(size[0], size[1], 1)
    depth.GetPointData().SetScalars(z)
    return window, camera, depth


def visible_runs(parts, camera, depth, size):
    """[(kind, strength, [(x, y) pixels, y down])] of every part's visible lines."""
    m = camera.GetCompositeProjectionTransformMatrix(size[0] / size[1], -1, 1)
    runs = []
    for _, surface in parts:
        lines = vtkstylize.vtkStylizeFeatureLines()
        lines.SetInputData(surface)
        lines.SetCamera(camera)
        visibility = vtkstylize.vtkStylizeLineVisibility()
        visibility.SetInputConnection(lines.GetOutputPort())
        visibility.SetCamera(camera)
        visibility.SetViewportSize(*size)
        visibility.SetDepthImage(depth)
        visibility.VisibleOnlyOn()
        visibility.Update()
        out = visibility.GetOutput()
        kinds = out.GetCellData().GetArray("FeatureKind")
        strength = out.GetPointData().GetArray("FeatureStrength")
        cells = out.GetLines()
        cells.InitTraversal()
        ids = vtkIdList()
        cell = 0
        while cells.GetNextCell(ids):
            points, weight = [], 0.0
            for i in range(ids.GetNumberOfIds()):
                x, y, z = out.GetPoint(ids.GetId(i))
                clip = [m.GetElement(r, 0) * x + m.GetElement(r, 1) * y + m.GetElement(r, 2) * z +
                        m.GetElement(r, 3) for r in range(4)]
                points.append(((clip[0] / clip[3] + 1) * 0.5 * size[0],
                               (1 - clip[1] / clip[3]) * 0.5 * size[1]))
                weight = max(weight, strength.GetValue(ids.GetId(i)))
            runs.append((KINDS[int(kinds.GetValue(cell))], weight, points))
            cell += 1
    return runs


def write_svg(runs, size, path):
    """The runs as SVG paths; written to a temporary file, then renamed (whole or nothing)."""
    lines = ['<?xml version="1.0" encoding="UTF-8"?>',
             '<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" '
             'viewBox="0 0 %d %d">' % (size[0], size[1], size[0], size[1]),
             '<rect width="100%" height="100%" fill="white"/>',
             '<g fill="none" stroke="black" stroke-linecap="round" stroke-linejoin="round">']
    count = points = 0
    for kind, weight, run in runs:
        run = simplify(run, TOLERANCE)
        if len(run) < 2 or weight <= 0.0:
            continue
        d = "M" + " L".join("%.2f %.2f" % p for p in run)
        opacity = "" if weight >= 1.0 else ' stroke-opacity="%.3f"' % weight
        lines.append('<path class="%s" stroke-width="%.2f"%s d="%s"/>' % (
            kind, WIDTH[kind], opacity, d))
        count += 1
        points += len(run)
    lines += ["</g>", "</svg>", ""]
    temporary = path + ".part"
    try:
        with open(temporary, "w") as f:
            f.write("\n".join(lines))
        os.replace(temporary, path)
    except OSError:
        if os.path.exists(temporary):
            os.remove(temporary)
        raise
    return count, points


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("file", nargs="?")
    parser.add_argument("-o", "--output", default="lines.svg")
    parser.add_argument("--size", type=parse_size, default=(800, 600))
    parser.add_argument("--azimuth", type=float, default=30.0)
    parser.add_argument("--elevation", type=float, default=20.0)
    args = parser.parse_args(argv)
    try:
        parts = load_parts(args.file)
        window, camera, depth = render(parts, args.size, args.azimuth, args.elevation)
        runs = visible_runs(parts, camera, depth, args.size)
        window.Finalize()
        count, points = write_svg(runs, args.size, args.output)
    except (Failure, OSError) as error:
        print("line_drawing.py: %s" % error, file=sys.stderr)
        return 1
    print(args.output)
    print("%d paths, %d points, %d bytes" % (count, points, os.path.getsize(args.output)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
