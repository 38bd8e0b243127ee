#!/bin/sh
# progress.sh VTKSTYLIZE: the progress bar. On a terminal (script(1) gives one) with no delay
# (VTKSTYLIZE_PROGRESS_DELAY=0), the line art of a sphere shows "finding the lines [...]" on
# stderr, cleared before the output path; with --quiet nothing is shown; without a terminal
# stderr stays empty.
exe="$1"
set -e
command -v script >/dev/null 2>&1 || { echo "SKIP: no script(1) (util-linux) for a terminal"; exit 77; }
mkdir -p out
rm -f out/progress.png out/progress.log
VTKSTYLIZE_PROGRESS_DELAY=0 script -qec "\"$exe\" --style lines --size 64x48 --output out/progress.png sphere.vtp" /dev/null > out/progress.log
grep -q 'vtkstylize: finding the lines \[' out/progress.log || { echo "FAIL: no bar"; cat -v out/progress.log; exit 1; }
# The bar's line is cleared (carriage return, erase line) before the path is printed: the last
# line, split at carriage returns and without the erase sequences, is the path alone.
last=$(tr '\r' '\n' < out/progress.log | sed 's/\x1b\[K//g' | grep -v '^$' | tail -n 1)
[ "$last" = "out/progress.png" ] || { echo "FAIL: the last line is '$last'"; cat -v out/progress.log; exit 1; }
test -s out/progress.png
VTKSTYLIZE_PROGRESS_DELAY=0 script -qec "\"$exe\" --quiet --style lines --size 64x48 --output out/progress.png sphere.vtp" /dev/null > out/progress.log
if grep -q 'vtkstylize' out/progress.log; then echo "FAIL: a bar with --quiet"; cat -v out/progress.log; exit 1; fi
VTKSTYLIZE_PROGRESS_DELAY=0 "$exe" --style lines --size 64x48 --output out/progress.png sphere.vtp 2> out/progress.err > /dev/null
if [ -s out/progress.err ]; then echo "FAIL: stderr without a terminal"; cat out/progress.err; exit 1; fi
echo "progress bar: shown on a terminal, cleared, absent with --quiet and without a terminal"
