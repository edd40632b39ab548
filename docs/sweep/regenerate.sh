#!/usr/bin/env bash
# Regenerates the committed sweep results, docs/sweep/<scene>/, for every shared scene and the
# two anchor scenes, with the default grid, counted on Cortex-M7 and Cortex-M0+ in QEMU.
#   docs/sweep/regenerate.sh [BUILD_DIR]      (default: build; needs bin/spanlight, the
#                                              firmware trees and the QEMU plugin built)
# Takes about 5 minutes in all on an idle 2-core machine. Run from anywhere; scene paths in the output are relative
# to the source tree.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
cd "$root"
# Which sources the figures come from: the commit, and any local change to the pipeline.
{
  echo "commit $(git rev-parse HEAD 2>/dev/null || echo unknown), swept $(date -u +%Y-%m-%d)"
  git status --short -- firmware fixedpoint 2>/dev/null | sed 's/^/local change: /'
} >docs/sweep/SOURCE.txt
# slide_projector, the scene of the target figures, with every configuration counted on QEMU
# (about 2 minutes); the others with QEMU's cost-relevant grid (under a minute each).
"$build/bin/spanlight" sweep scenes/slide_projector.json --out docs/sweep/slide_projector --qemu-grid full --pictures 3 \
  --firmware-dir "$build"
for scene in spot_shadow three_projectors horizon; do
  "$build/bin/spanlight" sweep "scenes/$scene.json" --out "docs/sweep/$scene" --pictures 3 --firmware-dir "$build"
done
# The anchor scenes of shared/anchors.md (RGB565, baked with 16-bit depth), for the comparison with tgx.
for scene in textured_room textured_room_nearest; do
  "$build/bin/spanlight" sweep "scenes/$scene.json" --out "docs/sweep/$scene" --format rgb565 --pictures 2 \
    --firmware-dir "$build"
done
