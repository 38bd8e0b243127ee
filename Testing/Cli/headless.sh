#!/bin/sh
# Runs without an X display (issue 39): vtkstylize, and pvbatch-stylize when given, with DISPLAY
# unset start their own Xvfb, render, and stop it; with no Xvfb on PATH they refuse in one line
# that names the package to install.
#   headless.sh VTKSTYLIZE OUTDIR [PVBATCH_STYLIZE CHECK_LOAD_PY]
set -u
exe=$1 out=$2 pvbatch=${3:-} script=${4:-}
rm -rf "$out" && mkdir -p "$out" || exit 1
fail() { echo "FAIL: $*"; exit 1; }
servers() { pgrep -f 'Xvfb -displayfd' | wc -l; }
before=$(servers)

env -u DISPLAY "$exe" --size 64x48 --output "$out/headless.png" >"$out/out" 2>"$out/err" ||
  fail "vtkstylize without DISPLAY: exit $? ($(cat "$out/err"))"
[ -s "$out/headless.png" ] || fail "vtkstylize without DISPLAY wrote no image"
[ "$(servers)" -eq "$before" ] || fail "vtkstylize left its Xvfb running"

env -u DISPLAY PATH=/nonexistent "$exe" --size 64x48 --output "$out/no_xvfb.png" >"$out/out" 2>"$out/err"
rc=$?
[ "$rc" -eq 1 ] || fail "vtkstylize without DISPLAY and Xvfb: exit $rc, expected 1"
[ "$(wc -l <"$out/err")" -eq 1 ] || fail "vtkstylize without Xvfb: not one line: $(cat "$out/err")"
grep -q 'apt install xvfb' "$out/err" || fail "vtkstylize without Xvfb does not name the package"
[ -e "$out/no_xvfb.png" ] && fail "vtkstylize without Xvfb wrote an image"
cat "$out/err"

if [ -n "$pvbatch" ]; then
  env -u DISPLAY "$pvbatch" "$script" "$out/pvbatch.png" >"$out/out" 2>"$out/err" ||
    fail "pvbatch-stylize without DISPLAY: exit $? ($(tail -3 "$out/err"))"
  [ -s "$out/pvbatch.png" ] || fail "pvbatch-stylize without DISPLAY wrote no image"
  [ "$(servers)" -eq "$before" ] || fail "pvbatch-stylize left its Xvfb running"
  env -u DISPLAY PATH=/nonexistent "$pvbatch" "$script" "$out/pv_no_xvfb.png" >"$out/out" 2>"$out/err"
  rc=$?
  [ "$rc" -eq 1 ] || fail "pvbatch-stylize without DISPLAY and Xvfb: exit $rc, expected 1"
  [ "$(wc -l <"$out/err")" -eq 1 ] || fail "pvbatch-stylize without Xvfb: not one line: $(cat "$out/err")"
  grep -q 'apt install xvfb' "$out/err" || fail "pvbatch-stylize without Xvfb: $(cat "$out/err")"
  cat "$out/err"
fi
echo "headless runs passed"
