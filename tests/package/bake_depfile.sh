#!/usr/bin/env bash
# spanlight_bake's depfile at work: builds tests/package/bake_consumer (an installed spanlight,
# the given CMake generator) on a scratch copy of a scene, then touches one file at a time and
# builds again. Touching the scene, a texture or an OBJ mesh must bake again (and recompile the
# baked source); touching anything else, or nothing, must run nothing.
#   bake_depfile.sh SOURCE_DIR PREFIX GENERATOR WORKDIR SCENE_DIR SCENE_FILE
set -euo pipefail
source_dir=$1 prefix=$2 generator=$3 work=$4 scene_dir=$5 scene_file=$6
rm -rf "$work"
mkdir -p "$work"
cp -r "$scene_dir" "$work/scene"
scene=$work/scene/$scene_file
echo "not read by the bake" >"$work/scene/notes.txt"
cp "$work/scene/$(sed -n 's/.*"image": *"\([^"]*\.png\)".*/\1/p' "$scene" | head -n 1)" "$work/scene/unused.png"

build=$work/build
cmake -S "$source_dir/tests/package/bake_consumer" -B "$build" -G "$generator" \
  -DCMAKE_PREFIX_PATH="$prefix" -DSCENE="$scene" >/dev/null

failed=0
# expect_build BAKES COMPILES WHAT: builds and checks how many bakes and compiles ran.
expect_build() {
  local log bakes compiles
  log=$(cmake --build "$build" 2>&1)
  bakes=$(grep -c "Baking " <<<"$log" || true)
  compiles=$(grep -c "Building CXX object" <<<"$log" || true)
  if [ "$bakes" != "$1" ] || [ "$compiles" != "$2" ]; then
    echo "FAIL ($generator) $3: $bakes bake(s) and $compiles compile(s), expected $1 and $2"
    echo "$log"
    failed=1
  else
    echo "ok ($generator) $3: $bakes bake(s), $compiles compile(s)"
  fi
}
# touch_later FILE: a new modification time, later than every output of the last build.
touch_later() {
  sleep 1
  touch "$1"
}

expect_build 1 1 "first build"
expect_build 0 0 "nothing changed"
touch_later "$work/scene/notes.txt"
expect_build 0 0 "a file the scene does not name"
touch_later "$work/scene/unused.png"
expect_build 0 0 "an image the scene does not name"
# The files the scene names: "image" and "mesh" values with an extension (a projector's "image"
# names a texture, not a file).
for asset in $(sed -n 's/.*"\(image\|mesh\)": *"\([^"]*\.[a-z]*\)".*/\2/p' "$scene" | sort -u); do
  touch_later "$work/scene/$asset"
  expect_build 1 1 "$asset"
done
touch_later "$scene"
expect_build 1 1 "the scene file"
expect_build 0 0 "nothing changed after that"
exit "$failed"
