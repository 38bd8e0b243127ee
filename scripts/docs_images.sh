#!/usr/bin/env bash
# Re-renders the manual's images of the built-in scene, the CLI test data and the real-data set
# (docs/images) with the current defaults: one vtkstylize command per image, as docs/overview.md
# and README.md give them. Needs a build whose test data exist (run scripts/test.sh, or at least
# the CLI and real-data tests, first) and an X display (scripts/common.sh starts Xvfb).
#   scripts/docs_images.sh [BUILD]     (default: build)
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
build="${1:-$STYLIZE_BUILD}"
program="$build/bin/vtkstylize"
cli="$build/Testing/Cli/data"
real="$build/Testing/RealData/data"
out="$STYLIZE_ROOT/docs/images"
for need in "$program" "$cli/hexes.vtu" "$cli/wavelet.vti" "$real/bunny.ply"; do
  if [ ! -e "$need" ]; then
    echo "missing $need: build and run the tests first (scripts/test.sh)" >&2
    exit 1
  fi
done
stylize_start_display

# A 16-colour list for --colors (PICO-8's palette).
pico8="#000000;#1d2b53;#7e2553;#008751;#ab5236;#5f574f;#c2c3c7;#fff1e8;#ff004d;#ffa300;#ffec27;#00e436;#29adff;#83769c;#ff77a8;#ffccaa"
ablation="--style comic --size 960x540 --no-annotations"
pixel="--style pixel --size 960x540"
sketch="--style sketch --size 960x540"

# name | options (a file name last, when the image is of data)
images=(
  "comic-scene|--style comic"
  "pixel-scene|$pixel"
  "pixel-fast|$pixel --mode fast"
  "sketch-scene|$sketch"
  "lighting-standard|--lighting standard --size 640x360"
  "lighting-comic|--lighting comic --size 640x360"
  "lighting-pixelart|--lighting pixelart --size 640x360"
  "lighting-comic-8lights|--lighting comic --lights 8 --subject 0.8 --size 640x360"
  "comic-hexes|--style comic --size 640x480 $cli/hexes.vtu"
  "pixel-hexes|$pixel --palette 16 $cli/hexes.vtu"
  "sketch-hexes|$sketch --tint all $cli/hexes.vtu"
  "comic-wavelet-tinted|--style comic --tint all --size 640x480 $cli/wavelet.vti"
  "pixel-wavelet|$pixel --palette colormap $cli/wavelet.vti"
  "sketch-wavelet|$sketch $cli/wavelet.vti"
  "comic|$ablation"
  "comic-no-edges|$ablation --no-edges"
  "comic-no-dots|$ablation --no-dots"
  "comic-no-hatching|$ablation --no-hatching"
  "comic-standard-lighting|$ablation --lighting standard"
  "comic-object-anchor|$ablation --anchor object"
  "comic-tinted|$ablation --tint all"
  "pixel-1bit|$pixel --palette 1bit"
  "pixel-4grays|$pixel --palette 4grays"
  "pixel-16|$pixel --palette 16"
  "pixel-colormap|$pixel --palette colormap"
  "pixel-custom|$pixel --colors $pico8"
  "pixel-size8|$pixel --pixel-size 8"
  "pixel-edges-sobel|$pixel --pixel-layer edges --edge-detector sobel --no-depth-edges"
  "pixel-edges-canny|$pixel --pixel-layer edges --no-depth-edges"
  "pixel-edges-canny-depth|$pixel --pixel-layer edges"
  "sketch-perlin|$sketch --noise perlin"
  "sketch-worley|$sketch --noise worley"
  "sketch-sparse|$sketch --noise sparse"
  "sketch-directions|$sketch --sketch-layer directions"
  "sketch-directions-model|$sketch --sketch-layer directions --direction-source model"
  "sketch-strokes|$sketch --sketch-layer strokes"
  "sketch-bisector|$sketch --direction bisector"
  "lines-scene|--style lines --size 960x540"
  "lines-shades-hexes|--style lines --tone shades --size 960x540 $cli/hexes.vtu"
)
for style in comic pixel sketch lines; do
  for mesh in bunny fandisk cow; do
    images+=("real-$mesh-$style|--style $style --size 640x360 $real/$mesh.ply")
  done
done

# The pencil on a face scan (the head's profile) and a held-out scan (issue 38).
images+=("pencil-head|--style sketch --size 640x360 --azimuth 0 --elevation 0 $real/head.ply")
images+=("pencil-mannequin|--style sketch --size 640x360 --up +Z --azimuth -20 --elevation 10 $real/mannequin.ply")
images+=("pencil-armadillo|--style sketch --size 640x360 $real/armadillo.ply")

for entry in "${images[@]}"; do
  name="${entry%%|*}"
  read -r -a options <<< "${entry#*|}"
  "$program" "${options[@]}" --output "$out/$name.png" > /dev/null
  echo "$out/$name.png"
done

# Vector figures of the fandisk (the README's and figures.md's): the sketch's embedded pencil and
# the vector pencil (--vector-pencil), the latter also rasterized for the sketch's gallery.
figures="$out/figures"
mkdir -p "$figures"
for style in sketch pencil; do
  options=(--style sketch)
  [ "$style" = pencil ] && options+=(--vector-pencil)
  "$program" "${options[@]}" --size 480x360 --no-annotations \
    --output "$figures/fandisk-$style.svg" "$real/fandisk.ply" > /dev/null
  echo "$figures/fandisk-$style.svg"
done
"$program" --style sketch --vector-pencil --size 640x360 --output "$out/pencil-bunny-vector.svg" \
  "$real/bunny.ply" > /dev/null
rsvg-convert -b white "$out/pencil-bunny-vector.svg" -o "$out/pencil-bunny-vector.png"
rm "$out/pencil-bunny-vector.svg"
echo "$out/pencil-bunny-vector.png"

# The sketch's orbit animation (the README's; the comic's and pixel art's are made alike).
"$program" --style sketch --orbit 36 --fps 12 --size 240x180 \
  --output "$figures/orbit-sketch.gif" "$real/bunny.ply" > /dev/null
rm -f "$figures"/orbit-sketch-[0-9]*.png # the frames the GIF was encoded from
echo "$figures/orbit-sketch.gif"

# The ParaView GUI (when the plugin was built): paraview.gui's own run, whose window captures are
# the manual's pictures of the GUI and of its Save Stylized Orbit dialog.
paraview="$build/paraview/bin/paraview-stylize"
if [ -x "$paraview" ]; then
  gui="$build/Testing/Temporary/paraview/gui"
  sh "$STYLIZE_ROOT/Testing/ParaView/run_gui.sh" "$paraview" "$gui" > /dev/null
  cp "$gui/gui-window.png" "$out/paraview-gui.png"
  # the dialog's corner of the window (the capture is 1280x800, the dialog near the view's top
  # left)
  ffmpeg -v error -y -i "$gui/gui-orbit-dialog.png" -vf crop=420:240:440:240 \
    "$out/paraview-orbit-dialog.png"
  echo "$out/paraview-gui.png $out/paraview-orbit-dialog.png"
fi

# Feature lines with hidden lines removed (realdata.lines' drawings) and the line-art style
# (realdata.lineart's pictures).
for mesh in mannequin lion fandisk armadillo; do
  for kind in lines lineart; do
    picture="$build/Testing/RealData/$kind/$kind-$mesh.png"
    if [ -f "$picture" ]; then
      cp "$picture" "$out/$kind-$mesh.png"
      echo "$out/$kind-$mesh.png"
    fi
  done
done
