#!/usr/bin/env bash
# The cost of a triangle apart from the cost of a pixel. `spanlight cost` measures SCENE at
# three frame sizes (W x H, W/2 x H/2, W/4 x H/4) with the same camera, so the same triangles
# reach setup while the pixels scale with the frame. A least-squares line over the three
#     instructions = per_frame + per_pixel * frame_pixels
# splits the frame: per_frame / triangles is what a triangle costs (its share of the vertex
# transforms and projections, clipping, setup, the per-object work), per_pixel what a pixel of
# the frame costs at the scene's coverage (clears, rows, spans, the pixel work).
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
triangles=$("$spanlight" analyze "$scene" | sed -nE 's/.* ([0-9]+) triangle\(s\).*/\1/p' | head -n 1)

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
echo "| core | instructions at ${width}x${height} | per frame (fit) | per triangle | per frame pixel (fit) | largest residual |"
echo "|---|---:|---:|---:|---:|---:|"
for cpu in cortex-m7 cortex-m0plus; do
  awk -v cpu="$cpu" -v tri="$triangles" '
    $1 == cpu { n++; x[n] = $2; y[n] = $3; sx += $2; sy += $3; sxx += $2 * $2; sxy += $2 * $3 }
    END {
      slope = (n * sxy - sx * sy) / (n * sxx - sx * sx); icept = (sy - slope * sx) / n
      worst = 0; for (i = 1; i <= n; i++) { r = y[i] - (icept + slope * x[i]); if (r < 0) r = -r; if (r > worst) worst = r }
      printf "| %s | %d | %.0f | %.0f | %.1f | %.0f |\n", cpu, y[1], icept, icept / tri, slope, worst
    }' "$results"
done
echo
echo "Exact QEMU counts of one render_frame call at each size (spanlight cost); the fit's residual"
echo "says how well cost splits into a part per frame and a part per pixel."
