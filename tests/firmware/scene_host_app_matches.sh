#!/usr/bin/env bash
# The host build of render_<scene> (same source, host HAL, baked Features) must produce the
# same frame as `spanlight render` (generic host Features): what a scene does not use
# changes no pixel.
#   scene_host_app_matches.sh HOST_APP SPANLIGHT REFERENCE_PNG WORKDIR
set -euo pipefail
app=$1 spanlight=$2 reference=$3 workdir=$4
mkdir -p "$workdir"
"$app" "$workdir/host_app.ppm"
"$spanlight" compare "$workdir/host_app.ppm" "$reference" --json > "$workdir/compare.json"
grep -q '"max_abs_lsb": 0' "$workdir/compare.json" || { cat "$workdir/compare.json"; exit 1; }
echo "$(basename "$app"): identical to $reference"
