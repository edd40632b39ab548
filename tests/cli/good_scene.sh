#!/usr/bin/env bash
# good_scene.sh SPANLIGHT BACKEND SCENE.json
#
# `spanlight render SCENE.json --backend BACKEND --out OUT.png` on an example
# scene exits 0, says nothing on stderr, and writes one PNG of the scene's
# output.width x output.height (and no temporary beside it).
export SPANLIGHT=$1
backend=$2
scene=$3
# shellcheck source=tests/cli/cli_lib.sh
source "$(dirname "$0")/cli_lib.sh"

# "output": { "width": W, "height": H } as the example scenes write it.
output=$(tr -d '\n' <"$scene" | grep -o '"output"[^}]*}')
width=$(sed -n 's/.*"width"[^0-9]*\([0-9]*\).*/\1/p' <<<"$output")
height=$(sed -n 's/.*"height"[^0-9]*\([0-9]*\).*/\1/p' <<<"$output")
if [[ -z "$width" || -z "$height" ]]; then
  fail "cannot read output.width and output.height from $scene"
  finish
fi

run_spanlight render "$scene" --backend "$backend" --out "$scratch/out.png"
expect_status 0
[[ -z "$err_text" ]] || fail "stderr should be empty, got: $err_text"
size=$(png_size "$scratch/out.png")
[[ "$size" == "$width $height" ]] || fail "out.png is '${size:-not a PNG}', expected '$width $height'"
expect_only_files "$scratch" out.png

# Against itself: identical, PSNR inf (the PNG reads back whole).
run_spanlight compare "$scratch/out.png" "$scratch/out.png"
expect_status 0
expect_stdout_has "PSNR            inf dB"

finish
