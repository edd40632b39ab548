#!/usr/bin/env bash
# `spanlight sweep`, `spanlight analyze` and `spanlight bake --config` from the command line
# (QEMU runs switched off: this checks the commands, not target figures).
#   sweep_cli.sh SPANLIGHT SOURCE_DIR
set -u
SPANLIGHT=$1
SOURCE=$2
SCENES=$SOURCE/tests/sweep/scenes
failures=0
last_command=""
scratch=$(mktemp -d "${TMPDIR:-/tmp}/spanlight-sweep-test.XXXXXX")
trap 'rm -rf "$scratch"' EXIT

fail() {
  echo "FAIL: $* (command: $last_command)"
  failures=$((failures + 1))
}
run_spanlight() {  # sets status, out_text, err_text
  last_command="spanlight $*"
  "$SPANLIGHT" "$@" >"$scratch/.stdout" 2>"$scratch/.stderr"
  status=$?
  out_text=$(cat "$scratch/.stdout")
  err_text=$(cat "$scratch/.stderr")
}
expect_status() { [ "$status" = "$1" ] || fail "exit status $status, expected $1; stderr: $err_text"; }
expect_stdout_has() { [[ "$out_text" == *"$1"* ]] || fail "stdout lacks '$1'; stdout: $out_text"; }
expect_stderr_has() { [[ "$err_text" == *"$1"* ]] || fail "stderr lacks '$1'; stderr: $err_text"; }
expect_no_file() { [ ! -e "$1" ] || fail "$1 exists but should not"; }

expect_file() { [ -s "$1" ] || fail "expected a non-empty file $1"; }
expect_lines() {  # FILE N: the file has N lines
  local n
  n=$(wc -l <"$1")
  [ "$n" -eq "$2" ] || fail "$1 has $n lines, expected $2"
}

# --- sweep: a small grid on a scene whose texture is bilinear -> filters scene and nearest
out=$scratch/sweep
run_spanlight sweep "$SCENES/wide_uv.json" --out "$out" --span 16,64 --table-bits 8 --newton 0,1 --depth-bits 24 \
  --passes fused,multipass --qemu-grid none --repeats 1 --pictures 2
expect_status 0
expect_stdout_has "swept wide_uv: 16 configurations"
expect_stdout_has "host: "
for f in sweep.csv report.html front.md pareto_host.svg; do expect_file "$out/$f"; done
expect_lines "$out/sweep.csv" 17
head -n 1 "$out/sweep.csv" | grep -q ",label,span,tolerance,table-bits,newton,depth-bits,passes,mip,filter," ||
  fail "the CSV's knob columns are not the knobs' names"
grep -q "^wide_uv,rgb888,[0-9]*,span=64 tolerance=5 table-bits=8 newton=1 depth-bits=24 passes=fused mip=trilinear filter=scene,64,5,8,1,24,fused,trilinear,scene," \
  "$out/sweep.csv" || fail "the default row is missing"
grep -q "n/a: QEMU runs switched off" "$out/sweep.csv" || fail "target cost should be n/a without QEMU"
ls "$out"/images/*-fixed.png >/dev/null 2>&1 || fail "no pictures written"
grep -q "<svg" "$out/pareto_host.svg" || fail "the plot is not SVG"
grep -q "Pareto front on host" "$out/front.md" || fail "front.md has no front table"
[[ "$err_text" == *"host: accuracy and time"* ]] || fail "no progress on stderr"

# --- sweep: bad input exits 2
run_spanlight sweep "$scratch/missing.json" --out "$scratch/x"
expect_status 2
run_spanlight sweep "$SCENES/wide_uv.json" --out "$scratch/x" --span 3
expect_status 2
expect_stderr_has "--span"
run_spanlight sweep "$SCENES/wide_uv.json" --out "$scratch/x" --format rgb888,rgb565 --qemu-grid none
expect_status 2
expect_stderr_has "--format: expected one format"
expect_no_file "$scratch/x"
run_spanlight sweep "$SCENES/wide_uv.json" --out "$scratch/x" --spans 4
expect_status 2  # the old option names are gone
run_spanlight sweep "$SCENES/wide_uv.json"
expect_status 2
run_spanlight sweep "$SCENES/far_positions.json" --out "$scratch/x" --qemu-grid none
expect_status 2
expect_stderr_has "beyond the supported"
expect_no_file "$scratch/x"

# --- analyze: formats rejected and chosen
run_spanlight analyze "$SCENES/wide_uv.json" --sweep-csv "$out/sweep.csv"
expect_status 0
expect_stdout_has "Q15.16: REJECTED (overflow), 64000 >= 8192"
expect_stdout_has "-> Q19.12: holds"
expect_stdout_has "spanlight bake $SCENES/wide_uv.json --out baked/ --span"
run_spanlight analyze "$SCENES/thin_depth.json" --qemu-grid none --quiet
expect_status 0
expect_stdout_has "16 bits: REJECTED (too coarse)"
expect_stdout_has "--depth-bits 24"
run_spanlight analyze "$SCENES/far_positions.json" --qemu-grid none --quiet
expect_status 2
expect_stdout_has "Q15.16: REJECTED (overflow), 21000 >= 16384"
run_spanlight analyze "$SCENES/wide_uv.json" --sweep-csv "$out/sweep.csv" --min-psnr 199
expect_status 1
expect_stdout_has "no configuration of the sweep meets PSNR >= 199 dB"
run_spanlight analyze "$SCENES/wide_uv.json" --min-psnr 30 --max-error-lsb 4
expect_status 2

# --- analyze --write-config, then bake --config
run_spanlight analyze "$SCENES/wide_uv.json" --sweep-csv "$out/sweep.csv" --min-psnr 30 --write-config "$scratch/knobs.json"
expect_status 0
expect_file "$scratch/knobs.json"
expect_stdout_has "--config $scratch/knobs.json"
span=$(sed -n 's/.*"span": \([0-9]*\).*/\1/p' "$scratch/knobs.json")
run_spanlight bake "$SCENES/wide_uv.json" --out "$scratch/baked" --config "$scratch/knobs.json"
expect_status 0
expect_file "$scratch/baked/baked_config.hpp"
grep -q "takes them: --span $span " "$scratch/baked/baked_config.hpp" || fail "the baked knobs do not carry span $span"
run_spanlight bake "$SCENES/wide_uv.json" --out "$scratch/baked2" --config "$scratch/knobs.json" --span 4
expect_status 2
echo '{"spanlight_knobs": 3, "span": 5}' >"$scratch/bad.json"
run_spanlight bake "$SCENES/wide_uv.json" --out "$scratch/baked3" --config "$scratch/bad.json"
expect_status 2
expect_stderr_has "bad.json: span: expected one of 1, 2, 4, 8, 16, 32, 64"
expect_no_file "$scratch/baked3"

if ((failures > 0)); then
  echo "$failures expectation(s) failed"
  exit 1
fi
echo "all expectations met"
