#!/bin/sh
# paraview.gui_fresh_start: the File menu's entries on first use, in a GUI that has run no Python,
# and File > Open of a PLY file stored as triangle strips.
#
#   run_gui_fresh.sh PARAVIEW_STYLIZE PVBATCH_STYLIZE OUTPUT_DIR STRIPS_PLY [TIMEOUT_SECONDS]
#
# pvbatch writes a state (make_gui_state.py: the Wavelet contour in a Render View (Stylize), Style
# Comic); the GUI starts from a fresh profile (gui_profile.sh, --dr) with that state (--state, XML:
# no Python) and plays QtTesting events only: File > Export Stylized Figure... (ParaView's file
# dialog, an SVG path), then File > Save Stylized Orbit... (a GIF path, the options dialog: 2
# frames over 20 degrees), and quits. Nothing runs Python before those clicks (run_gui.sh's test
# starts with a Python script, which hid a failure: "No module named 'stylize_paraview'" in a
# message box until the Python shell had been opened once). Then File > Open (ParaView's file
# dialog) of STRIPS_PLY and Apply: the plugin's checked reader must read it (ParaView's own PLY
# Reader reads a triangle-strip PLY with no cells), which the Python shell then records. Passes
# when paraview exits 0, both entries wrote their files (an SVG figure, a GIF and its 2 PNG
# frames), and the opened file is read by StylizeCheckedReader with cells.
set -u
usage="usage: run_gui_fresh.sh PARAVIEW_STYLIZE PVBATCH_STYLIZE OUTPUT_DIR STRIPS_PLY [TIMEOUT_SECONDS]"
paraview=${1:?$usage}
pvbatch=${2:?$usage}
out=${3:?$usage}
strips=${4:?$usage}
limit=${5:-180}
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$out" || exit 1
out=$(cd "$out" && pwd)
if [ -z "${DISPLAY:-}" ]; then
  echo "run_gui_fresh.sh: DISPLAY is not set (start Xvfb, e.g. Xvfb :95 &, and export DISPLAY=:95)" >&2
  exit 1
fi
rm -f "$out/fresh-figure.svg" "$out/fresh-orbit.gif" "$out"/fresh-orbit-*.png "$out/fresh-open.txt"
PYTHONPATH="${PYTHONPATH:+$PYTHONPATH:}$here" "$pvbatch" "$here/make_gui_state.py" \
  "$out/fresh.pvsm" || exit 1

. "$here/gui_profile.sh"
menu=pqClientMainWindow/menubar/menu_File
orbit=pqClientMainWindow/StylizeOrbitDialog
cat > "$tmp/events.xml" <<XML
<?xml version="1.0" ?>
<pqevents>
  <pqevent object="pqClientMainWindow" command="process_events" arguments="500" />
  <pqevent object="$menu" command="activate" arguments="actionStylizeExportFigure" />
  <pqevent object="pqClientMainWindow/StylizeFigureFileDialog" command="filesSelected"
      arguments="$out/fresh-figure.svg" />
  <pqevent object="pqClientMainWindow" command="process_events" arguments="200" />
  <pqevent object="$menu" command="activate" arguments="actionStylizeSaveOrbit" />
  <pqevent object="pqClientMainWindow/StylizeOrbitFileDialog" command="filesSelected"
      arguments="$out/fresh-orbit.gif" />
  <pqevent object="$orbit/frames" command="set_int" arguments="2" />
  <pqevent object="$orbit/degrees" command="set_double" arguments="20" />
  <pqevent object="$orbit/ButtonBox/OkButton" command="activate" arguments="" />
  <pqevent object="pqClientMainWindow" command="process_events" arguments="300" />
  <pqevent object="$menu" command="activate" arguments="actionFileOpen" />
  <pqevent object="pqClientMainWindow/FileOpenDialog" command="filesSelected"
      arguments="$strips" />
  <pqevent object="pqClientMainWindow/propertiesDock/propertiesPanel/Accept" command="activate"
      arguments="" />
  <pqevent object="pqClientMainWindow" command="process_events" arguments="300" />
  <pqevent object="pqClientMainWindow/pythonShellDock/pythonShell/consoleWidget"
      command="executeCommand"
      arguments="s = GetActiveSource(); open('$out/fresh-open.txt', 'w').write('%s %d' % (s.GetXMLName(), s.GetDataInformation().GetNumberOfCells()))" />
</pqevents>
XML

timeout -k 10 "$limit" "$paraview" --dr -geometry 1280x800+0+0 --state="$out/fresh.pvsm" \
  --test-script="$tmp/events.xml" --test-directory="$out" --exit
rc=$?
echo "paraview exited with $rc"
failed=0
if [ "$rc" -ne 0 ]; then
  echo "FAIL: paraview exited with $rc (124: it did not exit within $limit s; a message box?)"
  failed=1
fi
if grep -q '<svg' "$out/fresh-figure.svg" 2>/dev/null; then
  echo "Export Stylized Figure... wrote $(wc -c < "$out/fresh-figure.svg") bytes of SVG"
else
  echo "FAIL: Export Stylized Figure... wrote no SVG ($out/fresh-figure.svg)"
  failed=1
fi
if [ "$(head -c 6 "$out/fresh-orbit.gif" 2>/dev/null)" = GIF89a ] &&
   [ -s "$out/fresh-orbit-0000.png" ] && [ -s "$out/fresh-orbit-0001.png" ] &&
   [ ! -e "$out/fresh-orbit-0002.png" ]; then
  echo "Save Stylized Orbit... wrote a GIF and its 2 frames"
else
  echo "FAIL: Save Stylized Orbit... did not write the GIF and its 2 frames"
  ls -la "$out" | grep fresh-orbit
  failed=1
fi
opened=$(cat "$out/fresh-open.txt" 2>/dev/null)
case "$opened" in
  "StylizeCheckedReader "[1-9]*) echo "File > Open read $(basename "$strips") with $opened cells" ;;
  *) echo "FAIL: File > Open of $(basename "$strips"): '$opened' (StylizeCheckedReader with cells expected)"
     failed=1 ;;
esac
[ "$failed" -eq 0 ] && echo "paraview.gui_fresh_start passed"
exit "$failed"
