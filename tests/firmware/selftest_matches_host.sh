#!/usr/bin/env bash
# Runs selftest on one QEMU board and checks that both frames it writes (whole and tiled) are
# byte-identical to the host build's frame.
#   selftest_matches_host.sh RUNNER CPU ELF REFERENCE_PPM WORKDIR
set -euo pipefail
runner=$1 cpu=$2 elf=$3 reference=$4 workdir=$5

rm -rf "$workdir"
mkdir -p "$workdir"
cd "$workdir"
bash "$runner" --cpu "$cpu" "$elf" frame.ppm tiles.ppm
for frame in frame.ppm tiles.ppm; do
  if ! cmp "$reference" "$frame"; then
    echo "selftest on $cpu: $workdir/$frame differs from the host's $reference"
    exit 1
  fi
done
echo "selftest on $cpu: both frames match the host build byte for byte"
