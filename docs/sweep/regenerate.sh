#!/usr/bin/env bash
# Regenerates the committed sweep results, docs/sweep/<scene>/, for every shared scene, the
# two anchor scenes and mesh_bear, with the default grid (its values from the knob table: spans 1, 4, 16, 64,
# every table size, Newton 0 and 1, both depth settings), counted on Cortex-M7 and Cortex-M0+
# in QEMU through tools/qemu_icount/measure_elf.sh.
#   docs/sweep/regenerate.sh [BUILD_DIR [OUT_DIR [SWEEP_OPTION...]]]
#     BUILD_DIR  default build; needs bin/spanlight, the firmware trees (firmware-<cpu>/bin with
#                the sweep_bench_<scene> ELFs: configure with -DSPANLIGHT_SWEEP_BENCH_SCENES=all)
#                and the QEMU plugin built
#     OUT_DIR    default docs/sweep; another folder leaves the committed results alone
#     SWEEP_OPTION...  passed to every sweep, e.g. a small grid: --span 16,64 --table-bits 8
# Run from anywhere; scene paths in the output are relative to the source tree.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
out=${2:-$root/docs/sweep}
shift $(($# > 2 ? 2 : $#))
cd "$root"
# slide_projector, the scene of the target figures, is counted on QEMU at every point; the shared
# scenes with QEMU's cost-relevant grid (the default table and depth bits only); the anchor scenes
# of shared/anchors.md (RGB565, for the comparison with tgx) and the model of 2,400 small triangles
# (docs/meshes.md) the same way, in RGB565.
shared=(spot_shadow three_projectors horizon)
rgb565=(textured_room textured_room_nearest mesh_bear)
# Every bench must be one the firmware trees build now: a bench left in bin/ by an earlier
# configuration would be counted on an older engine without a word.
for cpu in cortex-m7 cortex-m0plus; do
  built=$(sed -n 's/^SPANLIGHT_SWEEP_BENCH_SCENES:STRING=//p' "$build/firmware-$cpu/CMakeCache.txt" 2>/dev/null || true)
  for scene in slide_projector "${shared[@]}" "${rgb565[@]}"; do
    case ";$built;" in
      *";all;"* | *";$scene;"*) ;;
      *) echo "regenerate: $build/firmware-$cpu builds sweep benches for '$built', not $scene: configure with" \
           "-DSPANLIGHT_SWEEP_BENCH_SCENES=all until that tree's CMakeCache.txt says so, and build" >&2
         exit 2 ;;
    esac
  done
done
mkdir -p "$out"
# Which sources the figures come from: the commit, and any local change to the pipeline.
{
  echo "commit $(git rev-parse HEAD 2>/dev/null || echo unknown), swept $(date -u +%Y-%m-%d)"
  git status --short -- pipeline fixedpoint firmware 2>/dev/null | sed 's/^/local change: /'
} >"$out/SOURCE.txt"
"$build/bin/spanlight" sweep scenes/slide_projector.json --out "$out/slide_projector" --qemu-grid full --pictures 3 \
  --firmware-dir "$build" "$@"
for scene in "${shared[@]}"; do
  "$build/bin/spanlight" sweep "scenes/$scene.json" --out "$out/$scene" --pictures 3 --firmware-dir "$build" "$@"
done
for scene in "${rgb565[@]}"; do
  "$build/bin/spanlight" sweep "scenes/$scene.json" --out "$out/$scene" --format rgb565 --pictures 2 \
    --firmware-dir "$build" "$@"
done
