"""The pixel art's output blit writes what its upsample stage writes (issue 41).

    test_pixel_blit.py DATA_DIR

Where every screen pixel shows its art pixel's colour, vtkPixelArtPass writes the screen with a
nearest-neighbour blit of the art stage's output colours instead of a full-size stage. On the
bunny scan and the fandisk CAD part, at an odd size (643x401: clipped art pixels at the edges),
FAST and FAITHFUL, 4 and 7 px art pixels, the blit's picture (DepthOutput AUTO, single-sampled)
must equal, pixel for pixel, the upsample stage's (DepthOutput ALWAYS, which needs the stage),
and the stage timing must name the path each took: "output blit" in the first, the upsample
stage in the second and under a multisampled window (where a blit cannot write).
"""
import sys

import vtkstylize
from stylize_test_scene import check as record, failures, mesh_window, ply_mesh
from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter

data = sys.argv[1]


def check(condition, message):
    if record(condition, message):
        print("ok  ", message)


def frame(window, ren, pass_):
    """The window's pixels after a render with `pass_`, and the stages that ran."""
    pass_.StageTimingOn()
    ren.SetPass(pass_)
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    scalars = grab.GetOutput().GetPointData().GetScalars()
    pixels = [scalars.GetValue(i) for i in range(scalars.GetNumberOfValues())]
    stages = [pass_.GetTimedStageName(i) for i in range(pass_.GetNumberOfTimedStages())]
    pass_.ReleaseGraphicsResources(window)
    ren.SetPass(None)
    return pixels, stages


def scene(mesh, samples):
    """The real-data mesh in a 643x401 offscreen window with `samples` multisamples."""
    window, ren, _ = mesh_window(ply_mesh(data, mesh), (0.9, 0.55, 0.3), (0.32, 0.34, 0.43),
                                 643, 401, 30, 15)
    window.SetMultiSamples(samples)
    return window, ren


def pixel_art(mode, size, depth):
    p = vtkstylize.vtkPixelArtPass()
    p.SetMode(mode)
    p.SetPixelSize(size)
    p.SetDepthOutput(depth)
    return p


FAST, FAITHFUL = 0, 1
AUTO, ALWAYS = 0, 1
for mesh in ("bunny", "fandisk"):
    window, ren = scene(mesh, 0)
    for mode in (FAST, FAITHFUL):
        for size in (4, 7):
            name = "%s %s %d px" % (mesh, "FAST" if mode == FAST else "FAITHFUL", size)
            blit, blit_stages = frame(window, ren, pixel_art(mode, size, AUTO))
            stage, stage_stages = frame(window, ren, pixel_art(mode, size, ALWAYS))
            check("output blit" in blit_stages and "PIXEL_STAGE_UPSAMPLE" not in blit_stages,
                  "%s: the blit writes the screen (%s)" % (name, blit_stages))
            check("PIXEL_STAGE_UPSAMPLE" in stage_stages,
                  "%s: with the depth, the upsample stage does" % name)
            differing = sum(1 for i in range(0, len(blit), 3) if blit[i:i + 3] != stage[i:i + 3])
            colours = len(set(tuple(blit[i:i + 3]) for i in range(0, len(blit), 3 * 7)))
            check(differing == 0 and colours > 3, "%s: blit and stage give the same picture "
                  "(%d of %d pixels differ; %d colours)" % (name, differing, len(blit) // 3,
                                                            colours))
    ren.SetPass(None)
    del window
    window, ren = scene(mesh, 4)
    _, stages = frame(window, ren, pixel_art(FAITHFUL, 4, AUTO))
    check("PIXEL_STAGE_UPSAMPLE" in stages and "output blit" not in stages,
          "%s: a multisampled window takes the upsample stage (%s)" % (mesh, stages))
    del window

print("%d failures" % len(failures))
sys.exit(1 if failures else 0)
