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


def overlay_match(plain, bare, styled, where, level, styled_bare=None):
    """Whether a style draws an overlay (axes, text) where the plain picture draws it: the
    overlay's pixels are where `plain` (with it) differs from `bare` (without it) by more than
    `level` summed over the channels, within the boolean mask `where`; what the style draws of
    it, where `styled` differs from `styled_bare` (the style's picture without it; default
    `bare`) so. Returns (recall: the share of the overlay's pixels within 1 px of the style's,
    precision: the share of the style's within 1 px of the overlay's, the overlay's pixel
    count)."""
    import numpy
    overlay = (numpy.abs(plain - bare).sum(axis=2) > level) & where
    drawn = (numpy.abs(styled - (bare if styled_bare is None else styled_bare)).sum(axis=2)
             > level) & where
    recall = float(near(drawn, 1)[overlay].mean()) if overlay.any() else 0.0
    precision = float(near(overlay, 1)[drawn].mean()) if drawn.any() else 0.0
    return recall, precision, int(overlay.sum())
