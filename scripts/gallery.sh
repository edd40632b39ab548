#!/usr/bin/env bash
# scripts/gallery.sh [SPANLIGHT]   (default: build/bin/spanlight)
#
# For every scenes/*.json: renders the fixed-point pipeline (default knobs) and
# the float model, the heat map of their difference (`spanlight compare
# --diff`), and puts the three side by side (fixed | float | heat map) with
# oiiotool into docs/images/<scene>.png. Writes docs/gallery.md: the panels and
# a table of the compare figures (fixed against the float reference).
# Needs bash, coreutils, sed, awk and oiiotool (openimageio-tools).
set -euo pipefail

repo=$(cd "$(dirname "$0")/.." && pwd)
spanlight=${1:-$repo/build/bin/spanlight}
[[ "$spanlight" == /* ]] || spanlight=$PWD/$spanlight

if [[ ! -x "$spanlight" ]]; then
  echo "gallery: no spanlight binary at $spanlight (build it: cmake --build build --target spanlight)" >&2
  exit 2
fi
if ! command -v oiiotool >/dev/null; then
  echo "gallery: needs oiiotool (Debian: openimageio-tools)" >&2
  exit 2
fi

images_dir=$repo/docs/images
gallery_md=$repo/docs/gallery.md
mkdir -p "$images_dir"
work=$(mktemp -d "${TMPDIR:-/tmp}/spanlight-gallery.XXXXXX")
trap 'rm -rf "$work"' EXIT

# Panel layout: three images of W x H, a margin of `pad` around and between
# them on a dark grey ground, and a caption row under them.
pad=8
caption=50
ground=0.2,0.2,0.2
font=DejaVuSans  # oiiotool --text has no default font on Debian; fonts-dejavu-core provides this one

# Captions need a font oiiotool can find; without one the panels have none.
if oiiotool --create 8x8 3 --text:font=$font:size=10 x -d uint8 -o "$work/font.png" >/dev/null 2>&1; then
  have_font=1
else
  have_font=0
  echo "gallery: oiiotool cannot load the font $font: panels without captions" >&2
fi

# Heat-map legend: differences of 0, 1, 2, 4, 8, 16, 32 LSB coloured by
# `spanlight compare --diff` itself, so the legend always matches the tool.
legend_levels=(0 1 2 4 8 16 32)
swatch=40   # colour box width
step=44     # box + gap
legend_args=(--create "$((step * ${#legend_levels[@]}))x10" 3)
for i in "${!legend_levels[@]}"; do
  v=$(awk -v k="${legend_levels[$i]}" 'BEGIN { printf "%.9f", k / 255 }')
  legend_args+=("--fill:color=$v,$v,$v" "${swatch}x10+$((i * step))+0")
done
oiiotool "${legend_args[@]}" -d uint8 -o "$work/legend_a.png"
oiiotool --create "$((step * ${#legend_levels[@]}))x10" 3 -d uint8 -o "$work/legend_b.png"
"$spanlight" compare "$work/legend_a.png" "$work/legend_b.png" --diff "$work/legend.png" >/dev/null

json_number() {  # json_number KEY < compare --json output
  sed -n "s/^ *\"$1\": *\([^,]*\),\{0,1\}\$/\1/p"
}

rows=()
for scene_file in "$repo"/scenes/*.json; do
  scene=$(basename "$scene_file" .json)
  echo "gallery: $scene"
  fixed=$work/$scene.fixed.png
  float=$work/$scene.float.png
  heat=$work/$scene.heat.png
  "$spanlight" render "$scene_file" --backend fixed --out "$fixed"
  "$spanlight" render "$scene_file" --backend float --out "$float"
  figures=$("$spanlight" compare "$fixed" "$float" --diff "$heat" --json)

  w=$(json_number width <<<"$figures")
  h=$(json_number height <<<"$figures")
  psnr=$(json_number psnr_db <<<"$figures")
  max=$(json_number max_abs_lsb <<<"$figures")
  mean=$(json_number mean_abs_lsb <<<"$figures")
  over2=$(json_number pct_over_2_lsb <<<"$figures")
  over8=$(json_number pct_over_8_lsb <<<"$figures")
  if [[ "$psnr" == null ]]; then psnr="inf (identical)"; else psnr=$(awk -v x="$psnr" 'BEGIN { printf "%.2f", x }'); fi
  row="| [$scene](../scenes/$scene.json) | $w x $h | $psnr | $(awk -v x="$max" 'BEGIN { printf "%g", x }')"
  row+=" | $(awk -v x="$mean" 'BEGIN { printf "%.3f", x }') | $(awk -v x="$over2" 'BEGIN { printf "%.2f", x }')"
  row+=" | $(awk -v x="$over8" 'BEGIN { printf "%.2f", x }') |"
  rows+=("$row")

  # fixed | float | heat map on a grey ground, captions below.
  x1=$pad
  x2=$((2 * pad + w))
  x3=$((3 * pad + 2 * w))
  panel_w=$((3 * w + 4 * pad))
  panel_h=$((h + 2 * pad + caption))
  # Captions first: oiiotool 2.4's --text aborts on an image read from a file,
  # so text goes onto the fresh ground, images after. `FG BG --paste` keeps BG's
  # size: each image is pushed on top of the ground, hence the --swap.
  args=(--create "${panel_w}x${panel_h}" 3 "--fill:color=$ground" "${panel_w}x${panel_h}+0+0")
  ly=$((pad + h + 22))
  if ((have_font)); then
    y=$((pad + h + 16))
    text=--text:font=$font:size=13:color=1,1,1
    args+=("$text:x=$x1:y=$y" "fixed point (default knobs)"
           "$text:x=$x2:y=$y" "float model (reference)"
           "$text:x=$x3:y=$y" "heat map: |fixed - float| in LSB")
    for i in "${!legend_levels[@]}"; do
      label=${legend_levels[$i]}
      ((i == ${#legend_levels[@]} - 1)) && label="$label+"
      args+=("--text:font=$font:size=11:color=1,1,1:x=$((x3 + i * step + 1)):y=$((ly + 24))" "$label")
    done
  fi
  args+=("$fixed" --swap --paste "+$x1+$pad" "$float" --swap --paste "+$x2+$pad" "$heat" --swap --paste "+$x3+$pad")
  ((have_font)) && args+=("$work/legend.png" --swap --paste "+$x3+$ly")  # the legend's numbers are captions
  oiiotool "${args[@]}" -d uint8 -o "$images_dir/$scene.png"
done

{
  cat <<'EOF'
# Gallery: fixed point against the float model

Generated by `scripts/gallery.sh`; do not edit by hand. Each panel shows one
example scene of `scenes/`: left, the fixed-point pipeline (the firmware's code,
run on the host) with the default knobs (`spanlight render --help` lists them and
their defaults); middle, the
double-precision float model, the reference; right, the heat map of
`spanlight compare fixed.png float.png --diff heat.png`: each pixel's largest
channel difference, black for none, then blue (1 LSB), green, yellow, red
(32 LSB and more) on a log scale.

Figures are those of `spanlight compare` (definitions in
`host_tools/compare/compare.hpp`): PSNR over all pixels and channels, the
largest and the mean absolute difference in 8-bit levels (LSB), and the
percentage of pixels whose largest channel difference exceeds 2 and 8 LSB.

| scene | size | PSNR (dB) | max (LSB) | mean (LSB) | % > 2 LSB | % > 8 LSB |
|---|---|---|---|---|---|---|
EOF
  printf '%s\n' "${rows[@]}"
  echo
  for scene_file in "$repo"/scenes/*.json; do
    scene=$(basename "$scene_file" .json)
    printf '## %s\n\n![%s: fixed | float | heat map](images/%s.png)\n\n' "$scene" "$scene" "$scene"
  done
  cat <<'EOF'
## Regenerating

From the repository root, after a build:

```sh
cmake --build build --target spanlight
scripts/gallery.sh build/bin/spanlight
```

It rewrites `docs/images/<scene>.png` for every `scenes/*.json` and this file.
Needs `oiiotool` (package `openimageio-tools`); captions need the DejaVu Sans
font (`fonts-dejavu-core`), without it the panels are drawn without them.
EOF
} >"$gallery_md"

echo "gallery: wrote $gallery_md and ${#rows[@]} panel(s) in $images_dir"
