#!/usr/bin/env python3
"""Render a dataset file (or VTK Stylize's built-in scene) in every style, one PNG each.

Usage (from the repository, with the build tree's Python package; /usr/bin/python3 is the
interpreter Debian's python3-vtk9 is built for; an X display is needed, e.g. Xvfb)::

    PYTHONPATH=build/python /usr/bin/python3 Examples/Python/stylize_dataset.py \\
        [FILE] [-o OUTDIR] [--size WxH] [--iso-lines N]

FILE      a dataset in any format vtkStylizeReader reads (VTK XML and legacy, .pvd, Exodus,
          EnSight, OpenFOAM, STL, OBJ, PLY), checked before VTK's reader opens it, so that a
          broken file is an error line rather than a crash. Points at NaN or infinity are left
          out with their cells (a warning). Polygonal data is drawn as is; other datasets as
          their outer surface
          (vtkDataSetSurfaceFilter); a 3D image with point scalars as the contour at the middle
          of the scalar range; a multiblock file block by block. Without FILE: the built-in
          scene (vtkStylizeDemoScene).
-o        output folder, created if needed (default: out-python).
--size    image size in pixels (default: 800x600).
--iso-lines  the contour plot of the coloured data drawn as lines, at most N round levels of the
          colour map's range, in the comic, the sketch and the line art (default: 0, none).

It writes OUTDIR/none.png, comic.png, pixel.png and sketch.png (the styles in
vtkstylize.STYLES, each with the pass's default settings; "none" is plain VTK rendering) and
prints their paths, one per line. Rendering is offscreen, without multisampling. Point (else
cell) scalars colour the surface through a cool-to-warm map; without scalars it is light gray.
Errors (missing, unreadable or broken file, nothing to draw, bad option) print one line on
stderr and exit with status 1 (2 for command-line syntax); no image is written then.
"""

import argparse
import os
import sys

try:
    import vtkstylize
except ImportError as error:
    sys.exit("stylize_dataset.py: cannot import vtkstylize (%s): put the build's python folder "
             "on PYTHONPATH, e.g. PYTHONPATH=build/python" % error)

from vtkmodules.vtkCommonCore import vtkCommand, vtkUnsignedCharArray
from vtkmodules.vtkCommonDataModel import (vtkCompositeDataSet, vtkDataSet, vtkImageData,
                                            vtkPolyData)
from vtkmodules.vtkFiltersCore import vtkContourFilter, vtkPolyDataNormals
from vtkmodules.vtkFiltersGeometry import vtkDataSetSurfaceFilter
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkActor, vtkColorTransferFunction, vtkPolyDataMapper,
                                         vtkRenderer, vtkRenderWindow, vtkWindowToImageFilter)

SOLID_COLOR = (0.80, 0.80, 0.80)

# What the reader left out (printed after a success, so that a failure stays one line).
WARNINGS = []


class Failure(Exception):
    """An error worth one line on stderr."""


def parse_size(text):
    try:
        width, height = (int(v) for v in text.lower().split("x"))
    except ValueError:
        raise argparse.ArgumentTypeError("expected WxH, e.g. 800x600, got %r" % text)
    if not (1 <= width <= 16384 and 1 <= height <= 16384):
        raise argparse.ArgumentTypeError("width and height must be in [1, 16384], got %r" % text)
    return width, height


def read(path):
    """The data object in path, read by vtkStylizeReader (checked: a broken file is an error)."""
    reader_class = vtkstylize.vtkStylizeReader
    if not reader_class.IsSupportedFile(path):
        raise Failure("%s: unknown format %r (known: %s)"
                      % (path, os.path.splitext(path)[1], reader_class.GetSupportedExtensions()))
    reader = reader_class()
    reader.SetFileName(path)
    # The reader's error is one line, GetErrorMessage(): these observers keep VTK from also
    # printing it (and the executive's "returned failure") in its multi-line form.
    quiet = lambda obj, event: None  # noqa: E731
    reader.AddObserver(vtkCommand.ErrorEvent, quiet)
    reader.GetExecutive().AddObserver(vtkCommand.ErrorEvent, quiet)
    reader.Update()
    if reader.GetErrorMessage():
        raise Failure(reader.GetErrorMessage())
    WARNINGS.extend(reader.GetWarning(i) for i in range(reader.GetNumberOfWarnings()))
    return reader.GetOutputDataObject(0)


def to_surface(dataset):
    """A vtkPolyData to draw for a dataset (see the module's documentation)."""
    if isinstance(dataset, vtkPolyData):
        return dataset
    if isinstance(dataset, vtkImageData):
        dims = dataset.GetDimensions()
        scalars = dataset.GetPointData().GetScalars()
        if scalars is not None and min(dims) > 1:
            low, high = scalars.GetRange(0)
            contour = vtkContourFilter()
            contour.SetInputData(dataset)
            contour.SetValue(0, 0.5 * (low + high))
            contour.ComputeNormalsOn()
            contour.ComputeScalarsOff()
            contour.Update()
            return contour.GetOutput()
    surface = vtkDataSetSurfaceFilter()
    surface.SetInputData(dataset)
    surface.Update()
    return surface.GetOutput()


def parts_of(data, name=""):
    """[(name, vtkPolyData)] for a dataset or every leaf of a composite dataset."""
    if isinstance(data, vtkCompositeDataSet):
        parts = []
        iterator = data.NewIterator()
        iterator.SkipEmptyNodesOn()
        iterator.InitTraversal()
        while not iterator.IsDoneWithTraversal():
            leaf = iterator.GetCurrentDataObject()
            meta = iterator.GetCurrentMetaData() if iterator.HasCurrentMetaData() else None
            leaf_name = meta.Get(vtkCompositeDataSet.NAME()) if meta is not None and \
                meta.Has(vtkCompositeDataSet.NAME()) else ""
            parts.extend(parts_of(leaf, leaf_name))
            iterator.GoToNextItem()
        return parts
    if not isinstance(data, vtkDataSet):
        raise Failure("the data is a %s, which cannot be drawn" % data.GetClassName())
    return [(name, to_surface(data))]


def with_normals(surface):
    if surface.GetPointData().GetNormals() is not None or surface.GetNumberOfPolys() + \
            surface.GetNumberOfStrips() == 0:
        return surface
    normals = vtkPolyDataNormals()
    normals.SetInputData(surface)
    normals.ConsistencyOn()
    normals.SplittingOn()
    normals.SetFeatureAngle(45.0)
    normals.Update()
    return normals.GetOutput()


def color_array(name, surface, built_in):
    """(array name, is point data) to colour a part by, or None for a solid colour."""
    if built_in:
        array = {"parametric": "Height", "streamlines": "Speed"}.get(name)
        return (array, True) if array else None
    for data, points in ((surface.GetPointData(), True), (surface.GetCellData(), False)):
        scalars = data.GetScalars()
        if scalars is not None:
            if not scalars.GetName():
                scalars.SetName("Scalars" if points else "CellScalars")
            return scalars.GetName(), points
    return None


def cool_warm(low, high):
    ctf = vtkColorTransferFunction()
    ctf.SetColorSpaceToDiverging()
    ctf.AddRGBPoint(low, 0.230, 0.299, 0.754)
    ctf.AddRGBPoint(high, 0.706, 0.016, 0.150)
    return ctf


def add_parts(renderer, parts, built_in):
    """One actor per part; parts coloured by the same array share one colour map."""
    choices = [color_array(name, surface, built_in) for name, surface in parts]
    ranges = {}
    for (name, surface), choice in zip(parts, choices):
        if choice is None:
            continue
        data = surface.GetPointData() if choice[1] else surface.GetCellData()
        array = data.GetArray(choice[0])
        if isinstance(array, vtkUnsignedCharArray) and array.GetNumberOfComponents() in (3, 4):
            continue  # direct colours
        low, high = array.GetRange(-1 if array.GetNumberOfComponents() > 1 else 0)
        old = ranges.get(choice[0], (low, high))
        ranges[choice[0]] = (min(old[0], low), max(old[1], high))
    maps = {}
    for array, (low, high) in ranges.items():
        if not high - low > 1e-6 * max(1.0, abs(low), abs(high)):
            low, high = low - 0.5, high + 0.5
        maps[array] = cool_warm(low, high)
    for (name, surface), choice in zip(parts, choices):
        mapper = vtkPolyDataMapper()
        mapper.SetInputData(surface)
        if choice is None:
            mapper.ScalarVisibilityOff()
        else:
            mapper.ScalarVisibilityOn()
            if choice[1]:
                mapper.SetScalarModeToUsePointFieldData()
            else:
                mapper.SetScalarModeToUseCellFieldData()
            mapper.SelectColorArray(choice[0])
            if choice[0] in maps:
                mapper.SetColorModeToMapScalars()
                mapper.SetLookupTable(maps[choice[0]])
                mapper.UseLookupTableScalarRangeOn()
                mapper.InterpolateScalarsBeforeMappingOn()
            else:
                mapper.SetColorModeToDirectScalars()
        actor = vtkActor()
        actor.SetMapper(mapper)
        prop = actor.GetProperty()
        prop.SetColor(*SOLID_COLOR)
        prop.SetAmbient(0.1)
        prop.SetDiffuse(0.75)
        prop.SetSpecular(0.15)
        prop.SetSpecularPower(30.0)
        renderer.AddActor(actor)


def load_parts(path):
    """[(name, vtkPolyData with normals)] to draw, from a file or the built-in scene."""
    if path is None:
        scene = vtkstylize.vtkStylizeDemoScene()
        scene.Update()
        data = scene.GetOutput()
    else:
        data = read(path)
    what = path or "the built-in scene"
    parts = [(name, surface) for name, surface in parts_of(data)
             if surface.GetNumberOfPoints() > 0 and surface.GetNumberOfCells() > 0]
    if not parts:
        raise Failure("%s: nothing to draw (no cells)" % what)
    return [(name, with_normals(surface)) for name, surface in parts]


def render_styles(parts, built_in, size, outdir, iso_lines=0):
    """Renders the parts in every style (with `iso_lines`, the iso-lines of the coloured data in
    the styles that draw them); returns the PNG paths written."""
    renderer = vtkRenderer()
    renderer.SetBackground(1.0, 1.0, 1.0)
    add_parts(renderer, parts, built_in)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)
    window.SetSize(*size)
    window.AddRenderer(renderer)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(0, 0, 1)
    camera.SetFocalPoint(0, 0, 0)
    camera.SetViewUp(0, 1, 0)
    renderer.ResetCamera()
    if built_in:
        camera.Azimuth(30.0)
        camera.Elevation(20.0)
        camera.OrthogonalizeViewUp()
    renderer.ResetCameraClippingRange()

    os.makedirs(outdir, exist_ok=True)
    paths = []
    for style in vtkstylize.STYLES:
        settings = {"IsoLines": iso_lines} if iso_lines and style not in ("none", "pixel") else {}
        vtkstylize.apply_style(renderer, style, **settings)
        window.Render()
        grab = vtkWindowToImageFilter()
        grab.SetInput(window)
        grab.SetInputBufferTypeToRGB()
        grab.ReadFrontBufferOff()
        grab.Update()
        path = os.path.join(outdir, style + ".png")
        writer = vtkPNGWriter()
        writer.SetFileName(path)
        writer.SetInputConnection(grab.GetOutputPort())
        writer.Write()
        if writer.GetErrorCode() != 0:
            raise Failure("%s: cannot be written" % path)
        paths.append(path)
    vtkstylize.apply_style(renderer, "none")  # releases the last pass's graphics resources
    window.Finalize()
    return paths


def main(argv=None):
    parser = argparse.ArgumentParser(
        prog="stylize_dataset.py",
        description="Render a dataset (or the built-in scene) in every VTK Stylize style.")
    parser.add_argument("file", nargs="?", help="dataset file (default: the built-in scene)")
    parser.add_argument("-o", "--output", default="out-python",
                        help="output folder (default: out-python)")
    parser.add_argument("--size", type=parse_size, default=(800, 600), metavar="WxH",
                        help="image size (default: 800x600)")
    parser.add_argument("--iso-lines", type=int, default=0, metavar="N",
                        help="iso-lines of the coloured data, at most N round levels of the "
                             "colour map's range, in the comic, sketch and line art (default: 0)")
    args = parser.parse_args(argv)
    try:
        parts = load_parts(args.file)
        paths = render_styles(parts, args.file is None, args.size, args.output, args.iso_lines)
    except (Failure, OSError) as error:
        print("stylize_dataset.py: %s" % error, file=sys.stderr)
        return 1
    for warning in WARNINGS:
        print("stylize_dataset.py: warning: %s" % warning, file=sys.stderr)
    for path in paths:
        print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
