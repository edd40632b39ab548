#!/usr/bin/env bash
# Runs icount_calibration on one QEMU board and checks each region's instruction count is
# exactly what its assembly executes (see firmware/apps/icount_calibration).
#   check_calibration.sh RUNNER CPU PLUGIN ELF WORKDIR
set -euo pipefail
runner=$1 cpu=$2 plugin=$3 elf=$4 workdir=$5
expected="2 1002 203 4"

rm -rf "$workdir"
mkdir -p "$workdir"
cd "$workdir"
bash "$runner" --cpu "$cpu" --plugin "$plugin" --count-file count.txt "$elf"
measured=$(sed -n 's/^spanlight-region: //p' count.txt | tr '\n' ' ' | sed 's/ $//')
if [ "$measured" != "$expected" ]; then
  echo "calibration on $cpu: regions counted '$measured', expected '$expected'"
  exit 1
fi
echo "calibration on $cpu: every region counted exactly ($expected)"
