#!/usr/bin/env bash
# hostile_cases.sh SPANLIGHT MEASURE SOURCE_DIR MEASURED_DIR CXX CASE
#
# One hostile input per CASE (ctest runs each as "hostile: CASE"; the case
# names are read from this file by CMakeLists.txt). Each runs `spanlight`
# through MEASURE (measure.cpp) and checks the exit status, a fragment of the
# message, that the command ended before its deadline (a kill, not a speed
# test: the deadlines are 10x and more what it takes), that its peak memory
# stayed under a cap, and that a refused render left no output. The figures
# go to MEASURED_DIR/CASE.txt, one line a run (case|status|seconds|KiB|
# deadline|cap MiB|fragment); `report.sh BUILD_DIR` tabulates them for
# docs/limits.md. Inputs are the files in files/ (README.md there) or made
# here at test time (the big ones, devices, FIFOs, symlink loops).
export SPANLIGHT=$1
measure=$2
source_dir=$3
measured_dir=$4
cxx=$5
case_name=$6
# shellcheck source=tests/cli/cli_lib.sh
source "$source_dir/tests/cli/cli_lib.sh"

files="$source_dir/tests/hostile/files"
out="$scratch/out"
mkdir -p "$out" "$measured_dir"
rm -f "$measured_dir/$case_name.txt"

deadline=5     # seconds; a run takes ~0.5 s, most of it loading OpenImageIO's 260 libraries
max_mib=400    # peak resident memory cap; a run starts at ~130 MiB for the same reason

# run_case STATUS FRAGMENT ARGS...: spanlight ARGS, measured; FRAGMENT must be
# on stderr (for status 0: stderr must be empty unless FRAGMENT is given).
run_case() {
  local expected=$1 fragment=$2
  shift 2
  last_command="spanlight $*"
  "$measure" "$deadline" "$scratch/.measure" "$SPANLIGHT" "$@" >"$scratch/.stdout" 2>"$scratch/.stderr"
  status=$?
  err_text=$(cat "$scratch/.stderr")
  local report seconds kib
  report=$(cat "$scratch/.measure" 2>/dev/null)
  seconds=$(sed -n 's/.*seconds=\([0-9.]*\).*/\1/p' <<<"$report")
  kib=$(sed -n 's/.*maxrss_kib=\([0-9]*\).*/\1/p' <<<"$report")
  [[ "$status" == 124 ]] && fail "did not end within $deadline s"
  expect_status "$expected"
  if [[ -n "$fragment" ]]; then
    expect_stderr_has "$fragment"
  elif [[ -n "$err_text" ]]; then
    fail "stderr should be empty, got: $err_text"
  fi
  if [[ -n "$kib" ]] && ((kib > max_mib * 1024)); then fail "peak memory $((kib / 1024)) MiB, above the cap of $max_mib MiB"; fi
  if [[ "$expected" == 2 ]]; then expect_only_files "$out"; fi
  local shown=${fragment//$scratch/SCRATCH}  # the same in every run
  echo "$case_name|$status|$seconds|$kib|$deadline|$max_mib|${shown:-(stderr empty)}" >>"$measured_dir/$case_name.txt"
}

render() { run_case "$@"; }  # readability: render STATUS FRAGMENT ARGS...

# scene_with MESH IMAGE: $scratch/scene.json, the base scene (files/base.json)
# drawing MESH textured with IMAGE (absolute paths).
scene_with() {
  sed -e "s|\"triangle.obj\"|\"$1\"|" -e "s|\"png_rgb8.png\"|\"$2\"|" "$files/base.json" >"$scratch/scene.json"
}
with_mesh() { scene_with "$1" "$files/png_rgb8.png"; }
with_image() { scene_with "$files/triangle.obj" "$1"; }
scene="$scratch/scene.json"

# mesh_refused FILE FRAGMENT, image_refused FILE FRAGMENT: the base scene with
# files/FILE as its mesh or image is refused with "FILE: FRAGMENT".
mesh_refused() {
  with_mesh "$files/$1"
  render 2 "$1: $2" render "$scene" --out "$out/out.png"
}
image_refused() {
  with_image "$files/$1"
  render 2 "$1: $2" render "$scene" --out "$out/out.png"
}

symlink_loop() {
  ln -s "$scratch/loop_b" "$scratch/loop_a"
  ln -s "$scratch/loop_a" "$scratch/loop_b"
}

case "$case_name" in
baseline_help)
  # The floor every run pays before reading anything: loading the binary's libraries.
  render 0 "" --help
  ;;
# ---------------------------------------------------------------- scene file
scene_empty)
  : >"$scratch/empty.json"
  render 2 "empty.json: (root): expected a JSON object, got an empty file" render "$scratch/empty.json" --out "$out/out.png"
  ;;
scene_utf8_bom)
  # RFC 8259 lets a parser ignore a byte order mark; nlohmann::json does.
  render 0 "" render "$files/bom.json" --out "$out/out.png"
  ;;
scene_nesting_100000)
  { printf '{"spanlight_scene": 1, "x": '; head -c 100000 /dev/zero | tr '\0' '['; head -c 100000 /dev/zero | tr '\0' ']'; printf '}'; } \
    >"$scratch/deep.json"
  render 2 "deep.json: x[0][0]" render "$scratch/deep.json" --out "$out/out.png"
  expect_stderr_has ": expected at most 32 nested arrays and objects, got more"
  ;;
scene_duplicate_keys)
  render 2 "duplicate_keys.json: output.width: expected each field once in an object" render "$files/duplicate_keys.json" --out "$out/out.png"
  ;;
scene_number_1e400)
  render 2 "number_1e400.json: camera.fovy_deg: expected a number that fits a double" render "$files/number_1e400.json" --out "$out/out.png"
  ;;
scene_negative_zero)
  # -0 is 0: fine where 0 is (eye, ambient), refused where a value must be > 0.
  render 0 "" render "$files/negative_zero.json" --out "$out/out.png"
  rm -f "$out/out.png"
  render 2 "negative_zero_near.json: camera.near: expected a number > 0" render "$files/negative_zero_near.json" --out "$out/out.png"
  ;;
scene_huge_integers)
  render 2 "huge_integer_width.json: output.width: expected an integer in 1..4096, got 18446744073709551616" \
    render "$files/huge_integer_width.json" --out "$out/out.png"
  render 2 "huge_integer_index.json: objects[1].triangles[0][2]: expected an integer in 0..2" \
    render "$files/huge_integer_index.json" --out "$out/out.png"
  render 2 "huge_integer_version.json: spanlight_scene: expected " render "$files/huge_integer_version.json" --out "$out/out.png"
  ;;
scene_invalid_utf8)
  render 2 "invalid_utf8.json: (root): expected valid JSON, got parse error" render "$files/invalid_utf8.json" --out "$out/out.png"
  expect_stderr_has "ill-formed UTF-8 byte"
  ;;
scene_nul_byte)
  render 2 "nul_byte.json: (root): expected valid JSON" render "$files/nul_byte.json" --out "$out/out.png"
  ;;
scene_50_mb)
  { cat "$files/base.json"; head -c $((50 * 1024 * 1024 - $(wc -c <"$files/base.json"))) /dev/zero | tr '\0' ' '; } >"$scratch/big.json"
  render 2 "big.json: (root): expected a scene file of at most 16777216 bytes (16.0 MiB), got 52428800 bytes (50.0 MiB)" \
    render "$scratch/big.json" --out "$out/out.png"
  ;;
scene_16_mb_accepted)
  # Just under the limit, the costliest kind of content: 4.6 million small
  # values (1.5 million inline triangles over 3 positions). Loads and renders;
  # the triangles have zero area, so the time is the loader's and the
  # per-triangle setup's, not the pixels' (docs/limits.md has covering ones).
  deadline=60
  max_mib=2048
  with_mesh "$files/triangle.obj"
  { sed -n '1,/"objects"/p' "$scene"
    printf '    { "positions": [[-1, -1, -1], [1, -1, -1], [0, 1, -1]], "triangles": [\n'
    yes '[0, 0, 1], [1, 2, 2],' | head -n 760000
    printf '[0, 1, 2]] }\n  ]\n}\n'; } >"$scratch/large.json"
  size=$(wc -c <"$scratch/large.json")
  ((size > 15 * 1024 * 1024 && size <= 16 * 1024 * 1024)) || fail "large.json is $size bytes, meant to be just under 16 MiB"
  render 0 "" render "$scratch/large.json" --out "$out/out.png"
  ;;
# ------------------------- not a regular file: as the scene, a mesh, an image
scene_dev_zero | scene_fifo | scene_symlink_loop | mesh_dev_zero | mesh_dev_urandom | mesh_fifo | mesh_symlink_loop | image_dev_zero | image_dev_urandom | image_fifo | image_symlink_loop)
  role=${case_name%%_*}  # scene, mesh or image
  what=${case_name#*_}   # dev_zero, dev_urandom, fifo or symlink_loop
  case $role in
  scene) kind="a scene file" field="(root)" ;;
  mesh) kind="an OBJ file" field="objects[0].mesh" ;;
  image) kind="an image file" field="textures.t.image" ;;
  esac
  case $what in
  dev_*)
    path=/dev/${what#dev_}
    expected="expected a regular file as $kind, got a character device"
    ;;
  fifo)
    path="$scratch/$role.fifo"
    mkfifo "$path"  # opened for reading, it would block until a writer came
    expected="expected a regular file as $kind, got a FIFO"
    ;;
  symlink_loop)
    symlink_loop
    path="$scratch/loop_a"
    expected="expected a readable ${kind#a* }, got a symlink loop"
    ;;
  esac
  case $role in
  scene) render 2 "$path: $field: $expected" render "$path" --out "$out/out.png" ;;
  mesh) with_mesh "$path" && render 2 "$field: $path: $expected" render "$scene" --out "$out/out.png" ;;
  image) with_image "$path" && render 2 "$field: $path: $expected" render "$scene" --out "$out/out.png" ;;
  esac
  ;;
# ----------------------------------------------------------------------- OBJ
obj_nan)
  mesh_refused obj_nan.obj "expected finite numbers after v, got 'nan' on line 1"
  ;;
obj_inf)
  mesh_refused obj_inf.obj "expected finite numbers after v, got 'inf' on line 2"
  ;;
obj_1e400)
  mesh_refused obj_1e400.obj "expected finite numbers after v, got '1e400' on line 3"
  ;;
obj_hex_and_comma)
  # tinyobjloader would read these as 0 and 1.
  mesh_refused obj_hex.obj "expected finite numbers after v, got '0x10' on line 2"
  mesh_refused obj_decimal_comma.obj "expected finite numbers after v, got '1,5' on line 2"
  mesh_refused obj_two_coordinates.obj "expected 3 or 4 coordinates (6 or 7 with a colour) after v, got 2 on line 2"
  ;;
obj_index_0)
  mesh_refused obj_index_0.obj "expected vertex (v) indices counted from 1 (or back from -1 to -3), got '0'"
  ;;
obj_negative_indices)
  # Relative indices are OBJ: -1 is the last vertex before the face.
  with_mesh "$files/obj_negative_indices.obj"
  render 0 "" render "$scene" --out "$out/out.png"
  rm -f "$out/out.png"
  mesh_refused obj_negative_out_of_range.obj "expected vertex (v) indices counted from 1 (or back from -1 to -3), got '-4'"
  ;;
obj_index_out_of_range)
  mesh_refused obj_index_out_of_range.obj "expected vertex (v) indices in 1..3, got 4 in face 1"
  mesh_refused obj_index_2_31.obj "expected vertex (v) indices counted from 1 (or back from -1 to -3), got '2147483648'"
  mesh_refused obj_index_huge.obj "expected vertex (v) indices counted from 1 (or back from -1 to -3), got '99999999999999999999'"
  ;;
obj_mtllib_dev_zero)
  # Materials are not read at all: no file an OBJ names is opened.
  with_mesh "$files/obj_mtllib_dev_zero.obj"
  render 0 "" render "$scene" --out "$out/out.png"
  ;;
obj_faces_10e6)
  deadline=60
  max_mib=2048
  # Zero-area faces, as in scene_16_mb_accepted: the loader's time, not the pixels'.
  { printf 'v -1 -1 0\nv 1 -1 0\nv 0 1 0\nv 0 -0.5 0.5\n'; yes 'f 1 1 2
f 3 4 4' | head -n 1000000; } >"$scratch/million.obj"
  with_mesh "$scratch/million.obj"
  render 0 "" render "$scene" --out "$out/out.png"
  ;;
# ----------------------------------------------------------------------- PNG
png_header_100000x100000)
  # 30 GB of pixels if decoded: refused from the header, nothing that size allocated.
  max_mib=300
  image_refused png_100000x100000.png "expected an image of 1..4096 texels a side, got 100000x100000"
  ;;
png_truncated)
  image_refused png_truncated.png "expected readable pixel data, got: "
  ;;
png_16bit | png_grey | png_grey_alpha | png_rgba)
  # The spec takes grey, RGB and RGBA, alpha ignored; 16 bits a channel are
  # rounded to the nearest 8-bit level (tests/scene/test_images.cpp checks the values).
  with_image "$files/$case_name.png"
  render 0 "" render "$scene" --out "$out/out.png"
  [[ "$(png_size "$out/out.png")" == "64 48" ]] || fail "no 64 x 48 render"
  ;;
# ---------------------------------------------------------------------- bake
bake_name_with_quotes)
  # The name is any JSON string; baked into C++ it must stay a string literal.
  render 0 "" bake "$files/name_with_quotes.json" --out "$out/baked"
  printf '#include <cstdio>\n#include "baked_config.hpp"\nint main() { std::fputs(baked::scene_name, stdout); }\n' >"$scratch/main.cpp"
  includes=(-I "$out/baked" -I "$source_dir/pipeline/include" -I "$source_dir/fixedpoint/include")
  "$cxx" -std=c++20 -fsyntax-only "${includes[@]}" "$out/baked/baked_scene.cpp" || fail "baked_scene.cpp does not compile"
  "$cxx" -std=c++20 "${includes[@]}" "$scratch/main.cpp" -o "$scratch/name" || fail "baked_config.hpp does not compile"
  expected=$'evil"; int injected = 1; // \\ and a\nnew line'
  [[ "$("$scratch/name")" == "$expected" ]] || fail "baked::scene_name is '$("$scratch/name")', expected '$expected'"
  ;;
*)
  fail "unknown case $case_name"
  ;;
esac

finish
