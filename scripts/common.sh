# Shared by scripts/demo.sh and scripts/test.sh: installs what is missing (Debian 12, apt,
# non-interactive, idempotent), starts Xvfb when there is no display, configures and builds.
set -euo pipefail

STYLIZE_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
STYLIZE_BUILD="${STYLIZE_BUILD:-$STYLIZE_ROOT/build}"
STYLIZE_JOBS="${STYLIZE_JOBS:-$(nproc)}"

# Debian packages the build, the tests and the demo need.
# paraview and paraview-dev are for the ParaView plugin (its python3-paraview conflicts with
# python3-vtk9, so the build unpacks it into the build tree instead of installing it), and
# mpi-default-bin gives mpiexec for the 1-rank against 2-rank test; libqt5svg5 draws the
# GUI's toolbar icons (Debian's paraview does not pull it in); qtbase5-dev, libqt5svg5-dev,
# libqt5opengl5-dev and qttools5-dev give the Qt CMake packages that ParaView's GUI modules ask
# for (the plugin's File menu entries build against them); libcli11-dev parses vtkstylize's
# command line; libcgal-demo ships the public test meshes of the real-data test set
# (Testing/RealData). Vector figures: libcairo2-dev writes SVG and PDF, libpotrace-dev traces
# outlines, fonts-liberation gives text VTK's Arial metrics; the tests rasterize figures back with
# librsvg2-bin (rsvg-convert) and poppler-utils (pdftoppm); orbit animations are encoded (GIF,
# MP4) by ffmpeg. clang and libclang-rt-14-dev build the libFuzzer targets of the sanitizer stage.
# The tests: python3-numpy (image measures), git (source.format lists the tracked files),
# clang-format (source.format). ccache keeps compilations between builds (the release and the
# sanitizer build share the tests' tools; a second run of CI compiles nothing it compiled before).
STYLIZE_PACKAGES=(cmake make g++ pkg-config git ccache libvtk9-dev python3-vtk9 python3-dev
  python3-numpy libglm-dev xvfb xauth
  x11-utils libgl1-mesa-dri paraview paraview-dev mpi-default-bin libqt5svg5 qtbase5-dev
  libqt5svg5-dev libqt5opengl5-dev qttools5-dev libcli11-dev
  libcgal-demo libcairo2-dev libpotrace-dev fonts-liberation librsvg2-bin poppler-utils ffmpeg
  clang-format clang libclang-rt-14-dev)

# ccache's keys hold paths relative to the checkout, so that the release and the sanitizer build
# trees (siblings in it) and other clones share entries; with CCACHE_NOHASHDIR the sanitizer
# build's objects (line tables: -g1) are shared by clones at other paths too (their debug
# information then names the folder of the clone that compiled them first).
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$STYLIZE_ROOT}"
export CCACHE_NOHASHDIR="${CCACHE_NOHASHDIR:-1}"

# stylize_stage NAME COMMAND...: runs COMMAND; with STYLIZE_STAGE_LOG set (by .ci/run), appends
# "NAME SECONDS STATUS" to it, so that CI prints its stages' times at the end.
stylize_stage() {
  local name="$1" start="$EPOCHREALTIME" rc=0
  shift
  "$@" || rc=$?
  if [ -n "${STYLIZE_STAGE_LOG:-}" ]; then
    awk -v n="$name" -v a="$start" -v b="$EPOCHREALTIME" -v rc="$rc" \
      'BEGIN { printf "%s\t%.0f\t%s\n", n, b - a, rc }' >>"$STYLIZE_STAGE_LOG"
  fi
  return "$rc"
}

stylize_install_dependencies() {
  local missing=()
  local pkg
  for pkg in "${STYLIZE_PACKAGES[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed"; then
      missing+=("$pkg")
    fi
  done
  if [ ${#missing[@]} -eq 0 ]; then
    echo "== dependencies: all installed"
    return 0
  fi
  echo "== installing: ${missing[*]}"
  local sudo=""
  if [ "$(id -u)" -ne 0 ]; then
    sudo="sudo"
  fi
  $sudo env DEBIAN_FRONTEND=noninteractive apt-get update -qq || return
  $sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
    "${missing[@]}" >/dev/null
}

# Starts Xvfb on a free display unless DISPLAY already works; stops it on exit.
stylize_start_display() {
  if [ -n "${DISPLAY:-}" ] && xdpyinfo >/dev/null 2>&1; then
    echo "== display: using DISPLAY=$DISPLAY"
    return 0
  fi
  local n
  for n in $(seq 90 140); do
    if [ ! -e "/tmp/.X${n}-lock" ] && [ ! -e "/tmp/.X11-unix/X${n}" ]; then
      # -noreset: by default Xvfb resets when its last client disconnects, and a test that
      # connects during the reset fails with "bad X server connection".
      Xvfb ":$n" -screen 0 1920x1080x24 -nolisten tcp -noreset >/dev/null 2>&1 &
      STYLIZE_XVFB_PID=$!
      export DISPLAY=":$n"
      trap 'kill "$STYLIZE_XVFB_PID" 2>/dev/null || true' EXIT
      local i
      for i in $(seq 1 50); do
        [ -e "/tmp/.X11-unix/X${n}" ] && break
        sleep 0.1
      done
      echo "== display: started Xvfb on DISPLAY=$DISPLAY"
      return 0
    fi
  done
  echo "no free X display number found" >&2
  return 1
}

stylize_build() {
  echo "== configuring and building in $STYLIZE_BUILD"
  cmake -S "$STYLIZE_ROOT" -B "$STYLIZE_BUILD" -DCMAKE_BUILD_TYPE=Release >/dev/null || return
  cmake --build "$STYLIZE_BUILD" -j "$STYLIZE_JOBS"
}
