"""PNG files as numpy arrays, for the tests that compare images pixel by pixel."""
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter


def png_array(path):
    """The image's pixels as a float array, rows top to bottom: (height, width, components)."""
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    w, h, _ = image.GetDimensions()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars()).reshape(h, w, -1)
    return pixels[::-1].astype(float)


def window_array(window):
    """A rendered window's RGB pixels (its back buffer) as uint8, rows top to bottom:
    (height, width, 3)."""
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    image = grab.GetOutput()
    w, h, _ = image.GetDimensions()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars()).reshape(h, w, -1)[:, :, :3]
    return pixels[::-1].copy()


def save_png(pixels, path):
    """Writes (height, width, 3) uint8 pixels, rows top to bottom, as a PNG."""
    from vtkmodules.util.numpy_support import numpy_to_vtk
    from vtkmodules.vtkCommonDataModel import vtkImageData
    from vtkmodules.vtkIOImage import vtkPNGWriter
    h, w, _ = pixels.shape
    image = vtkImageData()
    image.SetDimensions(w, h, 1)
    image.GetPointData().SetScalars(numpy_to_vtk(pixels[::-1].reshape(-1, 3).copy()))
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputData(image)
    writer.Write()


def luminance(pixels):
    """Rec. 709 luminance of (height, width, 3) pixels, in their units."""
    import numpy
    return pixels.astype(numpy.float64) @ numpy.array([0.2126, 0.7152, 0.0722])


def near(mask, radius):
    """The pixels within `radius` (chessboard distance) of a pixel of the boolean `mask`."""
    import numpy
    out = mask.copy()
    for dy in range(-radius, radius + 1):
        for dx in range(-radius, radius + 1):
            out |= numpy.roll(numpy.roll(mask, dy, axis=0), dx, axis=1)
    return out
