"""paraview.styles: the VTK Stylize plugin in pvbatch (run by pvbatch-stylize, which loads it).

    pvbatch-stylize test_styles.py OUTPUT_DIR

Checks that the view and its properties exist with their ranges and tooltips, renders each
style and checks the images (each differs from ParaView's own, comic keeps the data's colours
and is gray in black and white, pixel art is made
of whole art pixels, line art is gray ink on white paper), and that a Stylized Surface representation's subject factor changes
only that representation's comic lighting.
"""
import os
import sys

from paraview.simple import *  # noqa: F401,F403
from stylize_pv_scene import check, failures, pixels

out = sys.argv[1]
os.makedirs(out, exist_ok=True)


view = CreateView("StylizeView")
view.ViewSize = [320, 240]
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0
view.Background = [1.0, 1.0, 1.0]

# --- the properties: the style choice, each pass's settings with ranges and tooltips
style = view.GetProperty("Style")
entries = [style.GetDomain("enum").GetEntryText(i)
           for i in range(style.GetDomain("enum").GetNumberOfEntries())]
check(entries == ["None", "Comic", "Pixel art", "Sketch", "Line art"], "Style entries %s" % entries)
for name, low, high in [("ComicEdgeWidth", None, None), ("PixelArtPixelSize", None, None),
                        ("SketchStepLength", None, None), ("LightingSubjectFactor", 0.0, 1.0)]:
    prop = view.GetProperty(name)
    check(prop is not None, "view property %s exists" % name)
    if prop is None:
        continue
    domain = prop.GetDomain("range")
    check(domain is not None, "%s has a range" % name)
    doc = prop.GetDocumentation()
    check(doc is not None and "Range" in doc.GetDescription(), "%s has a tooltip with its range"
          % name)
    if domain is not None and low is not None:
        check(domain.GetMinimum(0) == low and domain.GetMaximum(0) == high,
              "%s range [%g, %g]" % (name, domain.GetMinimum(0), domain.GetMaximum(0)))
exposed = [p for p in view.ListProperties()
           if p.startswith(("Comic", "PixelArt", "Sketch", "Lighting"))]
print("exposed pass properties:", len(exposed))
check(len(exposed) >= 60, "at least 60 pass settings in the panel (%d)" % len(exposed))

# --- each style on a real dataset: a contour of the Wavelet source, coloured by a scalar
wavelet = Wavelet()
contour = Contour(Input=wavelet, ContourBy=["POINTS", "RTData"], Isosurfaces=[157.0],
                  ComputeScalars=1)
elevation = Elevation(Input=contour, LowPoint=[0, 0, -10], HighPoint=[0, 0, 10])
display = Show(elevation, view)
ColorBy(display, ("POINTS", "Elevation"))
view.CameraPosition = [30.0, -45.0, 25.0]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.0, 0.0, 1.0]
view.ResetCamera()

images = {}
for index, name in enumerate(["none", "comic", "pixel", "sketch", "lines"]):
    view.Style = index
    Render(view)
    path = os.path.join(out, "styles-%s.png" % name)
    SaveScreenshot(path, view, ImageResolution=[320, 240])
    images[name] = pixels(path)


def mean_difference(a, b):
    return sum(abs(x - y) for p, q in zip(a, b) for x, y in zip(p, q)) / (3.0 * len(a))


for name in ["comic", "pixel", "sketch", "lines"]:
    d = mean_difference(images["none"][1], images[name][1])
    check(d > 5.0, "%s differs from ParaView's image (mean %.1f levels)" % (name, d))
# comic: the elevation's colours under the ink (Tint Data colors, the default); black and white
# (gray) with Tint Black and white; the none image is coloured there
chroma = max(max(p) - min(p) for p in images["comic"][1])
none_chroma = max(max(p) - min(p) for p in images["none"][1])
check(chroma > 50 and none_chroma > 50,
      "comic keeps the data's colours (chroma %d; none %d)" % (chroma, none_chroma))
view.Style = 1
view.ComicTint = 0
Render(view)
path = os.path.join(out, "styles-comic-black-and-white.png")
SaveScreenshot(path, view, ImageResolution=[320, 240])
gray = max(max(p) - min(p) for p in pixels(path)[1])
check(gray <= 2, "comic with Tint Black and white is gray (chroma %d)" % gray)
view.ComicTint = 1
# line art: gray ink on white paper (lines thinner than a pixel at this size: light ink)
lines = images["lines"][1]
paper = sum(1 for p in lines if min(p) > 240)
check(max(max(p) - min(p) for p in lines) <= 2 and 500 < len(lines) - paper < 0.2 * len(lines),
      "line art is ink on paper (%d paper of %d pixels)" % (paper, len(lines)))
# pixel art: colours change only on the art-pixel grid (4 px by default): blocks are uniform
(w, h, _), art = images["pixel"]
size = int(view.PixelArtPixelSize[0] if hasattr(view.PixelArtPixelSize, "__len__")
           else view.PixelArtPixelSize)
inside = across = 0
for y in range(h):
    for x in range(1, w):
        if art[y * w + x] != art[y * w + x - 1]:
            if x % size == 0:
                across += 1
            else:
                inside += 1
check(across > 0 and inside <= 0.05 * (inside + across),
      "pixel art changes colour on a %d px grid (%d on grid lines, %d inside blocks)"
      % (size, across, inside))

# --- per representation: a Stylized Surface with its own subject factor
view.Style = 1
display.SetRepresentationType("Stylized Surface")
display.StylizeOverrideLighting = 1
for factor in [0.0, 1.0]:
    display.StylizeSubjectFactor = factor
    Render(view)
    SaveScreenshot(os.path.join(out, "subject-%g.png" % factor), view, ImageResolution=[320, 240])
d = mean_difference(pixels(os.path.join(out, "subject-0.png"))[1],
                    pixels(os.path.join(out, "subject-1.png"))[1])
check(d > 2.0, "the representation's subject factor changes the comic image (%.1f levels)" % d)
display.StylizeOverrideLighting = 0
Render(view)
SaveScreenshot(os.path.join(out, "subject-off.png"), view, ImageResolution=[320, 240])
d = mean_difference(pixels(os.path.join(out, "subject-off.png"))[1], images["comic"][1])
check(d < 0.5, "without the override the image is the view's comic image (%.2f levels)" % d)

print("%d failures" % len(failures))
# Delete the view before exiting: pvbatch closes its X display before it deletes the remaining
# views when a script calls sys.exit(), and a view that still holds OpenGL objects then crashes
# (ParaView's own eye-dome-lighting view does too).
Delete(view)
del view, display
sys.exit(1 if failures else 0)
