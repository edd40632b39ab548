#!/usr/bin/env bash
# The main job: set up, build the CLI (and only what it is made of), render the default scene
# with both backends and compare.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake --build build -j"$(nproc)" --target spanlight
scene=${1:-scenes/slide_projector.json}
out=out/$(basename "$scene" .json)
mkdir -p "$out"
build/bin/spanlight render "$scene" --backend fixed --out "$out/fixed.png"
build/bin/spanlight render "$scene" --backend float --out "$out/float.png"
build/bin/spanlight compare "$out/fixed.png" "$out/float.png" --diff "$out/diff.png"
echo "images in $out/"
