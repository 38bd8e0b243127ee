"""VTK Stylize in ParaView's Python (pvbatch, pvpython, the Python shell): figures and orbits.

Embedded in the VTKStylize plugin; importable once the plugin is loaded::

    from paraview.simple import *
    import stylize_paraview as stylize
    view = CreateView("StylizeView")
    view.Style = "Comic"
    ...
    stylize.SaveStylizedFigure("figure.svg", view)           # or figure.pdf
    stylize.SaveStylizedOrbit("orbit.gif", view, frames=36)  # frames orbit-0000.png ... too

Both render as the view renders (under MPI every rank takes part; the first writes).
"""

def _element(view, name):
    return view.SMProxy.GetProperty(name).GetElement(0)


def _set_element(view, name, value):
    view.SMProxy.GetProperty(name).SetElement(0, value)
    view.SMProxy.UpdateVTKObjects()


def _view(view):
    from paraview import simple
    view = view or simple.GetActiveView()
    if view is None or view.SMProxy.GetProperty("FigureFileName") is None:
        raise ValueError("not a VTK Stylize view (CreateView('StylizeView'))")
    return view


def _push(view, name, values):
    """Sets the view's internal command property `name` and pushes it even when unchanged;
    returns the view's FigureResult ("" after a success)."""
    proxy = view.SMProxy
    prop = proxy.GetProperty(name)
    for i, value in enumerate(values):
        prop.SetElement(i, str(value))
    proxy.UpdateProperty(name, 1)
    proxy.UpdatePropertyInformation(proxy.GetProperty("FigureResult"))
    result = proxy.GetProperty("FigureResult").GetElement(0) or ""
    # back to the empty value, which does nothing when it is pushed with other properties later
    for i in range(len(values)):
        prop.SetElement(i, "0" if name == "AnimationEncoding" and i == 1 else "")
    return result


def SaveStylizedFigure(filename, view=None):
    """Writes the view as a vector figure: SVG or PDF, from the extension of `filename`
    (vtkStylizeFigureWriter: comic outlines traced, dots and hatch lines exact, pixel art as
    rectangles, sketch pencil as an embedded image with traced outlines). The view's size, its
    current style. Raises RuntimeError with the writer's line on failure. Returns `filename`."""
    from paraview import simple
    view = _view(view)
    if _element(view, "Style") == 0:
        raise RuntimeError("cannot write a figure: the view's Style is None")
    simple.Render(view)
    error = _push(view, "FigureFileName", [str(filename)])
    if error:
        raise RuntimeError(error)
    return str(filename)


def SaveStylizedOrbit(output, view=None, frames=36, degrees=360.0, elevation=0.0, fps=25,
                      surface_anchor=True):
    """Renders an orbit of `frames` frames: the camera raised by `elevation` degrees, then turned
    by degrees / frames about the view-up axis between frames, and restored afterwards. Writes
    STEM-0000.png ... (STEM is `output` without its extension); when `output` ends in .gif or
    .mp4 they are also encoded into it with ffmpeg (as vtkstylize --orbit). With
    `surface_anchor` the style's pattern (comic dots and hatching, pixel-art texels, sketch
    noise: object space and the SPARSE noise) is anchored to the surface for the orbit, so that
    it does not swim. Returns the written paths."""
    import os
    from paraview import simple
    view = _view(view)
    frames = int(frames)
    if frames < 1 or frames > 100000:
        raise ValueError("frames must be in [1, 100000], got %r" % frames)
    stem, ext = os.path.splitext(str(output))
    if ext.lower() not in (".png", ".gif", ".mp4"):
        raise ValueError("the orbit's output must end in .png, .gif or .mp4, got %r" % output)
    if surface_anchor:
        # (vtkStylizeStylePass::AnchorPatternsToSurface() on every rank)
        _set_element(view, "PatternsAnchored", 1)
    camera = view.GetActiveCamera()
    saved = (camera.GetPosition(), camera.GetFocalPoint(), camera.GetViewUp())
    digits = max(4, len(str(frames - 1)))
    written = []
    try:
        if elevation:
            camera.Elevation(float(elevation))
            camera.OrthogonalizeViewUp()
        for f in range(frames):
            if f:
                camera.Azimuth(float(degrees) / frames)
                camera.OrthogonalizeViewUp()
            path = "%s-%0*d.png" % (stem, digits, f)
            simple.SaveScreenshot(path, view, ImageResolution=list(view.ViewSize))
            written.append(path)
        if ext.lower() in (".gif", ".mp4"):
            pattern = stem.replace("%", "%%") + "-%0" + str(digits) + "d.png"
            error = _push(view, "AnimationEncoding", [pattern, int(fps), str(output)])
            if error:
                raise RuntimeError(error)
            written.append(str(output))
    finally:
        camera.SetPosition(saved[0])
        camera.SetFocalPoint(saved[1])
        camera.SetViewUp(saved[2])
        if surface_anchor:
            _set_element(view, "PatternsAnchored", 0)
        simple.Render(view)
    return written
