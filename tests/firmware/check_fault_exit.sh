#!/usr/bin/env bash
# Runs fault_check on one QEMU board: its undefined instruction must reach the catch-all
# handler, which reports it and makes QEMU exit with 131 (128 + HardFault's number 3).
#   check_fault_exit.sh RUNNER CPU ELF
set -euo pipefail
runner=$1 cpu=$2 elf=$3

status=0
output=$(bash "$runner" --cpu "$cpu" --timeout 60 "$elf") || status=$?
echo "$output"
if [ "$status" -ne 131 ] || ! grep -q "unexpected exception 3 at pc 0x" <<<"$output"; then
  echo "fault_check on $cpu: exit status $status, expected 131 with a fault report"
  exit 1
fi
echo "fault_check on $cpu: the fault was reported and the run failed with 131"
