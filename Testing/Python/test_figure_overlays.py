"""The 2D actors of a VTK figure (issue 18): text, scalar bars and vtkContext2D items as vectors.

A comic torus in a 400x300 offscreen window with a vtkTextActor title, a vtkScalarBarActor and a
vtkContextActor whose scene holds a vtkBlockItem (a filled, outlined box with a label: painted
through vtkContext2D into the figure's cairo device), and a vtkCornerAnnotation (a 2D actor of
none of these kinds). Written as SVG and PDF with vtkstylize.save_figure and rasterized back at the
window's size (rsvg-convert, pdftocairo): SSIM >= 0.95 against the PNG over the whole image and
over the box's corner, which must hold the box (its fill colour); the SVG draws the box and its
label as vectors (no embedded image); the warning names the corner annotation, and only it; the
counts: at least 3 texts (title, box label, bar labels).
"""
import os
import shutil
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "RealData"))
import vtk  # noqa: E402
import vtkstylize  # noqa: E402
from figures import SSIM_MIN, rasterize, read_png, vector_content  # noqa: E402
from stylize_test_scene import check, failures, offscreen_window, torus_actor  # noqa: E402
from vtk.util.numpy_support import vtk_to_numpy  # noqa: E402
from vtkstylize_testing import vtkStylizeImageMetrics as M  # noqa: E402

BOX = (20, 200, 150, 60)  # x, y, width, height of the block item (pixels)
FILL = (40, 160, 90)

if not shutil.which("rsvg-convert") or not shutil.which("pdftocairo"):
    print("rsvg-convert and pdftocairo (Debian: librsvg2-bin, poppler-utils) are needed")
    sys.exit(1)

window = offscreen_window(400, 300)
renderer = vtk.vtkRenderer()
actor = torus_actor(0.35, 50)
renderer.AddActor(actor)
renderer.SetBackground(1, 1, 1)
window.AddRenderer(renderer)
renderer.ResetCamera()
# 1 point = 1 pixel: dots of 8 pixels, which the raster draws as the figure does (a window
# a quarter of ReferenceHeight tall fades them to the tone, the figure keeps them)
renderer.SetPass(vtkstylize.create_pass("comic", ReferenceHeight=300))

title = vtk.vtkTextActor()
title.SetInput("Torus")
title.GetTextProperty().SetFontSize(20)
title.GetTextProperty().SetColor(0, 0, 0)
title.SetPosition(250, 260)
renderer.AddActor2D(title)

lut = vtk.vtkLookupTable()
lut.SetRange(0, 1)
lut.Build()
bar = vtk.vtkScalarBarActor()
bar.SetLookupTable(lut)
bar.SetNumberOfLabels(3)
bar.GetLabelTextProperty().SetColor(0, 0, 0)
bar.SetPosition(0.85, 0.1)
bar.SetWidth(0.12)
bar.SetHeight(0.6)
renderer.AddActor2D(bar)

block = vtk.vtkBlockItem()
block.SetLabel("vtkContext2D")
block.SetDimensions(*BOX)
block.GetBrush().SetColor(*FILL)
block.GetPen().SetColor(0, 0, 0)
block.GetPen().SetWidth(2)
context = vtk.vtkContextActor()
context.GetScene().AddItem(block)
renderer.AddActor(context)

corner = vtk.vtkCornerAnnotation()
corner.SetText(0, "left out")
renderer.AddViewProp(corner)

window.Render()
folder = tempfile.mkdtemp(prefix="vtkstylize-overlays-")
try:
    png = os.path.join(folder, "figure.png")
    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.SetInputBufferTypeToRGB()
    grab.ReadFrontBufferOff()
    writer = vtk.vtkPNGWriter()
    writer.SetInputConnection(grab.GetOutputPort())
    writer.SetFileName(png)
    writer.Write()
    # the PNG without the corner annotation, which the figure leaves out
    corner.VisibilityOff()
    window.Render()
    grab.Modified()
    writer.Write()
    corner.VisibilityOn()
    reference = read_png(png)
    w, h, _ = reference.GetDimensions()

    def crop(image):
        voi = vtk.vtkExtractVOI()
        voi.SetInputData(image)
        x, y, bw, bh = BOX
        voi.SetVOI(x - 4, x + bw + 4, y - 4, y + bh + 4, 0, 0)
        voi.Update()
        return voi.GetOutput()

    rgb = vtk_to_numpy(crop(reference).GetPointData().GetScalars()).astype(int)
    filled = int((abs(rgb - FILL).max(axis=1) < 12).sum())
    check(filled > 0.5 * BOX[2] * BOX[3], "the PNG shows no box (%d fill pixels)" % filled)
    print("| format | bytes | SSIM | box's corner SSIM | texts |")
    print("|---|---:|---:|---:|---:|")
    for ext in ("svg", "pdf"):
        path = os.path.join(folder, "figure." + ext)
        figure = vtkstylize.save_figure(window, path)
        check(corner.GetVisibility() == 1, "the writer left the corner annotation hidden")
        warning = figure.GetWarning()
        check("vtkCornerAnnotation" in warning and "vtkContextActor" not in warning and
              "vtkScalarBarActor" not in warning,
              "%s: the warning should name the corner annotation only: %r" % (ext, warning))
        check(figure.GetNumberOfTexts() >= 3, "%s: %d texts" % (ext, figure.GetNumberOfTexts()))
        out = os.path.join(folder, "figure-%s.png" % ext)
        rasterize(path, out, w, h)
        image = read_png(out)
        ssim = M.SSIM(reference, image, 255.0)
        box = M.SSIM(crop(reference), crop(image), 255.0)
        print("| %s | %d | %.4f | %.4f | %d |" % (ext, os.path.getsize(path), ssim, box,
                                                   figure.GetNumberOfTexts()))
        check(ssim >= SSIM_MIN and box >= SSIM_MIN,
              "%s: SSIM %.4f, box's corner %.4f (< %.2f)" % (ext, ssim, box, SSIM_MIN))
        if ext == "svg":
            paths, images = vector_content(path)
            check(images == 0, "SVG: %d embedded images (vectors expected)" % images)
finally:
    if not os.environ.get("VTKSTYLIZE_KEEP"):
        shutil.rmtree(folder, ignore_errors=True)
    else:
        print("kept " + folder)
for f in failures:
    print("FAIL: " + f)
sys.exit(1 if failures else 0)
