#!/usr/bin/env bash
# Profiles icount_calibration with profile_on_qemu.sh and checks the attribution is exact:
# every measured instruction is attributed, and the per-function rows are the counts the
# calibration's assembly executes (1001 straight-line, 202 in the loop; see check_calibration.sh).
#   check_profile.sh PROFILER CPU PLUGIN ELF WORKDIR
set -euo pipefail
profiler=$1 cpu=$2 plugin=$3 elf=$4 workdir=$5

rm -rf "$workdir"
mkdir -p "$workdir"
report=$(bash "$profiler" --cpu "$cpu" --plugin "$plugin" --work "$workdir" "$elf")
echo "$report"
fail() { echo "profile on $cpu: $1"; exit 1; }
grep -qx 'Instructions attributed: 1211 (measured: 1211)' <<<"$report" || fail "attributed total is not the measured 1211"
grep -q '^| `::straight_line_region` | 1001 |' <<<"$report" || fail "straight_line_region is not 1001"
grep -q '^| `::loop_region` | 202 |' <<<"$report" || fail "loop_region is not 202"
echo "profile on $cpu: every instruction attributed to the function that executed it"
