"""Translucent surfaces are stylized (issue 16, item 3).

    test_translucent.py DATA_DIR OUTPUT_DIR

vtkStylizeStylePass::TranslucentLayers: after the opaque scene, the style runs again on each
translucent layer (depth peeling in the G-buffer), and the layers are composited front to back
over the stylized opaque scene with the surfaces' opacity, lines at full strength.

1. Compositing, exactly: three overlapping translucent planes in front of an opaque one, drawn
   through pixel art's PIXELATED layer at one screen pixel per art pixel (the style's colour is
   the lit colour itself). Peeled and composited by the style, with the actors given front to
   back, the picture must equal VTK's own blending of the same lit colours with the actors given
   back to front (the order in which unsorted blending is right), within 3 levels; the same
   unsorted blending with the actors front to back must differ (the test sees the order).
   Three layers are found (a fourth is empty), and two layers drop the farthest plane.
2. Every style on real data: a scanned bunny at opacity 0.35 around an opaque CAD part (a
   gear, pinion). The translucent surface is stylized (the picture differs from plain blending);
   the renderer's depth-peeling setting changes no pixel; the pinion shows through a translucent
   bunny and not through an opaque one, and more through a lower opacity; the comic and the
   line art draw the bunny's outline in full-strength ink (the line art not with
   TranslucentOutlines off); pixel art with PALETTE16 keeps every pixel of the bunny in the
   palette (its layers composited as a screen door).
3. A magnified screenshot (vtkWindowToImageFilter, 3 x 3 tiles) of the translucent scene equals
   the direct render at the full size within realdata.seams' limits (a pixel differs when a
   channel is more than 16 levels apart): pixel art none, comic at most 0.05%.

The images are written to OUTPUT_DIR for inspection.
"""
import os
import sys

import numpy as np
import vtkstylize
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkFiltersSources import vtkPlaneSource
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderer,
                                         vtkWindowToImageFilter)

from stylize_png import near
from stylize_test_scene import check, failures, offscreen_window, ply_mesh
from stylize_volume_measures import in_palette

data, out = sys.argv[1], sys.argv[2]
os.makedirs(out, exist_ok=True)


def capture(win, name=None, scale=1):
    """Renders `win` and returns its RGB pixels (rows bottom to top) as a float array."""
    w2i = vtkWindowToImageFilter()
    w2i.SetInput(win)
    w2i.SetScale(scale)
    w2i.ReadFrontBufferOff()
    w2i.Update()
    image = w2i.GetOutput()
    if name:
        writer = vtkPNGWriter()
        writer.SetFileName(os.path.join(out, name + ".png"))
        writer.SetInputData(image)
        writer.Write()
    w, h, _ = image.GetDimensions()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars()).reshape(h, w, -1)
    return pixels[:, :, :3].astype(float)


def differing(a, b, tolerance=16):
    """Pixels with a channel more than `tolerance` levels apart."""
    return int(np.count_nonzero(np.abs(a - b).max(axis=2) > tolerance))


# 1. Compositing against VTK's blending ----------------------------------------------------------
def plane(z, x, y, colour, opacity):
    src = vtkPlaneSource()
    src.SetOrigin(x - 1.0, y - 1.0, z)
    src.SetPoint1(x + 1.0, y - 1.0, z)
    src.SetPoint2(x - 1.0, y + 1.0, z)
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(src.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(*colour)
    actor.GetProperty().SetOpacity(opacity)
    return actor


def planes_scene(front_to_back, layers, peeling=False):
    win = offscreen_window(200, 160)
    ren = vtkRenderer()
    ren.SetBackground(1.0, 1.0, 1.0)
    ren.SetUseDepthPeeling(1 if peeling else 0)
    win.AddRenderer(ren)
    translucent = [plane(0.0, -0.5, -0.3, (0.9, 0.2, 0.2), 0.5),
                   plane(0.5, 0.0, 0.3, (0.2, 0.8, 0.3), 0.4),
                   plane(1.0, 0.5, -0.1, (0.2, 0.3, 0.9), 0.6)]  # far to near
    ren.AddActor(plane(-0.5, 0.0, 0.0, (0.8, 0.8, 0.5), 1.0))
    for actor in (reversed(translucent) if front_to_back else translucent):
        ren.AddActor(actor)
    camera = ren.GetActiveCamera()
    camera.SetPosition(0.0, 0.0, 8.0)
    camera.SetFocalPoint(0.0, 0.0, 0.0)
    camera.ParallelProjectionOn()
    camera.SetParallelScale(1.6)
    ren.ResetCameraClippingRange()
    style = vtkstylize.vtkPixelArtPass()
    style.SetLayer(vtkstylize.vtkPixelArtPass.PIXELATED)
    style.SetPixelSize(1)
    style.SetTranslucentLayers(layers)
    ren.SetPass(style)
    return win, style


win, _ = planes_scene(front_to_back=False, layers=0)
sorted_blend = capture(win, "planes_blended_sorted")
win, _ = planes_scene(front_to_back=True, layers=0)
unsorted_blend = capture(win, "planes_blended_unsorted")
win, style = planes_scene(front_to_back=True, layers=4)
peeled = capture(win, "planes_peeled")
found = style.GetLastTranslucentLayers()
win, _ = planes_scene(front_to_back=True, layers=2)
two = capture(win, "planes_two_layers")
win, _ = planes_scene(front_to_back=True, layers=4, peeling=True)
peeled_vtk_peeling = capture(win)

d_peeled = differing(peeled, sorted_blend, 3)
d_unsorted = differing(unsorted_blend, sorted_blend, 16)
d_two = differing(two, sorted_blend, 16)
print("planes: peeled vs sorted blending %d px over 3 levels (max %.0f); unsorted blending %d px; "
      "two layers %d px; layers found %d" % (d_peeled, np.abs(peeled - sorted_blend).max(),
                                             d_unsorted, d_two, found))
check(d_peeled == 0, "peeled layers differ from VTK's sorted blending in %d pixels" % d_peeled)
check(d_unsorted > 1000, "unsorted blending should differ (%d pixels): the test would not see "
      "the order" % d_unsorted)
check(found == 3, "three translucent layers expected, %d found" % found)
check(d_two > 1000, "two layers should leave the farthest plane out (%d pixels differ)" % d_two)
check(differing(peeled, peeled_vtk_peeling, 0) == 0,
      "the renderer's depth peeling changed the styled picture")


# 2. Every style on real data ----------------------------------------------------------------------
bunny, pinion = ply_mesh(data, "bunny"), ply_mesh(data, "pinion")


def bounds_centre_size(pd):
    b = pd.GetBounds()
    return [(b[2 * i] + b[2 * i + 1]) / 2 for i in range(3)], max(b[1] - b[0], b[3] - b[2],
                                                                  b[5] - b[4])


def real_scene(style_class, opacity=0.35, layers=4, with_pinion=True, with_bunny=True,
               peeling=False, size=(320, 260)):
    win = offscreen_window(*size)
    ren = vtkRenderer()
    ren.SetBackground(1.0, 1.0, 1.0)
    ren.SetUseDepthPeeling(1 if peeling else 0)
    win.AddRenderer(ren)
    (cb, sb), (cf, sf) = bounds_centre_size(bunny), bounds_centre_size(pinion)
    scale = 0.5 * sb / sf  # the gear inside the bunny's body (checked below)
    if with_pinion:
        mapper = vtkPolyDataMapper()
        mapper.SetInputData(pinion)
        actor = vtkActor()
        actor.SetMapper(mapper)
        actor.SetOrigin(*cf)
        actor.SetScale(scale)
        body = (0.1 * sb, -0.12 * sb, 0.0)
        actor.SetPosition(*[cb[i] - cf[i] + body[i] for i in range(3)])
        actor.GetProperty().SetColor(0.85, 0.45, 0.25)
        ren.AddActor(actor)
    if with_bunny:
        mapper = vtkPolyDataMapper()
        mapper.SetInputData(bunny)
        actor = vtkActor()
        actor.SetMapper(mapper)
        actor.GetProperty().SetColor(0.4, 0.6, 0.9)
        actor.GetProperty().SetOpacity(opacity)
        ren.AddActor(actor)
    camera = ren.GetActiveCamera()
    camera.SetFocalPoint(*cb)
    camera.SetPosition(cb[0], cb[1], cb[2] + 3.0 * sb)
    camera.SetViewUp(0.0, 1.0, 0.0)
    camera.SetViewAngle(30.0)
    ren.ResetCameraClippingRange()
    if not style_class:  # VTK's own rendering
        return win, None
    style = getattr(vtkstylize, style_class)()
    style.SetTranslucentLayers(layers)
    ren.SetPass(style)
    return win, style


# Where the bunny and the pinion are on the screen, from VTK's own rendering.
background = capture(real_scene(None, with_bunny=False, with_pinion=False)[0])
bunny_mask = np.abs(capture(real_scene(None, with_pinion=False)[0]) - background).max(axis=2) > 16
pinion_mask = np.abs(capture(real_scene(None, with_bunny=False)[0]) - background).max(axis=2) > 16
inside = pinion_mask & bunny_mask
print("pinion: %d px on the screen, %d of them inside the bunny"
      % (np.count_nonzero(pinion_mask), np.count_nonzero(inside)))
check(np.count_nonzero(pinion_mask) > 2000 and np.count_nonzero(inside) ==
      np.count_nonzero(pinion_mask), "the pinion should lie inside the bunny on the screen")

STYLES = {"comic": "vtkComicPass", "pixel": "vtkPixelArtPass", "sketch": "vtkSketchPass",
          "lines": "vtkLineArtPass"}
for key, cls in STYLES.items():
    win, style = real_scene(cls)
    styled = capture(win, key + "_translucent")
    layers_found = style.GetLastTranslucentLayers()
    plain = capture(real_scene(cls, layers=0)[0], key + "_plain")
    peeling = capture(real_scene(cls, peeling=True)[0])
    no_pinion = capture(real_scene(cls, with_pinion=False)[0], key + "_no_pinion")
    shows = float(np.abs(styled - no_pinion).max(axis=2)[inside].mean()) if inside.any() else 0.0
    low = capture(real_scene(cls, opacity=0.15)[0], key + "_opacity_015")
    low_no_pinion = capture(real_scene(cls, opacity=0.15, with_pinion=False)[0])
    shows_low = float(np.abs(low - low_no_pinion).max(axis=2)[inside].mean()) if inside.any() else 0.0
    opaque = capture(real_scene(cls, opacity=1.0)[0], key + "_opaque")
    opaque_no_pinion = capture(real_scene(cls, opacity=1.0, with_pinion=False)[0])
    shows_opaque = differing(opaque, opaque_no_pinion)
    restyled = differing(styled, plain)
    print("%s: %d layers; %d px differ from plain blending; depth peeling on: %d px; pinion "
          "through the bunny: mean %.1f levels at opacity 0.35, %.1f at 0.15, %d px when opaque"
          % (key, layers_found, restyled, differing(styled, peeling, 0), shows, shows_low,
             shows_opaque))
    check(layers_found >= 2, "%s: a closed translucent surface has at least two layers" % key)
    check(restyled > 0.2 * np.count_nonzero(bunny_mask),
          "%s: the translucent bunny is barely stylized (%d px differ from plain blending)"
          % (key, restyled))
    check(differing(styled, peeling, 0) == 0, "%s: the renderer's depth peeling changed it" % key)
    check(shows > 8.0, "%s: the pinion does not show through the translucent bunny (%.1f)"
          % (key, shows))
    check(shows_low > shows, "%s: a lower opacity should show the pinion more (%.1f <= %.1f)"
          % (key, shows_low, shows))
    check(shows_opaque == 0, "%s: the pinion shows through an opaque bunny (%d px)"
          % (key, shows_opaque))
    # the outline of the translucent bunny (the comic's edges, the line art's TranslucentOutlines):
    # ink as dark as on an opaque surface
    edge = bunny_mask & ~np.roll(bunny_mask, 3, axis=1)
    if key in ("comic", "lines"):
        dark = np.count_nonzero(near(styled.max(axis=2) < 64, 1)[edge])
        print("%s: %d of %d pixels at the bunny's left border have dark ink within 1 px"
              % (key, dark, np.count_nonzero(edge)))
        check(dark > 0.5 * np.count_nonzero(edge), "%s: the translucent outline is not inked" % key)
    if key == "lines":
        win, style = real_scene(cls)
        style.SetTranslucentOutlines(False)
        bare = capture(win, "lines_no_outlines")
        dark = np.count_nonzero(near(bare.max(axis=2) < 64, 1)[edge])
        check(dark < 0.1 * np.count_nonzero(edge),
              "lines: TranslucentOutlines off still inks the bunny's border (%d px)" % dark)
    if key == "pixel":
        # the layers composited as a screen door: the palette's colours only
        win, style = real_scene(cls)
        style.SetPalette(vtkstylize.vtkPixelArtPass.PALETTE16)
        on_palette = in_palette(capture(win, "pixel_translucent_palette16")[bunny_mask])
        print("pixel: %.3f of the bunny's pixels in PALETTE16" % on_palette)
        check(on_palette == 1.0, "pixel: translucent layers left the palette (%.3f in it)"
              % on_palette)

# 3. A magnified screenshot of the translucent scene ---------------------------------------------
for key in ("comic", "pixel"):
    cls = STYLES[key]
    win, style = real_scene(cls, size=(107, 83))
    if key == "pixel":
        style.SetPixelSize(4)
    tiled = capture(win, key + "_tiled_x3", scale=3)
    win, style = real_scene(cls, size=(321, 249))
    if key == "pixel":
        style.SetPixelSize(12)
    direct = capture(win, key + "_direct_x3")
    d = differing(tiled, direct)
    limit = 0.0005 * direct.shape[0] * direct.shape[1] if key == "comic" else 0  # realdata.seams'
    print("%s: 3x3 tiles against the direct render: %d px differ (%.3f%%)"
          % (key, d, 100.0 * d / (direct.shape[0] * direct.shape[1])))
    check(d <= limit, "%s: the magnified translucent scene has %d differing pixels" % (key, d))

if failures:
    print("%d failure(s)" % len(failures))
    sys.exit(1)
print("OK")
