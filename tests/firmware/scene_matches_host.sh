#!/usr/bin/env bash
# Renders a baked scene on one QEMU board and checks the frame is byte-identical (0 LSB in
# every channel of every pixel) to the host's fixed-point render with the same knobs.
# Keeps the instruction count in WORKDIR/count.txt for the firmware report.
#   scene_matches_host.sh RUNNER CPU PLUGIN ELF SPANLIGHT REFERENCE_PNG WORKDIR
set -euo pipefail
runner=$1 cpu=$2 plugin=$3 elf=$4 spanlight=$5 reference=$6 workdir=$7

rm -rf "$workdir"
mkdir -p "$workdir"
cd "$workdir"
bash "$runner" --cpu "$cpu" --plugin "$plugin" --count-file count.txt "$elf" frame.ppm | tee run.log
"$spanlight" compare frame.ppm "$reference" --json > compare.json
if ! grep -q '"max_abs_lsb": 0' compare.json; then
  echo "$(basename "$elf") on $cpu differs from the host render $reference:"
  cat compare.json
  exit 1
fi
echo "$(basename "$elf") on $cpu: frame identical to the host render; $(grep -m1 spanlight-instructions run.log)"
