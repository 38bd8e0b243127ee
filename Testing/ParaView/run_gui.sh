#!/bin/sh
# paraview.gui: runs the ParaView GUI (Qt) with the VTK Stylize plugin, non-interactively.
#
#   run_gui.sh PARAVIEW_STYLIZE OUTPUT_DIR [TIMEOUT_SECONDS]
#
# PARAVIEW_STYLIZE is the paraview-stylize wrapper (it sets PV_PLUGIN_PATH, so the plugin
# autoloads); DISPLAY must name an X server (Xvfb). The GUI runs test_gui.py as its startup
# script (--script), then plays the QtTesting events written below (--test-script) and quits
# (--exit; a failed event makes it exit 1). The events type "comic" into the properties panel's
# search box, check that the panel's Style widget reads Comic and the representation toolbar
# reads Stylized Surface, widen the panel, use File > Export Stylized Figure... and File > Save
# Stylized Orbit... (the file dialogs and the orbit's option dialog) and call
# test_gui.check_exports() (the files they wrote) and test_gui.capture_window() (the whole window)
# from the Python shell. The test passes when paraview exits 0 and OUTPUT_DIR/gui-result.txt says
# PASS with no failed line.
#
# Why --dr: without it ParaView reads the user's settings and, 1 s after the window shows, opens
# the modal "Welcome to ParaView" dialog; the first script call that processes Qt events (e.g.
# assigning a view to the layout) then runs that dialog's event loop and the script never
# returns. --dr (disable registry) skips the settings and the dialog. HOME and the XDG folders
# point to a fresh temporary folder as well, so nothing of the user's can interfere.
# -geometry is Qt's: the main window is 1280x800 at the screen's top-left corner.
set -u
paraview=${1:?usage: run_gui.sh PARAVIEW_STYLIZE OUTPUT_DIR [TIMEOUT_SECONDS]}
out=${2:?usage: run_gui.sh PARAVIEW_STYLIZE OUTPUT_DIR [TIMEOUT_SECONDS]}
limit=${3:-240}
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out" || exit 1
out=$(cd "$out" && pwd)
if [ -z "${DISPLAY:-}" ]; then
  echo "run_gui.sh: DISPLAY is not set (start Xvfb, e.g. Xvfb :95 &, and export DISPLAY=:95)" >&2
  exit 1
fi

. "$here/gui_profile.sh"
STYLIZE_GUI_OUT="$out"
export STYLIZE_GUI_OUT
# test_gui.py imports stylize_pv_scene from this folder (a --script does not put its own folder
# on Python's path); after the wrapper's entries, so that ParaView's modules come first
PYTHONPATH="${PYTHONPATH:+$PYTHONPATH:}$here"
export PYTHONPATH
rm -f "$out/gui-result.txt" "$out/gui-window.png" "$out/gui-comic.png" "$out/gui-none.png" \
  "$out/gui-figure.svg" "$out"/gui-orbit-*.png "$out/gui-orbit.gif" "$out/gui-orbit-dialog.png" "$out/gui-refused.svg"

panel=pqClientMainWindow/propertiesDock/propertiesPanel
sections=$panel/scrollArea/qt_scrollarea_viewport/scrollAreaWidgetContents
view_panel=$sections/ViewFrame/ProxyPanel
menu=pqClientMainWindow/menubar/menu_File
orbit=pqClientMainWindow/StylizeOrbitDialog
shell=pqClientMainWindow/pythonShellDock/pythonShell/consoleWidget

# click OBJECT: QtTesting events that click OBJECT's left button at (20, 10).
click() {
  cat <<EOF
  <pqevent object="$1" command="mousePress" arguments="1,1,0,20,10" />
  <pqevent object="$1" command="mouseRelease" arguments="1,0,0,20,10" />
EOF
}

# drag X Y X1 Y1 X2 Y2: QtTesting events that press the left button on the main window at
# (X, Y), move it through (X1, Y1) to (X2, Y2) and release it there.
drag() {
  cat <<EOF
  <pqevent object="pqClientMainWindow" command="mousePress" arguments="1,1,0,$1,$2" />
  <pqevent object="pqClientMainWindow" command="mouseMove" arguments="1,1,0,$3,$4" />
  <pqevent object="pqClientMainWindow" command="mouseMove" arguments="1,1,0,$5,$6" />
  <pqevent object="pqClientMainWindow" command="mouseRelease" arguments="1,0,0,$5,$6" />
EOF
}

cat > "$tmp/events.xml" <<EOF
<?xml version="1.0" ?>
<pqevents>
  <pqevent object="pqClientMainWindow" command="process_events" arguments="200" />
  <pqevent object="$panel/SearchBox/SearchLineEdit" command="set_string" arguments="comic" />
  <pqevent object="pqClientMainWindow" command="process_events" arguments="200" />
  <pqcheck object="$view_panel/Style/ComboBox" property="currentText" arguments="Comic" />
  <pqcheck object="$view_panel/ComicEdgeWidth" property="visible" arguments="true" />
  <pqcheck object="pqClientMainWindow/representationToolbar/displayRepresentation/comboBox"
      property="currentText" arguments="Stylized Surface" />
  <!-- for the screenshot: collapse the source's and the display's sections, widen the left
       dock area and shorten the pipeline browser (drag the dock separators) -->
$(click "$sections/PropertiesButtons/PropertiesButton")
$(click "$sections/DisplayButtons/DisplayButton")
$(drag 295 600 380 600 440 600)
$(drag 200 364 200 300 200 250)
  <pqevent object="pqClientMainWindow" command="process_events" arguments="300" />
  <!-- File > Export Stylized Figure... and File > Save Stylized Orbit... (its option dialog:
       3 frames over 30 degrees at 5 frames per second, patterns not anchored) -->
  <pqevent object="$menu" command="activate" arguments="actionStylizeExportFigure" />
  <pqevent object="pqClientMainWindow/StylizeFigureFileDialog" command="filesSelected"
      arguments="$out/gui-figure.svg" />
  <pqevent object="$menu" command="activate" arguments="actionStylizeSaveOrbit" />
  <pqevent object="pqClientMainWindow/StylizeOrbitFileDialog" command="filesSelected"
      arguments="$out/gui-orbit.gif" />
  <pqevent object="$orbit/frames" command="set_int" arguments="3" />
  <pqevent object="$orbit/degrees" command="set_double" arguments="30" />
  <pqevent object="$orbit/fps" command="set_int" arguments="5" />
  <pqevent object="$orbit/surface_anchor" command="set_boolean" arguments="false" />
  <pqevent object="pqClientMainWindow" command="process_events" arguments="200" />
  <pqevent object="pqClientMainWindow/pythonShellDock/pythonShell/consoleWidget" command="executeCommand"
      arguments="import __main__; __main__.capture_window('gui-orbit-dialog.png')" />
  <pqevent object="$orbit/ButtonBox/OkButton" command="activate" arguments="" />
  <pqevent object="pqClientMainWindow" command="process_events" arguments="300" />
  <!-- a refusal: under the style None, Export Stylized Figure... shows the function's line in
       the StylizeMessage box and writes nothing; then back to Comic -->
  <pqevent object="$shell" command="executeCommand" arguments="import __main__; __main__.set_style(0)" />
  <pqevent object="$menu" command="activate" arguments="actionStylizeExportFigure" />
  <pqevent object="pqClientMainWindow/StylizeFigureFileDialog" command="filesSelected"
      arguments="$out/gui-refused.svg" />
  <pqcheck object="pqClientMainWindow/StylizeMessage" property="text"
      arguments="cannot write a figure: the view's Style is None" />
  <pqevent object="pqClientMainWindow/StylizeMessage/qt_msgbox_buttonbox/1QPushButton0"
      command="activate" arguments="" />
  <pqevent object="$shell" command="executeCommand" arguments="import __main__; __main__.set_style(1)" />
  <pqevent object="$shell" command="executeCommand" arguments="import __main__; __main__.check_exports()" />
  <pqevent object="pqClientMainWindow/pythonShellDock/pythonShell/consoleWidget"
      command="executeCommand" arguments="import __main__; __main__.capture_window()" />
</pqevents>
EOF

timeout -k 10 "$limit" "$paraview" --dr -geometry 1280x800+0+0 \
  --script="$here/test_gui.py" --test-script="$tmp/events.xml" --test-directory="$out" --exit
rc=$?
echo "paraview exited with $rc"
if [ "$rc" -eq 124 ] || [ "$rc" -eq 137 ]; then
  echo "FAIL: paraview did not exit within $limit s (a modal dialog waiting for a click?)"
fi
if [ ! -f "$out/gui-result.txt" ]; then
  echo "FAIL: test_gui.py wrote no $out/gui-result.txt (the script did not run or did not end)"
  exit 1
fi
cat "$out/gui-result.txt"
[ "$rc" -eq 0 ] || exit 1
if [ "$(head -n 1 "$out/gui-result.txt")" != PASS ] || grep -q '^FAIL' "$out/gui-result.txt" ||
   ! grep -q '^window captured' "$out/gui-result.txt" ||
   ! grep -q '^Export Stylized Figure... wrote' "$out/gui-result.txt"; then
  exit 1
fi
echo "paraview.gui passed"
