"""Renders a CT volume in the stylized view (ParaView's Volume representation), for
test_volumes.py, on one rank or split across several.

    mpiexec -n N pvbatch-stylize render_volume.py OUTPUT_PREFIX DATA_DIR

The real-data set's skull.vti (a CT of a skull) read by ParaView's XML image reader, which reads
one piece of the extent per rank, shown as a Volume with the transfer functions of
realdata.volumes' skull (Testing/RealData/volumes.py), 400x300. Writes OUTPUT_PREFIX-<name>.png:
  vtk     Style None: the volume as ParaView draws it
  bare    Style None without the volume (the volume's region is where the two differ)
  white, black   the volume alone as ParaView draws it over white and over black (its opacity)
  comic, pixel, sketch, lines   each style at its defaults (pixel art: Palette 16; VolumeHaze 1,
          HAZE_FOG: VTK's fog, on 2 ranks sampled on the pieces gathered)
  haze    the comic with VolumeHaze 0.5 in HAZE_SHELL (the tissue below the opacity threshold as
          a translucent surface)
  solid, solid-lines   the comic and the line art with VolumeHaze 0 (the solid part alone)
  plain-comic, plain-lines   the comic and the line art with the display's StylizeVolume off
          (the volume left to ParaView); restyled: the comic with it on again
  sphere-vtk, sphere-plain-comic, sphere-plain-lines   an opaque sphere inside the skull, partly
          behind its bone: Style None, and the comic and the line art with StylizeVolume off;
          sphere-alone: the sphere without the volume (Style None)
  top-vtk, top-plain-lines   seen from above, across the cut between the pieces: Style None,
          and the line art with StylizeVolume off
  grid-<style>   the data axes grid on: vtk (Style None) and each style
  disk-<style>   ParaView's disk_out_ref simulation, an unstructured volume redistributed over
                 the ranks, seen across the cut between their pieces: vtk and each style
  disk-streams-<style>   the same with streamlines of its flow running down into the hot dome
                 (dark lines inside the volume's material): vtk, comic and lines
and prints "pieces K" and "disk pieces K" (how many ranks hold part of each volume).
"""
import sys

import paraview.simple as simple
from paraview.simple import (ColorBy, CreateView, ExodusIIReader, GetColorTransferFunction,
                             GetOpacityTransferFunction, Hide, MergeBlocks, RedistributeDataSet,
                             Render, SaveScreenshot, Show, Sphere, StreamTracer,
                             XMLImageDataReader)
from stylize_pv_scene import make_view

prefix, data = sys.argv[1], sys.argv[2]
SIZE = [400, 300]
view = CreateView("StylizeView")
make_view(view, SIZE)
reader = XMLImageDataReader(FileName=[data + "/skull.vti"])
reader.UpdatePipeline()
name = reader.PointData.keys()[0]
display = Show(reader, view)
display.SetRepresentationType("Volume")
ColorBy(display, ("POINTS", name))
lut = GetColorTransferFunction(name)
lut.AutomaticRescaleRangeMode = "Never"
lut.RGBPoints = [0.0, 0.2, 0.1, 0.05, 1.5, 0.9, 0.5, 0.4, 3.0, 1.0, 0.95, 0.85, 5.5, 1.0, 1.0, 1.0]
opacity = GetOpacityTransferFunction(name)
opacity.Points = [0.0, 0.0, 0.5, 0.0, 1.0, 0.0, 0.5, 0.0, 2.0, 0.05, 0.5, 0.0,
                  2.9, 0.6, 0.5, 0.0, 5.5, 0.9, 0.5, 0.0]
display.Shade = 1
# how many ranks read part of the volume
ids = (getattr(simple, "GenerateProcessIds", None) or simple.ProcessIdScalars)(Input=reader)
ids.UpdatePipeline()
array = ids.PointData.GetArray("ProcessId")
low, high = array.GetRange() if array else (0, 0)
print("pieces %d" % (int(high - low) + 1))
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraPosition = [0.0, -1.0, 0.15]
view.CameraViewUp = [0.0, 0.0, 1.0]
view.ResetCamera()
view.GetActiveCamera().Dolly(1.5)  # (the skull fills most of the view's height)


def shot(label):
    Render(view)
    SaveScreenshot("%s-%s.png" % (prefix, label), view, ImageResolution=SIZE)


def plain_shots(shown, shots):
    """The (style, label) shots with the display `shown` left to ParaView (StylizeVolume off)."""
    shown.StylizeVolume = 0
    for style, label in shots:
        view.Style = style
        shot(label)
    shown.StylizeVolume = 1


view.PixelArtPalette = 2
for style, label in enumerate(["vtk", "comic", "pixel", "sketch", "lines"]):
    view.Style = style
    shot(label)
view.Style = 1
view.ComicVolumeHaze = 0.5
view.ComicVolumeHazeMode = 0  # (the shell)
shot("haze")
view.ComicVolumeHaze = 0.0
view.ComicVolumeHazeMode = 1
shot("solid")
view.ComicVolumeHaze = 1.0
view.Style = 4
view.LineArtVolumeHaze = 0.0
shot("solid-lines")
view.LineArtVolumeHaze = 1.0
# The volume left to ParaView (the display's StylizeVolume off) in the comic and the line art,
# then stylized again; then with an opaque sphere inside the skull, partly behind its bone.
plain_shots(display, ((1, "plain-comic"), (4, "plain-lines")))
view.Style = 1
shot("restyled")
box = reader.GetDataInformation().GetBounds()
sphere = Sphere(Center=[0.75 * box[0] + 0.25 * box[1], 0.55 * box[2] + 0.45 * box[3],
                        0.5 * (box[4] + box[5])],
                Radius=0.2 * (box[1] - box[0]), ThetaResolution=48, PhiResolution=48)
sphere_display = Show(sphere, view)
sphere_display.ColorArrayName = ["POINTS", ""]
sphere_display.AmbientColor = sphere_display.DiffuseColor = [0.2, 0.4, 0.9]
view.Style = 0
shot("sphere-vtk")
plain_shots(display, ((1, "sphere-plain-comic"), (4, "sphere-plain-lines")))
display.Visibility = 0
view.Style = 0
shot("sphere-alone")
display.Visibility = 1
Hide(sphere, view)
view.Style = 0
background = list(view.Background)
for label, color in (("white", [1.0, 1.0, 1.0]), ("black", [0.0, 0.0, 0.0])):
    view.Background = color
    shot(label)
view.Background = background
# the data axes grid, plain (Style None) and in each style, and the plain picture without it
display.DataAxesGrid.GridAxesVisibility = 1
for style, label in enumerate(["vtk", "comic", "pixel", "sketch", "lines"]):
    view.Style = style
    shot("grid-" + label)
display.DataAxesGrid.GridAxesVisibility = 0
# Seen from above, across the cut between the ranks' pieces (the volume is read in slabs along
# z): ParaView's picture, and the line art with the volume left to ParaView.
camera = [list(view.CameraPosition), list(view.CameraFocalPoint), list(view.CameraViewUp)]
view.CameraPosition = [0.5 * (box[0] + box[1]), 0.5 * (box[2] + box[3]), 4.0 * box[5]]
view.CameraFocalPoint = [0.5 * (box[0] + box[1]), 0.5 * (box[2] + box[3]), 0.5 * box[5]]
view.CameraViewUp = [0.0, 1.0, 0.0]
view.ResetCamera()
view.Style = 0
shot("top-vtk")
plain_shots(display, ((4, "top-plain-lines"),))
view.CameraPosition, view.CameraFocalPoint, view.CameraViewUp = camera
view.Style = 0
display.Visibility = 0
shot("bare")

# An unstructured volume split over the ranks: ParaView's tutorial simulation disk_out_ref.ex2,
# its blocks merged and redistributed (RedistributeDataSet), shown as a Volume by the
# temperature (the ramp of realdata.volumes' disk scene), seen across the cut between the ranks'
# pieces; its surface must not be closed along that cut.
disk = ExodusIIReader(FileName=[data + "/disk_out_ref.ex2"])
disk.PointVariables = ["Temp", "V"]
split = RedistributeDataSet(Input=MergeBlocks(Input=disk))
split.UpdatePipeline()
disk_display = Show(split, view)
disk_display.SetRepresentationType("Volume")
ColorBy(disk_display, ("POINTS", "Temp"))
temp = GetColorTransferFunction("Temp")
temp.AutomaticRescaleRangeMode = "Never"
low, high = 293.15, 913.15
temp.RGBPoints = [low, 1.0, 0.9, 0.5, high, 0.8, 0.2, 0.0]
GetOpacityTransferFunction("Temp").Points = [low, 0.0, 0.5, 0.0, low + 0.4 * (high - low), 0.0,
                                             0.5, 0.0, high, 0.8, 0.5, 0.0]
ids = (getattr(simple, "GenerateProcessIds", None) or simple.ProcessIdScalars)(Input=split)
ids.UpdatePipeline()
array = ids.PointData.GetArray("ProcessId")
low_id, high_id = array.GetRange() if array else (0, 0)
print("disk pieces %d" % (int(high_id - low_id) + 1))
Render(view)
view.CameraFocalPoint = [0.0, 0.0, 1.5]
view.CameraPosition = [3.0, 14.0, 6.0]  # (the cut, x = 0, crosses the view from top to bottom)
view.CameraViewUp = [0.0, 0.0, 1.0]
for style, label in enumerate(["vtk", "comic", "pixel", "sketch", "lines"]):
    view.Style = style
    shot("disk-" + label)
# left to ParaView: on 2 ranks the pieces of a k-d split composited in visibility order
plain_shots(disk_display, ((4, "disk-plain-lines"),))
# Streamlines of the flow (opaque dark lines) running down into the hot dome, inside the volume's
# material; disk-streams-<style> for vtk, comic and lines.
streams = StreamTracer(Input=split, SeedType="Point Cloud")
streams.Vectors = ["POINTS", "V"]
streams.SeedType.Center = [0.0, 0.0, 0.5]
streams.SeedType.Radius = 4.0
streams.SeedType.NumberOfPoints = 60
streams.MaximumStreamlineLength = 20.0
streams_display = Show(streams, view)
streams_display.ColorArrayName = ["POINTS", ""]
streams_display.AmbientColor = streams_display.DiffuseColor = [0.1, 0.3, 0.1]
streams_display.LineWidth = 2.0
for style, label in ((0, "vtk"), (1, "comic"), (4, "lines")):
    view.Style = style
    shot("disk-streams-" + label)
print("rendered")
