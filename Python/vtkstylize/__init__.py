"""VTK Stylize: non-photorealistic render passes for VTK, as one Python package.

The package holds the project's four wrapped VTK modules, re-exported at package level:

Render passes (module ``vtkstylize.vtkStylizePasses``):

- ``vtkComicPass``: black-and-white comic rendering: toon lighting, depth, normal and colour
  edges, halftone dots where bright, hatching where dark.
- ``vtkPixelArtPass``: pixel art: pixelation to art pixels, Canny outlines, ordered dither to
  a palette (levels per channel, grays, 16 colours, a user list or the data's colormap).
- ``vtkSketchPass``: pencil sketch: line integral convolution of surface noise along the
  principal curvature directions, pencil tone and cross-hatching.
- ``vtkLineArtPass``: line art: contours, creases, ridges, valleys and suggestive contours found
  on the meshes, hidden lines removed, drawn in ink on paper over an optional flat tone.
- ``vtkStylizeStylePass``: the base of the four styles, an image-processing pass (it renders
  the geometry itself, or stylizes the image of a delegate pass when one is set).
- ``vtkStylizeLightingPass``: VTK's lighting replaced by a selectable model (Standard, Comic,
  PixelArt); the lighting stage of the four styles (``GetLightingPass()``).
- ``vtkStylizeGBufferPass``: the shared G-buffer (lit colour, depth, normals, positions) the
  screen-space styles read.
- ``vtkStylizeSceneLights``: ``AddLights(renderer, count, center, distance, ...)``, the
  deterministic lights of ``vtkstylize --lights N``: white scene lights spread over a sphere.
- ``vtkStylizeAtomicFile``: ``Write(path, array)`` writes a file whole or not at all (a
  temporary file renamed over it); returns 0 or an ``errno`` value.

Filters (module ``vtkstylize.vtkStylizeFilters``):

- ``vtkStylizeDemoScene``: the built-in scene (wavelet isosurface, torus, streamline tubes) as
  a multiblock dataset.
- ``vtkStylizePrincipalCurvatures``: per-point principal curvatures and directions of a surface.
- ``vtkStylizeFeatureLines``: the lines an illustrator draws on a surface seen by a camera
  (contours, boundaries, creases, ridges, valleys, suggestive contours), as polylines.
- ``vtkStylizeLineVisibility``: hidden-line removal for those lines, against a rendering's depth
  buffer or by ray casting: the lines split where they pass behind a surface.
- ``vtkStylizeRayOccluder``: a surface's triangles under a bounding volume hierarchy, built once
  and shared by the ray casting of every line filter and thread.
- ``vtkStylizeViewFilter``: the base of those two (the camera and the model matrix).
- ``vtkStylizeVolumeSurface``: the surface a volume shows, where its scalar opacity reaches a
  threshold (the styles draw volumes as it: ``StylizeVolumes``).

Checked reading and the animation encoder (module ``vtkstylize.vtkStylizeIO``):

- ``vtkStylizeReader``: reads any dataset file the project renders (VTK XML and legacy, .pvd,
  Exodus, EnSight, OpenFOAM, STL, OBJ, PLY), checked before VTK's reader opens it and validated
  after, so that a broken or hostile file gives one error line (``GetErrorMessage()``) instead
  of a crash, a hang or a huge allocation.
- ``vtkStylizeOutputWindow``: an output window that records VTK's messages, for a program that
  reports the first failure in one line.
- ``vtkStylizeAnimationEncoder``: numbered PNG frames into a GIF or MP4 with ffmpeg (``encode()``).

Figures (module ``vtkstylize.vtkStylizeFigures``):

- ``vtkStylizeFigureWriter``: a stylized render window as a vector figure (SVG, PDF): comic
  outlines traced, dots and hatch lines exact, pixel art as rectangles, sketch pencil as an
  image under vector outlines, line art as stroked paths from the geometry, text and scalar bars as vector text and shapes.

And a small pure-Python layer:

- ``STYLES``: the style names, ``("none", "comic", "pixel", "sketch", "lines")``.
- ``create_pass(style, **settings)``: a new pass for a style, its settings given by VTK setter
  name (``EdgeWidth=2.0`` calls ``SetEdgeWidth(2.0)``); ``None`` for ``"none"``.
- ``apply_style(renderer, style, **settings)``: sets that pass on a renderer and returns it;
  ``"none"`` restores VTK's default rendering (``renderer.SetPass(None)``).
- ``configure(obj, **settings)``: the same setter calls on any VTK object, e.g. a style's
  lighting pass.
- ``settings_of(obj)``: the setting names of a pass (or any VTK object or class).
- ``save_figure(window, path, **settings)``: writes the window as a vector figure (``.svg`` or
  ``.pdf``; settings of ``vtkStylizeFigureWriter`` by setter name); raises ``RuntimeError``
  with the writer's one-line message on failure.
- ``orbit(window, frames, path_pattern, degrees=360, elevation=0, surface_anchor=True)``: an
  orbit animation: writes ``frames`` PNGs (``path_pattern % index``), the camera turned by
  ``degrees / frames`` between them, the patterns anchored to the surface (restored after);
  ``encode(path_pattern, output, fps=25)`` makes a ``.gif`` or ``.mp4`` of them with ffmpeg.

Importing: put the build's ``python`` folder (``<build>/python``) or the installed ``python``
folder on ``PYTHONPATH`` and use the interpreter VTK's Python is built for (``/usr/bin/python3``
with Debian's python3-vtk9)::

    import vtkstylize
    comic = vtkstylize.apply_style(renderer, "comic", EdgeWidth=2.0, Tint="ALL_COLORS")
    vtkstylize.configure(comic.GetLightingPass(), SubjectFactor=0.5)

    from vtkstylize import vtkPixelArtPass          # the wrapped classes, as before
    pixel = vtkstylize.create_pass("pixel", PixelSize=6, Palette="PALETTE16")
    renderer.SetPass(pixel)

Setting values: a number, bool or string is passed to ``Set<Name>``; a tuple or list is
unpacked (``OutlineColor=(1, 0, 0)``); a string names a ``Set<Name>To<Value>`` method when one
exists (``Mode="Fast"``, ``Anchor="Object"``, ``Model="Comic"``) or an enum constant of the
class (``Palette="PALETTE16"``, ``Layer="EDGES"``). The passes' setters clamp out-of-range
values, so read back with ``Get<Name>``. An unknown setting raises ``ValueError``, a value the
setter does not accept ``TypeError``.
"""

import difflib as _difflib

import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (loads VTK's OpenGL classes first)
from vtkmodules.vtkRenderingOpenGL2 import vtkOpenGLRenderPass as _vtkOpenGLRenderPass

from .vtkStylizePasses import *  # noqa: F401,F403
from .vtkStylizeIO import *  # noqa: F401,F403
from .vtkStylizeFilters import *  # noqa: F401,F403
from .vtkStylizeFigures import *  # noqa: F401,F403
from .vtkStylizePasses import vtkComicPass as _vtkComicPass
from .vtkStylizePasses import vtkPixelArtPass as _vtkPixelArtPass
from .vtkStylizePasses import vtkSketchPass as _vtkSketchPass
from .vtkStylizePasses import vtkLineArtPass as _vtkLineArtPass

#: The style names accepted by create_pass() and apply_style(), "none" first.
STYLES = ("none", "comic", "pixel", "sketch", "lines")

_STYLE_CLASSES = {
    "comic": _vtkComicPass,
    "pixel": _vtkPixelArtPass,
    "sketch": _vtkSketchPass,
    "lines": _vtkLineArtPass,
}


def _style_class(style):
    """The pass class of a style name (None for "none"); ValueError for an unknown name."""
    key = style.strip().lower() if isinstance(style, str) else style
    if key == "none":
        return None
    if key in _STYLE_CLASSES:
        return _STYLE_CLASSES[key]
    raise ValueError("unknown style %r: use one of %s" % (style, ", ".join(STYLES)))


def settings_of(obj):
    """The setting names of a VTK object or class: names with both Set<Name> and Get<Name>,
    without those every render pass has (Debug, ReferenceCount, ...), sorted."""
    names = dir(obj)
    base = set(dir(_vtkOpenGLRenderPass))
    return sorted(n[3:] for n in names
                  if n.startswith("Set") and len(n) > 3 and ("Get" + n[3:]) in names
                  and n not in base)


def _find_method(obj, name):
    """obj's method called name, or, ignoring case, the one method whose name matches."""
    method = getattr(obj, name, None)
    if method is not None:
        return method
    matches = [n for n in dir(obj) if n.lower() == name.lower()]
    return getattr(obj, matches[0]) if len(matches) == 1 else None


def _apply_setting(obj, name, value):
    cls = obj.GetClassName() if hasattr(obj, "GetClassName") else type(obj).__name__
    setter = getattr(obj, "Set" + name, None) if name.isidentifier() else None
    if setter is None or not callable(setter):
        known = settings_of(obj)
        close = _difflib.get_close_matches(name, known, n=3)
        hint = (" (did you mean %s?)" % ", ".join(close)) if close else ""
        raise ValueError("%s has no setting %r (no method Set%s)%s; its settings: %s"
                         % (cls, name, name, hint, ", ".join(known)))
    call = "%s.Set%s" % (cls, name)
    if isinstance(value, str):
        # Set<Name>To<Value>() (SetModeToFast), else an enum constant (PALETTE16), else the
        # string itself (DirectionArrayName).
        to = _find_method(obj, "Set%sTo%s" % (name, value.replace(" ", "")))
        if to is not None and callable(to):
            to()
            return
        getter = getattr(obj, "Get" + name, None)
        current = getter() if callable(getter) else None
        constant = getattr(type(obj), value.upper(), None)
        if isinstance(current, int) and not isinstance(current, bool):
            if not isinstance(constant, int):
                raise ValueError("%s: %r is neither a Set%sTo%s method nor a constant of %s"
                                 % (call, value, name, value, cls))
            value = constant
    try:
        if isinstance(value, (tuple, list)):
            setter(*value)
        else:
            setter(value)
    except TypeError as error:
        raise TypeError("%s(%r): %s" % (call, value, error)) from None


def configure(obj, **settings):
    """Calls obj.Set<Name>(value) for each Name=value (see the package's documentation for
    how values are passed); returns obj. Settings apply in the order given. An unknown name
    raises ValueError, a value the setter does not take TypeError."""
    for name, value in settings.items():
        _apply_setting(obj, name, value)
    return obj


def create_pass(style, **settings):
    """A new render pass for style (one of STYLES, any case), configured with settings by
    setter name: create_pass("comic", EdgeWidth=2.0) calls SetEdgeWidth(2.0). Returns a
    vtkComicPass, vtkPixelArtPass, vtkSketchPass or vtkLineArtPass; None for "none" (which
    takes no settings).
    ValueError for an unknown style or setting."""
    cls = _style_class(style)
    if cls is None:
        if settings:
            raise ValueError("style 'none' takes no settings (got %s)"
                             % ", ".join(sorted(settings)))
        return None
    return configure(cls(), **settings)


def apply_style(renderer, style, **settings):
    """Sets create_pass(style, **settings) on renderer and returns the pass. Style "none"
    restores VTK's default rendering (renderer.SetPass(None)) and returns None. The pass the
    renderer had releases its graphics resources in the renderer's window first. Render the
    window afterwards."""
    new_pass = create_pass(style, **settings)
    old_pass = renderer.GetPass()
    window = renderer.GetRenderWindow()
    if old_pass is not None and window is not None:
        old_pass.ReleaseGraphicsResources(window)
    renderer.SetPass(new_pass)
    return new_pass


def save_figure(window, path, **settings):
    """Writes `window` (rendered with a style) as a vector figure at `path` (.svg or .pdf)."""
    writer = vtkStylizeFigureWriter()
    configure(writer, **settings)
    writer.SetRenderWindow(window)
    writer.SetFileName(str(path))
    if not writer.Write():
        raise RuntimeError(writer.GetErrorMessage())
    return writer


def _surface_anchor(style_pass):
    """Anchors a style's pattern to the surface; returns the call that restores it."""
    if not hasattr(style_pass, "AnchorPatternsToSurface"):
        return lambda: None
    style_pass.AnchorPatternsToSurface()
    return style_pass.RestorePatternAnchors


def orbit(window, frames, path_pattern, degrees=360.0, elevation=0.0, surface_anchor=True,
          magnification=1):
    """Renders an orbit of `frames` PNGs named ``path_pattern % i`` (e.g. "orbit-%04d.png").

    The active camera of the window's first renderer is raised by `elevation` degrees, then
    turned by ``degrees / frames`` about the view-up axis between frames, and restored
    afterwards (as SaveStylizedOrbit in ParaView does). With `surface_anchor` the styles'
    patterns (comic dots and hatching, pixel-art texels, sketch noise: object space and the
    SPARSE noise) are anchored to the surface for the animation and restored afterwards.
    Returns the written paths.
    """
    from vtkmodules.vtkIOImage import vtkPNGWriter
    from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter
    frames = int(frames)
    if frames < 1:
        raise ValueError("frames must be at least 1, got %r" % frames)
    renderer = window.GetRenderers().GetFirstRenderer()
    if renderer is None:
        raise ValueError("the window has no renderer")
    restores = []
    if surface_anchor:
        renderers = window.GetRenderers()
        renderers.InitTraversal()
        for _ in range(renderers.GetNumberOfItems()):
            restores.append(_surface_anchor(renderers.GetNextItem().GetPass()))
    camera = renderer.GetActiveCamera()
    saved = (camera.GetPosition(), camera.GetFocalPoint(), camera.GetViewUp())
    written = []
    try:
        if elevation:
            camera.Elevation(float(elevation))
            camera.OrthogonalizeViewUp()
        for index in range(frames):
            if index:
                camera.Azimuth(float(degrees) / frames)
                camera.OrthogonalizeViewUp()
            renderer.ResetCameraClippingRange()
            window.Render()
            grab = vtkWindowToImageFilter()
            grab.SetInput(window)
            grab.SetInputBufferTypeToRGB()
            grab.ReadFrontBufferOff()
            grab.SetScale(int(magnification))
            grab.Update()
            writer = vtkPNGWriter()
            writer.SetInputConnection(grab.GetOutputPort())
            path = path_pattern % index
            writer.SetFileName(path)
            writer.Write()
            written.append(path)
    finally:
        camera.SetPosition(saved[0])
        camera.SetFocalPoint(saved[1])
        camera.SetViewUp(saved[2])
        renderer.ResetCameraClippingRange()
        for restore in restores:
            restore()
    return written


def encode(path_pattern, output, fps=25):
    """Encodes the numbered PNGs `path_pattern` (ffmpeg's printf-style name, e.g.
    "orbit-%04d.png") into `output` (.gif or .mp4) with ffmpeg, as vtkstylize --orbit does
    (vtkStylizeAnimationEncoder.Encode). Raises RuntimeError with the failure's line."""
    error = vtkStylizeAnimationEncoder.Encode(str(path_pattern), int(fps), str(output))
    if error:
        raise RuntimeError(error)
    return str(output)
