"""Python test: the wrapped modules import as one package and the passes render.

Run with the build's python folder on PYTHONPATH and a display (the suite does both).
"""
import sys

import vtkstylize
from vtkstylize_testing import vtkStylizeImageMetrics
from vtkmodules.vtkRenderingCore import vtkRenderer, vtkWindowToImageFilter
from vtkmodules.vtkCommonCore import vtkFloatArray

from stylize_test_scene import check, failures, offscreen_window, sphere_actor


def render(model, gbuffer):
    win = offscreen_window(160, 120)
    ren = vtkRenderer()
    win.AddRenderer(ren)
    actor = sphere_actor()
    ren.AddActor(actor)
    lighting = vtkstylize.vtkStylizeLightingPass()
    lighting.SetModel(model)
    vtkstylize.vtkStylizeLightingPass.SetActorSubjectFactor(actor, 0.7)
    if gbuffer:
        gb = vtkstylize.vtkStylizeGBufferPass()
        gb.SetLightingPass(lighting)
        gb.SetChannels(vtkstylize.vtkStylizeGBufferPass.NORMAL)
        ren.SetPass(gb)
    else:
        ren.SetPass(lighting)
    ren.ResetCamera()
    win.Render()
    normals = None
    if gbuffer:
        normals = vtkFloatArray()
        check(gb.DownloadChannel(vtkstylize.vtkStylizeGBufferPass.NORMAL_BUFFER, normals),
              "normal download")
    w2i = vtkWindowToImageFilter()
    w2i.SetInput(win)
    w2i.ReadFrontBufferOff()
    w2i.Update()
    image = w2i.GetOutput()
    win.Finalize()
    return image, normals


plain = None
for name in ("standard", "comic", "pixelart"):
    model = vtkstylize.vtkStylizeLightingPass.GetModelFromName(name)
    check(model >= 0, "model name %s" % name)
    for gbuffer in (False, True):
        image, normals = render(model, gbuffer)
        scalars = image.GetPointData().GetScalars()
        lo, hi = scalars.GetRange(0)
        check(hi > lo, "%s%s: the image is flat" % (name, " (G-buffer)" if gbuffer else ""))
        if normals is not None:
            check(vtkStylizeImageMetrics.CountNonFinite(normals) == 0,
                  "%s: non-finite normals" % name)
        if name == "standard" and not gbuffer:
            plain = image
        print("%-9s %-9s ok, range %g..%g" % (name, "gbuffer" if gbuffer else "lighting", lo, hi))
comic, _ = render(1, False)
check(vtkStylizeImageMetrics.MaximumDifference(plain, comic) > 10,
      "comic looks like standard")


def render_style(style_pass, colour=None, inspect=None):
    """A 200x150 sphere on white through style_pass; returns the image's scalars.

    inspect(), when given, runs after the render while the window's context is alive."""
    win = offscreen_window(200, 150)
    ren = vtkRenderer()
    ren.SetBackground(1, 1, 1)
    win.AddRenderer(ren)
    actor = sphere_actor(64, 32)
    if colour:
        actor.GetProperty().SetColor(*colour)
    ren.AddActor(actor)
    ren.GetActiveCamera().SetPosition(0, 0, 3)
    ren.ResetCameraClippingRange()
    ren.SetPass(style_pass)
    win.Render()
    w2i = vtkWindowToImageFilter()
    w2i.SetInput(win)
    w2i.ReadFrontBufferOff()
    w2i.Update()
    scalars = w2i.GetOutput().GetPointData().GetScalars()
    if inspect:
        inspect()
    win.Finalize()
    return scalars


def render_comic(configure):
    """The comic pass; returns the number of ink (dark) pixels."""
    comic_pass = vtkstylize.vtkComicPass()
    comic_pass.SetReferenceHeight(150)
    configure(comic_pass)
    scalars = render_style(comic_pass)
    return sum(1 for i in range(scalars.GetNumberOfTuples()) if scalars.GetComponent(i, 0) < 128)


# The comic pass: settings clamp, the edge layer is a thin outline, the full image has more ink.
c = vtkstylize.vtkComicPass()
c.SetDotSpacing(0.5)
check(c.GetDotSpacing() == c.GetDotSpacingMinValue(), "DotSpacing does not clamp")
check(c.GetLightingPass().GetModel() == vtkstylize.vtkStylizeLightingPass.COMIC,
      "the comic pass does not use the Comic lighting model")
edges = render_comic(lambda p: p.SetLayer(vtkstylize.vtkComicPass.EDGES))
full = render_comic(lambda p: None)
print("comic: %d ink pixels in the edge layer, %d in the full image" % (edges, full))
check(200 < edges < 3000, "edge layer: %d ink pixels" % edges)
check(full > edges, "the full comic image has no more ink than its edges")


def render_pixel(configure):
    """The pixel-art pass on an orange sphere; returns (image colours as a set, block, grid)."""
    pixel_pass = vtkstylize.vtkPixelArtPass()
    configure(pixel_pass)
    scalars = render_style(pixel_pass, (0.9, 0.5, 0.2))
    colours = set(scalars.GetTuple3(i) for i in range(scalars.GetNumberOfTuples()))
    block, grid = [0, 0], [0, 0]
    pixel_pass.GetLastGrid(block, grid)
    return colours, block, grid


# The pixel-art pass: settings clamp, the 1-bit palette gives black and white only, the grid
# follows the pixel size, the dither matrix is the paper's.
P = vtkstylize.vtkPixelArtPass
p = P()
p.SetPixelSize(0)
check(p.GetPixelSize() == p.GetPixelSizeMinValue(), "PixelSize does not clamp")
check(p.GetLightingPass().GetModel() == vtkstylize.vtkStylizeLightingPass.PIXEL_ART,
      "the pixel-art pass does not use the PixelArt lighting model")
matrix = P.GetDitherMatrix()
check(sorted(matrix[i] for i in range(64)) == list(range(1, 65)),
      "the dither matrix is not a permutation of 1..64")
colours, block, grid = render_pixel(lambda q: (q.SetPaletteToOneBit(), q.SetPixelSize(5)))
print("pixel art: 1-bit colours %s, block %s, grid %s" % (sorted(colours), block, grid))
check(colours <= {(0.0, 0.0, 0.0), (255.0, 255.0, 255.0)}, "1-bit output has other colours")
check(len(colours) == 2, "1-bit output is not black and white")
check(block == [5, 5] and grid == [40, 30], "unexpected grid %s %s" % (block, grid))
colours16, _, _ = render_pixel(lambda q: (q.SetPalette(P.PALETTE16), q.DepthEdgesOff(),
                                          q.SetEdgeDetector(P.NO_EDGES)))
palette = P.GetPalette16()
allowed = {tuple(float(round(255 * palette[3 * i + c])) for c in range(3)) for i in range(16)}
allowed.add((255.0, 255.0, 255.0))  # the background is not quantized
check(colours16 <= allowed, "16-colour output leaves the palette: %s" % (colours16 - allowed))

# The sketch pass: settings clamp, the layers render, pencil strokes are gray levels between the
# pencil and the paper, and the direction field has a unit direction on every surface pixel.
S = vtkstylize.vtkSketchPass
sketch_pass = S()
sketch_pass.SetNeighbors(7)
check(sketch_pass.GetNeighbors() == 8, "neighbours do not snap to 2, 4, 8")
sketch_pass.SetSteps(100000)
check(sketch_pass.GetSteps() == 256, "steps are not clamped")
sketch_pass.SetSteps(10)
sketch_pass.SetNoise(S.PERLIN)
field = vtkFloatArray()
downloaded = []
scalars = render_style(sketch_pass, inspect=lambda: downloaded.append(
    sketch_pass.DownloadDirections(field)))
grays = [scalars.GetTuple3(i) for i in range(scalars.GetNumberOfTuples())]
ink = sum(1 for c in grays if c[0] < 200)
print("sketch: %d pixels darker than 200 of %d" % (ink, len(grays)))
check(ink > 300, "sketch: no pencil strokes (%d dark pixels)" % ink)
check(all(abs(c[0] - c[2]) < 12 for c in grays), "sketch: pencil output is not gray")
check(downloaded == [True], "sketch: direction download")
surface = [field.GetTuple4(i) for i in range(field.GetNumberOfTuples())
           if field.GetTuple4(i)[3] > 0]
bad = sum(1 for v in surface if abs(v[0] ** 2 + v[1] ** 2 + v[2] ** 2 - 1.0) > 1e-2)
check(len(surface) > 1000 and bad == 0,
      "sketch: %d of %d surface pixels without a unit direction" % (bad, len(surface)))
for layer in (S.DIRECTIONS, S.STROKES, S.TONE):
    layered = S()
    layered.SetLayer(layer)
    render_style(layered)

sys.exit(1 if failures else 0)
