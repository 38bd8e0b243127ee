"""python.gbuffer_order: the G-buffer's channels do not depend on the order triangles are drawn in.

A closed curved mesh (a torus) with the Principal Curvatures filter's directions is drawn twice by
the sketch along model directions (DirectionSource MODEL): once as it is, once with its triangles
in reverse order. Each pixel of the G-buffer must hold what its nearest triangle wrote, whatever
was drawn there before: the DIRECTION channel (unit direction and the confidence in w) and the
NORMAL channel must be the same for both orders (within 1e-5), and the stored direction must have
unit length where its confidence is not 0. VTK keeps blending on for opaque geometry; blended by
their alpha, the channels mixed with the surface behind (the direction was scaled by its
confidence and a rank's piece of a mesh, drawn in another order, gave other directions: issue 16).
"""
import sys

import numpy as np
import vtkstylize
from vtkmodules.vtkCommonCore import vtkFloatArray
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderer
from vtkmodules.util.numpy_support import numpy_to_vtkIdTypeArray, vtk_to_numpy

from stylize_test_scene import check, failures, offscreen_window, torus_actor

G = vtkstylize.vtkStylizeGBufferPass
SIZE = (240, 180)

# a torus seen at a slant: its inner side lies behind its outer side on many pixels
source = torus_actor(0.45, 0.0).GetMapper().GetInputAlgorithm()
source.Update()
curvatures = vtkstylize.vtkStylizePrincipalCurvatures()
curvatures.SetInputData(source.GetOutput())
curvatures.Update()
mesh = curvatures.GetOutput()


def reversed_cells(poly):
    """poly with its triangles in reverse order (the same points and point data)."""
    polys = poly.GetPolys()
    offsets = vtk_to_numpy(polys.GetOffsetsArray())
    connectivity = vtk_to_numpy(polys.GetConnectivityArray())
    cells = [connectivity[offsets[i]:offsets[i + 1]] for i in range(len(offsets) - 1)][::-1]
    new_offsets = np.concatenate([[0], np.cumsum([len(c) for c in cells])]).astype(np.int64)
    array = vtkCellArray()
    array.SetData(numpy_to_vtkIdTypeArray(new_offsets, deep=1),
                  numpy_to_vtkIdTypeArray(np.concatenate(cells).astype(np.int64), deep=1))
    out = vtkPolyData()
    out.SetPoints(poly.GetPoints())
    out.GetPointData().ShallowCopy(poly.GetPointData())
    out.SetPolys(array)
    return out


def channels(poly):
    window = offscreen_window(*SIZE)
    renderer = vtkRenderer()
    window.AddRenderer(renderer)
    mapper = vtkPolyDataMapper()
    mapper.SetInputData(poly)
    mapper.ScalarVisibilityOff()
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.RotateX(62.0)
    renderer.AddActor(actor)
    renderer.ResetCamera()
    sketch = vtkstylize.vtkSketchPass()
    sketch.SetDirectionSource(vtkstylize.vtkSketchPass.MODEL)
    renderer.SetPass(sketch)
    window.Render()
    result = {}
    for name, buffer in (("direction", G.DIRECTION_BUFFER), ("normal", G.NORMAL_BUFFER)):
        array = vtkFloatArray()
        check(sketch.GetGBufferPass().DownloadChannel(buffer, array), "%s download" % name)
        result[name] = vtk_to_numpy(array).reshape(-1, 4).copy()
    window.Finalize()
    return result


first = channels(mesh)
second = channels(reversed_cells(mesh))
surface = first["normal"][:, 3] > 0.5
direction = first["direction"]
defined = surface & (direction[:, 3] > 0.0)
print("surface pixels %d, with a direction %d" % (surface.sum(), defined.sum()))
check(surface.sum() > 5000 and defined.sum() > 0.9 * surface.sum(),
      "the torus covers too few pixels or has too few directions")
for name in ("direction", "normal"):
    worst = np.abs(first[name] - second[name]).max()
    print("%s: largest difference between the two triangle orders %.3g" % (name, worst))
    check(worst <= 1e-5, "the %s channel depends on the triangle order (%.3g)" % (name, worst))
length = np.linalg.norm(direction[defined, :3], axis=1)
print("direction length where defined: %.4f..%.4f" % (length.min(), length.max()))
check(np.abs(length - 1.0).max() < 1e-3,
      "the stored direction is not a unit vector (%.4f..%.4f)" % (length.min(), length.max()))
sys.exit(1 if failures else 0)
