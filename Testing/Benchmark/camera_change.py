#!/usr/bin/python3
"""The frame after a camera change (issue 54): in one process, the median time of a frame after
the camera turns, line art against comic, on a mesh that may have millions of triangles.

    camera_change.py MESH.ply [--size 1280x720] [--frames 5]

Per style (comic, then lines): the first frame (the line art finds its view-independent lines
and the curvature then), then FRAMES frames, each after turning the camera 5 degrees about the
view-up axis. Prints one table row per style (first frame, median of the others, their ratio to
the comic's). Needs the vtkstylize package on PYTHONPATH and a display (or Xvfb).
"""
import argparse
import statistics
import time

import vtkstylize
from vtkmodules.vtkFiltersCore import vtkPolyDataNormals
from vtkmodules.vtkIOPLY import vtkPLYReader
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderer, vtkRenderWindow
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL factories)


def frames(mesh, style, size, count):
    renderer = vtkRenderer()
    renderer.SetBackground(1, 1, 1)
    mapper = vtkPolyDataMapper()
    mapper.SetInputData(mesh)
    actor = vtkActor()
    actor.SetMapper(mapper)
    renderer.AddActor(actor)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(*size)
    window.AddRenderer(renderer)
    vtkstylize.apply_style(renderer, style)
    renderer.ResetCamera()
    start = time.perf_counter()
    window.Render()
    first = time.perf_counter() - start
    times = []
    for _ in range(count):
        renderer.GetActiveCamera().Azimuth(5.0)
        renderer.ResetCameraClippingRange()
        start = time.perf_counter()
        window.Render()
        times.append(time.perf_counter() - start)
    window.Finalize()
    return first, statistics.median(times)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("mesh")
    parser.add_argument("--size", default="1280x720")
    parser.add_argument("--frames", type=int, default=5)
    args = parser.parse_args()
    size = tuple(int(v) for v in args.size.split("x"))
    reader = vtkPLYReader()
    reader.SetFileName(args.mesh)
    normals = vtkPolyDataNormals()
    normals.SetInputConnection(reader.GetOutputPort())
    normals.Update()
    mesh = normals.GetOutput()
    print("%s: %d triangles, %dx%d" % (args.mesh, mesh.GetNumberOfCells(), size[0], size[1]))
    print("| style | first frame (s) | frame after a camera change (s, median of %d) | "
          "against comic |" % args.frames)
    print("|---|---:|---:|---:|")
    comic = None
    for style in ("comic", "lines"):
        first, after = frames(mesh, style, size, args.frames)
        comic = comic or after
        print("| %s | %.2f | %.3f | %.2fx |" % (style, first, after, after / comic), flush=True)


if __name__ == "__main__":
    main()
