"""Python test: Examples/Python/stylize_dataset.py renders files and the built-in scene in every
style, and each image is what its style promises.

Writes its own data into a temporary folder: a sphere coloured by elevation (.vtp) and the
wavelet (.vti, contoured at the middle of its range). Each run must write none.png, comic.png,
pixel.png and sketch.png at the requested size. Checks (each fails on a broken pass):
- every image has the object on the background (neither blank nor filled);
- each style differs from `none` and from every other style by a mean absolute difference of
  at least MIN_STYLE_DIFFERENCE levels per channel inside the object's area;
- comic and sketch put dark ink on the object; on data coloured through the colour map (the
  sphere, the built-in scene's tubes and ellipsoid) they keep the map's hues under the ink (the
  Tint default, DATA_COLORS: chroma above 60), on uncoloured data (the wavelet's contour, one
  value of the map's neutral middle) they are gray;
- pixel art: every channel of every pixel is one of the pass's Levels values (0, 85, 170, 255
  by default), so the image has at most Levels^3 colours, and the image changes only at the
  borders of a PixelSize grid (blocks of art pixels);
- a missing input file gives exit status 1, one line on stderr and no output folder; so does a
  broken one (a polyhedron face naming a point that does not exist), with the reader's line.

Run with the build's python folder on PYTHONPATH and a display (the suite does both); argv[1],
when given, is the example script.
"""
import os
import subprocess
import sys
import tempfile

import vtkstylize
from vtkmodules.vtkFiltersCore import vtkElevationFilter
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.vtkIOXML import vtkXMLImageDataWriter, vtkXMLPolyDataWriter

from stylize_test_scene import check, failures

HERE = os.path.dirname(os.path.abspath(__file__))
EXAMPLE = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
    HERE, "..", "..", "Examples", "Python", "stylize_dataset.py")

# Inside the object's area, in levels (0-255) per channel. Seen: 46 to 101 (see the output).
MIN_STYLE_DIFFERENCE = 20.0


class Image:
    """A PNG as width, height and a bytes object of RGB triples (rows bottom to top)."""

    def __init__(self, path):
        reader = vtkPNGReader()
        reader.SetFileName(path)
        reader.Update()
        data = reader.GetOutput()
        self.width, self.height, _ = data.GetDimensions()
        scalars = data.GetPointData().GetScalars()
        components = scalars.GetNumberOfComponents()
        raw = bytes(memoryview(scalars))
        if components == 3:
            self.rgb = raw
        else:  # drop alpha (or expand gray)
            self.rgb = bytes(raw[i + min(c, components - 1)] for i in range(0, len(raw), components)
                             for c in range(3))
        self.count = self.width * self.height

    def pixel(self, i):
        return self.rgb[3 * i:3 * i + 3]


def object_mask(none):
    """Pixels of the object in the `none` image (white background), grown by 8 pixels so that
    outlines and art pixels just outside the silhouette count as the object's area."""
    w, h = none.width, none.height
    mask = bytearray(1 if min(none.pixel(i)) < 245 else 0 for i in range(none.count))
    for _ in range(8):
        grown = bytearray(mask)
        for y in range(h):
            row = y * w
            for x in range(w):
                if mask[row + x]:
                    continue
                if (x > 0 and mask[row + x - 1]) or (x + 1 < w and mask[row + x + 1]) or \
                        (y > 0 and mask[row + x - w]) or (y + 1 < h and mask[row + x + w]):
                    grown[row + x] = 1
        mask = grown
    return mask


def mean_difference(a, b, mask):
    """Mean absolute difference per channel over the masked pixels."""
    total, n = 0, 0
    for i in range(a.count):
        if mask[i]:
            pa, pb = a.pixel(i), b.pixel(i)
            total += abs(pa[0] - pb[0]) + abs(pa[1] - pb[1]) + abs(pa[2] - pb[2])
            n += 1
    return total / (3.0 * max(n, 1))


def chroma(image):
    """Largest max - min channel over the image's pixels, and the mean over its pixels."""
    values = [max(image.pixel(i)) - min(image.pixel(i)) for i in range(image.count)]
    return max(values), sum(values) / float(len(values))


def dark_fraction(image, mask, level=100):
    inside = [i for i in range(image.count) if mask[i]]
    return sum(1 for i in inside if max(image.pixel(i)) < level) / float(max(len(inside), 1))


def grid_concentration(image, size, horizontal):
    """The share of colour changes between neighbours (along x or y) that fall on the most
    frequent position modulo size: 1 for an image of size x size blocks, about 1/size for
    an ordinary image."""
    w, h = image.width, image.height
    counts = [0] * size
    rgb = image.rgb
    for y in range(h - (0 if horizontal else 1)):
        for x in range(w - (1 if horizontal else 0)):
            i = 3 * (y * w + x)
            j = i + 3 if horizontal else i + 3 * w
            if rgb[i:i + 3] != rgb[j:j + 3]:
                counts[(x if horizontal else y) % size] += 1
    total = sum(counts)
    return max(counts) / float(total) if total else 0.0


def run_example(args):
    return subprocess.run([sys.executable, EXAMPLE] + args, stdout=subprocess.PIPE,
                          stderr=subprocess.PIPE, universal_newlines=True, timeout=600)


def check_run(label, args, outdir, size, coloured):
    print("== %s: stylize_dataset.py %s" % (label, " ".join(args)))
    result = run_example(args + ["-o", outdir])
    sys.stdout.write(result.stderr)
    if not check(result.returncode == 0, "%s: exit status %d" % (label, result.returncode)):
        return
    expected = [os.path.join(outdir, s + ".png") for s in vtkstylize.STYLES]
    check(result.stdout.split() == expected,
          "%s: printed %r, expected %r" % (label, result.stdout.split(), expected))
    images = {}
    before = len(failures)
    for style, path in zip(vtkstylize.STYLES, expected):
        if not check(os.path.isfile(path), "%s: %s missing" % (label, path)):
            return
        image = Image(path)
        check((image.width, image.height) == size, "%s %s: size %dx%d, expected %dx%d"
              % (label, style, image.width, image.height, size[0], size[1]))
        images[style] = image
    if len(failures) > before:
        return

    none = images["none"]
    mask = object_mask(none)
    covered = sum(mask) / float(none.count)
    print("%s: object area %.1f%% of the image" % (label, 100 * covered))
    check(0.03 < covered < 0.9, "%s: the object covers %.1f%% of the image" % (label, 100 * covered))
    for style, image in images.items():
        lo = min(min(image.pixel(i)) for i in range(image.count))
        hi = max(max(image.pixel(i)) for i in range(image.count))
        check(hi - lo > 100, "%s %s: blank image (levels %d..%d)" % (label, style, lo, hi))

    styles = vtkstylize.STYLES
    for a in range(len(styles)):
        for b in range(a + 1, len(styles)):
            d = mean_difference(images[styles[a]], images[styles[b]], mask)
            print("%s: %s vs %s: mean difference %.1f levels in the object's area"
                  % (label, styles[a], styles[b], d))
            check(d >= MIN_STYLE_DIFFERENCE, "%s: %s and %s differ by %.1f levels only"
                  % (label, styles[a], styles[b], d))

    none_chroma = chroma(none)
    for style, limit in (("comic", 2), ("sketch", 12)):
        c = chroma(images[style])
        ink = dark_fraction(images[style], mask)
        print("%s: %s chroma max %d mean %.2f (none: max %d), ink %.1f%% of the object's area"
              % (label, style, c[0], c[1], none_chroma[0], 100 * ink))
        if coloured:
            check(c[0] > 60, "%s: %s lost the data's colours (chroma %d)" % (label, style, c[0]))
        else:
            check(c[0] <= limit, "%s: %s is not gray (chroma %d)" % (label, style, c[0]))
        check(ink > 0.05, "%s: %s has no ink (%.1f%%)" % (label, style, 100 * ink))
    if coloured:
        check(none_chroma[0] > 60, "%s: the none image is not coloured (chroma %d): the gray "
              "checks prove nothing" % (label, none_chroma[0]))

    defaults = vtkstylize.vtkPixelArtPass()
    levels, size_px = defaults.GetLevels(), defaults.GetPixelSize()
    allowed = set(int(round(k * 255.0 / (levels - 1))) for k in range(levels))
    pixel = images["pixel"]
    off = sum(1 for i in range(pixel.count) if any(v not in allowed for v in pixel.pixel(i)))
    colours = set(pixel.pixel(i) for i in range(pixel.count))
    hx = grid_concentration(pixel, size_px, True)
    vy = grid_concentration(pixel, size_px, False)
    nx = grid_concentration(none, size_px, True)
    print("%s: pixel: %d colours (palette: %d), %d pixels off the %d levels, changes on the "
          "%d-pixel grid: %.3f across, %.3f down (none: %.3f)"
          % (label, len(colours), levels ** 3, off, levels, size_px, hx, vy, nx))
    check(off == 0, "%s: pixel: %d pixels with values off the palette's levels" % (label, off))
    check(len(colours) <= levels ** 3, "%s: pixel: %d colours" % (label, len(colours)))
    check(len(colours) >= 4, "%s: pixel: only %d colours" % (label, len(colours)))
    check(hx > 0.97 and vy > 0.97, "%s: pixel: no %d-pixel blocks (%.3f, %.3f)"
          % (label, size_px, hx, vy))
    check(nx < 0.6, "%s: the none image already looks blocky (%.3f)" % (label, nx))


with tempfile.TemporaryDirectory(prefix="stylize-example-") as tmp:
    sphere = vtkSphereSource()
    sphere.SetThetaResolution(48)
    sphere.SetPhiResolution(24)
    elevation = vtkElevationFilter()  # point scalars: the example colours the sphere by them
    elevation.SetInputConnection(sphere.GetOutputPort())
    elevation.SetLowPoint(0, -0.5, 0)
    elevation.SetHighPoint(0, 0.5, 0)
    sphere_path = os.path.join(tmp, "sphere.vtp")
    writer = vtkXMLPolyDataWriter()
    writer.SetFileName(sphere_path)
    writer.SetInputConnection(elevation.GetOutputPort())
    check(writer.Write() == 1, "cannot write %s" % sphere_path)

    wavelet = vtkRTAnalyticSource()
    wavelet.SetWholeExtent(-10, 10, -10, 10, -10, 10)
    wavelet_path = os.path.join(tmp, "wavelet.vti")
    image_writer = vtkXMLImageDataWriter()
    image_writer.SetFileName(wavelet_path)
    image_writer.SetInputConnection(wavelet.GetOutputPort())
    check(image_writer.Write() == 1, "cannot write %s" % wavelet_path)

    check_run("sphere.vtp", [sphere_path, "--size", "320x240"], os.path.join(tmp, "sphere"),
              (320, 240), True)
    check_run("wavelet.vti", [wavelet_path, "--size", "240x200"], os.path.join(tmp, "wavelet"),
              (240, 200), False)
    check_run("built-in scene", [], os.path.join(tmp, "scene"), (800, 600), True)

    # A missing file: status 1, one line on stderr, nothing written.
    missing_out = os.path.join(tmp, "missing")
    result = run_example([os.path.join(tmp, "absent.vtp"), "-o", missing_out])
    print("== missing file: status %d, stderr %r" % (result.returncode, result.stderr))
    check(result.returncode == 1, "missing file: exit status %d" % result.returncode)
    check(len(result.stderr.strip().splitlines()) == 1, "missing file: stderr %r" % result.stderr)
    check(not os.path.exists(missing_out), "missing file: the output folder was created")

    # A broken file (a polyhedron face naming point 999999, which crashed VTK's surface filter):
    # the checked reader's one line, nothing written.
    broken = os.path.join(tmp, "far_id.vtu")
    with open(broken, "w") as f:
        f.write('<?xml version="1.0"?>\n<VTKFile type="UnstructuredGrid" version="1.0">\n'
                '<UnstructuredGrid><Piece NumberOfPoints="4" NumberOfCells="1">\n'
                '<Points><DataArray type="Float32" NumberOfComponents="3" format="ascii">'
                '0 0 0 1 0 0 0 1 0 0 0 1</DataArray></Points>\n<Cells>\n'
                '<DataArray type="Int64" Name="connectivity" format="ascii">0 1 2 3</DataArray>\n'
                '<DataArray type="Int64" Name="offsets" format="ascii">4</DataArray>\n'
                '<DataArray type="UInt8" Name="types" format="ascii">42</DataArray>\n'
                '<DataArray type="Int64" Name="faces" format="ascii">'
                '4 3 0 1 2 3 0 1 3 3 0 2 3 3 1 2 999999</DataArray>\n'
                '<DataArray type="Int64" Name="faceoffsets" format="ascii">17</DataArray>\n'
                '</Cells></Piece></UnstructuredGrid></VTKFile>\n')
    broken_out = os.path.join(tmp, "broken")
    result = run_example([broken, "-o", broken_out])
    print("== broken file: status %d, stderr %r" % (result.returncode, result.stderr))
    check(result.returncode == 1, "broken file: exit status %d" % result.returncode)
    lines = result.stderr.strip().splitlines()
    check(len(lines) == 1 and "999999" in result.stderr and
          lines[0].startswith("stylize_dataset.py: cannot read"), "broken file: stderr %r" % result.stderr)
    check(not os.path.exists(broken_out), "broken file: the output folder was created")

print("%d failure(s)" % len(failures))
sys.exit(1 if failures else 0)
