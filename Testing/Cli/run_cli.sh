#!/bin/sh
# Test driver for vtkstylize. Runs the command after "--" and checks its outcome.
#
#   run_cli.sh fail RC OUTPUT -- COMMAND...
#       exit status RC (1 or 2), stderr exactly one line starting with "vtkstylize: " (and not an
#       internal error), nothing on stdout, OUTPUT absent and no temporary file left beside it.
#   run_cli.sh render OUTPUT WIDTH HEIGHT BACKGROUND CHECKER STDOUT -- COMMAND...
#       exit status 0, stdout is "OUTPUT" (STDOUT=path) or empty (STDOUT=quiet), no temporary
#       file left, and CHECKER OUTPUT WIDTH HEIGHT BACKGROUND passes (a PNG of that size that is
#       not just the background). stderr: nothing but "vtkstylize: note: " lines (the values the
#       program chose, e.g. a contour value), and nothing at all with STDOUT=quiet.
#   run_cli.sh warn OUTPUT TEXT -- COMMAND...
#       exit status 0, OUTPUT written, stderr has a line "vtkstylize: warning: TEXT..." and every
#       stderr line is a warning or a note.
#   run_cli.sh help "WORD..." -- COMMAND...
#       exit status 0, nothing on stderr, every WORD appears in stdout.
#   run_cli.sh version -- COMMAND...
#       exit status 0, nothing on stderr, stdout is one line starting with "vtkstylize ".
#
# OUTPUT is removed before the command runs.

fail() {
  echo "FAIL: $*"
  echo "--- command:"; echo "$cmdline"
  echo "--- exit status: $rc"
  echo "--- stdout:"; cat "$tmp.out"
  echo "--- stderr:"; cat "$tmp.err"
  rm -f "$tmp.out" "$tmp.err"
  exit 1
}

# No leftover ".NAME.XXXXXX" temporary file beside OUTPUT.
check_no_temporary() {
  dir=$(dirname "$1")
  base=$(basename "$1")
  for f in "$dir"/."$base".*; do
    [ -e "$f" ] && fail "temporary file $f left behind"
  done
  return 0
}

mode=$1
shift
case "$mode" in
  fail)
    expected_rc=$1; output=$2; shift 2 ;;
  render)
    output=$1; width=$2; height=$3; background=$4; checker=$5; stdout_mode=$6; shift 6 ;;
  warn)
    output=$1; text=$2; shift 2 ;;
  help)
    words=$1; shift ;;
  version) ;;
  *) echo "run_cli.sh: unknown mode '$mode'"; exit 2 ;;
esac
[ "$1" = "--" ] || { echo "run_cli.sh: expected -- before the command"; exit 2; }
shift

tmp=$(mktemp "${TMPDIR:-/tmp}/vtkstylize-cli.XXXXXX") || exit 2
cmdline=""
for a in "$@"; do cmdline="$cmdline '$a'"; done
[ -n "$output" ] && rm -f "$output"

"$@" >"$tmp.out" 2>"$tmp.err"
rc=$?
rm -f "$tmp"

case "$mode" in
  fail)
    [ "$rc" -eq "$expected_rc" ] || fail "expected exit status $expected_rc"
    [ "$(wc -l <"$tmp.err")" -eq 1 ] || fail "stderr is not exactly one line"
    [ "$(wc -c <"$tmp.err")" -gt 13 ] || fail "stderr message is empty"
    head -c 12 "$tmp.err" | grep -q '^vtkstylize: $' || fail "stderr does not start with 'vtkstylize: '"
    grep -q 'internal error' "$tmp.err" && fail "internal error"
    [ -s "$tmp.out" ] && fail "stdout is not empty"
    [ -e "$output" ] && fail "output file $output exists"
    check_no_temporary "$output"
    cat "$tmp.err"
    ;;
  render)
    [ "$rc" -eq 0 ] || fail "expected exit status 0"
    if [ "$stdout_mode" = quiet ]; then
      [ -s "$tmp.err" ] && fail "stderr is not empty with --quiet"
      [ -s "$tmp.out" ] && fail "stdout is not empty with --quiet"
    else
      grep -v '^vtkstylize: note: ' "$tmp.err" | grep -q . && fail "stderr has more than notes"
      [ "$(cat "$tmp.out")" = "$output" ] || fail "stdout is not the output path"
      [ "$(wc -l <"$tmp.out")" -eq 1 ] || fail "stdout is not one line"
    fi
    [ -f "$output" ] || fail "no output file $output"
    check_no_temporary "$output"
    check=$("$checker" "$output" "$width" "$height" "$background") || fail "image check: $check"
    echo "$check"
    ;;
  warn)
    [ "$rc" -eq 0 ] || fail "expected exit status 0"
    [ -s "$output" ] || fail "no output file $output"
    grep -q -F -e "vtkstylize: warning: $text" "$tmp.err" || fail "no warning '$text'"
    grep -v -e '^vtkstylize: warning: ' -e '^vtkstylize: note: ' "$tmp.err" | grep -q . &&
      fail "stderr has more than warnings and notes"
    cat "$tmp.err"
    ;;
  help)
    [ "$rc" -eq 0 ] || fail "expected exit status 0"
    [ -s "$tmp.err" ] && fail "stderr is not empty"
    for w in $words; do
      grep -q -e "$w" "$tmp.out" || fail "help does not mention $w"
    done
    ;;
  version)
    [ "$rc" -eq 0 ] || fail "expected exit status 0"
    [ -s "$tmp.err" ] && fail "stderr is not empty"
    [ "$(wc -l <"$tmp.out")" -eq 1 ] || fail "stdout is not one line"
    grep -q '^vtkstylize ' "$tmp.out" || fail "stdout does not start with 'vtkstylize '"
    ;;
esac
rm -f "$tmp.out" "$tmp.err"
echo "PASS"
exit 0
