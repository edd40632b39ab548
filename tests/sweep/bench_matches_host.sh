#!/usr/bin/env bash
# sweep_bench in QEMU renders the same frame as the host for every point it is asked for
# (the sweep compares frame hashes), on Cortex-M7 and Cortex-M0+, with a count for each.
#   bench_matches_host.sh SPANLIGHT SOURCE_DIR BUILD_DIR
set -euo pipefail
spanlight=$1
source_dir=$2
build=$3
out=$(mktemp -d "${TMPDIR:-/tmp}/spanlight-bench-check.XXXXXX")
trap 'rm -rf "$out"' EXIT

# Corners of the grid on spot_shadow (a shadowed pcf projector): short and long spans, the
# smallest and the default table, with and without a Newton step, both depth settings, both
# pass plans, and every texture forced to nearest.
"$spanlight" sweep "$source_dir/scenes/spot_shadow.json" --out "$out/sweep" --span 4,64 --table-bits 6,8 --newton 0,1 \
  --depth-bits 16,24 --passes fused,multipass --filters scene,nearest --qemu-grid full --firmware-dir "$build" \
  --pictures 0 --no-per-pass --repeats 1 --quiet >"$out/stdout" 2>"$out/stderr" || {
  cat "$out/stderr"
  exit 1
}
failed=0
# hash_checked: the QEMU frame of every run behind the row's counts equals the host render's.
unchecked=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next } $col["hash_checked"] != 1 { print $col["label"] }' \
  "$out/sweep/sweep.csv")
[ -z "$unchecked" ] || { echo "FAIL: frame hash differs or is missing for:"; echo "$unchecked"; grep note "$out/stderr"; failed=1; }
missing=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
  $col["m7_instructions"] == "n/a" || $col["m0plus_instructions"] == "n/a"' "$out/sweep/sweep.csv" | wc -l)
[ "$missing" -eq 0 ] || { echo "FAIL: $missing row(s) without a target count"; grep "note" "$out/stderr"; failed=1; }
rows=$(($(wc -l <"$out/sweep/sweep.csv") - 1))
[ "$rows" -eq 64 ] || { echo "FAIL: $rows rows, expected 64"; failed=1; }
[ "$failed" -eq 0 ] && echo "ok: $rows points, every frame hash equal, every count present"
exit "$failed"
