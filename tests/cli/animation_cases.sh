#!/usr/bin/env bash
# animation_cases.sh SPANLIGHT SOURCE_DIR CASE: `render --animation` and `bake --animation`
# on a good animation (scenes/live_spotlight.json with its animation).
#   render_animation_both  every frame of both backends, compare/psnr.csv with one line a
#                          frame, the worst frame printed; a second run into the same folder works
#   bake_animation         baked::animation, frame_count and object_count in the sources, and
#                          the depfile names the animation file
export SPANLIGHT=$1
source_dir=$2
case_name=$3
# shellcheck source=tests/cli/cli_lib.sh
source "$(dirname "$0")/cli_lib.sh"
scene=$source_dir/scenes/live_spotlight.json
animation=$source_dir/scenes/animations/live_spotlight.json

case "$case_name" in
render_animation_both)
  for run in first again; do
    run_spanlight render "$scene" --animation "$animation" --backend both --out "$scratch/out"
    expect_status 0
    expect_stdout_has "frame 0059: PSNR fixed vs float "
    expect_stdout_has "worst frame "
    for backend in fixed float; do
      count=$(find "$scratch/out/$backend" -name 'frame_*.png' | wc -l)
      [[ "$count" == 60 ]] || fail "$run run: $count frames in $backend/, expected 60"
    done
    expect_no_file "$scratch/out/fixed/frame_0060.png"
    lines=$(wc -l < "$scratch/out/compare/psnr.csv")
    [[ "$lines" == 61 ]] || fail "$run run: compare/psnr.csv has $lines lines, expected a header and 60"
  done
  ;;
bake_animation)
  run_spanlight bake "$scene" --animation "$animation" --out "$scratch/baked" --depfile "$scratch/baked/baked.d"
  expect_status 0
  grep -q "extern const spanlight::SceneAnimation animation;" "$scratch/baked/baked_config.hpp" || fail "no baked::animation"
  grep -q "inline constexpr std::uint32_t frame_count = 60;" "$scratch/baked/baked_config.hpp" || fail "no frame_count = 60"
  grep -q "inline constexpr std::uint16_t object_count = 3;" "$scratch/baked/baked_config.hpp" || fail "no object_count = 3"
  grep -q "const SceneAnimation animation{60, " "$scratch/baked/baked_scene.cpp" || fail "no animation definition"
  grep -qF "$animation" "$scratch/baked/baked.d" || fail "the depfile does not name $animation"
  ;;
*)
  fail "unknown case $case_name"
  ;;
esac
finish
