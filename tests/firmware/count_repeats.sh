#!/usr/bin/env bash
# Runs an app twice on one QEMU board with the instruction-count plugin and checks the count
# is reported, non-zero, and identical both times.
#   count_repeats.sh RUNNER CPU PLUGIN ELF WORKDIR [APP_ARG]...
set -euo pipefail
runner=$1 cpu=$2 plugin=$3 elf=$4 workdir=$5
shift 5

rm -rf "$workdir"
mkdir -p "$workdir"
cd "$workdir"
counts=()
for run in 1 2; do
  bash "$runner" --cpu "$cpu" --plugin "$plugin" --count-file "count$run.txt" "$elf" "$@" >"log$run.txt"
  cat "log$run.txt"
  count=$(sed -n 's/^spanlight-instructions: \([0-9][0-9]*\)$/\1/p' "count$run.txt")
  if [ -z "$count" ] || [ "$count" -eq 0 ]; then
    echo "run $run on $cpu: no instruction count reported"
    exit 1
  fi
  counts+=("$count")
done
if [ "${counts[0]}" != "${counts[1]}" ]; then
  echo "instruction count on $cpu differs between runs: ${counts[0]} vs ${counts[1]}"
  exit 1
fi
echo "instruction count on $cpu repeats exactly: ${counts[0]}"
