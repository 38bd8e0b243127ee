#!/usr/bin/env bash
# README command 1: install what is missing, build, and render the built-in demo scene in every
# style (and each lighting model) into PNG files, with vtkstylize, the Python example and,
# when the ParaView plugin was built, pvbatch.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
stylize_install_dependencies
stylize_start_display
stylize_build

OUT="${1:-$STYLIZE_ROOT/out}"
PYTHON_FOR_DEMO=/usr/bin/python3
export PYTHONPATH="$STYLIZE_BUILD/python${PYTHONPATH:+:$PYTHONPATH}"
mkdir -p "$OUT"
STYLIZE="$STYLIZE_BUILD/bin/vtkstylize"
echo "== rendering the built-in scene"
for model in standard comic pixelart; do
  "$STYLIZE" --style none --lighting "$model" --size 1280x720 --output "$OUT/demo-none-$model.png"
done
"$STYLIZE" --style comic --size 1280x720 --output "$OUT/demo-comic.png"
"$STYLIZE" --style none --lighting comic --lights 8 --size 1280x720 --output "$OUT/demo-none-comic-8lights.png"
"$STYLIZE" --style comic --tint all --size 1280x720 --output "$OUT/demo-comic-tinted.png"
"$STYLIZE" --style pixel --size 1280x720 --output "$OUT/demo-pixel.png"
"$STYLIZE" --style pixel --mode fast --palette 16 --size 1280x720 --output "$OUT/demo-pixel-16.png"
"$STYLIZE" --style pixel --palette 1bit --size 1280x720 --output "$OUT/demo-pixel-1bit.png"
"$STYLIZE" --style sketch --size 1280x720 --output "$OUT/demo-sketch.png"
"$STYLIZE" --style sketch --noise perlin --direction bisector --size 1280x720 --output "$OUT/demo-sketch-perlin.png"
"$STYLIZE" --style sketch --sketch-layer directions --size 1280x720 --output "$OUT/demo-sketch-directions.png"
PVBATCH="$STYLIZE_BUILD/paraview/bin/pvbatch-stylize"
if [ -x "$PVBATCH" ]; then
  echo "== rendering a Wavelet contour in the ParaView view (pvbatch, each style)"
  "$PVBATCH" "$STYLIZE_ROOT/Testing/ParaView/render_styles.py" "$OUT/paraview" 800 600 >/dev/null
fi
"$PYTHON_FOR_DEMO" "$STYLIZE_ROOT/Examples/Python/stylize_dataset.py" -o "$OUT/python" --size 800x600 >/dev/null
echo "== done: the images are in $OUT"
ls -1 "$OUT"/*.png "$OUT"/python/*.png
