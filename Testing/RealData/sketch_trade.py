#!/usr/bin/env python3
"""The sketch's speed trade: ms per frame and SSIM against the full-quality picture, per setting.

For each scene (the real-data set's bunny scan and the 969k-triangle wavelet isosurface of the
benchmark) it renders, offscreen at the given size with one headlight, VTK's plain frame,
vtkSSAOPass (the benchmark's settings) and the sketch pass at each setting below, in one run:
2 warm-up frames, then the median of N timed frames (each a 0.5 degree azimuth step, Render()
and a pixel read-back to finish it), and the still frame at the start view, compared by SSIM
with the full-quality setting's. It prints one table per scene: ms, added ms over plain, added
over SSAO's added, and SSIM. Times are this machine's (llvmpipe): compare them within a run.

usage: sketch_trade.py BUNNY.ply [--size WxH] [--frames N] [--scenes bunny,iso] [--out DIR]
"""
import argparse
import os
import statistics
import sys
import time

import vtk
from vtkstylize import vtkSketchPass
from vtkstylize_testing import vtkStylizeImageMetrics as M

# name: settings of vtkSketchPass over its defaults. "full" is the reference: the field at every
# pixel and the paper's 10 steps of 1.5 points; "before" is also the tone before issue 38.
SETTINGS = [
    ("full", {"FieldTexelSize": 1.0, "Steps": 10, "StepLength": 1.5}),
    ("before (issue 38)", {"FieldTexelSize": 1.0, "Steps": 10, "StepLength": 1.5,
                           "BrightThresholds": (0.8, 0.95)}),
    ("texel 2", {"FieldTexelSize": 2.0, "Steps": 10, "StepLength": 1.5}),
    ("texel 4", {"FieldTexelSize": 4.0, "Steps": 10, "StepLength": 1.5}),
    ("texel 6", {"FieldTexelSize": 6.0, "Steps": 10, "StepLength": 1.5}),
    ("texel 3, steps 6 x 2.5", {"FieldTexelSize": 3.0, "Steps": 6, "StepLength": 2.5}),
    ("texel 3, steps 4 x 3.75", {"FieldTexelSize": 3.0, "Steps": 4, "StepLength": 3.75}),
    ("texel 3, smoothing 1", {"FieldTexelSize": 3.0, "SmoothingIterations": 1}),
    ("texel 3, steps 1 (the final stage's floor)", {"FieldTexelSize": 3.0, "Steps": 1,
                                                  "StepLength": 15.0}),
    ("defaults (texel 3, steps 10 x 1.5)", {}),
]


def scene_mesh(name, bunny):
    if name == "bunny":
        reader = vtk.vtkPLYReader()
        reader.SetFileName(bunny)
        normals = vtk.vtkPolyDataNormals()
        normals.SetInputConnection(reader.GetOutputPort())
        normals.SplittingOff()
        normals.ConsistencyOn()
        normals.Update()
        return normals.GetOutput()
    wavelet = vtk.vtkRTAnalyticSource()
    wavelet.SetWholeExtent(-120, 120, -120, 120, -120, 120)
    contour = vtk.vtkContourFilter()
    contour.SetInputConnection(wavelet.GetOutputPort())
    contour.SetValue(0, 160.0)
    contour.ComputeNormalsOn()
    contour.ComputeScalarsOff()
    contour.Update()
    return contour.GetOutput()


def make_window(mesh, size):
    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)
    window.SetSize(*size)
    renderer = vtk.vtkRenderer()
    renderer.SetBackground(1, 1, 1)
    window.AddRenderer(renderer)
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputData(mesh)
    actor = vtk.vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetAmbient(0.1)
    actor.GetProperty().SetDiffuse(0.75)
    actor.GetProperty().SetSpecular(0.15)
    renderer.AddActor(actor)
    renderer.ResetCamera()
    camera = renderer.GetActiveCamera()
    camera.Azimuth(30)
    camera.Elevation(15)
    renderer.ResetCamera()
    renderer.ResetCameraClippingRange()
    return window, renderer


def capture(window):
    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.SetInputBufferTypeToRGB()
    grab.ReadFrontBufferOff()
    grab.Update()
    image = vtk.vtkImageData()
    image.DeepCopy(grab.GetOutput())
    return image


def time_frames(window, renderer, frames):
    camera = renderer.GetActiveCamera()
    for _ in range(2):
        window.Render()
    times = []
    for _ in range(frames):
        camera.Azimuth(0.5)
        start = time.perf_counter()
        window.Render()
        window.WaitForCompletion()  # glFinish
        times.append(1000.0 * (time.perf_counter() - start))
    camera.Azimuth(-0.5 * frames)
    window.Render()
    return statistics.median(times)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("bunny")
    parser.add_argument("--size", default="1920x1080")
    parser.add_argument("--frames", type=int, default=5)
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--scenes", default="bunny,iso")
    parser.add_argument("--out", default="")
    args = parser.parse_args()
    size = [int(v) for v in args.size.split("x")]
    for scene in args.scenes.split(","):
        mesh = scene_mesh(scene, args.bunny)
        rows = []
        window, renderer = make_window(mesh, size)
        ssao_pass = vtk.vtkSSAOPass()
        ssao_pass.SetDelegatePass(vtk.vtkRenderStepsPass())
        diagonal = mesh.GetLength()
        ssao_pass.SetRadius(0.1 * diagonal)
        ssao_pass.SetBias(0.001 * diagonal)
        ssao_pass.SetKernelSize(32)
        ssao_pass.BlurOff()
        passes = [("plain", None), ("ssao", ssao_pass)]
        for name, settings in SETTINGS:
            sketch = vtkSketchPass()
            for key, value in settings.items():
                values = value if isinstance(value, tuple) else (value,)
                getattr(sketch, "Set" + key)(*values)
            passes.append((name, sketch))
        # Rounds over all configurations (the median of each's frames over the rounds), so that
        # the machine's drift is spread over all of them.
        times = {name: [] for name, _ in passes}
        images = {}
        for _ in range(args.rounds):
            for name, render_pass in passes:
                renderer.SetPass(render_pass)
                times[name].append(time_frames(window, renderer, args.frames))
                if name not in images:
                    images[name] = capture(window)
        ms = {name: statistics.median(values) for name, values in times.items()}
        stages = {}
        for name, render_pass in passes[2:]:
            renderer.SetPass(render_pass)
            render_pass.StageTimingOn()
            window.Render()
            stages[name] = ", ".join("%s %.0f" % (
                render_pass.GetTimedStageName(k).replace("_STAGE", "").lower(),
                render_pass.GetTimedStageMilliseconds(k))
                for k in range(render_pass.GetNumberOfTimedStages()))
            render_pass.StageTimingOff()
        plain, ssao = ms["plain"], ms["ssao"]
        for name, _ in passes[2:]:
            ssim = M.SSIM(images["full"], images[name], 255.0)
            if args.out:
                os.makedirs(args.out, exist_ok=True)
                writer = vtk.vtkPNGWriter()
                writer.SetInputData(images[name])
                writer.SetFileName(os.path.join(args.out, "%s-%s.png" % (
                    scene, name.replace(" ", "").replace(",", "-"))))
                writer.Write()
            rows.append((name, ms[name], ssim, stages[name]))
        renderer.SetPass(None)
        print("\n%s, %dx%d: plain %.1f ms, ssao %.1f ms (added %.1f)\n" % (
            scene, size[0], size[1], plain, ssao, ssao - plain))
        print("| setting | ms | added | added / ssao added | SSIM to full | stages (ms, one frame) |")
        print("| --- | ---: | ---: | ---: | ---: | --- |")
        for name, ms, ssim, stage in rows:
            print("| %s | %.1f | %.1f | %.2f | %.4f | %s |" % (
                name, ms, ms - plain, (ms - plain) / max(ssao - plain, 1e-9), ssim, stage))
        sys.stdout.flush()
        window.Finalize()
    return 0


if __name__ == "__main__":
    sys.exit(main())
