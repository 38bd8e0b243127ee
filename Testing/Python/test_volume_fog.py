"""A volume's haze as VTK's ray casting accumulates it (VolumeHazeMode HAZE_FOG, issue 55),
against the analytic opacity.

    test_volume_fog.py

An image of 64^3 samples (spacing 1, opacity unit distance 1) holds a ball of fog (radius 24,
scalar opacity 0.05 per unit, black) around a solid core (radius 10, opaque, white), in nothing
(opacity 0). Seen along -z with a parallel projection through pixel art's PIXELATED layer at
one screen pixel per art pixel (the layers blended by their opacity, the colour the lit colour),
over white paper. The black fog lets 1 - A of what lies behind through, so A is read back as
1 - (picture with the haze) / (picture without it), and must match the opacity VTK's ray casting
accumulates, 1 - (1 - 0.05)^L over the fog's length L on the ray (the ball's boundary ramps
over a sample, hence the tolerance):
- through the core's centre, L = 24 - 10 = 14: A = 0.512;
- beside the core, 17 units from the centre, L is the chord 2 sqrt(24^2 - 17^2) = 33.9 (the
  front layer of the haze holds the whole chord, its back layer nothing): A = 0.824;
- VolumeHaze 0.5 halves both; HAZE_SHELL gives the VolumeHaze opacity (0.4) at the core's
  centre, whatever the fog's length (the shell's front layer: its back lies behind the core).
While the camera moves (the window's desired update rate 15) the last still frame's fog is kept
(turned 90 degrees, the core's centre is seen through the kept fog of the ball's side: below half
the expected opacity), and the next still frame makes it again (as a new window's, within 2
levels). The ball as an unstructured grid (an unstructured mapper's volume): the fog's opacity
is VTK's unstructured mappers' 1 - exp(-0.05 L) (0.503 through the core, 0.816 beside it), and a
white fog with the volume's Shade on is unlit there (white over the white core), lit for the
image's mapper (darker). A soft ball whose solid part (at the style's threshold) is larger than
where VTK's picture looks solid: the line art draws one outline, at VTK's half-opacity
(the solid surface cut to where it looks solid).
"""
import math
import sys

import numpy as np
import vtkmodules.vtkRenderingVolumeOpenGL2  # noqa: F401 (the volume mappers' factory)
import vtkstylize
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPiecewiseFunction
from vtkmodules.vtkFiltersSources import vtkPlaneSource
from vtkmodules.vtkRenderingCore import (vtkActor, vtkColorTransferFunction, vtkPolyDataMapper,
                                         vtkRenderer, vtkVolume,
                                         vtkVolumeProperty, vtkWindowToImageFilter)
from vtkmodules.vtkFiltersCore import vtkAppendFilter
from vtkmodules.vtkRenderingVolume import (vtkFixedPointVolumeRayCastMapper,
                                           vtkProjectedTetrahedraMapper)

from stylize_test_scene import check, failures, offscreen_window

N, RADIUS, CORE, FOG = 64, 24.0, 10.0, 0.05


def ball():
    """Scalars: 200 in the core, 100 in the fog, 0 outside, each boundary a linear ramp over one
    unit."""
    c = (N - 1) / 2.0
    z, y, x = np.mgrid[0:N, 0:N, 0:N].astype(float)
    r = np.sqrt((x - c) ** 2 + (y - c) ** 2 + (z - c) ** 2)
    values = 100.0 * np.clip(RADIUS + 0.5 - r, 0.0, 1.0) + 100.0 * np.clip(CORE + 0.5 - r, 0.0, 1.0)
    image = vtkImageData()
    image.SetDimensions(N, N, N)
    array = numpy_to_vtk(values.ravel().astype(np.float32), deep=True)
    array.SetName("value")
    image.GetPointData().SetScalars(array)
    return image


def volume_window(mapper, opacity, colour, unit, size, background=1.0, shade=False):
    """An offscreen window of `size` pixels square whose renderer (its background gray
    `background`) holds a vtkVolume of `mapper` with the scalar `opacity` and `colour` functions,
    the opacity per `unit` distance, linear interpolation, shaded with `shade`; and the
    renderer."""
    prop = vtkVolumeProperty()
    prop.SetScalarOpacity(opacity)
    prop.SetColor(colour)
    prop.SetScalarOpacityUnitDistance(unit)
    prop.SetInterpolationTypeToLinear()
    prop.SetShade(shade)
    volume = vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    win = offscreen_window(size, size)
    ren = vtkRenderer()
    ren.SetBackground(background, background, background)
    win.AddRenderer(ren)
    ren.AddVolume(volume)
    return win, ren


def ramp_volume(values, origin, spacing, top, top_opacity, rgb, unit, size, background=1.0):
    """volume_window() of the image of `values` (z, y, x) at `origin` and `spacing`, drawn by
    fixed-point ray casting: its opacity rising from 0 at 0 to `top_opacity` at `top`, all in
    colour `rgb`."""
    image = vtkImageData()
    image.SetDimensions(values.shape[2], values.shape[1], values.shape[0])
    image.SetOrigin(*origin)
    image.SetSpacing(*spacing)
    array = numpy_to_vtk(values.ravel().astype(np.float32), deep=True)
    array.SetName("value")
    image.GetPointData().SetScalars(array)
    opacity = vtkPiecewiseFunction()
    opacity.AddPoint(0.0, 0.0)
    opacity.AddPoint(top, top_opacity)
    colour = vtkColorTransferFunction()
    colour.AddRGBPoint(0.0, *rgb)
    colour.AddRGBPoint(top, *rgb)
    mapper = vtkFixedPointVolumeRayCastMapper()
    mapper.SetInputData(image)
    return volume_window(mapper, opacity, colour, unit, size, background)


def look_down_z(ren, focal, scale):
    """`ren`'s camera (returned): parallel, along -z at `focal` from 200 units away, `scale` the
    half height of the view."""
    camera = ren.GetActiveCamera()
    camera.SetFocalPoint(*focal)
    camera.SetPosition(focal[0], focal[1], focal[2] + 200.0)
    camera.SetViewUp(0.0, 1.0, 0.0)
    camera.ParallelProjectionOn()
    camera.SetParallelScale(scale)
    ren.ResetCameraClippingRange()
    return camera


def scene(haze, mode, azimuth=0.0, unstructured=False, white=False):
    """The window of the ball in pixel art's PIXELATED layer, seen along -z (turned by `azimuth`
    degrees about the ball's centre); `unstructured`: the ball as an unstructured grid of
    hexahedra (an unstructured mapper's volume); `white`: the fog white too, shaded (the
    volume's Shade on)."""
    opacity = vtkPiecewiseFunction()
    for value, o in ((0.0, 0.0), (100.0, FOG), (150.0, FOG), (160.0, 1.0), (200.0, 1.0)):
        opacity.AddPoint(value, o)
    colour = vtkColorTransferFunction()
    fog = 1.0 if white else 0.0
    colour.AddRGBPoint(0.0, fog, fog, fog)
    colour.AddRGBPoint(120.0, fog, fog, fog)
    colour.AddRGBPoint(140.0, 1.0, 1.0, 1.0)
    colour.AddRGBPoint(200.0, 1.0, 1.0, 1.0)
    if unstructured:
        grid = vtkAppendFilter()
        grid.SetInputData(ball())
        grid.Update()
        mapper = vtkProjectedTetrahedraMapper()
        mapper.SetInputData(grid.GetOutput())
    else:
        mapper = vtkFixedPointVolumeRayCastMapper()
        mapper.SetInputData(ball())
    win, ren = volume_window(mapper, opacity, colour, 1.0, N, shade=white)
    c = (N - 1) / 2.0
    camera = look_down_z(ren, (c, c, c), N / 2.0)
    ren.SetPass(pixelated(haze, mode))
    camera.Azimuth(azimuth)
    return win


def pixelated(haze, mode):
    """Pixel art's PIXELATED layer at one screen pixel per art pixel, no edges: the layers
    blended by their opacity."""
    style = vtkstylize.vtkPixelArtPass()
    style.SetLayer(vtkstylize.vtkPixelArtPass.PIXELATED)
    style.SetPixelSize(1)
    style.SetEdgeDetector(vtkstylize.vtkPixelArtPass.NO_EDGES)
    style.SetDepthEdges(False)
    style.SetNormalEdges(False)
    style.SetVolumeHaze(haze)
    style.SetVolumeHazeMode(mode)
    return style


def grab(win, size=N):
    """The picture's red channel (0-255) of a window `size` pixels square."""
    w2i = vtkWindowToImageFilter()
    w2i.SetInput(win)
    w2i.ReadFrontBufferOff()
    w2i.Update()
    pixels = vtk_to_numpy(w2i.GetOutput().GetPointData().GetScalars()).reshape(size, size, -1)
    return pixels[:, :, 0].astype(float)


def render(haze, mode):
    return grab(scene(haze, mode))


FOG_MODE, SHELL = vtkstylize.vtkPixelArtPass.HAZE_FOG, vtkstylize.vtkPixelArtPass.HAZE_SHELL
plain = render(0.0, FOG_MODE)
centre, beside = (N // 2, N // 2), (N // 2 + 17, N // 2)  # (row, column)


def opacity_at(picture, pixel):
    """A: the share of what lies behind that the black fog hides at `pixel` (3 x 3 mean)."""
    r, c = pixel
    behind = plain[r - 1:r + 2, c - 1:c + 2].mean()
    return 1.0 - picture[r - 1:r + 2, c - 1:c + 2].mean() / max(behind, 1.0)


expected_centre = 1.0 - (1.0 - FOG) ** (RADIUS - CORE)
expected_beside = 1.0 - (1.0 - FOG) ** (2.0 * math.sqrt(RADIUS ** 2 - 17.0 ** 2))
cases = [("fog, VolumeHaze 1, through the core", render(1.0, FOG_MODE), centre, expected_centre, 0.05),
         ("fog, VolumeHaze 1, beside the core", None, beside, expected_beside, 0.05),
         ("fog, VolumeHaze 0.5, through the core", render(0.5, FOG_MODE), centre,
          0.5 * expected_centre, 0.05),
         ("fog, VolumeHaze 0.5, beside the core", None, beside, 0.5 * expected_beside, 0.05),
         ("shell, VolumeHaze 0.4, through the core", render(0.4, SHELL), centre, 0.4, 0.03)]
last = None
print("behind: %.0f at the core's centre, %.0f beside it" % (plain[centre], plain[beside]))
check(plain[centre] > 100 and plain[beside] > 200, "the core and the paper must be bright")
for name, picture, pixel, expected, tolerance in cases:
    picture = last if picture is None else picture
    last = picture
    measured = opacity_at(picture, pixel)
    print("%s: opacity %.3f, expected %.3f" % (name, measured, expected))
    check(abs(measured - expected) <= tolerance,
          "%s: opacity %.3f, expected %.3f +- %.2f" % (name, measured, expected, tolerance))

# While the camera moves (the window's desired update rate 15, as VTK's interactor styles set it)
# the last still frame's fog is kept, and made again at the next still frame: turned by 90
# degrees, the core's centre is seen through what was the ball's side, whose kept fog is the
# grazing ray's (nearly nothing) where the fresh one is 0.512.
win = scene(1.0, FOG_MODE)
win.Render()  # (a still frame: the fog made for the view along -z)
win.GetRenderers().GetFirstRenderer().GetActiveCamera().Azimuth(90.0)
win.SetDesiredUpdateRate(15.0)
moving = grab(win)
win.SetDesiredUpdateRate(0.0001)
still = grab(win)
fresh = grab(scene(1.0, FOG_MODE, 90.0))
print("turned 90 degrees: opacity %.3f while moving, %.3f at the still frame, %.3f when new"
      % (opacity_at(moving, centre), opacity_at(still, centre), opacity_at(fresh, centre)))
check(opacity_at(moving, centre) < 0.5 * expected_centre,
      "while the camera moves the last still frame's fog must be kept")
check(np.abs(still - fresh).max() <= 2.0, "the still frame must make the fog again")

# An unstructured mapper's volume (VTK's unstructured mappers take the opacity as an attenuation,
# 1 - exp(-0.05 L), and do not shade): the ball as hexahedra, sampled on an image for the fog;
# shaded and white, the fog is lit for the image's mapper (darker than the white core behind it)
# and not for the unstructured one (white over white).
grid = grab(scene(1.0, FOG_MODE, unstructured=True))
for name, pixel, length in (("through the core", centre, RADIUS - CORE),
                            ("beside the core", beside, 2.0 * math.sqrt(RADIUS ** 2 - 17.0 ** 2))):
    expected = 1.0 - math.exp(-FOG * length)
    measured = opacity_at(grid, pixel)
    print("unstructured, fog %s: opacity %.3f, expected %.3f" % (name, measured, expected))
    check(abs(measured - expected) <= 0.05, "unstructured fog %s: opacity %.3f, expected %.3f"
          % (name, measured, expected))
lit = grab(scene(1.0, FOG_MODE, white=True))[centre]
unlit = grab(scene(1.0, FOG_MODE, unstructured=True, white=True))[centre]
print("white shaded fog over the white core: %.0f (image's mapper, lit), %.0f (unstructured, "
      "unlit)" % (lit, unlit))
check(lit < 200 and unlit > 240, "the fog lit for the image's mapper only")

# A slab of fog that fills its image (5 units thick, 0.05 per unit, black): the haze's surface
# is closed past the image's faces (padded), its points outside the image, where VTK takes no
# samples. Seen along -z and 30 degrees from it, A = 1 - 0.95^(5 / cos): 0.226 and 0.256. Before
# the march began where the ray enters the image, the faces' values clamped outside it added
# 0.04 (0.267) and 0.03 (0.282).
def slab(elevation):
    """The slab's picture (red channel) in the fog and without it (VolumeHaze 0)."""
    values = np.full((6, 40, 40), 100.0)
    values[:, :4, :4] = 0.0  # (a corner empty: the haze has a surface, not the image's faces)
    pictures = []
    for haze in (1.0, 0.0):
        win, ren = ramp_volume(values, (-19.5, -19.5, 0.0), (1.0, 1.0, 1.0), 100.0, FOG,
                               (0.0, 0.0, 0.0), 1.0, N)
        look_down_z(ren, (0.0, 0.0, 2.5), 10.0).Elevation(elevation)
        ren.ResetCameraClippingRange()
        ren.SetPass(pixelated(haze, FOG_MODE))
        pictures.append(grab(win))
    return pictures


for elevation in (0.0, 30.0):
    fogged, bare = slab(elevation)
    measured = 1.0 - fogged[N // 2, N // 2] / max(bare[N // 2, N // 2], 1.0)
    expected = 1.0 - (1.0 - FOG) ** (5.0 / math.cos(math.radians(elevation)))
    print("slab filling its image, %g degrees: opacity %.3f, expected %.3f"
          % (elevation, measured, expected))
    check(abs(measured - expected) <= 0.012, "slab filling its image, %g degrees: opacity %.3f, "
          "expected %.3f +- 0.012" % (elevation, measured, expected))

# Opaque geometry inside solid material (streamlines through a glowing region): VTK shows it
# through the material in front of it. A slab of white material 20 units thick (0.2 per unit:
# solid at the styles' threshold, its front face the solid surface drawn) holds a blue square 1
# unit behind its front face (seen through an opacity of 0.2) and a red one 8 units behind it
# (0.83). The solid surface stores the depth where the view ray's opacity reaches one half (3.1
# units in): the blue square shows in the style, the red one stays hidden. Before, the solid
# surface hid both.
def buried_squares(style):
    """The slab with its squares (RGB), drawn by VTK or `style`."""
    win, ren = ramp_volume(np.full((21, 40, 40), 100.0), (-19.5, -19.5, 0.0), (1.0, 1.0, 1.0),
                           100.0, 0.2, (1.0, 1.0, 1.0), 1.0, N)
    for x, z, rgb in ((-8.0, 19.0, (0.0, 0.0, 1.0)), (8.0, 12.0, (1.0, 0.0, 0.0))):
        square = vtkPlaneSource()
        square.SetOrigin(x - 4.0, -4.0, z)
        square.SetPoint1(x + 4.0, -4.0, z)
        square.SetPoint2(x - 4.0, 4.0, z)
        square_mapper = vtkPolyDataMapper()
        square_mapper.SetInputConnection(square.GetOutputPort())
        actor = vtkActor()
        actor.SetMapper(square_mapper)
        actor.GetProperty().SetColor(*rgb)
        actor.GetProperty().SetAmbient(1.0)
        actor.GetProperty().SetDiffuse(0.0)
        ren.AddActor(actor)
    look_down_z(ren, (0.0, 0.0, 10.0), 20.0)
    if style:
        ren.SetPass(style)
    w2i = vtkWindowToImageFilter()
    w2i.SetInput(win)
    w2i.ReadFrontBufferOff()
    w2i.Update()
    pixels = vtk_to_numpy(w2i.GetOutput().GetPointData().GetScalars()).reshape(N, N, -1)
    return pixels[:, :, :3].astype(float)


# (each square's pixel against the material's between them, the levels' differences summed: VTK's
# 408 for the blue one, 86 for the red one, 17% of it showing)
blue_at, red_at = (N // 2, N // 2 - int(8 * N / 40)), (N // 2, N // 2 + int(8 * N / 40))
for name, style in (("VTK", None), ("pixel art", pixelated(1.0, FOG_MODE)),
                    ("comic", vtkstylize.vtkComicPass()), ("sketch", vtkstylize.vtkSketchPass())):
    picture = buried_squares(style)
    material = picture[N // 2, N // 2]
    blue, red = (float(np.abs(picture[at] - material).sum()) for at in (blue_at, red_at))
    print("squares in solid material, %s: the blue one 1 unit in differs by %.0f, the red one "
          "8 units in by %.0f" % (name, blue, red))
    check(blue > 200, "%s: the square in front of where the material looks solid must show "
          "(%.0f)" % (name, blue))
    check(red < 100, "%s: the square behind where the material looks solid must stay hidden "
          "(%.0f)" % (name, red))


# A soft ball (the scalar 1 - r, opacity 0 to 0.6 per 0.2 units of it: solid, at the style's
# threshold 0.1, out to r = 0.83, but looking solid only within r = 0.69, where VTK's picture is
# half opaque): the line art draws one outline, at VTK's. Before the solid surface was cut to
# where it looks solid, its own outline was a second ring 10 px outside (at 400 px).
S = 160


def soft_ball(style=None, background=1.0):
    """The soft ball's picture (red channel), drawn by VTK or the line art with the fog."""
    n = 48
    g = np.linspace(-1.0, 1.0, n)
    z, y, x = np.meshgrid(g, g, g, indexing="ij")
    values = np.clip(1.0 - np.sqrt(x * x + y * y + z * z), 0.0, 1.0)
    step = 2.0 / (n - 1)
    win, ren = ramp_volume(values, (-1.0, -1.0, -1.0), (step, step, step), 1.0, 0.6,
                           (0.8, 0.3, 0.2), 0.2, S, background)
    camera = ren.GetActiveCamera()
    camera.SetPosition(0.0, 0.0, 10.0)
    camera.SetFocalPoint(0.0, 0.0, 0.0)
    camera.ParallelProjectionOn()
    camera.SetParallelScale(1.2)
    ren.ResetCameraClippingRange()
    if style:
        style.SetVolumeHaze(1.0)
        ren.SetPass(style)
    return grab(win, S)


alpha = 1.0 - (soft_ball() - soft_ball(background=0.0)) / 255.0
row = S // 2
half = np.nonzero(alpha[row] >= 0.5)[0]
ink = np.nonzero(soft_ball(vtkstylize.vtkLineArtPass())[row] < 128)[0]
print("soft ball: VTK half opaque from %d to %d, the line art's ink at %s"
      % (half.min(), half.max(), list(ink)))
check(len(ink) > 0 and np.all(np.minimum(np.abs(ink - half.min()), np.abs(ink - half.max())) <= 2),
      "the soft ball's line art must draw one outline, at VTK's (within 2 px)")

if failures:
    print("%d failure(s)" % len(failures))
    sys.exit(1)
print("OK")
