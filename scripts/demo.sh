#!/usr/bin/env bash
# README command 1: install what is missing, build, and render the built-in demo scene in every
# style implemented so far (and each lighting model) into PNG files.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
stylize_install_dependencies
stylize_start_display
stylize_build

OUT="${1:-$STYLIZE_ROOT/out}"
mkdir -p "$OUT"
STYLIZE="$STYLIZE_BUILD/bin/vtkstylize"
echo "== rendering the built-in scene"
for style in none; do
  for model in standard comic pixelart; do
    "$STYLIZE" --style "$style" --lighting "$model" --size 1280x720 \
      --output "$OUT/demo-$style-$model.png"
  done
done
"$STYLIZE" --style none --lighting comic --lights 8 --size 1280x720 --output "$OUT/demo-none-comic-8lights.png"
echo "== done: the images are in $OUT"
ls -1 "$OUT"/*.png
