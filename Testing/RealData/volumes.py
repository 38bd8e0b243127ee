#!/usr/bin/env python3
"""realdata.volumes: volumes drawn in every style (vtkStylizeStylePass::StylizeVolumes), measured.

Three scenes, each rendered by VTK (with and without its volume) and by the four styles at their
defaults:
- skull: the CT of a skull (CGAL's skull_2.9.inr) as a shaded volume; its transfer functions were
  chosen looking at it;
- liver: a segmented liver (CGAL's liver.inr.gz, labels 0 and 255), held out: a ramp set once,
  never looked at before the measures were fixed;
- field: a ParaView-like scene of VTK's wavelet field: a slice coloured by a colour map, arrow
  glyphs of the gradient, streamlines, an isosurface, cube axes and the field as a volume;
- vessel (not in the default scenes): the Exodus vessel by its temperature as an unstructured
  volume (projected tetrahedra, as ParaView draws one by default), held out until stop 69;
- headsq (not in the default scenes): VTK's headsq CT of a head (vtkdata/) with the transfer
  functions of VTK's MedicalDemo4 example, held out (never tuned on);
- disk (not in the default scenes): ParaView's tutorial flow simulation disk_out_ref.ex2
  (vtkdata/) as the tutorial shows it: the temperature as an unstructured volume, a slice
  coloured by the pressure, streamlines and arrow glyphs of the velocity, the outline, cube axes;
  held out on its first measures (below), looked at since.

The volume's region is where VTK's picture with the volume differs from the one without it
(more than 24 levels summed over the channels). Measures per style in that region: the share of
pixels left exactly as VTK draws them (goal <= 0.2); comic: the share of plain gradient
(stylize_volume_measures.gradient_share: the value varies by 4 to 48 levels over the pixel's 7x7
neighbourhood, neither a flat paper, tint or ink nor a dot, hatch or edge; goal <= 0.1, VTK's
own in brackets); pixel art (PALETTE16): the share of pixels
in the palette, its black outline ink or the white paper (goal 1); sketch: the correlation of the
tone (luminance blurred over 4 px) with VTK's (goal >= 0.8); line art: the recall within 2 px,
by ink, of the outline of where the volume looks solid in the scene (its opacity in front of the
scene's opaque props at least 0.5: the scene with flat white props over white and flat black ones
over black; until stop 72 the volume's picture alone, which counts the opacity behind props the
picture hides: the disk's dome behind its slice) (goal >= 0.9); with --bench, the median frame time of each style against VTK's frame with the volume
(with a haze, also while the camera moves: the window's desired update rate 15, the fog kept).
The styles draw at their defaults (VolumeHaze 1, HAZE_FOG: the volume's translucent part as
VTK's fog); the comic with VolumeHaze 0.4 (HAZE_SHELL) must change the comic's picture (at least
0.5% of the pixels); --haze OPACITY measures every style with that haze instead (0: the solid
part alone; with --haze-mode shell, a shell of that opacity).
With --primitives field,disk, the scenes' streamlines (dark line primitives), their boxes' outlines (light
ones), points of the field (4 px, coloured by it; not in the scene's pictures) and arrow glyphs
(about 10 px) are drawn alone: per style, the share of VTK's pixels of them with a styled pixel within 1 px
(goal >= 0.9), the share of them left as VTK draws them (within 24 levels summed over the
channels; lines: goal <= 0.2: pencil in the sketch, ink in the line art, the palette in
pixel art), the share of them drawn in ink (no channel above 64; lines in the comic and the line
art: goal >= 0.8), and
for pixel art the share of those styled pixels in the palette (goal 1).
Writes OUTDIR/volume-SCENE-STYLE.png and prints markdown tables; --check fails the run below the
goals.

usage: volumes.py DATA OUTDIR [--check] [--bench] [--primitives SCENE,...] [--scenes skull,liver,field]
                  [--size WxH] [--haze OPACITY] [--haze-mode shell|fog] [--figures] [--unmet SCENE.STYLE.MEASURE,...]
"""
import argparse
import os
import statistics
import sys
import time

import numpy as np
import vtk

import vtkmodules.vtkRenderingVolumeOpenGL2  # noqa: F401 (the GPU ray caster's factory)
from vtkstylize import save_figure, vtkComicPass, vtkLineArtPass, vtkPixelArtPass, vtkSketchPass

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "Python"))
from stylize_png import luminance, near, window_array  # noqa: E402
from stylize_png import save_png as save  # noqa: E402
from stylize_volume_measures import gradient_share, in_palette, measure  # noqa: E402

STYLES = {"comic": vtkComicPass, "pixel": vtkPixelArtPass, "sketch": vtkSketchPass,
          "lines": vtkLineArtPass}
HAZE_MODES = {"shell": vtkComicPass.HAZE_SHELL, "fog": vtkComicPass.HAZE_FOG}
GOAL_PLAIN = 0.2
GOAL_GRADIENT = 0.1
GOAL_PALETTE = 1.0
GOAL_TONE = 0.8
GOAL_RECALL = 0.9
GOAL_COVERED = 0.9
GOAL_INK = 0.8


def read_image(path):
    reader = vtk.vtkXMLImageDataReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def volume_of(image, colors, opacities, shade=True):
    """A vtkVolume of `image` (GPU ray casting) with (value, r, g, b) colours and (value,
    opacity) points."""
    mapper = vtk.vtkGPUVolumeRayCastMapper()
    mapper.SetInputData(image)
    prop = vtk.vtkVolumeProperty()
    prop.SetInterpolationTypeToLinear()
    prop.SetShade(shade)
    ctf = vtk.vtkColorTransferFunction()
    for v, r, g, b in colors:
        ctf.AddRGBPoint(v, r, g, b)
    otf = vtk.vtkPiecewiseFunction()
    for v, o in opacities:
        otf.AddPoint(v, o)
    prop.SetColor(ctf)
    prop.SetScalarOpacity(otf)
    volume = vtk.vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    return volume


def skull(data):
    volume = volume_of(read_image(os.path.join(data, "skull.vti")),
                       [(0, 0.2, 0.1, 0.05), (1.5, 0.9, 0.5, 0.4), (3.0, 1.0, 0.95, 0.85),
                        (5.5, 1, 1, 1)],
                       [(0, 0), (1.0, 0), (2.0, 0.05), (2.9, 0.6), (5.5, 0.9)])
    return [volume], [], (180 + 20, 10, 1.3)


def liver(data):
    volume = volume_of(read_image(os.path.join(data, "liver.vti")),
                       [(0, 0.5, 0.1, 0.1), (255, 0.9, 0.4, 0.3)], [(0, 0), (255, 0.8)])
    return [volume], [], (30, 20, 1.2)


def diverging(low, high):
    """ParaView's cool-to-warm colour map over [low, high]."""
    lut = vtk.vtkColorTransferFunction()
    lut.SetColorSpaceToDiverging()
    lut.AddRGBPoint(low, 0.23, 0.30, 0.75)
    lut.AddRGBPoint(high, 0.71, 0.02, 0.15)
    return lut


def tagged_actor(props, lut, algorithm, tag, colored=True, color=(1, 1, 1), width=1.0,
                 array=None):
    """An actor of `algorithm`'s output appended to `props`, coloured through `lut` (by the point
    array `array`, else the active scalars) or in `color`, tagged for render(only=...)."""
    mapper = vtk.vtkDataSetMapper()
    mapper.SetInputConnection(algorithm.GetOutputPort())
    mapper.SetLookupTable(lut)
    mapper.SetScalarVisibility(colored)
    if array:
        mapper.SetScalarModeToUsePointFieldData()
        mapper.SelectColorArray(array)
    mapper.UseLookupTableScalarRangeOn()
    a = vtk.vtkActor()
    a.SetMapper(mapper)
    a.GetProperty().SetColor(*color)
    a.GetProperty().SetLineWidth(width)
    a.tag = tag
    props.append(a)
    return a


def black_cube_axes(bounds):
    """vtkCubeAxesActor around `bounds`, its lines, titles and labels black."""
    axes = vtk.vtkCubeAxesActor()
    axes.SetBounds(bounds)
    for i in range(3):
        axes.GetTitleTextProperty(i).SetColor(0, 0, 0)
        axes.GetLabelTextProperty(i).SetColor(0, 0, 0)
    for lines in (axes.GetXAxesLinesProperty(), axes.GetYAxesLinesProperty(),
                  axes.GetZAxesLinesProperty()):
        lines.SetColor(0, 0, 0)
    return axes


def field(_data):
    """VTK's wavelet as ParaView shows a field: slice, glyphs, streamlines, contour, axes, volume."""
    source = vtk.vtkRTAnalyticSource()
    source.SetWholeExtent(-20, 20, -20, 20, -20, 20)
    source.Update()
    image = source.GetOutput()
    lo, hi = image.GetPointData().GetScalars().GetRange()
    lut = diverging(lo, hi)
    props = []

    def actor(algorithm, tag, **kwargs):
        return tagged_actor(props, lut, algorithm, tag, **kwargs)

    plane = vtk.vtkPlane()
    plane.SetOrigin(0, 0, -12)
    plane.SetNormal(0, 0, 1)
    cut = vtk.vtkCutter()
    cut.SetInputData(image)
    cut.SetCutFunction(plane)
    actor(cut, "slice")
    gradient = vtk.vtkGradientFilter()
    gradient.SetInputData(image)
    gradient.SetResultArrayName("gradient")
    gradient.Update()
    grad = gradient.GetOutput()
    grad.GetPointData().SetActiveVectors("gradient")
    seeds = vtk.vtkLineSource()  # (not random: the same streamlines in every picture)
    seeds.SetPoint1(-8, -8, 12)
    seeds.SetPoint2(8, 8, 12)
    seeds.SetResolution(30)
    tracer = vtk.vtkStreamTracer()
    tracer.SetInputData(grad)
    tracer.SetSourceConnection(seeds.GetOutputPort())
    tracer.SetMaximumPropagation(60)
    tracer.SetIntegrationDirectionToBoth()
    actor(tracer, "streamlines", colored=False, color=(0.1, 0.3, 0.1), width=2.0)
    mask = vtk.vtkMaskPoints()
    mask.SetInputData(grad)
    mask.SetOnRatio(331)
    mask.RandomModeOff()
    arrow = vtk.vtkArrowSource()
    glyph = vtk.vtkGlyph3D()
    glyph.SetInputConnection(mask.GetOutputPort())
    glyph.SetSourceConnection(arrow.GetOutputPort())
    glyph.SetVectorModeToUseVector()
    glyph.SetScaleModeToDataScalingOff()
    glyph.SetScaleFactor(3.0)
    glyph.SetColorModeToColorByScalar()
    actor(glyph, "glyphs")
    contour = vtk.vtkContourFilter()
    contour.SetInputData(image)
    contour.SetValue(0, 0.9 * hi)
    actor(contour, "contour", colored=False, color=(0.9, 0.85, 0.6))
    # Points (ParaView's Points representation), measured alone (not in the scene's pictures)
    cloud = vtk.vtkMaskPoints()
    cloud.SetInputData(image)
    cloud.SetOnRatio(97)
    cloud.RandomModeOff()
    cloud.GenerateVerticesOn()
    dots = actor(cloud, "points")
    dots.GetProperty().SetPointSize(4)
    dots.alone = True
    outline = vtk.vtkOutlineFilter()  # (ParaView's Outline representation: light lines)
    outline.SetInputData(image)
    actor(outline, "outline", colored=False, color=(1.0, 0.75, 0.3), width=1.5)
    volume = volume_of(image, [(lo, 0.23, 0.30, 0.75), (hi, 0.71, 0.02, 0.15)],
                       [(lo, 0.0), (0.5 * (lo + hi), 0.0), (0.75 * (lo + hi) / 1.5 + 0.25 * hi, 0.3),
                        (hi, 0.8)])
    props.append(black_cube_axes(image.GetBounds()))
    return [volume], props, (35, 25, 1.0)


def exodus_grid(path):
    """The first block of an Exodus II file with all its point arrays."""
    reader = vtk.vtkExodusIIReader()
    reader.SetFileName(path)
    reader.UpdateInformation()
    for i in range(reader.GetNumberOfPointResultArrays()):
        reader.SetPointResultArrayStatus(reader.GetPointResultArrayName(i), 1)
    reader.Update()
    blocks = reader.GetOutput().NewIterator()
    blocks.InitTraversal()
    return blocks.GetCurrentDataObject()


def unstructured_volume(grid, name, low_color, high_color, opacities):
    """`grid` tetrahedralized as a vtkVolume of VTK's projected tetrahedra mapper (ParaView's
    default for unstructured volumes) by its array `name`: colours from `low_color` to
    `high_color` over its range, (fraction of the range, opacity) points, opacity per 5% of the
    mesh's diagonal. (Not VTK's unstructured ray caster: its integrators take the opacity
    function's points only where the colour function has points too, so a ramp with a knee is
    drawn as the straight ramp between the colour points: on a slab 2 units thick, ramp (0, 0),
    (0.5, 0.05), (1, 0.8) per unit, 0.558 opaque where the integral along the ray and the
    projected tetrahedra give 0.362. See docs/gbuffer.md, "Volumes".)"""
    tets = vtk.vtkDataSetTriangleFilter()
    tets.SetInputData(grid)
    tets.Update()
    cells = tets.GetOutput()
    cells.GetPointData().SetActiveScalars(name)
    lo, hi = cells.GetPointData().GetArray(name).GetRange()
    mapper = vtk.vtkProjectedTetrahedraMapper()
    mapper.SetInputData(cells)
    prop = vtk.vtkVolumeProperty()
    prop.ShadeOn()
    prop.SetInterpolationTypeToLinear()
    ctf = vtk.vtkColorTransferFunction()
    ctf.AddRGBPoint(lo, *low_color)
    ctf.AddRGBPoint(hi, *high_color)
    otf = vtk.vtkPiecewiseFunction()
    for fraction, o in opacities:
        otf.AddPoint(lo + fraction * (hi - lo), o)
    prop.SetColor(ctf)
    prop.SetScalarOpacity(otf)
    prop.SetScalarOpacityUnitDistance(0.05 * cells.GetLength())
    volume = vtk.vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)
    return volume


def headsq(data):
    """VTK's headsq CT (64 x 64 x 93) with the transfer functions of VTK's MedicalDemo4 example
    (skin at a sixth of full opacity, bone nearly opaque; not chosen here), seen as VTK's
    Medical examples see it (from the front, at 30 degrees); held out."""
    volume = volume_of(read_image(os.path.join(data, "headsq.vti")),
                       [(0, 0, 0, 0), (500, 1.0, 0.5, 0.3), (1000, 1.0, 0.5, 0.3),
                        (1150, 1.0, 1.0, 0.9)],
                       [(0, 0.0), (500, 0.15), (1000, 0.15), (1150, 0.85)])
    return [volume], [], (30, 30, 1.2, (0, -1, 0), (0, 0, -1))


def disk(data):
    """ParaView's tutorial simulation (disk_out_ref.ex2: gas over a heated rotating disk) as
    ParaView's tutorial shows it: the temperature as a volume, a slice across the flow coloured
    by the pressure, streamlines of the velocity, arrow glyphs of it on the slice, the domain's
    outline and cube axes."""
    grid = exodus_grid(os.path.join(data, "disk_out_ref.ex2"))
    grid.GetPointData().SetActiveVectors("V")
    props = []
    lut = diverging(*grid.GetPointData().GetArray("Pres").GetRange())

    def actor(algorithm, tag, **kwargs):
        return tagged_actor(props, lut, algorithm, tag, array="Pres", **kwargs)

    plane = vtk.vtkPlane()
    plane.SetNormal(1, 0, 0)
    cut = vtk.vtkCutter()
    cut.SetInputData(grid)
    cut.SetCutFunction(plane)
    actor(cut, "slice")
    seeds = vtk.vtkLineSource()  # (not random: the same streamlines in every picture)
    seeds.SetPoint1(-1.5, -1.5, 2)
    seeds.SetPoint2(1.5, 1.5, 2)
    seeds.SetResolution(11)
    tracer = vtk.vtkStreamTracer()
    tracer.SetInputData(grid)
    tracer.SetSourceConnection(seeds.GetOutputPort())
    tracer.SetMaximumPropagation(30)
    tracer.SetIntegrationDirectionToBoth()
    actor(tracer, "streamlines", colored=False, color=(0.1, 0.3, 0.1), width=2.0)
    # The glyphs on a regular grid over the slice's plane (ParaView's uniform distribution), the
    # velocity probed there: the cutter's point order varies between runs (it is threaded), so
    # every n-th of its points would be other points in each picture.
    grid_points = vtk.vtkPlaneSource()
    grid_points.SetOrigin(0, -5.5, -9.8)
    grid_points.SetPoint1(0, 5.5, -9.8)
    grid_points.SetPoint2(0, -5.5, 9.9)
    grid_points.SetResolution(18, 32)
    probe = vtk.vtkProbeFilter()
    probe.SetInputConnection(grid_points.GetOutputPort())
    probe.SetSourceData(grid)
    probe.Update()
    probed = probe.GetOutput()
    probed.GetPointData().SetActiveScalars("vtkValidPointMask")
    probed.GetPointData().SetActiveVectors("V")
    inside = vtk.vtkThresholdPoints()  # (the grid's points inside the mesh)
    inside.SetInputData(probed)
    inside.ThresholdByUpper(0.5)
    arrow = vtk.vtkArrowSource()
    glyph = vtk.vtkGlyph3D()
    glyph.SetInputConnection(inside.GetOutputPort())
    glyph.SetSourceConnection(arrow.GetOutputPort())
    glyph.SetVectorModeToUseVector()
    glyph.SetScaleModeToDataScalingOff()
    glyph.SetScaleFactor(0.8)
    actor(glyph, "glyphs", colored=False, color=(0.2, 0.2, 0.2))
    outline = vtk.vtkOutlineFilter()
    outline.SetInputData(grid)
    actor(outline, "outline", colored=False, color=(0.3, 0.3, 0.3), width=1.5)
    volume = unstructured_volume(grid, "Temp", (1.0, 0.9, 0.5), (0.8, 0.2, 0.0),
                                 ((0.0, 0.0), (0.4, 0.0), (1.0, 0.8)))
    props.append(black_cube_axes(grid.GetBounds()))
    return [volume], props, (35, 15, 1.0, (1, 0, 0), (0, 0, 1))


def vessel(data):
    """The real-data set's Exodus vessel (hexahedra) by its temperature, tetrahedralized, as an
    unstructured volume; held out: its ramp was set once."""
    volume = unstructured_volume(exodus_grid(os.path.join(data, "vessel.ex2")), "Temp",
                                 (0.23, 0.30, 0.75), (0.71, 0.02, 0.15),
                                 ((0.0, 0.0), (0.5, 0.05), (1.0, 0.8)))
    return [volume], [], (30, 20, 1.2)


SCENES = {"skull": skull, "liver": liver, "field": field, "vessel": vessel, "headsq": headsq,
          "disk": disk}


def render(builder, data, style, size, with_volume=True, times=0, only_volume=False,
           background=1.0, only=None, haze=None, figure=None, haze_mode="fog", moving=False):
    """The scene's picture (H x W x 3 uint8) drawn by VTK (style None) or a style; with `times`,
    also the median of that many more frames' seconds; `only`: the one tagged prop drawn (no
    volume)."""
    volumes, props, view = builder(data)
    azimuth, elevation, zoom = view[:3]
    props = [] if only_volume else props
    if only:
        props = [p for p in props if getattr(p, "tag", None) == only]
        with_volume = False
    else:
        props = [p for p in props if not getattr(p, "alone", False)]
    renderer = vtk.vtkRenderer()
    renderer.SetBackground(background, background, background)
    for p in props:
        if isinstance(p, vtk.vtkCubeAxesActor):
            p.SetCamera(renderer.GetActiveCamera())
        renderer.AddViewProp(p)
    for v in volumes:
        renderer.AddVolume(v)
    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)
    window.SetSize(*size)
    window.AddRenderer(renderer)
    camera = renderer.GetActiveCamera()
    if len(view) > 3:  # the direction to the camera and its view-up, before the turns
        camera.SetFocalPoint(0, 0, 0)
        camera.SetPosition(*view[3])
        camera.SetViewUp(*view[4])
    renderer.ResetCamera()
    camera.Azimuth(azimuth)
    camera.Elevation(elevation)
    camera.OrthogonalizeViewUp()
    camera.Zoom(zoom)
    renderer.ResetCameraClippingRange()
    if not with_volume:
        for v in volumes:
            v.VisibilityOff()
    style_pass = None
    if style:
        style_pass = STYLES[style]()
        if haze is not None:  # (else the style's default)
            style_pass.SetVolumeHaze(haze)
        style_pass.SetVolumeHazeMode(HAZE_MODES[haze_mode])
        if style == "pixel":
            style_pass.SetPalette(vtkPixelArtPass.PALETTE16)
        renderer.SetPass(style_pass)
    window.Render()
    pixels = window_array(window)
    surfaces = style_pass.GetNumberOfVolumeSurfaces() if style_pass else 0
    if figure:
        save_figure(window, figure)
    seconds = []  # (after the picture: each frame turns the camera a little)
    if moving:  # (as VTK's interactor styles set it while the camera moves)
        window.SetDesiredUpdateRate(15.0)
    for _ in range(times):
        camera.Azimuth(0.5)
        start = time.perf_counter()
        window.Render()
        seconds.append(time.perf_counter() - start)
    return pixels, (statistics.median(seconds) if seconds else None), surfaces


def flat_props(builder, value):
    """`builder` with its opaque props unlit in one gray `value` (no scalar colours) and its cube
    axes left out: rendered with the volume over a background of the same value, over white and
    over black, the pictures give the volume's opacity in front of whatever the scene shows."""
    def flat(data):
        volumes, props, view = builder(data)
        kept = []
        for p in props:
            if isinstance(p, vtk.vtkCubeAxesActor):
                continue
            if isinstance(p, vtk.vtkActor):
                p.GetMapper().ScalarVisibilityOff()
                prop = p.GetProperty()
                prop.SetColor(value, value, value)
                prop.SetLighting(False)
                prop.SetAmbient(1.0)
                prop.SetDiffuse(0.0)
                prop.SetSpecular(0.0)
            kept.append(p)
        return volumes, kept, view
    return flat


def primitives(name, data, size, outdir):
    """Streamlines and glyphs of a scene (field or disk), each alone: per style, the share of
    VTK's pixels of them with a styled pixel (not paper) within 1 px, and for pixel art the share
    of those styled pixels in the palette."""
    rows = []
    tags = ("streamlines", "outline", "points", "glyphs") if name == "field" else \
        ("streamlines", "outline", "glyphs")
    for tag in tags:
        plain, _, _ = render(SCENES[name], data, None, size, only=tag)
        drawn = np.abs(plain.astype(int) - 255).sum(axis=2) > 24
        for style in STYLES:
            styled, _, _ = render(SCENES[name], data, style, size, only=tag)
            save(styled, os.path.join(outdir, "primitive-%s-%s-%s.png" % (name, tag, style)))
            ink = np.abs(styled.astype(int) - 255).sum(axis=2) > 24
            m = {"covered": float(np.mean(near(ink, 1)[drawn])),
                 "plain": float(np.mean(np.abs(styled[drawn].astype(int) -
                                               plain[drawn].astype(int)).sum(axis=1) <= 24)),
                 # ink: no channel above a quarter of full value
                 "ink": float(np.mean(styled[drawn].max(axis=1) <= 64))}
            if style == "pixel":
                m["palette"] = in_palette(styled[ink])
            rows.append(("%s %s" % (name, tag), style, m))
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("data")
    parser.add_argument("outdir")
    parser.add_argument("--check", action="store_true")
    parser.add_argument("--bench", action="store_true")
    parser.add_argument("--scenes", default="skull,liver,field")
    parser.add_argument("--size", default="640x480")
    parser.add_argument("--figures", action="store_true",
                        help="also write each style's vector figure (OUTDIR/volume-SCENE-STYLE.svg)")
    parser.add_argument("--haze", type=float, default=None,
                        help="the styles' VolumeHaze (default: the styles' own, 0: the solid "
                             "surface alone; 1: VTK's fog)")
    parser.add_argument("--haze-mode", default="fog", choices=sorted(HAZE_MODES),
                        help="the styles' VolumeHazeMode (default fog, the styles' own)")
    parser.add_argument("--primitives", default="",
                        help="SCENE,...: also measure these scenes' (field, disk) streamlines "
                             "and glyphs alone")
    parser.add_argument("--unmet", default="",
                        help="SCENE.STYLE.MEASURE or SCENE-PROP.STYLE,...: goals known not to be "
                             "met there (issue 55), printed and not checked")
    args = parser.parse_args()
    unmet = set(filter(None, args.unmet.split(",")))
    size = tuple(int(v) for v in args.size.split("x"))
    os.makedirs(args.outdir, exist_ok=True)
    failures = []
    rows = []
    times = 5 if args.bench else 0
    for name in args.scenes.split(","):
        builder = SCENES[name]
        plain, plain_time, _ = render(builder, args.data, None, size, True, times)
        bare, _, _ = render(builder, args.data, None, size, False)
        region = np.abs(plain.astype(int) - bare.astype(int)).sum(axis=2) > 24
        # the volume's opacity as the scene shows it (in front of its opaque props): the scene
        # with flat white props over white and with flat black ones over black
        white, _, _ = render(flat_props(builder, 1.0), args.data, None, size, True)
        black, _, _ = render(flat_props(builder, 0.0), args.data, None, size, True,
                             background=0.0)
        alpha = 1.0 - (white.astype(float) - black.astype(float)).mean(axis=2) / 255.0
        solid = region & (alpha >= 0.5)
        save(plain, os.path.join(args.outdir, "volume-%s-vtk.png" % name))
        for style in STYLES:
            figure = os.path.join(args.outdir, "volume-%s-%s.svg" % (name, style)) \
                if args.figures else None
            styled, styled_time, surfaces = render(builder, args.data, style, size, True, times,
                                                   haze=args.haze, figure=figure,
                                                   haze_mode=args.haze_mode)
            save(styled, os.path.join(args.outdir, "volume-%s-%s.png" % (name, style)))
            m = measure(style, styled, plain, region, solid)
            m["surfaces"] = surfaces
            if args.bench:
                m["cost"] = styled_time / plain_time
                if args.haze != 0:  # (the fog kept while the camera moves)
                    _, moving_time, _ = render(builder, args.data, style, size, True, times,
                                               haze=args.haze, haze_mode=args.haze_mode,
                                               moving=True)
                    m["moving"] = moving_time / plain_time
            if style == "comic":
                m["gradient_vtk"] = gradient_share(plain, region)
            rows.append((name, style, int(region.sum()), m))
            if m["plain"] > GOAL_PLAIN or surfaces < 1:
                failures.append("%s %s: %.3f left as VTK draws it, %d surfaces"
                                % (name, style, m["plain"], surfaces))
            for key, goal, above in (("palette", GOAL_PALETTE, True), ("tone", GOAL_TONE, True),
                                     ("recall", GOAL_RECALL, True),
                                     ("gradient", GOAL_GRADIENT, False)):
                if key in m and (m[key] < goal if above else m[key] > goal):
                    text = "%s %s: %s %.3f, goal %s %.2f" % (
                        name, style, key, m[key], ">=" if above else "<=", goal)
                    if "%s.%s.%s" % (name, style, key) in unmet:
                        print("open (not checked): " + text)
                    else:
                        failures.append(text)
            if style == "comic" and args.haze is None:
                # the haze (VolumeHaze 0.4): a translucent layer where the opacity reaches a
                # tenth of the threshold, so the picture changes around and over the solid part
                # (the defaults draw the solid part alone)
                hazy, _, _ = render(builder, args.data, style, size, True, haze=0.4,
                                    haze_mode="shell")
                changed = float(np.mean(np.abs(hazy.astype(int) - styled.astype(int)).sum(axis=2)
                                        > 24))
                print("%s: VolumeHaze 0.4 (shell) changes %.3f of the comic's picture"
                      % (name, changed))
                if changed < 0.005:
                    failures.append("%s: VolumeHaze 0.4 (shell) changed %.4f of the comic"
                                    % (name, changed))
    print("| scene | style | region (px) | left as VTK | comic: plain gradient (VTK's) | palette "
          "| tone corr. | outline recall |" + (" cost vs VTK |" if args.bench else "") +
          (" moving vs VTK |" if args.bench and args.haze != 0 else ""))
    print("|---|---|---:|---:|---:|---:|---:|---:|" + ("---:|" if args.bench else "") +
          ("---:|" if args.bench and args.haze != 0 else ""))
    for name, style, n, m in rows:
        cells = [m.get(k) for k in ("plain", "gradient", "palette", "tone", "recall")]
        text = ["" if c is None else "%.3f" % c for c in cells]
        if "gradient_vtk" in m:
            text[1] += " (%.3f)" % m["gradient_vtk"]
        line = "| %s | %s | %d | " % (name, style, n) + " | ".join(text) + " |"
        if args.bench:
            line += " %.2fx |" % m["cost"]
        if "moving" in m:
            line += " %.2fx |" % m["moving"]
        print(line)
    if args.primitives:
        print("\n| prop | style | VTK's pixels covered | left as VTK | ink | pixel art in palette |"
              "\n|---|---|---:|---:|---:|---:|")
        for tag, style, m in [row for name in args.primitives.split(",")
                              for row in primitives(name, args.data, size, args.outdir)]:
            print("| %s | %s | %.3f | %.3f | %.3f | %s |" % (
                tag, style, m["covered"], m["plain"], m["ink"],
                "%.3f" % m["palette"] if "palette" in m else ""))
            # (the comic's tinted ink keeps a line's hue at a quarter of full value: a dark line
            # is drawn much as VTK draws it, so the comic's lines are held to being ink; the
            # field's outline is a light one; pixel art is held to its palette, which may hold
            # VTK's colour of a line: the disk's dark gray outline)
            drawn_as_vtk = m["plain"] > GOAL_PLAIN and style not in ("comic", "pixel")
            if m["covered"] < GOAL_COVERED or m.get("palette", 1.0) < GOAL_PALETTE or \
                    (not tag.endswith("glyphs") and (drawn_as_vtk or (
                        style in ("comic", "lines") and m["ink"] < GOAL_INK))):
                text = "%s %s: covered %.3f, left as VTK %.3f, palette %.3f" % (
                    tag, style, m["covered"], m["plain"], m.get("palette", 1.0))
                if "%s.%s" % (tag.replace(" ", "-"), style) in unmet:
                    print("open (not checked): " + text)
                else:
                    failures.append(text)
    if failures:
        print("\n".join(failures), file=sys.stderr)
    return 1 if args.check and failures else 0


if __name__ == "__main__":
    sys.exit(main())
