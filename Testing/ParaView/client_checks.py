"""What a pvpython client sees of the plugin on a server (run by paraview.client_server).

    pvpython client_checks.py HOST:PORT both|server-only|client-only

both: pvpython-stylize against pvserver-stylize. The server lists VTKStylize as loaded (so
LoadDistributedPlugin finds it), LoadDistributedPlugin("VTKStylize", remote=False) succeeds,
the view renders a style, and the Stylize Checked Reader reads a file on the server (through
its helper program there). server-only: a pvpython without the plugin against
pvserver-stylize; client-only: pvpython-stylize against a pvserver without it. In both, creating
the view must raise an error that the script can catch (no abort), and a render view still works.
Prints "checks passed" at the end.
"""
import sys

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager

host, port = sys.argv[1].rsplit(":", 1)
mode = sys.argv[2]
Connect(host, int(port))
connection = servermanager.ActiveConnection
manager = servermanager.vtkSMProxyManager.GetProxyManager().GetPluginManager()


def plugin_state(info):
    for i in range(info.GetNumberOfPlugins()):
        if info.GetPluginName(i) == "VTKStylize":
            return "loaded" if info.GetPluginLoaded(i) else "listed"
    return "absent"


server = plugin_state(manager.GetRemoteInformation(connection.Session))
client = plugin_state(manager.GetLocalInformation())
print("plugin on the server: %s, on the client: %s" % (server, client))
expected = {"both": ("loaded", "loaded"), "server-only": ("loaded", "absent"),
            "client-only": ("absent", "loaded")}[mode]
if (server, client) != expected:
    sys.exit("FAIL: expected server %s, client %s" % expected)

if mode == "both":
    LoadDistributedPlugin("VTKStylize", remote=False, ns=globals())
    view = CreateView("StylizeView")
    view.ViewSize = [200, 150]
    view.Style = 1
    Show(Sphere(), view)
    Render(view)
    print("rendered the comic style")
    # The checked reader on the server: its helper (vtkstylize-read) reads there and the data
    # arrives as the file holds it.
    import os
    import tempfile
    from vtkmodules.vtkFiltersSources import vtkSphereSource
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
    sphere = vtkSphereSource()
    sphere.SetThetaResolution(20)
    sphere.SetPhiResolution(12)
    writer = vtkXMLPolyDataWriter()
    path = os.path.join(tempfile.mkdtemp(), "sphere.vtp")
    writer.SetFileName(path)
    writer.SetInputConnection(sphere.GetOutputPort())
    writer.Write()
    sphere.Update()
    reader = StylizeCheckedReader(FileName=path)
    reader.UpdatePipeline()
    cells = reader.GetDataInformation().GetNumberOfCells()
    print("the checked reader on the server: %d cells (the file: %d)"
          % (cells, sphere.GetOutput().GetNumberOfCells()))
    if cells != sphere.GetOutput().GetNumberOfCells():
        sys.exit("FAIL: the checked reader gave %d cells" % cells)
    os.remove(path)
    os.rmdir(os.path.dirname(path))
else:
    try:
        CreateView("StylizeView")
    except RuntimeError as error:
        print("CreateView refused: %s" % (error,))
    else:
        sys.exit("FAIL: the view was created although one side lacks the plugin")
    view = CreateView("RenderView")
    Show(Sphere(), view)
    Render(view)
    print("a render view still works")
print("checks passed")
