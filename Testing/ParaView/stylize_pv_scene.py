"""The scene the ParaView tests render (render_styles.py, render_transparent.py): a contour of
ParaView's Wavelet source, which ParaView splits across ranks, on a coloured background."""
from paraview.simple import ColorBy, Contour, Show, Wavelet

BACKGROUND = [0.32, 0.34, 0.43]


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
