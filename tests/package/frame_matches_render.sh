#!/usr/bin/env bash
# Checks a frame is byte-identical (0 LSB in every channel of every pixel) to `spanlight render`
# of its scene with the knobs it was baked with.
#   frame_matches_render.sh FRAME SPANLIGHT SCENE [KNOB]...
set -euo pipefail
frame=$1 spanlight=$2 scene=$3
shift 3
work=$(dirname "$frame")
"$spanlight" render "$scene" --backend fixed "$@" --out "$work/reference.png"
"$spanlight" compare "$frame" "$work/reference.png" --json >"$work/compare.json"
if ! grep -q '"max_abs_lsb": 0' "$work/compare.json"; then
  echo "$frame differs from spanlight render $scene $*:"
  cat "$work/compare.json"
  exit 1
fi
echo "$frame: identical to spanlight render $scene $*"
