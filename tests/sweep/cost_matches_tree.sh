#!/usr/bin/env bash
# `spanlight cost` counts exactly what the firmware tree's render_<scene>.elf counts for the
# same scene and knobs (both are render_baked's source, baked alike): textured_room on Cortex-M7.
#   cost_matches_tree.sh SPANLIGHT MEASURE_ELF PLUGIN BUILD_DIR SOURCE_DIR
set -euo pipefail
spanlight=$1
measure=$2
plugin=$3
build=$4
source_dir=$5
work=$(mktemp -d "${TMPDIR:-/tmp}/spanlight-cost-tree.XXXXXX")
trap 'rm -rf "$work"' EXIT
(cd "$work" && bash "$measure" --cpu cortex-m7 --plugin "$plugin" "$build/firmware-cortex-m7/bin/render_textured_room.elf" > tree.log)
tree=$(awk '$1 == "spanlight-measure:" && $2 == "instructions" { print $3 }' "$work/tree.log")
"$spanlight" cost "$source_dir/scenes/textured_room.json" --format rgb565 --depth-bits 16 --cpu cortex-m7 > "$work/cost.txt"
cat "$work/cost.txt"
cost=$(awk -F'|' '$2 ~ /cortex-m7/ { gsub(/ /, "", $3); print $3 }' "$work/cost.txt")
[ -n "$tree" ] && [ "$cost" = "$tree" ] || { echo "FAIL: cost counts '$cost', the tree's ELF $tree"; exit 1; }
echo "ok: both count $tree instructions"
