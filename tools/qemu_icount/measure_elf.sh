#!/usr/bin/env bash
# The one measuring path for a spanlight firmware ELF: runs it in QEMU with the
# instruction-count plugin (run_on_qemu.sh) and reads its sizes, then prints
#
#   the app's own log, unchanged, then
#   spanlight-measure: instructions N        exact count of the measured region(s), summed
#   spanlight-measure: regions N1 N2 ...     each measured region (one when the app measures once)
#   spanlight-measure: covered_pixels N      from the app's "covered N pixels" (omitted if it says none)
#   spanlight-measure: stack_peak N          bytes, from the app's "stack peak N bytes"
#   spanlight-measure: render_stack N        bytes render_frame itself takes, from "render_frame stack N bytes"
#   spanlight-measure: flash N               .text + .rodata + .data
#   spanlight-measure: scene_data N          the baked scene's own data: every symbol in namespace baked
#   spanlight-measure: pipeline_flash N      flash - scene_data (the pipeline, HAL, start-up and libc)
#   spanlight-measure: ram N                 .data + .bss (frame buffers; the stack reserve is not counted)
#
# Usage: measure_elf.sh --plugin libspanlight_icount.so [--cpu CPU] [--timeout S] ELF [APP_ARG]...
# Run it where the app may write its files. The exit status is the app's (3 when no count came back).
# scripts/firmware-report.sh, `spanlight sweep` and `spanlight cost` read these lines.
set -euo pipefail

usage() { sed -n '2,18s/^# \{0,1\}//p' "$0" >&2; exit 2; }

cpu=cortex-m7
plugin=
timeout_s=300
while [ $# -gt 0 ]; do
  case "$1" in
    --cpu) cpu=$2; shift 2 ;;
    --plugin) plugin=$2; shift 2 ;;
    --timeout) timeout_s=$2; shift 2 ;;
    -h|--help) usage ;;
    --*) echo "measure_elf: unknown option $1" >&2; usage ;;
    *) break ;;
  esac
done
[ $# -ge 1 ] && [ -n "$plugin" ] || usage
elf=$1
shift
[ -f "$elf" ] || { echo "measure_elf: no such ELF: $elf" >&2; exit 2; }

log=$(mktemp)
trap 'rm -f "$log"' EXIT
status=0
bash "$(dirname "$0")/run_on_qemu.sh" --cpu "$cpu" --plugin "$plugin" --timeout "$timeout_s" "$elf" "$@" > "$log" || status=$?
grep -v '^spanlight-\(instructions\|regions\|region\):' "$log" || true

instructions=$(awk '/^spanlight-instructions:/ { print $2 }' "$log")
[ -n "$instructions" ] || { echo "measure_elf: no instruction count from $elf" >&2; exit $((status ? status : 3)); }
echo "spanlight-measure: instructions $instructions"
echo "spanlight-measure: regions $(awk '/^spanlight-region:/ { printf "%s%s", sep, $2; sep = " " }' "$log")"
covered=$(sed -n 's/.*covered \([0-9]*\) pixels.*/\1/p' "$log" | head -n 1)
[ -z "$covered" ] || echo "spanlight-measure: covered_pixels $covered"
stack=$(sed -n 's/.*stack peak \([0-9]*\) bytes.*/\1/p' "$log" | head -n 1)
[ -z "$stack" ] || echo "spanlight-measure: stack_peak $stack"
render_stack=$(sed -n 's/.*render_frame stack \([0-9]*\) bytes.*/\1/p' "$log" | head -n 1)
[ -z "$render_stack" ] || echo "spanlight-measure: render_stack $render_stack"

# Bytes of one section (0 when absent), and of the baked scene's symbols.
section() { arm-none-eabi-size -A "$elf" | awk -v s="$1" '$1 == s { print $2; f = 1 } END { if (!f) print 0 }'; }
scene_data=0
for size in $(arm-none-eabi-nm -S -C "$elf" | awk '$4 ~ /^baked::/ { print $2 }'); do scene_data=$((scene_data + 16#$size)); done
text=$(section .text); rodata=$(section .rodata); data=$(section .data); bss=$(section .bss)
flash=$((text + rodata + data))
echo "spanlight-measure: flash $flash"
echo "spanlight-measure: scene_data $scene_data"
echo "spanlight-measure: pipeline_flash $((flash - scene_data))"
echo "spanlight-measure: ram $((data + bss))"
exit "$status"
