"""install.paraview_plugin: the installed pvbatch-stylize loads the plugin and renders a style.

    pvbatch-stylize check_load.py OUTPUT_PNG
"""
import sys

from paraview.simple import *  # noqa: F401,F403

view = CreateView("StylizeView")  # fails when the plugin did not load
view.ViewSize = [200, 150]
Show(Sphere(), view)
view.Style = 1
Render(view)
SaveScreenshot(sys.argv[1], view, ImageResolution=[200, 150])
print("plugin loaded from", [p for p in __import__("os").environ.get("PV_PLUGIN_PATH", "").split(":")][0])
Delete(view)
del view
