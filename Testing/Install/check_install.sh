#!/bin/sh
# install.fresh_prefix: installs the build into a fresh prefix, moves the prefix elsewhere, then
# runs what the install offers from there with a clean environment (env -i: PATH, HOME and
# DISPLAY only, plus PYTHONPATH for Python, as docs/install.md documents):
#   - bin/vtkstylize renders a comic PNG (the program finds the project's libraries through
#     its RUNPATH, $ORIGIN/../lib);
#   - the Python package renders a comic image (check_python.py);
#   - bin/pvbatch-stylize and bin/pvpython-stylize load the installed plugin and render (when the
#     plugin is built); bin/pvserver-stylize is there.
# It also fails when anything test-only or build-only is installed.
#
#   check_install.sh CMAKE BUILD_DIR SOURCE_DIR WORK_DIR WITH_PYTHON WITH_PLUGIN [PYTHON]
# (PYTHON: the interpreter, /usr/bin/python3 unless given: the sanitizer build gives a wrapper
# that preloads the sanitizers' runtimes; their *SAN_OPTIONS pass through the clean environment)
set -eu
cmake=$1 build=$2 source=$3 work=$4 with_python=$5 with_plugin=$6 python=${7:-/usr/bin/python3}

fail() {
  echo "install.fresh_prefix: $*" >&2
  exit 1
}
clean() {
  env -i PATH=/usr/bin:/bin HOME="$work" DISPLAY="${DISPLAY:-}" \
    ${ASAN_OPTIONS+ASAN_OPTIONS="$ASAN_OPTIONS"} ${UBSAN_OPTIONS+UBSAN_OPTIONS="$UBSAN_OPTIONS"} "$@"
}

rm -rf "$work"
mkdir -p "$work"
"$cmake" --install "$build" --prefix "$work/first" >"$work/install.log" 2>&1 ||
  fail "cmake --install failed (see $work/install.log)"

# Nothing test-only (the image metrics) or build-only (static client-server libraries).
unwanted=$(find "$work/first" \( -name '*TestingSupport*' -o -name 'vtkstylize_testing' \
  -o -name '*.a' \) -print)
[ -z "$unwanted" ] || fail "installed but test-only or build-only: $unwanted"

# A prefix that was never the install prefix: nothing may depend on the first location.
mv "$work/first" "$work/moved"
prefix="$work/moved"

clean "$prefix/bin/vtkstylize" --style comic --size 96x72 --output "$work/cli.png" ||
  fail "the installed vtkstylize did not run from $prefix"
[ -s "$work/cli.png" ] || fail "the installed vtkstylize wrote no image"
echo "vtkstylize from the moved prefix: $work/cli.png"

if [ "$with_python" = ON ]; then
  clean PYTHONPATH="$prefix/python" "$python" "$source/Testing/Install/check_python.py" \
    "$prefix" || fail "the installed Python package did not work from $prefix"
fi

# check_plugin WRAPPER STEM NOT_FROM_PREFIX: the installed WRAPPER runs check_load.py, which
# writes $work/STEM.png (log: $work/STEM.log) and must say that the plugin was loaded from the
# prefix; NOT_FROM_PREFIX is the failure's message when it was loaded from elsewhere.
check_plugin() {
  clean "$prefix/bin/$1" "$source/Testing/ParaView/check_load.py" \
    "$work/$2.png" >"$work/$2.log" 2>&1 ||
    fail "the installed $1 did not load the plugin (see $work/$2.log)"
  grep -q "plugin loaded from $prefix/" "$work/$2.log" ||
    fail "$3: $(cat "$work/$2.log")"
}

if [ "$with_plugin" = ON ]; then
  check_plugin pvbatch-stylize plugin "the plugin was not loaded from $prefix"
  [ -s "$work/plugin.png" ] || fail "pvbatch-stylize wrote no image"
  # pvpython-stylize (ParaView's Python before Debian's VTK 9.1 modules), in its built-in session
  check_plugin pvpython-stylize pvpython "pvpython-stylize did not load the plugin from $prefix"
  [ -x "$prefix/bin/pvserver-stylize" ] || fail "no pvserver-stylize in $prefix/bin"
  echo "plugin from the moved prefix: $work/plugin.png, $work/pvpython.png"
fi
echo "install.fresh_prefix: passed"
