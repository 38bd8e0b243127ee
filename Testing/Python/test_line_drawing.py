"""Python test: Examples/Python/line_drawing.py writes a vector line drawing, hidden lines removed.

On a sphere in front of a larger cube (a .vtp file written here, 800x600, seen head-on):
- the SVG parses, holds paths of the classes contour and crease only, with finite coordinates
  inside the image;
- the sphere's contour is one path, a circle: its points lie within 1.5 px of one radius about
  one centre;
- hidden lines are removed: no path point lies inside the sphere's disc but the contour's own
  (the cube's creases behind the sphere are cut), and the cube's creases that are not hidden
  are drawn;
- the built-in scene also gives a drawing; a missing file gives exit status 1, one line on
  stderr and no output.
argv[1], when given, is the example script.
"""
import math
import os
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ElementTree

from vtkmodules.vtkFiltersCore import vtkAppendPolyData, vtkTriangleFilter
from vtkmodules.vtkFiltersSources import vtkCubeSource, vtkSphereSource
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

from stylize_test_scene import check, failures

HERE = os.path.dirname(os.path.abspath(__file__))
EXAMPLE = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
    HERE, "..", "..", "Examples", "Python", "line_drawing.py")
NS = "{http://www.w3.org/2000/svg}"


def scene(path):
    sphere = vtkSphereSource()
    sphere.SetRadius(1.0)
    sphere.SetCenter(2.0, 0.0, 1.5)  # over the cube's right edge, which passes behind it
    sphere.SetThetaResolution(96)
    sphere.SetPhiResolution(64)
    cube = vtkCubeSource()
    cube.SetXLength(4.0)
    cube.SetYLength(3.0)
    cube.SetZLength(1.0)
    append = vtkAppendPolyData()
    append.AddInputConnection(sphere.GetOutputPort())
    append.AddInputConnection(cube.GetOutputPort())
    triangles = vtkTriangleFilter()
    triangles.SetInputConnection(append.GetOutputPort())
    writer = vtkXMLPolyDataWriter()
    writer.SetFileName(path)
    writer.SetInputConnection(triangles.GetOutputPort())
    writer.Write()


def run(args):
    return subprocess.run([sys.executable, EXAMPLE] + args, capture_output=True, text=True)


def paths(svg):
    out = []
    for p in ElementTree.parse(svg).getroot().iter(NS + "path"):
        numbers = [float(v) for v in p.get("d").replace("M", " ").replace("L", " ").split()]
        out.append((p.get("class"), list(zip(numbers[0::2], numbers[1::2]))))
    return out


with tempfile.TemporaryDirectory() as tmp:
    data = os.path.join(tmp, "scene.vtp")
    scene(data)
    svg = os.path.join(tmp, "lines.svg")
    result = run([data, "-o", svg, "--size", "800x600", "--azimuth", "0", "--elevation", "0"])
    check(result.returncode == 0, "exit status %d: %s" % (result.returncode, result.stderr))
    drawn = paths(svg) if os.path.exists(svg) else []
    kinds = sorted({k for k, _ in drawn})
    print("paths %d, kinds %s" % (len(drawn), kinds))
    check(set(kinds) <= {"contour", "crease"} and "crease" in kinds and "contour" in kinds,
          "kinds drawn %s (expected contours and creases)" % kinds)
    points = [p for _, pts in drawn for p in pts]
    check(all(math.isfinite(x) and math.isfinite(y) and -2 <= x <= 802 and -2 <= y <= 602
              for x, y in points), "path points outside the image or not finite")
    # The sphere's contour: the longest contour path, a circle.
    contours = [pts for k, pts in drawn if k == "contour"]
    circle = max(contours, key=len) if contours else []
    if circle:
        cx = sum(x for x, _ in circle) / len(circle)
        cy = sum(y for _, y in circle) / len(circle)
        radii = [math.hypot(x - cx, y - cy) for x, y in circle]
        r = sum(radii) / len(radii)
        spread = max(abs(v - r) for v in radii)
        print("sphere contour: %d points, centre (%.1f, %.1f), radius %.1f +- %.2f px"
              % (len(circle), cx, cy, r, spread))
        check(spread <= 1.5, "the sphere's contour is not a circle (radius %.1f +- %.2f)"
              % (r, spread))
        inside = [(x, y) for k, pts in drawn if pts is not circle for x, y in pts
                  if math.hypot(x - cx, y - cy) < r - 2.0]
        check(not inside, "%d path points inside the sphere's disc (hidden lines drawn)"
              % len(inside))
        # The cube's right edge runs behind the sphere: drawn above and below the disc only.
        creases = [(x, y) for k, pts in drawn if k == "crease" for x, y in pts]
        edge = max((x for x, _ in creases), default=0.0)
        right = [(x, y) for x, y in creases if x > edge - 2.0]
        print("the cube's right edge at x = %.1f px, %d points" % (edge, len(right)))
        above = any(y < cy - r - 1 for _, y in right)
        below = any(y > cy + r + 1 for _, y in right)
        check(above and below, "the cube's right edge is not drawn on both sides of the sphere")
    else:
        check(False, "no contour drawn")

    scene_svg = os.path.join(tmp, "scene.svg")
    result = run(["-o", scene_svg])
    check(result.returncode == 0 and len(paths(scene_svg)) > 0,
          "the built-in scene: status %d, %s" % (result.returncode, result.stderr))

    missing = os.path.join(tmp, "missing.svg")
    result = run([os.path.join(tmp, "nothing.vtp"), "-o", missing])
    lines = result.stderr.strip().splitlines()
    check(result.returncode == 1 and len(lines) == 1 and not os.path.exists(missing),
          "missing file: status %d, stderr %r" % (result.returncode, result.stderr))

print("%d failures" % len(failures))
sys.exit(1 if failures else 0)
