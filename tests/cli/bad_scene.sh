#!/usr/bin/env bash
# bad_scene.sh SPANLIGHT BACKEND SCENE.json FIELD NAMED_FILE
#
# `spanlight render SCENE.json --backend BACKEND --out OUT.png` on a malformed
# scene must exit 2 with "FILE: FIELD: expected ..." on stderr, where FILE is
# the scene and the message also names NAMED_FILE ("-": the scene itself; else
# the asset at fault, as "FILE: FIELD: ASSET: expected ..."), and must leave no
# output behind: no OUT.png, no temporary beside it, and an OUT.png that was
# already there is left byte for byte as it was.
export SPANLIGHT=$1
backend=$2
scene=$3
field=$4
named_file=$5
# shellcheck source=tests/cli/cli_lib.sh
source "$(dirname "$0")/cli_lib.sh"

scene_name=$(basename "$scene")
[[ "$named_file" == "-" ]] && named_file=$scene_name
if [[ "$field" == "-" ]]; then
  fail "$(basename "$scene") is not in tests/cli/bad_fields.txt: add its field path there"
  finish
fi

check_message() {
  expect_status 2
  expect_stderr_has "$scene_name: "  # the scene first, also when an asset is at fault
  expect_stderr_has "$named_file"
  # The field as the message's second part, not merely somewhere in a path
  # ("name" is also in "name_not_string.json").
  expect_stderr_has ": $field: "
  expect_stderr_has "expected "
  if [[ -n "$out_text" ]]; then fail "stdout should be empty, got: $out_text"; fi
}

# 1. No output file beforehand: none afterwards.
mkdir "$scratch/fresh"
run_spanlight render "$scene" --backend "$backend" --out "$scratch/fresh/out.png"
check_message
expect_no_file "$scratch/fresh/out.png"
expect_only_files "$scratch/fresh"

# 2. An earlier output: left as it was.
mkdir "$scratch/existing"
make_previous_output "$scratch/existing/out.png"
run_spanlight render "$scene" --backend "$backend" --out "$scratch/existing/out.png"
check_message
expect_unchanged_previous_output "$scratch/existing/out.png"
expect_only_files "$scratch/existing" out.png

finish
