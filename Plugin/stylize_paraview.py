"""VTK Stylize in ParaView's Python (pvbatch, pvpython, the Python shell): figures and orbits.

Embedded in the VTKStylize plugin; importable once the plugin is loaded::

    from paraview.simple import *
    import stylize_paraview as stylize
    view = CreateView("StylizeView")
    view.Style = "Comic"
    ...
    stylize.SaveStylizedFigure("figure.svg", view)           # or figure.pdf
    stylize.SaveStylizedOrbit("orbit.gif", view, frames=36)  # frames orbit-0000.png ... too

Both render as the view renders (under MPI every rank takes part; the first writes). The GUI's
File menu offers both ("Export Stylized Figure...", "Save Stylized Orbit...",
Plugin/pqStylizeFigureActions.cxx): they call the functions below through _gui_call, and the orbit
dialog's fields are ORBIT_OPTIONS with the function's defaults.
"""

# The orbit's options as the GUI's dialog shows them and as SaveStylizedOrbit checks them:
# (keyword, label, minimum, maximum, help); the defaults are SaveStylizedOrbit's own. A bool
# option has no range. The ranges are vtkstylize's (--orbit, --orbit-degrees, --orbit-elevation,
# --fps).
ORBIT_OPTIONS = (
    ("frames", "Frames", 1, 3600, "Number of frames (images) of the orbit."),
    ("degrees", "Degrees", -3600.0, 3600.0,
     "Angle the camera turns about the view-up axis over the whole orbit, in degrees; "
     "negative turns the other way."),
    ("elevation", "Elevation", -89.0, 89.0,
     "Angle the camera is raised (negative: lowered) before the orbit, in degrees."),
    ("fps", "Frame rate", 1, 100, "Frames per second of the GIF or MP4 (unused for .png frames)."),
    ("surface_anchor", "Anchor patterns to the surface", None, None,
     "Anchor the style's pattern (comic dots and hatching, pixel-art texels, sketch noise) to "
     "the surface for the orbit, so that it does not swim."),
)


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


def _checked(name, value):
    """`value` when it lies in ORBIT_OPTIONS' range for `name`; ValueError otherwise."""
    low, high = next((o[2], o[3]) for o in ORBIT_OPTIONS if o[0] == name)
    if not low <= value <= high:
        raise ValueError("%s must be in [%s, %s], got %r" % (name, low, high, value))
    return value


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
    frames = _checked("frames", int(frames))
    degrees = _checked("degrees", float(degrees))
    elevation = _checked("elevation", float(elevation))
    fps = _checked("fps", int(fps))
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


def _gui_orbit_options():
    """ORBIT_OPTIONS with SaveStylizedOrbit's defaults, as JSON (for the GUI's orbit dialog)."""
    import inspect
    import json
    defaults = inspect.signature(SaveStylizedOrbit).parameters
    kinds = {type(defaults[o[0]].default).__name__ for o in ORBIT_OPTIONS}
    if not kinds <= {"bool", "int", "float"}:  # the dialog has fields for these alone
        raise TypeError("orbit options of types the dialog cannot show: %s" % sorted(kinds))
    return json.dumps([{"name": name, "label": label, "default": defaults[name].default,
                        "type": type(defaults[name].default).__name__,
                        "minimum": low, "maximum": high, "help": text}
                       for name, label, low, high, text in ORBIT_OPTIONS])


def _gui_call(request):
    """Runs {"function": "SaveStylizedFigure" or "SaveStylizedOrbit", "arguments": {...}} (JSON)
    on the active view, as the GUI's File menu asks; returns JSON {"error": "" or the failure's
    line, "written": [paths]}. A failure is returned, not raised, so that the GUI can show it."""
    import json
    request = json.loads(request)
    functions = {"SaveStylizedFigure": SaveStylizedFigure, "SaveStylizedOrbit": SaveStylizedOrbit}
    try:
        result = functions[request["function"]](**request["arguments"])
    except Exception as error:  # every failure becomes the dialog's message
        return json.dumps({"error": str(error) or type(error).__name__, "written": []})
    return json.dumps({"error": "", "written": result if isinstance(result, list) else [result]})
