#!/usr/bin/env bash
# Where a baked scene's frame spends its instructions, on the target: runs
# tools/qemu_icount/profile_on_qemu.sh on render_<scene> for Cortex-M7 and
# Cortex-M0+ and writes docs/profile/<scene>-<cpu>.md (per stage, pass, machine
# function and hottest source lines; the attributed total is the exact count).
#   scripts/profile-report.sh [BUILD_DIR] [SCENE]...   (default: build; slide_projector textured_room)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
shift || true
scenes=("$@")
[ ${#scenes[@]} -gt 0 ] || scenes=(slide_projector textured_room)
plugin=$build/tools/qemu_icount/libspanlight_icount.so
out=$root/docs/profile
mkdir -p "$out"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for scene in "${scenes[@]}"; do
  for cpu in cortex-m7 cortex-m0plus; do
    elf=$build/firmware-$cpu/bin/render_$scene.elf
    [ -f "$elf" ] || { echo "profile-report: no $elf (build first)" >&2; exit 2; }
    echo "profile-report: $scene on $cpu" >&2
    tables=$(cd "$work" && "$root/tools/qemu_icount/profile_on_qemu.sh" --cpu "$cpu" --plugin "$plugin" --top 30 \
      --work "$work/$scene-$cpu" "$elf" "$work/$scene-$cpu.ppm")
    {
      echo "# $scene on $cpu: where the frame's instructions go"
      echo
      echo "Written by \`scripts/profile-report.sh\` on $(date -u +%Y-%m-%d), commit $(git -C "$root" rev-parse --short HEAD)."
      echo "Every instruction of the measured \`render_frame\` call, counted by the QEMU plugin and attributed to the"
      echo "source line it was compiled from (inlined code counts in its own file; the pass is the kernel it was"
      echo "inlined into). Default knobs, as \`render_$scene\` is baked."
      echo
      echo "$tables"
    } >"$out/$scene-$cpu.md"
  done
done
