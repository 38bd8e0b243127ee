"""The ParaView GUI's startup script for paraview_gui_drags.sh (not run directly).

Shows STYLIZE_MESH in a Render View (Stylize) with style STYLIZE_STYLE (1 comic ... 4 line art)
in place of the default view, keeps ParaView's timer log at full length, and every 0.3 s runs
the Python file STYLIZE_COMMAND if it exists (then removes it), so that the driver can ask for
the timer log once its mouse drags are done (timer_log(PATH))."""
import os

from paraview.benchmark import logbase
from paraview.simple import (AssignViewToLayout, CreateView, Delete, GetActiveView, GetLayout,
                             OpenDataFile, Render, SetActiveView, Show)

logbase.maximize_logs()
old = GetActiveView()
if old is not None:
    Delete(old)
view = CreateView("StylizeView")
AssignViewToLayout(view=view, layout=GetLayout(), hint=0)
SetActiveView(view)
Show(OpenDataFile(os.environ["STYLIZE_MESH"]), view)
view.ResetCamera()
view.Style = int(os.environ["STYLIZE_STYLE"])
if os.environ.get("STYLIZE_LOD_THRESHOLD"):
    view.LODThreshold = float(os.environ["STYLIZE_LOD_THRESHOLD"])
Render(view)


def timer_log(path):
    """Writes the client's timer log (builtin: the one process's) to path."""
    logbase.get_logs()
    with open(path + ".tmp", "w") as f:
        f.write(logbase.logs[0].toString(True) if logbase.logs else "")
    os.replace(path + ".tmp", path)


def _run_command(caller, event):
    command = os.environ["STYLIZE_COMMAND"]
    if os.path.exists(command):
        code = open(command).read()
        os.remove(command)
        exec(code, globals())


_interactor = view.GetRenderWindow().GetInteractor()
_interactor.AddObserver("TimerEvent", _run_command)
_interactor.CreateRepeatingTimer(300)
