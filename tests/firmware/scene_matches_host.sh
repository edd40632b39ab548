#!/usr/bin/env bash
# Renders a baked scene on one QEMU board and checks the frame is byte-identical (0 LSB in
# every channel of every pixel) to the host's fixed-point render with the same knobs.
# Keeps the instruction count in WORKDIR/count.txt for the firmware report. With
# SPANLIGHT_RENDER_STACK_LIMIT set, also checks the stack render_frame itself took (the app's
# "render_frame stack N bytes", hal::stack_mark) is at most that many bytes.
# BAND_ROWS, when given, is passed to the app: the frame drawn in bands of that many rows.
#   scene_matches_host.sh RUNNER CPU PLUGIN ELF SPANLIGHT REFERENCE_PNG WORKDIR [BAND_ROWS]
set -euo pipefail
runner=$1 cpu=$2 plugin=$3 elf=$4 spanlight=$5 reference=$6 workdir=$7 band_rows=${8:-}

rm -rf "$workdir"
mkdir -p "$workdir"
cd "$workdir"
bash "$runner" --cpu "$cpu" --plugin "$plugin" --count-file count.txt "$elf" frame.ppm $band_rows | tee run.log
"$spanlight" compare frame.ppm "$reference" --json > compare.json
if ! grep -q '"max_abs_lsb": 0' compare.json; then
  echo "$(basename "$elf") on $cpu differs from the host render $reference:"
  cat compare.json
  exit 1
fi
echo "$(basename "$elf") on $cpu: frame identical to the host render; $(grep -m1 spanlight-instructions run.log)"
if [ -n "${SPANLIGHT_RENDER_STACK_LIMIT:-}" ]; then
  stack=$(sed -n 's/.*render_frame stack \([0-9]*\) bytes.*/\1/p' run.log | head -n 1)
  if [ -z "$stack" ] || [ "$stack" -gt "$SPANLIGHT_RENDER_STACK_LIMIT" ]; then
    echo "$(basename "$elf") on $cpu: render_frame took ${stack:-an unreported number of} bytes of stack, over the $SPANLIGHT_RENDER_STACK_LIMIT-byte bound"
    exit 1
  fi
  echo "$(basename "$elf") on $cpu: render_frame's own stack $stack bytes, within $SPANLIGHT_RENDER_STACK_LIMIT"
fi
