"""Interactive frames at a reduced image size (InteractiveImageReduction, issue 41).

    test_interactive_reduction.py DATA_DIR

While the window renders at an interactive rate, a style with InteractiveImageReduction k > 1
renders its picture at 1/k of the viewport's size and draws it scaled up. On the bunny scan and
the head scan (400x300), for the sketch and the line art at their own factor (2) and the comic
at 3, this test requires:

- the stage timing names the path: UPSCALE in interactive frames with k > 1; not with k = 1, not
  in still frames (screenshots stay at full size), never for the pixel art (which declines);
- the still frame after reduced frames equals the still frame before them;
- the scaled-up picture carries the scene's depth: a translucent red plane behind the mesh (drawn
  by VTK after the style, TranslucentLayers 0) is hidden where the mesh is, as at full size
  (its red covers as many pixels, within 15%), and the mesh does hide part of it (the red covers
  fewer pixels than with the mesh hidden);
- for the sketch and the line art, the reduced frame is the full-size interactive frame at lower
  detail: at least 85% of its ink lies within 2 pixels of the full-size frame's ink, more than
  for a frame with the camera turned by 10 degrees (the measure tells pictures apart), and its
  ink (darkness summed over the pixels) is 0.7 to 1.5 times the full-size frame's for the
  sketch (its strokes are scaled with the image), 0.7 to 5 times for the line art (its strokes
  stay at least a pixel of the reduced image wide: bolder, never gone).
"""
import sys

import vtkstylize
from stylize_test_scene import check as record, failures, mesh_window, ply_mesh
from vtkmodules.vtkFiltersSources import vtkPlaneSource
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkWindowToImageFilter

data = sys.argv[1]
W, H = 400, 300
STILL, INTERACTIVE = 0.0001, 15.0


def check(condition, message):
    if record(condition, message):
        print("ok  ", message)


def grab(window):
    image = vtkWindowToImageFilter()
    image.SetInput(window)
    image.ReadFrontBufferOff()
    image.Update()
    scalars = image.GetOutput().GetPointData().GetScalars()
    return [scalars.GetValue(i) for i in range(scalars.GetNumberOfValues())]


def frame(window, style, rate):
    """The window's RGB values after a render at `rate`, and the stages that ran."""
    window.SetDesiredUpdateRate(rate)
    window.Render()
    stages = [style.GetTimedStageName(i) for i in range(style.GetNumberOfTimedStages())]
    return grab(window), stages


def ink_mask(rgb):
    """Pixels darker than the paper and the background by a clear margin (ink)."""
    n = len(rgb) // 3
    return {i for i in range(n) if rgb[3 * i] + rgb[3 * i + 1] + rgb[3 * i + 2] < 3 * 150}


def ink_amount(rgb):
    """Ink summed over the pixels: each pixel's darkness below light grey (200), in [0, 1]."""
    n = len(rgb) // 3
    return sum(max(0.0, 1.0 - (rgb[3 * i] + rgb[3 * i + 1] + rgb[3 * i + 2]) / 600.0)
               for i in range(n))


def near(mask, reach=2):
    """`mask` grown by `reach` pixels (a square)."""
    out = set()
    for i in mask:
        x, y = i % W, i // W
        for dy in range(-reach, reach + 1):
            if 0 <= y + dy < H:
                row = (y + dy) * W
                for dx in range(-reach, reach + 1):
                    if 0 <= x + dx < W:
                        out.add(row + x + dx)
    return out


def within(mask, region):
    return sum(1 for i in mask if i in region) / max(1, len(mask))


def red(rgb):
    """Pixels where the red plane shows: red well above green and blue."""
    n = len(rgb) // 3
    return sum(1 for i in range(n)
               if rgb[3 * i] > rgb[3 * i + 1] + 60 and rgb[3 * i] > rgb[3 * i + 2] + 60)


def scene(mesh, plane, hide_mesh=False):
    window, ren, actor = mesh_window(ply_mesh(data, mesh), (0.9, 0.85, 0.75),
                                     (0.85, 0.88, 0.95), W, H, 25, 10)
    camera = ren.GetActiveCamera()
    if plane:
        # A translucent red plane through the mesh's far half, facing the camera.
        b = actor.GetBounds()
        centre = [(b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2]
        direction = camera.GetDirectionOfProjection()
        extent = max(b[1] - b[0], b[3] - b[2], b[5] - b[4])
        far = [centre[i] + 0.25 * extent * direction[i] for i in range(3)]
        up = camera.GetViewUp()
        right = [direction[1] * up[2] - direction[2] * up[1],
                 direction[2] * up[0] - direction[0] * up[2],
                 direction[0] * up[1] - direction[1] * up[0]]
        # 1.6 times the mesh's size, centred behind it
        corner = [far[i] - 0.8 * extent * (up[i] + right[i]) for i in range(3)]
        source = vtkPlaneSource()
        source.SetOrigin(corner)
        source.SetPoint1([corner[i] + 1.6 * extent * right[i] for i in range(3)])
        source.SetPoint2([corner[i] + 1.6 * extent * up[i] for i in range(3)])
        plane_mapper = vtkPolyDataMapper()
        plane_mapper.SetInputConnection(source.GetOutputPort())
        plane_actor = vtkActor()
        plane_actor.SetMapper(plane_mapper)
        plane_actor.GetProperty().SetColor(1.0, 0.0, 0.0)
        plane_actor.GetProperty().SetOpacity(0.6)
        plane_actor.GetProperty().LightingOff()
        ren.AddActor(plane_actor)
    ren.ResetCameraClippingRange()
    actor.SetVisibility(not hide_mesh)
    return window, ren


STYLES = (
    ("sketch", "vtkSketchPass", None),
    ("line art", "vtkLineArtPass", None),
    ("comic", "vtkComicPass", 3),
    ("pixel art", "vtkPixelArtPass", 2),
)

# the styles whose reduced frames keep their look: the bounds of their ink, reduced / full size
FIDELITY = {"sketch": (0.7, 1.5), "line art": (0.7, 5.0)}

for mesh in ("bunny", "head"):
    for name, class_name, factor in STYLES:
        label = "%s, %s" % (mesh, name)
        for plane in (False, True):
            window, ren = scene(mesh, plane)
            style = getattr(vtkstylize, class_name)()
            style.StageTimingOn()
            if plane:
                style.SetTranslucentLayers(0)
            k = factor or style.GetInteractiveImageReduction()
            style.SetInteractiveImageReduction(k)
            ren.SetPass(style)
            still, still_stages = frame(window, style, STILL)
            reduced, reduced_stages = frame(window, style, INTERACTIVE)
            after, _ = frame(window, style, STILL)
            style.SetInteractiveImageReduction(1)
            full, full_stages = frame(window, style, INTERACTIVE)
            if not plane:
                ren.GetActiveCamera().Azimuth(10)
                turned, _ = frame(window, style, INTERACTIVE)
            ren.SetPass(None)
            style.ReleaseGraphicsResources(window)
            window.Finalize()
            if name == "pixel art":
                check("UPSCALE" not in reduced_stages,
                      label + ": the pixel art declines the reduction (its art resolution)")
                break

            if plane:
                window, ren = scene(mesh, True, hide_mesh=True)
                ren.SetPass(style)
                style.SetInteractiveImageReduction(k)
                bare, _ = frame(window, style, INTERACTIVE)
                ren.SetPass(None)
                style.ReleaseGraphicsResources(window)
                window.Finalize()
                r_reduced, r_full, r_bare = red(reduced), red(full), red(bare)
                print("%-18s red plane pixels: reduced %d, full size %d, mesh hidden %d" % (
                    label, r_reduced, r_full, r_bare))
                check(r_full > 0.03 * W * H, label + ": the red plane shows at full size")
                check(r_full < r_bare - 0.03 * W * H, label + ": the mesh hides part of the plane")
                check(abs(r_reduced - r_full) <= 0.15 * r_full,
                      label + ": the reduced frame hides the plane where the mesh is, as the "
                      "full-size frame does")
                continue
            check(k > 1 and "UPSCALE" in reduced_stages,
                  label + ": an interactive frame at reduction %d is scaled up" % k)
            check("UPSCALE" not in full_stages, label + ": reduction 1 renders at full size")
            check("UPSCALE" not in still_stages, label + ": a still frame renders at full size")
            check(after == still, label + ": the still frame after reduced frames is unchanged")
            if name not in FIDELITY:
                continue
            full_ink = ink_mask(full)
            region = near(full_ink)
            reduced_ink, turned_ink = ink_mask(reduced), ink_mask(turned)
            placed, placed_turned = within(reduced_ink, region), within(turned_ink, region)
            amounts = ink_amount(reduced), ink_amount(full)
            ratio = amounts[0] / max(1e-9, amounts[1])
            print("%-18s k=%d ink within 2 px of the full frame's: reduced %.3f, turned 10 deg "
                  "%.3f; ink reduced / full %.0f / %.0f = %.2f" % (
                      label, k, placed, placed_turned, amounts[0], amounts[1], ratio))
            check(len(full_ink) > 100, label + ": the full-size frame has ink")
            check(placed >= 0.85 and placed > placed_turned,
                  label + ": the reduced frame's ink lies where the full-size frame's does")
            low, high = FIDELITY[name]
            check(low <= ratio <= high,
                  label + ": the reduced frame's strokes are scaled with the image")

if failures:
    print("%d failure(s)" % len(failures))
    sys.exit(1)
print("interactive_reduction: reduced interactive frames show the full-size picture, with depth")
