#!/bin/bash
# The ParaView GUI's own timer log while a user drags the camera (issue 52): not a test. The GUI
# (the plugin's paraview-stylize, a fresh profile) shows MESH in a Render View (Stylize) with
# STYLE (1 comic, 2 pixel art, 3 sketch, 4 line art); xdotool drags the mouse over the view three
# times (12 moves each, then a pause for the still frame); the timer log's Still Render and
# Interactive Render entries then give each still frame, each drag's first interactive frame and
# the median interactive frame. Needs an X display (DISPLAY; Xvfb) and xdotool (Debian's
# package; the suite does not use it).
#
#   paraview_gui_drags.sh PARAVIEW_STYLIZE MESH STYLE [LOD_THRESHOLD_MB [PAUSE_S]]
#
# LOD_THRESHOLD_MB: ParaView's LOD threshold (default ParaView's, 20; 0 draws the decimated copy
# in every interactive frame). PAUSE_S: seconds after each drag (default 8; longer when still
# frames take longer). Prints one line; the log is kept as OUT.log beside a temporary profile.
set -u
paraview=${1:?usage: paraview_gui_drags.sh PARAVIEW_STYLIZE MESH STYLE [LOD_THRESHOLD_MB [PAUSE_S]]}
mesh=$(realpath "${2:?mesh}")
style=${3:?style}
lod=${4:-}
pause=${5:-8}
command -v xdotool >/dev/null || { echo "paraview_gui_drags.sh: needs xdotool (apt-get install xdotool)" >&2; exit 2; }
[ -n "${DISPLAY:-}" ] || { echo "paraview_gui_drags.sh: needs DISPLAY (an X server, e.g. Xvfb)" >&2; exit 2; }
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d) || exit 1
trap 'kill "$pid" 2>/dev/null; rm -rf "$tmp"' EXIT
mkdir -p "$tmp/home"
HOME="$tmp/home" STYLIZE_MESH="$mesh" STYLIZE_STYLE="$style" STYLIZE_LOD_THRESHOLD="$lod" \
  STYLIZE_COMMAND="$tmp/command.py" "$paraview" --dr -geometry 1440x700+0+0 \
  --script="$here/paraview_gui_setup.py" >"$tmp/paraview.out" 2>&1 &
pid=$!
# (the first still frame computes what a style keeps: wait for it, from the log)
for _ in $(seq 1 600); do
  echo "timer_log('$tmp/start.log')" > "$tmp/command.py"
  sleep 1
  [ -s "$tmp/start.log" ] && grep -q "^Still Render" "$tmp/start.log" && break
done
drag() {
  xdotool mousemove "$1" "$2" mousedown 1
  for i in $(seq 1 12); do
    xdotool mousemove $(( $1 + ($3 - $1) * i / 12 )) $(( $2 + ($4 - $2) * i / 12 ))
    sleep 0.08
  done
  xdotool mouseup 1
  sleep "$pause"
}
drag 860 420 920 400
drag 860 420 800 430
drag 860 420 880 360
echo "timer_log('$tmp/drags.log')" > "$tmp/command.py"
for _ in $(seq 1 120); do [ -s "$tmp/drags.log" ] && break; sleep 1; done
/usr/bin/python3 - "$tmp/drags.log" "$(basename "$mesh")" "$style" <<'PY'
import re, statistics, sys
entries = [(m.group(1)[0], 1000.0 * float(m.group(2))) for m in
           (re.match(r"^(Still Render|Interactive Render),\s+([0-9.e+-]+) seconds", l)
            for l in open(sys.argv[1])) if m]
runs, current, stills = [], [], []
for kind, ms in entries:
    if kind == "I":
        current.append(ms)
        continue
    if current:
        runs.append(current)
        current = []
    stills.append(ms)
runs += [current] if current else []
drags = [r for r in runs if len(r) >= 6]  # (the GUI's own short runs at startup aside)
inter = [ms for r in drags for ms in r]
print("%s style %s: still frames %s ms; drags' first interactive %s ms; median interactive "
      "%.0f ms" % (sys.argv[2], sys.argv[3], " ".join("%.0f" % s for s in stills),
                   " ".join("%.0f" % r[0] for r in drags),
                   statistics.median(inter) if inter else float("nan")))
PY
