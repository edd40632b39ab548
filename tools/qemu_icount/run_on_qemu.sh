#!/usr/bin/env bash
# Runs a spanlight firmware ELF on its QEMU mps2 board with semihosting, deterministic time
# (-icount shift=0) and, given --plugin, the instruction-count plugin.
#
#   run_on_qemu.sh [--cpu cortex-m7|cortex-m4|cortex-m0plus | --machine MACHINE]
#                  [--plugin libspanlight_icount.so] [--count-file FILE] [--profile FILE]
#                  [--nm arm-none-eabi-nm] [--timeout SECONDS] [--qemu-arg ARG]...
#                  ELF [APP_ARG]...
#
# The app's log (semihosting SYS_WRITE0) goes to stdout; files it opens are relative to the
# current directory; APP_ARGs reach it as args[1..] (none may contain a space). With --plugin,
# the instruction count follows on stdout as
#   spanlight-instructions: N      (sum over all measured regions)
#   spanlight-regions: K           and one "spanlight-region: n" line per region
# and is also kept in --count-file when given. --profile FILE writes the plugin's per-address
# counts ("ADDRESS COUNT"; profile_on_qemu.sh reads them). The exit status is the app's.
set -euo pipefail

usage() { sed -n '2,17s/^# \{0,1\}//p' "$0" >&2; exit 2; }

cpu=cortex-m7
machine=
plugin=
count_file=
profile=
nm=arm-none-eabi-nm
timeout_s=120
qemu_extra=()
while [ $# -gt 0 ]; do
  case "$1" in
    --cpu) cpu=$2; shift 2 ;;
    --machine) machine=$2; shift 2 ;;
    --plugin) plugin=$2; shift 2 ;;
    --count-file) count_file=$2; shift 2 ;;
    --profile) profile=$2; shift 2 ;;
    --nm) nm=$2; shift 2 ;;
    --timeout) timeout_s=$2; shift 2 ;;
    --qemu-arg) qemu_extra+=("$2"); shift 2 ;;
    -h|--help) usage ;;
    --*) echo "run_on_qemu: unknown option $1" >&2; usage ;;
    *) break ;;
  esac
done
[ $# -ge 1 ] || usage
elf=$1
shift
[ -f "$elf" ] || { echo "run_on_qemu: no such ELF: $elf" >&2; exit 2; }

# The board whose core runs each build: an500 has a Cortex-M7, an386 a Cortex-M4, and an385's
# Cortex-M3 runs ARMv6-M (Cortex-M0+) code, a subset of its ARMv7-M instruction set.
if [ -z "$machine" ]; then
  case "$cpu" in
    cortex-m7) machine=mps2-an500 ;;
    cortex-m4) machine=mps2-an386 ;;
    cortex-m0plus) machine=mps2-an385 ;;
    *) echo "run_on_qemu: unknown cpu $cpu" >&2; exit 2 ;;
  esac
fi

# QEMU splits option values at commas; a literal comma is written twice.
escape_commas() { printf '%s' "${1//,/,,}"; }

# The app's command line: program name, then the arguments.
semihosting="enable=on,target=native,chardev=semihost,arg=$(escape_commas "$(basename "$elf" .elf)")"
for arg in "$@"; do
  semihosting+=",arg=$(escape_commas "$arg")"
done

plugin_opts=()
report=
if [ -n "$plugin" ]; then
  symbol_address() {
    "$nm" "$elf" | awk -v name="$1" '$3 == name { print "0x" $1; found = 1 } END { exit !found }'
  }
  begin=$(symbol_address spanlight_measure_begin) && end=$(symbol_address spanlight_measure_end) || {
    echo "run_on_qemu: $elf has no spanlight_measure_begin/end (not linked with spanlight_hal_cortex_m?)" >&2
    exit 2
  }
  report=${count_file:-$(mktemp)}
  rm -f "$report"
  plugin_spec="$(escape_commas "$plugin"),begin=$begin,end=$end,out=$(escape_commas "$report")"
  [ -z "$profile" ] || plugin_spec+=",profile=$(escape_commas "$profile")"
  plugin_opts=(-plugin "$plugin_spec")
fi

# No display, monitor, serial or parallel port: stdio belongs to the semihosting console alone.
# -icount shift=0: each instruction advances virtual time by exactly 1 ns, so timer readings,
# and with them the whole run, repeat exactly.
status=0
timeout "$timeout_s" qemu-system-arm -M "$machine" \
  -display none -monitor none -serial none -parallel none \
  -chardev stdio,id=semihost -semihosting-config "$semihosting" \
  -icount shift=0 \
  "${plugin_opts[@]}" "${qemu_extra[@]}" \
  -kernel "$elf" </dev/null || status=$?
if [ "$status" -eq 124 ]; then
  echo "run_on_qemu: $elf did not finish within ${timeout_s}s" >&2
fi

if [ -n "$report" ]; then
  if [ -s "$report" ]; then
    cat "$report"
  else
    echo "run_on_qemu: the plugin wrote no instruction count" >&2
    [ "$status" -ne 0 ] || status=3
  fi
  [ -n "$count_file" ] || rm -f "$report"
fi
exit "$status"
