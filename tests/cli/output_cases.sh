#!/usr/bin/env bash
# output_cases.sh SPANLIGHT SOURCE_DIR CASE
#
# What the commands will and will not write (host_tools/io): never over a
# device, a FIFO or a folder, never over one of the run's inputs however it is
# spelled (another path, a symlink, a hard link), into bake and sweep folders
# only what they wrote before unless --force, and a whole file or nothing,
# also with eight renders racing for one output. The scenes are copied into the
# scratch folder first, so a regression damages copies, never the source tree.
export SPANLIGHT=$1
source_dir=$2
case_name=$3
# shellcheck source=tests/cli/cli_lib.sh
source "$(dirname "$0")/cli_lib.sh"

work="$scratch/work"
mkdir -p "$work"
cp -r "$source_dir/scenes/slide_projector.json" "$source_dir/scenes/assets" "$work/"
cp "$source_dir/tests/sweep/scenes/wide_uv.json" "$work/wide_uv.json"
sed -i 's|"\.\./\.\./\.\./scenes/assets/|"assets/|' "$work/wide_uv.json"  # now beside its texture
scene="$work/slide_projector.json"
refused_input="expected a file that is not one of this run's inputs, got the same file as the input"

# refused_over_input PATH_AS_GIVEN FILE_IT_IS ARGS...: the command refuses
# (exit 2, the message), and FILE_IT_IS keeps its bytes.
refused_over_input() {
  local given=$1 file=$2
  shift 2
  cp "$file" "$scratch/before"
  run_spanlight "$@"
  expect_status 2
  expect_stderr_has "$given: "
  expect_stderr_has "$refused_input"
  cmp -s "$file" "$scratch/before" || fail "$file was changed"
}

case "$case_name" in
render_out_device)
  # A device node of our own when allowed (root), so a regression cannot touch /dev.
  if mknod "$scratch/null" c 1 3 2>/dev/null; then device="$scratch/null"; else device=/dev/null; fi
  run_spanlight render "$scene" --out "$device"
  expect_status 2
  expect_stderr_has "$device: --out: expected a regular file or a new name, got a character device (left as it is)"
  [[ -c "$device" ]] || fail "$device is no longer a character device"
  if [[ "$device" == "$scratch/null" ]]; then expect_only_files "$scratch" null work; fi  # no temporary beside it
  ;;
render_out_fifo_and_folder)
  mkfifo "$scratch/fifo"
  run_spanlight render "$scene" --out "$scratch/fifo"
  expect_status 2
  expect_stderr_has "fifo: --out: expected a regular file or a new name, got a FIFO"
  [[ -p "$scratch/fifo" ]] || fail "the FIFO was replaced"
  run_spanlight render "$scene" --out "$work/assets"
  expect_status 2
  expect_stderr_has "assets: --out: expected a regular file or a new name, got a folder"
  ;;
render_out_symlinks)
  ln -s nothing "$scratch/dangling.png"
  run_spanlight render "$scene" --out "$scratch/dangling.png"
  expect_status 2
  expect_stderr_has "dangling.png: --out: expected a regular file or a new name, got a symlink to no file"
  ln -s loop_b "$scratch/loop_a"
  ln -s loop_a "$scratch/loop_b"
  run_spanlight render "$scene" --out "$scratch/loop_a"
  expect_status 2
  expect_stderr_has "loop_a: --out: expected a regular file or a new name, got a symlink loop"
  # A symlink to a regular file: that file is replaced, the link kept.
  mkdir "$scratch/real"
  make_previous_output "$scratch/real/out.png"
  ln -s real/out.png "$scratch/link.png"
  run_spanlight render "$scene" --out "$scratch/link.png"
  expect_status 0
  [[ -L "$scratch/link.png" ]] || fail "link.png is no longer a symlink"
  [[ "$(png_size "$scratch/real/out.png")" == "320 240" ]] || fail "the file link.png names was not replaced by the render"
  expect_only_files "$scratch/real" out.png
  ;;
render_out_is_an_input)
  refused_over_input "$scene" "$scene" render "$scene" --out "$scene"
  refused_over_input "$work/assets/../slide_projector.json" "$scene" render "$scene" --out "$work/assets/../slide_projector.json"
  refused_over_input "$work/assets/textures/wood.png" "$work/assets/textures/wood.png" \
    render "$scene" --out "$work/assets/textures/wood.png"
  refused_over_input "$work/assets/meshes/room.obj" "$work/assets/meshes/room.obj" \
    render "$scene" --out "$work/assets/meshes/room.obj" --backend float
  ln "$scene" "$scratch/hard_link.json"
  refused_over_input "$scratch/hard_link.json" "$scene" render "$scene" --out "$scratch/hard_link.json"
  ln -s "$work/assets/textures/slide.png" "$scratch/soft_link.png"
  refused_over_input "$scratch/soft_link.png" "$work/assets/textures/slide.png" render "$scene" --out "$scratch/soft_link.png"
  # The scene given by another spelling, the output by its plain name.
  refused_over_input "$scene" "$scene" render "$work/assets/../slide_projector.json" --out "$scene"
  # A copy is another file: replaced.
  cp "$work/assets/textures/wood.png" "$scratch/copy.png"
  run_spanlight render "$scene" --out "$scratch/copy.png"
  expect_status 0
  ;;
compare_diff_is_an_input)
  a="$work/assets/textures/brick.png"
  b="$work/assets/textures/wood.png"
  refused_over_input "$a" "$a" compare "$a" "$b" --diff "$a"
  ln "$b" "$scratch/b_again.png"
  refused_over_input "$scratch/b_again.png" "$b" compare "$a" "$b" --diff "$scratch/b_again.png"
  if [[ -n "$out_text" ]]; then fail "a refused compare printed figures: $out_text"; fi
  run_spanlight compare "$a" "$b" --diff "$scratch/heat.png"
  expect_status 0
  [[ "$(png_size "$scratch/heat.png")" == "128 128" ]] || fail "no 128 x 128 heat map"
  ;;
analyze_write_config_is_an_input)
  # Refused before any sweeping: the scene, or the CSV it reads.
  refused_over_input "$work/wide_uv.json" "$work/wide_uv.json" \
    analyze "$work/wide_uv.json" --qemu-grid none --write-config "$work/wide_uv.json"
  printf 'not read: the output check comes first\n' >"$scratch/sweep.csv"
  refused_over_input "$scratch/sweep.csv" "$scratch/sweep.csv" \
    analyze "$work/wide_uv.json" --sweep-csv "$scratch/sweep.csv" --write-config "$scratch/sweep.csv"
  ;;
bake_folder_rules)
  out="$scratch/baked"
  manifest=.spanlight-written
  run_spanlight bake "$scene" --out "$out"
  expect_status 0
  expect_only_files "$out" "$manifest" baked_config.hpp baked_scene.cpp
  run_spanlight bake "$scene" --out "$out" --span 4  # again, into its own folder
  expect_status 0
  grep -q -- "--span 4 " "$out/baked_config.hpp" || fail "the second bake (--span 4) did not replace baked_config.hpp"
  printf 'mine\n' >"$out/notes.txt"
  run_spanlight bake "$scene" --out "$out"
  expect_status 2
  expect_stderr_has "$out: --out: expected a new or empty folder, or one holding only files spanlight wrote there"
  expect_stderr_has "got 1 other file(s): notes.txt"
  run_spanlight bake "$scene" --out "$out" --force
  expect_status 0
  [[ "$(cat "$out/notes.txt")" == mine ]] || fail "--force touched notes.txt"
  # A folder of the user's own, such as the scene's: refused.
  run_spanlight bake "$scene" --out "$work"
  expect_status 2
  expect_stderr_has "other file(s): assets/"
  expect_only_files "$work" assets slide_projector.json wide_uv.json
  run_spanlight bake "$scene" --out "$scene"
  expect_status 2
  expect_stderr_has "$scene: --out: expected a folder or a new name, got a regular file"
  ;;
sweep_folder_rules)
  out="$scratch/sweep"
  small_grid=(--table-bits 8 --newton 1 --depth-bits 24 --passes fused --qemu-grid none --repeats 1 --no-per-pass --quiet)
  mkdir "$out"
  printf 'mine\n' >"$out/notes.txt"
  run_spanlight sweep "$work/wide_uv.json" --out "$out" "${small_grid[@]}" --span 64 --filters scene
  expect_status 2
  expect_stderr_has "got 1 other file(s): notes.txt"
  rm "$out/notes.txt"
  # Rows: scene/span 1, scene/span 64 (the default, always pictured), nearest/1, nearest/64.
  run_spanlight sweep "$work/wide_uv.json" --out "$out" "${small_grid[@]}" --span 1,64 --filters scene,nearest --pictures 2
  expect_status 0
  [[ -f "$out/images/1-fixed.png" ]] || fail "the default row's picture is missing"
  # Again with one row: the earlier pictures go, a file of the user's in images/ stays (--force).
  printf 'mine\n' >"$out/images/keep.txt"
  run_spanlight sweep "$work/wide_uv.json" --out "$out" "${small_grid[@]}" --span 64 --filters scene --pictures 1
  expect_status 2
  run_spanlight sweep "$work/wide_uv.json" --out "$out" "${small_grid[@]}" --span 64 --filters scene --pictures 1 --force
  expect_status 0
  [[ "$(find "$out/images" -name '*-fixed.png' | wc -l)" == 1 && -f "$out/images/0-fixed.png" ]] ||
    fail "the earlier pictures were not removed"
  [[ -f "$out/images/keep.txt" ]] || fail "the user's file in images/ was removed"
  ;;
render_eight_at_once)
  # Eight renders of one scene to one output at once: every one succeeds, and
  # what is left is one PNG equal to a single render, with no temporary.
  mkdir "$scratch/race"
  "$SPANLIGHT" render "$scene" --out "$scratch/single.png" || fail "the single render failed"
  pids=()
  for i in 1 2 3 4 5 6 7 8; do
    "$SPANLIGHT" render "$scene" --out "$scratch/race/out.png" 2>"$scratch/err_$i" &
    pids+=($!)
  done
  for i in "${!pids[@]}"; do
    wait "${pids[$i]}" || fail "render $((i + 1)) of 8 failed: $(cat "$scratch/err_$((i + 1))")"
  done
  cmp -s "$scratch/race/out.png" "$scratch/single.png" || fail "out.png differs from a single render"
  [[ "$(png_size "$scratch/race/out.png")" == "320 240" ]] || fail "out.png is not a valid 320 x 240 PNG"
  expect_only_files "$scratch/race" out.png
  ;;
*)
  fail "unknown case $case_name"
  ;;
esac

finish
