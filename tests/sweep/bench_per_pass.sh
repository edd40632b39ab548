#!/usr/bin/env bash
# sweep_bench --per-pass on spot_shadow (one shadowed projector): one measured region per
# pass, named in the frame plan's order (render_frame's hooks), each counted, and together
# fewer instructions than the whole frame (which also clears the buffers between passes).
#   bench_per_pass.sh MEASURE_ELF PLUGIN CPU ELF
set -euo pipefail
measure=$1
plugin=$2
cpu=$3
elf=$4
work=$(mktemp -d "${TMPDIR:-/tmp}/spanlight-per-pass.XXXXXX")
trap 'rm -rf "$work"' EXIT
failed=0
measured() { awk -v k="$2" '$1 == "spanlight-measure:" && $2 == k { $1 = ""; $2 = ""; sub(/^ +/, ""); print }' "$1"; }

for plan in "fused:shadow0 fused" "multipass:shadow0 depth_ambient light0 modulate"; do
  passes=${plan%%:*}
  expected=${plan#*:}
  (cd "$work" && bash "$measure" --cpu "$cpu" --plugin "$plugin" "$elf" --passes "$passes" > whole.log)
  (cd "$work" && bash "$measure" --cpu "$cpu" --plugin "$plugin" "$elf" --passes "$passes" --per-pass > parts.log)
  names=$(sed -n 's/^sweep_bench: regions //p' "$work/parts.log")
  regions=$(measured "$work/parts.log" regions)
  whole=$(measured "$work/whole.log" instructions)
  sum=$(measured "$work/parts.log" instructions)
  [ "$names" = "$expected" ] || { echo "FAIL: $passes: regions named '$names', expected '$expected'"; failed=1; }
  [ "$(wc -w <<<"$regions")" -eq "$(wc -w <<<"$expected")" ] ||
    { echo "FAIL: $passes: $(wc -w <<<"$regions") region counts for '$expected'"; failed=1; }
  for n in $regions; do [ "$n" -gt 0 ] || { echo "FAIL: $passes: a region counted 0"; failed=1; }; done
  [ -n "$whole" ] && [ -n "$sum" ] && [ "$sum" -lt "$whole" ] ||
    { echo "FAIL: $passes: passes sum to $sum, not fewer than the whole frame's $whole"; failed=1; }
  # The frame is the same either way: the hooks only bracket the counter.
  [ "$(grep -o 'hash=[0-9a-fx]*' "$work/whole.log")" = "$(grep -o 'hash=[0-9a-fx]*' "$work/parts.log")" ] ||
    { echo "FAIL: $passes: --per-pass renders another frame"; failed=1; }
  echo "$passes: $names = $regions (sum $sum of $whole)"
done
exit "$failed"
