#!/usr/bin/env bash
# Plays the live_spotlight demo (every 4th frame) as its host build, or on one QEMU board,
# and checks each frame byte for byte:
#   host:  against the host CLI's fixed-point render of the same animation
#          (REFERENCE, the folder with fixed/frame_NNNN.png), with `spanlight compare`;
#   board: against the host build's frames (REFERENCE, the host run's WORKDIR), with cmp,
#          so board == host build == CLI render. On a board it also checks the RAM working
#          set: .data + .bss + the stack reserve <= 64 KiB, and the stack peak below the reserve.
#   live_spotlight_matches_host.sh host PROGRAM SPANLIGHT REFERENCE WORKDIR
#   live_spotlight_matches_host.sh RUNNER CPU PLUGIN ELF REFERENCE WORKDIR
set -euo pipefail
budget=65536
step=4
if [ "$1" = host ]; then
  program=$2 spanlight=$3 reference=$4 workdir=$5 cpu=host
else
  runner=$1 cpu=$2 plugin=$3 elf=$4 reference=$5 workdir=$6
fi

rm -rf "$workdir"
mkdir -p "$workdir"
cd "$workdir"
if [ "$cpu" = host ]; then
  "$program" frame "$step" > run.log 2>&1
else
  bash "$runner" --cpu "$cpu" --plugin "$plugin" "$elf" frame "$step" > run.log 2>&1
fi

failed=0
frames=0
for ((k = 0; k < 60; k += step)); do
  name=$(printf 'frame_%04d' "$k")
  frames=$((frames + 1))
  if [ "$cpu" = host ]; then
    if ! "$spanlight" compare "$name.ppm" "$reference/fixed/$name.png" --json > "$name.json" 2>&1 ||
       ! grep -q '"max_abs_lsb": 0' "$name.json"; then
      echo "live_spotlight on $cpu: frame $k differs from the CLI's render:"
      cat "$name.json"
      failed=1
    fi
  elif ! cmp -s "$name.ppm" "$reference/$name.ppm"; then
    echo "live_spotlight on $cpu: frame $k differs from the host build's ($reference/$name.ppm)"
    failed=1
  fi
done

if [ "$cpu" != host ]; then
  section() { arm-none-eabi-size -A "$elf" | awk -v s="$1" '$1 == s { print $2; f = 1 } END { if (!f) print 0 }'; }
  data=$(section .data) bss=$(section .bss) reserve=$(section .stack)
  working_set=$((data + bss + reserve))
  peak=$(sed -n 's/.*stack peak \([0-9]*\) bytes.*/\1/p' run.log)
  echo "live_spotlight on $cpu: working set $working_set bytes (.data $data + .bss $bss + stack reserve $reserve), stack peak $peak"
  if [ "$working_set" -gt "$budget" ]; then
    echo "live_spotlight on $cpu: working set $working_set bytes is above the $budget-byte budget"
    failed=1
  fi
  if [ -z "$peak" ] || [ "$peak" -ge "$reserve" ]; then
    echo "live_spotlight on $cpu: stack peak '${peak}' is not below the $reserve-byte reserve"
    failed=1
  fi
fi
[ "$failed" -eq 0 ] || exit 1
echo "live_spotlight on $cpu: $frames frames identical to the host render"
