"""install.fresh_prefix: the installed Python package, imported with PYTHONPATH=PREFIX/python
only, renders a comic image (black and white ink over a sphere).

    check_python.py PREFIX
"""
import os
import sys

prefix = os.path.realpath(sys.argv[1])
import vtkstylize  # noqa: E402
from vtkmodules.vtkFiltersSources import vtkSphereSource  # noqa: E402
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderer,  # noqa: E402
                                         vtkRenderWindow, vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: E402,F401

where = os.path.realpath(vtkstylize.__file__)
if not where.startswith(prefix + os.sep):
    sys.exit("vtkstylize was imported from %s, not from %s" % (where, prefix))

sphere = vtkSphereSource()
sphere.SetThetaResolution(48)
sphere.SetPhiResolution(24)
mapper = vtkPolyDataMapper()
mapper.SetInputConnection(sphere.GetOutputPort())
actor = vtkActor()
actor.SetMapper(mapper)
renderer = vtkRenderer()
renderer.AddActor(actor)
renderer.SetBackground(1, 1, 1)
vtkstylize.apply_style(renderer, "comic")
window = vtkRenderWindow()
window.SetOffScreenRendering(1)
window.SetMultiSamples(0)
window.SetSize(120, 90)
window.AddRenderer(renderer)
window.Render()
grab = vtkWindowToImageFilter()
grab.SetInput(window)
grab.Update()
scalars = grab.GetOutput().GetPointData().GetScalars()
values = [scalars.GetTuple(i) for i in range(scalars.GetNumberOfTuples())]
black = sum(1 for v in values if max(v[:3]) < 64)
gray = all(v[0] == v[1] == v[2] for v in values)
window.Finalize()
if black < 50 or not gray:
    sys.exit("the comic image is not black-and-white ink (%d dark pixels, gray: %s)" % (black, gray))
print("Python package from %s: comic image with %d dark pixels" % (where, black))
