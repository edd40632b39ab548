#!/usr/bin/env bash
# `spanlight bake --depfile FILE`: the file names the scene and every asset it read; a depfile
# name that is one of the inputs, a baked source, a directory or a FIFO is bad input (exit 2,
# "FILE: --depfile: expected ...") and nothing is written.
#   bake_depfile_cli.sh SPANLIGHT SOURCE_DIR
SPANLIGHT=$1
root=$2
# shellcheck source=../cli/cli_lib.sh
source "$root/tests/cli/cli_lib.sh"

cp -r "$root/scenes/assets" "$scratch/assets"
cp "$root/scenes/textured_room.json" "$scratch/room.json"

run_spanlight bake "$scratch/room.json" --out "$scratch/baked" --depfile "$scratch/baked.d"
expect_status 0
# textured_room.json names two images and two OBJ files (see the scene).
expected="$scratch/baked/baked_scene.cpp $scratch/baked/baked_config.hpp: \\
  $scratch/room.json \\
  $scratch/assets/textures/wood.png \\
  $scratch/assets/textures/brick.png \\
  $scratch/assets/meshes/room.obj \\
  $scratch/assets/meshes/box.obj"
[[ "$(cat "$scratch/baked.d")" == "$expected" ]] || fail "depfile reads [$(cat "$scratch/baked.d")], expected [$expected]"

# Refused names: nothing is written, the inputs are unchanged.
cp "$scratch/room.json" "$scratch/room.json.before"
mkfifo "$scratch/fifo"
mkdir "$scratch/folder"
for depfile in "$scratch/room.json" "$scratch/assets/meshes/box.obj" "$scratch/fresh/baked_scene.cpp" \
               "$scratch/fifo" "$scratch/folder"; do
  run_spanlight bake "$scratch/room.json" --out "$scratch/fresh" --depfile "$depfile"
  expect_status 2
  expect_stderr_has "$depfile: --depfile: expected"
  expect_no_file "$scratch/fresh"
done
cmp -s "$scratch/room.json" "$scratch/room.json.before" || fail "the scene was changed"
[[ -p "$scratch/fifo" ]] || fail "the FIFO was replaced"
finish
