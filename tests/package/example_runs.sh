#!/usr/bin/env bash
# Runs one board's ELF of examples/firmware on a QEMU machine with that board's memory map and
# checks the frame it writes (through semihosting) equals `spanlight render` of its scene.
#   example_runs.sh RUNNER MACHINE ELF SPANLIGHT WORKDIR SCENE [KNOB]...
set -euo pipefail
runner=$1 machine=$2 elf=$3 spanlight=$4 work=$5 scene=$6
shift 6
rm -rf "$work"
mkdir -p "$work"
(cd "$work" && bash "$runner" --machine "$machine" --timeout 60 "$elf")
bash "$(dirname "$0")/frame_matches_render.sh" "$work/frame.ppm" "$spanlight" "$scene" "$@"
