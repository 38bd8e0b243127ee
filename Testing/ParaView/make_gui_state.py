"""A ParaView state for paraview.gui_fresh_start (run_gui_fresh.sh): the Wavelet contour shown in a
Render View (Stylize), Style Comic, the view in the layout. Written by pvbatch, loaded by the GUI
with --state, so that the GUI runs no Python before the File menu's entries are used.

    pvbatch-stylize make_gui_state.py STATE.pvsm
"""
import sys

from paraview.simple import CreateLayout, CreateView, SaveState
from stylize_pv_scene import make_contour, make_view, show_framed

view = CreateView("StylizeView")
make_view(view, [640, 480])
show_framed(make_contour(), view)
view.Style = 1
CreateLayout().AssignView(0, view)
SaveState(sys.argv[1])
print("state written")
