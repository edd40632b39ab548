#!/usr/bin/env bash
# bad_animation.sh SPANLIGHT COMMAND ANIMATION.json SCENE.json FIELD NAMED
#
# COMMAND is render-fixed, render-float, render-both or bake. On a malformed animation
# (or an animation whose pose the pipeline cannot build) the command must exit 2 with
# "FILE: FIELD: expected ..." on stderr, FILE being the animation (NAMED = animation)
# or the scene (NAMED = scene), print nothing on stdout, and leave no output folder.
export SPANLIGHT=$1
command=$2
animation=$3
scene=$4
field=$5
named=$6
# shellcheck source=tests/cli/cli_lib.sh
source "$(dirname "$0")/cli_lib.sh"

named_file=$(basename "$animation")
[[ "$named" == "scene" ]] && named_file=$(basename "$scene")

out="$scratch/frames"
case "$command" in
  render-*) run_spanlight render "$scene" --animation "$animation" --backend "${command#render-}" --out "$out" ;;
  bake) run_spanlight bake "$scene" --animation "$animation" --out "$out" --depfile "$out/baked.d" ;;
  *) fail "unknown command $command" ;;
esac
expect_status 2
expect_stderr_has "$named_file: $field: expected "
if [[ -n "$out_text" ]]; then fail "stdout should be empty, got: $out_text"; fi
expect_no_file "$out"
expect_only_files "$scratch"
finish
