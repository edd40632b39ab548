#!/usr/bin/env bash
# The cost of a triangle apart from the cost of a pixel. `spanlight cost` measures SCENE at
# three frame sizes (scale s = 1, 1/2, 1/4 of W x H) with the same camera, so the same
# triangles reach setup while their rows scale with s and their pixels with s^2. The parabola
# through the three counts,
#     instructions(s) = per_frame + per_rows * s + per_pixels * s^2,
# splits the frame: per_frame (its value at s = 0) / triangles is what a triangle costs apart
# from its rows and pixels (its share of the vertex transforms and projections, clipping,
# setup, the per-object work); per_rows is the part that grows with the rows (row edges, span
# ends, segments), per_pixels the part that grows with the area (clears, the pixel work).
#   scripts/triangle-cost.sh [BUILD_DIR] SCENE.json [KNOB...]
#     BUILD_DIR  default build (needs bin/spanlight; spanlight cost cross-builds in a scratch folder)
#     KNOB...    passed to spanlight cost, e.g. --format rgb565 --depth-bits 16
# The scene's "output" must name width and height on one line, as the repository's scenes do.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build="$root/build"
if [ $# -gt 0 ] && [ -d "$1" ]; then build=$(cd "$1" && pwd); shift; fi
[ $# -ge 1 ] || { echo "usage: scripts/triangle-cost.sh [BUILD_DIR] SCENE.json [KNOB...]" >&2; exit 2; }
scene=$1; shift
[ -f "$scene" ] || { echo "triangle-cost: $scene: no such scene file" >&2; exit 2; }
spanlight="$build/bin/spanlight"
scene_dir=$(cd "$(dirname "$scene")" && pwd)

size=$(grep -oE '"output"[^}]*' "$scene" | head -n 1)
width=$(sed -nE 's/.*"width": *([0-9]+).*/\1/p' <<<"$size")
height=$(sed -nE 's/.*"height": *([0-9]+).*/\1/p' <<<"$size")
[ -n "$width" ] && [ -n "$height" ] ||
  { echo "triangle-cost: $scene: output: expected width and height on the \"output\" line" >&2; exit 2; }
triangles=$("$spanlight" analyze "$scene" 2>/dev/null | sed -nE 's/.* ([0-9]+) triangle\(s\).*/\1/p' | head -n 1)

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
results="$work/results.txt"
for divisor in 1 2 4; do
  w=$((width / divisor)) h=$((height / divisor))
  copy="$work/scene_${w}x${h}.json"
  # The same scene at another size; its files named from the scene's own folder.
  sed -E -e "/\"output\"/{s/(\"width\": *)[0-9]+/\1$w/; s/(\"height\": *)[0-9]+/\1$h/}" \
         -e "s#\"(image|mesh)\": *\"([^/\"][^\"]*)\"#\"\1\": \"$scene_dir/\2\"#g" "$scene" >"$copy"
  echo "triangle-cost: ${w}x${h}" >&2
  "$spanlight" cost "$copy" --cpu cortex-m7,cortex-m0plus "$@" |
    awk -v px=$((w * h)) -F'|' '/^\| cortex-/ { gsub(/ /, "", $2); gsub(/ /, "", $3); gsub(/ /, "", $4); print $2, px, $3, $4 }' >>"$results"
done

echo "$(basename "$scene") at ${width}x${height}, /2 and /4; $triangles triangles; knobs: ${*:-defaults}"
echo
echo "| core | at s = 1 | s = 1/2 | s = 1/4 | per frame (s = 0) | per triangle | rows part at s = 1 | pixels part at s = 1 |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|"
for cpu in cortex-m7 cortex-m0plus; do
  # Lagrange: the parabola's coefficients from its values y1, y2, y3 at s = 1, 1/2, 1/4.
  awk -v cpu="$cpu" -v tri="$triangles" '
    $1 == cpu { n++; y[n] = $3 }
    END {
      a = y[1] / 3 - 2 * y[2] + 8 * y[3] / 3          # value at s = 0
      c = (8 * y[1] - 24 * y[2] + 16 * y[3]) / 3      # s^2 coefficient
      b = y[1] - a - c                                 # s coefficient
      printf "| %s | %.2f M | %.2f M | %.2f M | %.2f M | %.0f | %.2f M | %.2f M |\n", cpu, y[1] / 1e6, y[2] / 1e6,
        y[3] / 1e6, a / 1e6, a / tri, b / 1e6, c / 1e6
    }' "$results"
done
echo
echo "Exact QEMU counts of one render_frame call at each size (spanlight cost), s the frame's scale."
