#!/usr/bin/env python3
"""Axes and 3D text stay readable in every style (issue 55, PlainAnnotations).

A sphere inside vtkCubeAxesActor (ticks, labels and titles: polygonal 3D text) and a
vtkTextActor3D, at 480x360. The annotations' pixels are those of VTK's picture of the axes and
the text alone; each style must draw ink (a pixel away from the white paper) within 1 px of at
least 95% of them, and where the sphere covers none of them, leave them as VTK draws them for at
least 90% (they are drawn by VTK over the stylized picture). With PlainAnnotations off the line
art loses its labels (printed, not held: the measure's contrast). Depth still hides them: the
part of the axes behind the sphere is not drawn by the pixel art either (it writes its depth for
them).
"""
import sys

import numpy as np
import vtk
from stylize_png import near, window_array
from vtkstylize import vtkComicPass, vtkLineArtPass, vtkPixelArtPass, vtkSketchPass

SIZE = (480, 360)
STYLES = {"comic": vtkComicPass, "pixel": vtkPixelArtPass, "sketch": vtkSketchPass,
          "lines": vtkLineArtPass}


def picture(style=None, sphere=True, annotations=True, plain=True):
    renderer = vtk.vtkRenderer()
    renderer.SetBackground(1, 1, 1)
    if sphere:
        source = vtk.vtkSphereSource()
        source.SetRadius(0.6)
        source.SetThetaResolution(48)
        source.SetPhiResolution(48)
        mapper = vtk.vtkPolyDataMapper()
        mapper.SetInputConnection(source.GetOutputPort())
        actor = vtk.vtkActor()
        actor.SetMapper(mapper)
        renderer.AddActor(actor)
    if annotations:
        axes = vtk.vtkCubeAxesActor()
        axes.SetBounds(-1, 1, -1, 1, -1, 1)
        axes.SetCamera(renderer.GetActiveCamera())
        for i in range(3):
            axes.GetTitleTextProperty(i).SetColor(0, 0, 0)
            axes.GetLabelTextProperty(i).SetColor(0, 0, 0)
        for p in (axes.GetXAxesLinesProperty(), axes.GetYAxesLinesProperty(),
                  axes.GetZAxesLinesProperty()):
            p.SetColor(0, 0, 0)
        renderer.AddViewProp(axes)
        text = vtk.vtkTextActor3D()
        text.SetInput("label")
        text.GetTextProperty().SetColor(0, 0, 0)
        text.GetTextProperty().SetFontSize(48)
        text.SetScale(0.01)
        text.SetPosition(-0.9, 0.75, 1.0)
        renderer.AddViewProp(text)
    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)
    window.SetSize(*SIZE)
    window.AddRenderer(renderer)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(3.5, 2.5, 5.0)
    camera.SetFocalPoint(0, 0, 0)
    camera.SetViewUp(0, 1, 0)
    renderer.ResetCamera()
    if style:
        p = STYLES[style]()
        p.SetPlainAnnotations(plain)
        renderer.SetPass(p)
    window.Render()
    return window_array(window)


def ink(pixels):
    return np.abs(pixels.astype(int) - 255).sum(axis=2) > 24


def main():
    alone = picture(sphere=False)
    marks = ink(alone)
    sphere = ink(picture(annotations=False))
    vtk_full = picture()
    free = marks & ~near(sphere, 2)  # annotation pixels away from the sphere
    failures = 0
    for style in STYLES:
        styled = picture(style)
        covered = float(np.mean(near(ink(styled), 1)[marks & ~sphere]))
        same = float(np.mean(np.all(styled[free] == vtk_full[free], axis=1)))
        off = picture(style, plain=False)
        covered_off = float(np.mean(near(ink(off), 1)[marks & ~sphere]))
        print("%-6s annotations covered %.3f, as VTK draws them %.3f; PlainAnnotations off: "
              "covered %.3f" % (style, covered, same, covered_off))
        if covered < 0.95 or same < 0.9:
            print("FAIL: %s leaves the annotations unreadable" % style)
            failures += 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
