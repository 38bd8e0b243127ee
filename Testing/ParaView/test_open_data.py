"""paraview.open_data: which reader ParaView picks for a file with the plugin loaded (issue 52).

    pvbatch-stylize test_open_data.py DATA_DIR

With the plugin, paraview.simple.OpenDataFile (ParaView's reader factory, as File > Open and
drag-and-drop use it) must give a PLY file stored as triangle strips to the Stylize Checked
Reader, which reads its cells (ParaView's own PLY Reader reads such a file with no cells), and
every other file to ParaView's own reader as before; File > Open's file types must list the
checked reader (its PLY entry apart from the rest).
"""
import os
import sys

from paraview import servermanager
from paraview.simple import OpenDataFile, StylizeCheckedReader

data = sys.argv[1]
failures = []


def check(condition, message):
    print(("ok   " if condition else "FAIL ") + message, flush=True)
    if not condition:
        failures.append(message)


def opened(name):
    reader = OpenDataFile(os.path.join(data, name))
    reader.UpdatePipeline()
    return reader.GetXMLName(), reader.GetDataInformation().GetNumberOfCells()


for name in ("strips.ply", "strips_binary.ply"):
    explicit = StylizeCheckedReader(FileName=os.path.join(data, name))
    explicit.UpdatePipeline()
    expected = explicit.GetDataInformation().GetNumberOfCells()
    reader, cells = opened(name)
    check(reader == "StylizeCheckedReader" and cells == expected and cells > 0,
          "%s (triangle strips): %s, %d cells (the checked reader reads %d)" % (
              name, reader, cells, expected))
# ParaView's readers for everything else (the checked reader declines them)
for name, expected in (("sphere.ply", "PLYReader"), ("colored.ply", "PLYReader"),
                       ("hexes.vtu", "XMLUnstructuredGridReader"),
                       ("sphere.vtp", "XMLPolyDataReader"), ("sphere_binary.stl", "stlreader"),
                       ("sphere.obj", "objreader"), ("mesh.ex2", "IOSSReader"),
                       ("wavelet.vti", "XMLImageDataReader")):
    reader, cells = opened(name)
    check(reader == expected and cells > 0, "%s: %s, %d cells (%s expected)" % (
        name, reader, cells, expected))
factory = servermanager.vtkSMProxyManager.GetProxyManager().GetReaderFactory()
types = factory.GetSupportedFileTypes(servermanager.ActiveConnection.Session).split(";;")
stylize = [t for t in types if t.startswith("Stylize Checked Reader")]
check(len(stylize) == 2 and stylize[0].endswith("(*.ply)") and "*.vtu" in stylize[1],
      "File > Open's file types: %s" % stylize)
for f in failures:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
