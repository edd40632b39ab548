#!/usr/bin/env bash
# cli_cases.sh SPANLIGHT SOURCE_DIR CASE
#
# One command-line behaviour per CASE (ctest runs each as its own test):
# bad input other than a malformed scene (missing or odd files, unknown
# options, knobs out of range) must exit 2 with a message naming the file or
# option and leave no output behind; `compare` reports identical and
# different images as documented in host_tools/compare/compare.hpp.
export SPANLIGHT=$1
source_dir=$2
case_name=$3
# shellcheck source=tests/cli/cli_lib.sh
source "$(dirname "$0")/cli_lib.sh"

good_scene="$source_dir/scenes/horizon.json"
small_png="$source_dir/tests/scene/bad/assets/npot_3x3.png"    # 3 x 3 RGB
other_png="$source_dir/scenes/assets/textures/checker.png"     # 64 x 64 RGB
wide_png="$source_dir/tests/scene/bad/assets/wide_4097x1.png"  # 4097 x 1 grey: beyond the 4096 limit

# render GOOD_SCENE with extra arguments that must be refused: exit 2, stderr
# names WHAT, no output written, and an existing output left as it was.
expect_refused_render() {
  local what=$1
  shift
  mkdir -p "$scratch/fresh" "$scratch/existing"
  run_spanlight render "$good_scene" --out "$scratch/fresh/out.png" "$@"
  expect_status 2
  expect_stderr_has "$what"
  expect_only_files "$scratch/fresh"
  make_previous_output "$scratch/existing/out.png"
  run_spanlight render "$good_scene" --out "$scratch/existing/out.png" "$@"
  expect_status 2
  expect_unchanged_previous_output "$scratch/existing/out.png"
  expect_only_files "$scratch/existing" out.png
  rm -rf "$scratch/fresh" "$scratch/existing"
}

# Renders the good scene (for tests that need two different images of one size).
render_to() {  # render_to BACKEND OUT.png
  "$SPANLIGHT" render "$good_scene" --backend "$1" --out "$2" >/dev/null 2>&1 ||
    fail "could not render $good_scene with --backend $1 (needed by this test)"
}

case "$case_name" in
# ---------------------------------------------------------------- render: files
render_missing_scene)
  for backend in fixed float; do
    run_spanlight render "$scratch/no_such_scene.json" --backend "$backend" --out "$scratch/out.png"
    expect_status 2
    expect_stderr_has "no_such_scene.json"
    expect_stderr_has "no such file"
    expect_only_files "$scratch"
  done
  make_previous_output "$scratch/out.png"
  run_spanlight render "$scratch/no_such_scene.json" --out "$scratch/out.png"
  expect_status 2
  expect_unchanged_previous_output "$scratch/out.png"
  expect_only_files "$scratch" out.png
  ;;
render_scene_is_directory)
  mkdir "$scratch/a_folder.json" "$scratch/o"
  for backend in fixed float; do
    run_spanlight render "$scratch/a_folder.json" --backend "$backend" --out "$scratch/o/out.png"
    expect_status 2
    expect_stderr_has "a_folder.json"
    expect_only_files "$scratch/o"
  done
  ;;
render_out_folder_missing)
  for backend in fixed float; do
    run_spanlight render "$good_scene" --backend "$backend" --out "$scratch/no_such_folder/out.png"
    expect_status 2
    expect_stderr_has "no_such_folder/out.png"
    expect_no_file "$scratch/no_such_folder"
    expect_only_files "$scratch"
  done
  ;;
render_out_is_directory)
  # --out names an existing folder: refused, the folder and its contents kept,
  # no temporary left beside it.
  mkdir -p "$scratch/out.png"
  make_previous_output "$scratch/out.png/keep"
  run_spanlight render "$good_scene" --out "$scratch/out.png"
  expect_status 2
  expect_stderr_has "out.png"
  expect_only_files "$scratch" out.png
  expect_only_files "$scratch/out.png" keep
  expect_unchanged_previous_output "$scratch/out.png/keep"
  ;;
# -------------------------------------------------------------- render: options
render_missing_out)
  run_spanlight render "$good_scene"
  expect_status 2
  expect_stderr_has "--out"
  ;;
render_missing_scene_argument)
  run_spanlight render --out "$scratch/out.png"
  expect_status 2
  expect_stderr_has "scene"
  expect_only_files "$scratch"
  ;;
render_unknown_option)
  expect_refused_render "--frobnicate" --frobnicate 3
  ;;
render_unknown_backend)
  expect_refused_render "--backend" --backend gpu
  ;;
render_both_needs_animation)
  expect_refused_render "--backend: expected fixed or float without --animation, got both" --backend both
  ;;
render_span_3)
  expect_refused_render "--span" --span 3
  ;;
render_span_128)
  expect_refused_render "--span" --span 128
  ;;
render_span_not_a_number)
  expect_refused_render "--span" --span sixteen
  ;;
render_table_bits_7)
  expect_refused_render "--table-bits" --table-bits 7
  ;;
render_newton_3)
  expect_refused_render "--newton" --newton 3
  ;;
render_depth_bits_20)
  expect_refused_render "--depth-bits" --depth-bits 20
  ;;
render_tolerance_11)
  expect_refused_render "--tolerance" --tolerance 11
  ;;
render_format_unknown)
  expect_refused_render "--format" --format rgb444
  ;;
no_subcommand)
  run_spanlight
  expect_status 2
  run_spanlight frobnicate
  expect_status 2
  ;;
help)
  run_spanlight --help
  expect_status 0
  expect_stdout_has "render"
  expect_stdout_has "compare"
  run_spanlight render --help
  expect_status 0
  expect_stdout_has "--span"
  ;;
# --------------------------------------------------------------- render: knobs
render_every_knob)
  # Every accepted value of every knob renders (fixed backend) and writes a PNG
  # of the scene's size; nothing else is left in the folder.
  i=0
  for knobs in "--span 1" "--span 64" "--table-bits 6" "--table-bits 12" "--newton 0" "--newton 2" \
      "--depth-bits 16" "--format rgb565" "--format rgb565-be" "--passes multipass" "--passes fused" \
      "--tolerance 0" "--tolerance 10" "--mip segment" "--mip trilinear" \
      "--span 4 --table-bits 10 --newton 2 --depth-bits 16 --format rgb565 --passes multipass --tolerance 5"; do
    i=$((i + 1))
    # shellcheck disable=SC2086  # the knobs are meant to split
    run_spanlight render "$good_scene" --backend fixed --out "$scratch/knobs_$i.png" $knobs
    expect_status 0
    if [[ "$(png_size "$scratch/knobs_$i.png")" != "320 240" ]]; then
      fail "$knobs: $scratch/knobs_$i.png is not a 320 x 240 PNG"
    fi
    mapfile -t visible < <(cd "$scratch" && ls)
    expect_only_files "$scratch" "${visible[@]}"  # no hidden temporaries
  done
  mapfile -t rendered < <(for k in $(seq 1 "$i"); do echo "knobs_$k.png"; done)
  expect_only_files "$scratch" "${rendered[@]}"
  ;;
render_inaccurate_knobs_warn)
  # A reciprocal worse than 2^-11 (no Newton step, table below 12 bits) renders
  # but warns with its error bound (docs/reciprocal.md: 7.83e-3 for 6 bits, 2.00
  # texels at 256); every other combination is silent.
  for knobs in "--table-bits 6 --newton 0" "--table-bits 8 --newton 0" "--table-bits 10 --newton 0"; do
    # shellcheck disable=SC2086  # the knobs are meant to split
    run_spanlight render "$good_scene" --out "$scratch/out.png" $knobs
    expect_status 0
    expect_stderr_has "warning: $knobs: the per-span divide is off by up to "
    [[ "$(png_size "$scratch/out.png")" == "320 240" ]] || fail "$knobs: no 320 x 240 PNG despite the warning"
  done
  expect_stderr_has "up to 5.0e-04 (relative), 0.13 texel"  # 10 bits: 2^-11 + 2^-16 = 5.04e-4
  run_spanlight render "$good_scene" --out "$scratch/out.png" --table-bits 6 --newton 0
  expect_stderr_has "up to 7.8e-03 (relative), 2.00 texel"
  for knobs in "" "--table-bits 12 --newton 0" "--table-bits 6" "--table-bits 6 --newton 2"; do
    # shellcheck disable=SC2086
    run_spanlight render "$good_scene" --out "$scratch/out.png" $knobs
    expect_status 0
    [[ -z "$err_text" ]] || fail "'$knobs' should render without a word on stderr, got: $err_text"
  done
  run_spanlight bake "$good_scene" --out "$scratch/baked" --table-bits 8 --newton 0
  expect_status 0
  expect_stderr_has "warning: --table-bits 8 --newton 0"
  ;;
render_replaces_existing_output)
  # A successful render replaces an earlier file of the same name, atomically.
  make_previous_output "$scratch/out.png"
  run_spanlight render "$good_scene" --out "$scratch/out.png"
  expect_status 0
  [[ "$(png_size "$scratch/out.png")" == "320 240" ]] || fail "out.png was not replaced by a 320 x 240 PNG"
  expect_only_files "$scratch" out.png
  ;;
# --------------------------------------------------------------------- compare
compare_missing_file)
  run_spanlight compare "$scratch/no_such_a.png" "$small_png"
  expect_status 2
  expect_stderr_has "no_such_a.png"
  run_spanlight compare "$small_png" "$scratch/no_such_b.png"
  expect_status 2
  expect_stderr_has "no_such_b.png"
  run_spanlight compare "$small_png" "$scratch/no_such_b.png" --diff "$scratch/heat.png"
  expect_status 2
  expect_stderr_has "no_such_b.png"
  expect_only_files "$scratch"
  ;;
compare_not_an_image)
  run_spanlight compare "$good_scene" "$small_png"
  expect_status 2
  expect_stderr_has "horizon.json"
  run_spanlight compare "$small_png" "$source_dir/tests/scene/bad/assets/corrupt.png"
  expect_status 2
  expect_stderr_has "corrupt.png"
  ;;
compare_different_sizes)
  run_spanlight compare "$small_png" "$other_png"
  expect_status 2
  expect_stderr_has "differ in size"
  # The rule: a message naming the file(s).
  expect_stderr_has "npot_3x3.png"
  expect_stderr_has "checker.png"
  run_spanlight compare "$small_png" "$other_png" --diff "$scratch/heat.png"
  expect_status 2
  expect_only_files "$scratch"
  make_previous_output "$scratch/heat.png"
  run_spanlight compare "$small_png" "$other_png" --diff "$scratch/heat.png"
  expect_status 2
  expect_unchanged_previous_output "$scratch/heat.png"
  expect_only_files "$scratch" heat.png
  # Beyond 4096 texels a side: refused from the header, before any pixel is decoded.
  run_spanlight compare "$small_png" "$wide_png"
  expect_status 2
  expect_stderr_has "wide_4097x1.png: expected an image of 1..4096 texels a side, got 4097x1"
  ;;
compare_missing_argument)
  run_spanlight compare "$small_png"
  expect_status 2
  run_spanlight compare "$small_png" "$small_png" --frobnicate
  expect_status 2
  expect_stderr_has "--frobnicate"
  ;;
compare_diff_folder_missing)
  run_spanlight compare "$small_png" "$small_png" --diff "$scratch/no_such_folder/heat.png"
  expect_status 2
  expect_stderr_has "no_such_folder/heat.png"
  expect_only_files "$scratch"
  ;;
compare_identical)
  run_spanlight compare "$small_png" "$small_png"
  expect_status 0
  expect_stdout_has "size            3 x 3"
  expect_stdout_has "PSNR            inf dB"
  expect_stdout_has "max |diff|      0 LSB"
  expect_stdout_has "mean |diff|     0.000 LSB"
  expect_stdout_has "pixels > 2 LSB  0.00 %"
  expect_stdout_has "pixels > 8 LSB  0.00 %"
  run_spanlight compare "$small_png" "$small_png" --diff "$scratch/heat.png"
  expect_status 0
  [[ "$(png_size "$scratch/heat.png")" == "3 3" ]] || fail "heat.png is not a 3 x 3 PNG"
  expect_only_files "$scratch" heat.png
  ;;
compare_identical_json)
  run_spanlight compare "$small_png" "$small_png" --json
  expect_status 0
  for key in '"width": 3' '"height": 3' '"psnr_db": null' '"max_abs_lsb": 0' '"mean_abs_lsb": 0' \
      '"pct_over_2_lsb": 0' '"pct_over_8_lsb": 0'; do
    expect_stdout_has "$key"
  done
  [[ "$out_text" == "{"*"}" ]] || fail "--json output is not one JSON object: $out_text"
  ;;
compare_different_json)
  render_to fixed "$scratch/fixed.png"
  render_to float "$scratch/float.png"
  run_spanlight compare "$scratch/fixed.png" "$scratch/float.png" --json --diff "$scratch/heat.png"
  expect_status 0
  expect_stdout_has '"width": 320'
  expect_stdout_has '"height": 240'
  for key in psnr_db max_abs_lsb mean_abs_lsb pct_over_2_lsb pct_over_8_lsb; do
    # each key once, with a number (not null: the two backends differ somewhere)
    if ! grep -Eq "^  \"$key\": -?[0-9][0-9.eE+-]*,?\$" <<<"$out_text"; then
      fail "--json has no numeric \"$key\": $out_text"
    fi
  done
  [[ "$(png_size "$scratch/heat.png")" == "320 240" ]] || fail "heat.png is not a 320 x 240 PNG"
  expect_only_files "$scratch" fixed.png float.png heat.png
  ;;
*)
  fail "unknown case $case_name"
  ;;
esac

finish
