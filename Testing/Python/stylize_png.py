"""PNG files as numpy arrays, for the tests that compare images pixel by pixel."""
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader


def png_array(path):
    """The image's pixels as a float array, rows top to bottom: (height, width, components)."""
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    w, h, _ = image.GetDimensions()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars()).reshape(h, w, -1)
    return pixels[::-1].astype(float)
