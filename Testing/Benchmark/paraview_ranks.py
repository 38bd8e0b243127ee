"""ParaView on 1 rank against 2 (issue 54): the line art's first frame of a large mesh, each rank
holding part of it, and the picture.

    mpiexec -n N pvbatch-stylize paraview_ranks.py MESH.ply OUTPUT_PREFIX [WxH]

The mesh is read by the plugin's Stylize Checked Reader, split by Redistribute DataSet with a
layer of ghost cells and shown through Extract Surface in the stylized view (as a ParaView user
would). Prints, from rank 0, one line "seconds STEP S" per step: "split" (reading and
redistributing), "comic" (a still comic frame, the reference), "lines first" (the line art's
first frame: its lines and curvature found on every rank), "lines after camera" (a frame after
the camera turned 5 degrees); writes OUTPUT_PREFIX-lines.png. The 1-rank and 2-rank pictures,
as paraview.mpi measures them (SSIM, share of pixels more than 16 levels apart):

    python3 paraview_ranks.py --compare ONE-lines.png TWO-lines.png   (vtkstylize_testing on
    PYTHONPATH)
"""
import sys
import time


def main():
    import paraview.simple as simple
    from paraview.simple import CreateView, ExtractSurface, Render, SaveScreenshot, Show
    import stylize_paraview  # noqa: F401 (the plugin's proxies)

    mesh, prefix = sys.argv[1], sys.argv[2]
    size = [int(v) for v in (sys.argv[3] if len(sys.argv) > 3 else "1280x720").split("x")]
    controller = simple.servermanager.vtkProcessModule.GetProcessModule().GetGlobalController()
    rank = controller.GetLocalProcessId() if controller else 0

    def report(step, seconds):
        if rank == 0:
            print("seconds %s %.2f" % (step, seconds), flush=True)

    view = CreateView("StylizeView")
    view.ViewSize = size
    view.OrientationAxesVisibility = 0
    start = time.perf_counter()
    parts = simple.RedistributeDataSet(Input=simple.StylizeCheckedReader(FileName=mesh))
    parts = simple.GhostCellsGenerator(Input=parts)
    parts.BuildIfRequired = 0
    surface = ExtractSurface(Input=parts)
    surface.UpdatePipeline()
    report("split", time.perf_counter() - start)
    display = Show(surface, view)
    display.ColorArrayName = ["POINTS", ""]
    view.CameraPosition = [0.0, 0.0, 1.0]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.ResetCamera()
    view.Style = 1
    Render(view)  # (the geometry uploaded once, outside the timing)
    start = time.perf_counter()
    Render(view)
    report("comic", time.perf_counter() - start)
    view.Style = 4
    start = time.perf_counter()
    Render(view)
    report("lines first", time.perf_counter() - start)
    SaveScreenshot(prefix + "-lines.png", view, ImageResolution=size)
    camera = simple.GetActiveCamera()
    camera.Azimuth(5.0)
    start = time.perf_counter()
    Render(view)
    report("lines after camera", time.perf_counter() - start)


def compare_ranks(one, two):
    """SSIM and the share of pixels more than 16 levels apart of two PNGs (paraview.mpi's
    measure: at least 0.99 and at most 0.005 for equal pictures)."""
    from vtkstylize_testing import vtkStylizeImageMetrics as M
    from vtkmodules.vtkIOImage import vtkPNGReader
    images = []
    for path in (one, two):
        reader = vtkPNGReader()
        reader.SetFileName(path)
        reader.Update()
        images.append(reader.GetOutput())
    dims = images[0].GetDimensions()
    far = M.CountDifferences(images[0], images[1], 16.0)
    return M.SSIM(images[0], images[1], 255.0), far / float(dims[0] * dims[1])


if __name__ == "__main__":
    if sys.argv[1:2] == ["--compare"]:
        print("SSIM %.4f, pixels beyond 16 levels %.4f" % compare_ranks(sys.argv[2], sys.argv[3]))
    else:
        main()
