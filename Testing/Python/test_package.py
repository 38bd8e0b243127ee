"""Python test: the vtkstylize package layer (Python/vtkstylize/__init__.py).

- the package documents and re-exports every wrapped class, and the build tree's copy of
  __init__.py is the source file (argv[1], when given);
- STYLES lists the five style names; create_pass() builds each style's pass and applies settings by
  setter name: set values read back, out-of-range values come back clamped, strings select
  Set<Name>To<Value> methods and enum constants, tuples are unpacked, settings apply in order;
- unknown styles and settings raise ValueError naming the culprit (with a suggestion), a value
  the setter refuses raises TypeError, and "none" takes no settings;
- apply_style() sets the pass on a renderer and returns it, switches between styles without VTK
  errors, and "none" restores VTK's default rendering: the image equals a renderer that never
  had a pass (needs a display).

Run with the build's python folder on PYTHONPATH and a display (the suite does both).
"""
import sys

import vtkstylize
import vtkstylize.vtkStylizeFilters
import vtkstylize.vtkStylizeIO
import vtkstylize.vtkStylizePasses
from vtkstylize_testing import vtkStylizeImageMetrics
from vtkmodules.vtkCommonCore import vtkOutputWindow, vtkStringOutputWindow
from vtkmodules.vtkRenderingCore import vtkRenderer, vtkWindowToImageFilter

from stylize_test_scene import check, failures, offscreen_window, sphere_actor


def raises(kind, call, *needles):
    """Whether call() raises kind with every needle in its message; prints the message."""
    try:
        call()
    except kind as error:
        print("  %s: %s" % (kind.__name__, error))
        return all(n in str(error) for n in needles)
    except Exception as error:  # noqa: BLE001 (the wrong kind is a failure)
        print("  unexpected %s: %s" % (type(error).__name__, error))
        return False
    print("  nothing raised")
    return False


# The package: documented, every wrapped class re-exported, the build copy is the source.
doc = vtkstylize.__doc__ or ""
for module in (vtkstylize.vtkStylizePasses, vtkstylize.vtkStylizeIO,
               vtkstylize.vtkStylizeFilters):
    for name in (n for n in dir(module) if n.startswith("vtk")):
        check(getattr(vtkstylize, name, None) is getattr(module, name),
              "%s is not re-exported by the package" % name)
        check("``%s``" % name in doc, "%s is not described in the package's docstring" % name)
for name in ("STYLES", "create_pass", "apply_style", "configure"):
    check("``%s" % name in doc, "%s is not described in the package's docstring" % name)
    check(getattr(vtkstylize, name, None) is not None, "vtkstylize.%s is missing" % name)
from vtkstylize import vtkComicPass, vtkLineArtPass, vtkPixelArtPass, vtkSketchPass  # noqa: E402
if len(sys.argv) > 1:
    with open(sys.argv[1], encoding="utf-8") as source, \
            open(vtkstylize.__file__, encoding="utf-8") as built:
        check(source.read() == built.read(),
              "%s is not a copy of %s: re-run cmake" % (vtkstylize.__file__, sys.argv[1]))

# STYLES and create_pass for each style.
check(vtkstylize.STYLES == ("none", "comic", "pixel", "sketch", "lines"), "STYLES: %r" % (vtkstylize.STYLES,))
check(vtkstylize.create_pass("none") is None, "create_pass('none') is not None")
classes = {"comic": vtkComicPass, "pixel": vtkPixelArtPass, "sketch": vtkSketchPass,
           "lines": vtkLineArtPass}
for style, cls in classes.items():
    p = vtkstylize.create_pass(style)
    check(isinstance(p, cls), "create_pass(%r) gave %r" % (style, p))
    q = vtkstylize.create_pass(style.upper())
    check(isinstance(q, cls) and q is not p, "create_pass(%r) gave %r" % (style.upper(), q))

# Settings: applied, clamped, strings, tuples, booleans.
c = vtkstylize.create_pass("comic", EdgeWidth=2.0, DotSpacing=0.5, HatchSpacing=1e9,
                           Dots=False, Tint="ALL_COLORS", EdgeWeights=(1, 0, 0), Anchor="Object")
check(c.GetEdgeWidth() == 2.0, "comic EdgeWidth: %g" % c.GetEdgeWidth())
check(c.GetDotSpacing() == c.GetDotSpacingMinValue() == 2.0,
      "comic DotSpacing 0.5 not clamped to the minimum: %g" % c.GetDotSpacing())
check(c.GetHatchSpacing() == c.GetHatchSpacingMaxValue() == 200.0,
      "comic HatchSpacing 1e9 not clamped to the maximum: %g" % c.GetHatchSpacing())
check(not c.GetDots() and c.GetTint() == vtkComicPass.ALL_COLORS, "comic Dots/Tint not applied")
check(tuple(c.GetEdgeWeights()) == (1.0, 0.0, 0.0), "comic EdgeWeights: %r" % (c.GetEdgeWeights(),))
check(c.GetAnchor() == vtkComicPass.OBJECT, "comic Anchor='Object': %d" % c.GetAnchor())

p = vtkstylize.create_pass("pixel", PixelSize=0, Levels=1000, Mode="fast",
                           Palette="PALETTE16", OutlineColor=(1, 0, 0), Layer="EDGES")
check(p.GetPixelSize() == p.GetPixelSizeMinValue() == 1, "pixel PixelSize 0: %d" % p.GetPixelSize())
check(p.GetLevels() == p.GetLevelsMaxValue() == 256, "pixel Levels 1000: %d" % p.GetLevels())
check(p.GetMode() == vtkPixelArtPass.FAST, "pixel Mode='fast': %d" % p.GetMode())
check(p.GetPalette() == vtkPixelArtPass.PALETTE16, "pixel Palette: %d" % p.GetPalette())
check(tuple(p.GetOutlineColor()) == (1.0, 0.0, 0.0), "pixel OutlineColor: %r" % (p.GetOutlineColor(),))
check(p.GetLayer() == vtkPixelArtPass.EDGES, "pixel Layer='EDGES': %d" % p.GetLayer())
# In order: PaletteToOneBit sets GRAYS and 2 levels, then Levels=3 overrides the levels.
p = vtkstylize.create_pass("pixel", Palette="OneBit", Levels=3)
check(p.GetPalette() == vtkPixelArtPass.GRAYS and p.GetLevels() == 3,
      "pixel Palette='OneBit', Levels=3: palette %d, levels %d" % (p.GetPalette(), p.GetLevels()))

s = vtkstylize.create_pass("sketch", Neighbors=7, Steps=100000, StepLength=-5,
                           PaperColor=(2, 0.5, -1), DirectionArrayName="PrincipalMinDirection")
check(s.GetNeighbors() == 8, "sketch Neighbors 7 does not snap to 8: %d" % s.GetNeighbors())
check(s.GetSteps() == 256, "sketch Steps not clamped: %d" % s.GetSteps())
check(s.GetStepLength() == s.GetStepLengthMinValue(), "sketch StepLength: %g" % s.GetStepLength())
check(tuple(s.GetPaperColor()) == (1.0, 0.5, 0.0), "sketch PaperColor: %r" % (s.GetPaperColor(),))
check(s.GetDirectionArrayName() == "PrincipalMinDirection",
      "sketch DirectionArrayName: %r" % s.GetDirectionArrayName())

# configure() on a style's lighting pass.
lighting = vtkstylize.configure(s.GetLightingPass(), Model="Comic", SubjectFactor=3.0)
check(lighting is s.GetLightingPass(), "configure does not return its object")
check(lighting.GetModel() == vtkstylize.vtkStylizeLightingPass.COMIC and
      lighting.GetSubjectFactor() == 1.0,
      "lighting Model/SubjectFactor: %d, %g" % (lighting.GetModel(), lighting.GetSubjectFactor()))

# Errors.
print("errors:")
check(raises(ValueError, lambda: vtkstylize.create_pass("cartoon"), "cartoon", "comic", "sketch"),
      "an unknown style does not raise a clear ValueError")
check(raises(ValueError, lambda: vtkstylize.create_pass("comic", EdgeWidht=2.0),
             "EdgeWidht", "vtkComicPass", "EdgeWidth"),
      "an unknown setting does not raise a clear ValueError")
check(raises(ValueError, lambda: vtkstylize.create_pass("pixel", PixelSise=4), "PixelSise"),
      "an unknown pixel setting does not raise")
check(raises(ValueError, lambda: vtkstylize.create_pass("sketch", Palette="PALETTE16"), "Palette"),
      "a setting of another style does not raise")
check(raises(ValueError, lambda: vtkstylize.create_pass("pixel", Palette="bogus"), "bogus"),
      "an unknown enum name does not raise")
check(raises(TypeError, lambda: vtkstylize.create_pass("comic", EdgeWidth="wide"),
             "SetEdgeWidth", "wide"),
      "a value of the wrong type does not raise a clear TypeError")
check(raises(ValueError, lambda: vtkstylize.create_pass("none", EdgeWidth=2.0), "none"),
      "'none' accepts settings")
check(raises(ValueError, lambda: vtkstylize.configure(lighting, Bogus=1), "Bogus"),
      "configure accepts an unknown setting")

# apply_style on a renderer: the pass is set and returned; "none" restores plain VTK.
messages = vtkStringOutputWindow()
vtkOutputWindow.SetInstance(messages)
window = offscreen_window(160, 120)
renderer = vtkRenderer()
renderer.SetBackground(1, 1, 1)
window.AddRenderer(renderer)
actor = sphere_actor()
renderer.AddActor(actor)
renderer.ResetCamera()


def grab():
    window.Render()
    w2i = vtkWindowToImageFilter()
    w2i.SetInput(window)
    w2i.ReadFrontBufferOff()
    w2i.Update()
    return w2i.GetOutput()


metrics = vtkStylizeImageMetrics
plain = grab()
for style in ("comic", "pixel", "sketch", "lines", "comic"):
    applied = vtkstylize.apply_style(renderer, style, ReferenceHeight=120) \
        if style != "pixel" else vtkstylize.apply_style(renderer, style, PixelSize=8)
    check(isinstance(applied, classes[style]) and renderer.GetPass() is applied,
          "apply_style(%r) did not set its pass" % style)
    styled = grab()
    d = metrics.MaximumDifference(plain, styled)
    print("apply_style(%r): max difference from plain VTK %g" % (style, d))
    check(d > 100, "apply_style(%r) renders like plain VTK (max difference %g)" % (style, d))
check(renderer.GetPass().GetReferenceHeight() == 120, "apply_style settings not applied")
check(vtkstylize.apply_style(renderer, "none") is None, "apply_style('none') returned a pass")
check(renderer.GetPass() is None, "apply_style('none') left a pass on the renderer")
restored = grab()
d = metrics.MaximumDifference(plain, restored)
print("apply_style('none'): max difference from plain VTK %g" % d)
check(d == 0, "apply_style('none') does not restore plain VTK rendering (max difference %g)" % d)
window.Finalize()
window = renderer = actor = None  # destroy the window and the last pass now
log = messages.GetOutput() or ""
check("ERROR" not in log.upper(), "VTK errors while switching styles:\n%s" % log)

print("%d failure(s)" % len(failures))
sys.exit(1 if failures else 0)
