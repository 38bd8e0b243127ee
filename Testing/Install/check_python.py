"""install.fresh_prefix: the installed Python package, imported with PYTHONPATH=PREFIX/python
only, renders a comic image (black and white ink over a sphere).

    check_python.py PREFIX
"""
import os
import sys

prefix = os.path.realpath(sys.argv[1])
import vtkstylize  # noqa: E402
from vtkmodules.vtkRenderingCore import vtkRenderer, vtkWindowToImageFilter  # noqa: E402
import vtkmodules.vtkRenderingOpenGL2  # noqa: E402,F401

# The Python tests' shared scene pieces. Their folder goes last on the path, so that vtkstylize
# can only come from PYTHONPATH (the prefix), as checked below.
sys.path.append(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Python"))
from stylize_test_scene import offscreen_window, sphere_actor  # noqa: E402

where = os.path.realpath(vtkstylize.__file__)
if not where.startswith(prefix + os.sep):
    sys.exit("vtkstylize was imported from %s, not from %s" % (where, prefix))

renderer = vtkRenderer()
renderer.AddActor(sphere_actor(48, 24))
renderer.SetBackground(1, 1, 1)
vtkstylize.apply_style(renderer, "comic")
window = offscreen_window(120, 90)
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
