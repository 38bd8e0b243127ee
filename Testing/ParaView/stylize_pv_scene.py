"""The scene the ParaView tests render (render_styles.py, render_transparent.py): a contour of
ParaView's Wavelet source, which ParaView splits across ranks, on a coloured background; and the
checks' bookkeeping and PNG reading of the tests that run inside ParaView (test_styles.py,
test_gui.py)."""
from paraview.simple import ColorBy, Contour, Show, Wavelet
from paraview.vtk.vtkIOImage import vtkPNGReader

BACKGROUND = [0.32, 0.34, 0.43]

failures = []


def check(condition, message):
    """Prints the outcome ("ok" or "FAIL" and the message) and records a failure."""
    print(("ok   " if condition else "FAIL ") + message, flush=True)
    if not condition:
        failures.append(message)


def pixels(path):
    """The PNG's dimensions and its pixels as RGB tuples (rows bottom to top)."""
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    scalars = image.GetPointData().GetScalars()
    n = scalars.GetNumberOfComponents()
    values = [scalars.GetValue(i) for i in range(scalars.GetNumberOfValues())]
    return image.GetDimensions(), [tuple(values[i:i + 3]) for i in range(0, len(values), n)]


def make_view(view, size):
    """Sizes the view and gives it the tests' flat background, without the orientation axes."""
    view.ViewSize = size
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = BACKGROUND


def make_contour():
    return Contour(Input=Wavelet(), ContourBy=["POINTS", "RTData"], Isosurfaces=[157.0])


def show_framed(source, view):
    """Shows source in view in its solid colour, from the tests' camera direction."""
    display = Show(source, view)
    ColorBy(display, None)
    view.CameraPosition = [30.0, -45.0, 25.0]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.ResetCamera()
    return display
