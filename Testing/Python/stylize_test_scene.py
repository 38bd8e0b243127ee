"""Shared pieces of the Python tests: failure bookkeeping, styles by class and settings, a sphere
and a torus test object (a curved surface whose principal directions are defined everywhere)."""
import os

import vtkstylize
from vtkmodules.vtkCommonComputationalGeometry import vtkParametricTorus
from vtkmodules.vtkFiltersCore import vtkPolyDataNormals
from vtkmodules.vtkFiltersSources import vtkParametricFunctionSource, vtkSphereSource
from vtkmodules.vtkIOPLY import vtkPLYReader
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderer, vtkRenderWindow
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL factories)

failures = []


def check(cond, message):
    """Records and prints a failure when cond is false; returns cond."""
    if not cond:
        failures.append(message)
        print("FAIL:", message)
    return cond


def style_maker(class_name, **settings):
    """A function that makes a new vtkstylize pass of class `class_name` with the settings given
    by name (Set<Name>(value), a tuple for several arguments)."""
    def make():
        style = getattr(vtkstylize, class_name)()
        for name, value in settings.items():
            args = value if isinstance(value, tuple) else (value,)
            getattr(style, "Set" + name)(*args)
        return style
    return make


def sphere_actor(theta_resolution=None, phi_resolution=None):
    """A vtkSphereSource (its default resolutions unless given) as an actor."""
    sphere = vtkSphereSource()
    if theta_resolution is not None:
        sphere.SetThetaResolution(theta_resolution)
    if phi_resolution is not None:
        sphere.SetPhiResolution(phi_resolution)
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(sphere.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    return actor


def torus_actor(cross_section, tilt):
    """A torus (ring radius 1, the given cross-section radius) with point normals, rotated by
    `tilt` degrees about x."""
    torus = vtkParametricTorus()
    torus.SetRingRadius(1.0)
    torus.SetCrossSectionRadius(cross_section)
    src = vtkParametricFunctionSource()
    src.SetParametricFunction(torus)
    src.SetUResolution(120)
    src.SetVResolution(60)
    normals = vtkPolyDataNormals()
    normals.SetInputConnection(src.GetOutputPort())
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(normals.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.RotateX(tilt)
    return actor


def offscreen_window(width, height):
    """An offscreen window without multisampling."""
    win = vtkRenderWindow()
    win.SetSize(width, height)
    win.SetMultiSamples(0)
    win.OffScreenRenderingOn()
    return win


def ply_mesh(data, name):
    """Mesh `name`.ply of the real-data set in folder `data`, with point normals."""
    reader = vtkPLYReader()
    reader.SetFileName(os.path.join(data, name + ".ply"))
    normals = vtkPolyDataNormals()
    normals.SetInputConnection(reader.GetOutputPort())
    normals.Update()
    return normals.GetOutput()


def mesh_window(mesh, color, background, width, height, azimuth, elevation):
    """`mesh` (vtkPolyData) as an actor of `color` in a renderer of `background`, in a new
    width x height offscreen window, the camera reset and turned; returns (window, renderer,
    actor)."""
    mapper = vtkPolyDataMapper()
    mapper.SetInputData(mesh)
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(*color)
    ren = vtkRenderer()
    ren.AddActor(actor)
    ren.SetBackground(*background)
    window = offscreen_window(width, height)
    window.AddRenderer(ren)
    ren.ResetCamera()
    ren.GetActiveCamera().Azimuth(azimuth)
    ren.GetActiveCamera().Elevation(elevation)
    return window, ren, actor
