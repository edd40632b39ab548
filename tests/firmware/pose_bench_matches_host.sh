#!/usr/bin/env bash
# Runs pose_bench on one QEMU board and checks that every frame's matrices (the "frame N:"
# log lines: statuses and hashes of the pipeline blocks) equal the host build's, and that the
# instruction count of every measured region is reported.
#   pose_bench_matches_host.sh RUNNER CPU PLUGIN ELF HOST_PROGRAM WORKDIR
set -euo pipefail
runner=$1 cpu=$2 plugin=$3 elf=$4 host=$5 workdir=$6

rm -rf "$workdir"
mkdir -p "$workdir"
cd "$workdir"
"$host" > host.log 2>&1
bash "$runner" --cpu "$cpu" --plugin "$plugin" "$elf" > target.log 2>&1
grep '^frame ' host.log > host_frames.txt
grep '^frame ' target.log > target_frames.txt
if [ "$(wc -l < host_frames.txt)" -ne 60 ]; then
  echo "pose_bench: the host logged $(wc -l < host_frames.txt) frames, not 60"
  exit 1
fi
if ! diff host_frames.txt target_frames.txt; then
  echo "pose_bench on $cpu: the matrices differ from the host build's ($workdir)"
  exit 1
fi
regions=$(grep -c '^spanlight-region: ' target.log || true)
if [ "$regions" -ne 69 ]; then
  echo "pose_bench on $cpu: $regions measured regions reported, not 69 (60 frames and 9 builders)"
  exit 1
fi
echo "pose_bench on $cpu: all 60 frames' matrices match the host build's"
