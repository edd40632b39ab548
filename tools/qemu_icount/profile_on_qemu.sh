#!/usr/bin/env bash
# Where a firmware frame's instructions go, on the target itself: runs an ELF in QEMU with
# the exact-count plugin's per-address profile, then attributes every executed instruction
# to source with arm-none-eabi-addr2line (debug info; -g does not change the code). Inlined
# code counts where it was written, so the pipeline's files read as stages (setup, span,
# sample, shade, ...); the pass is the kernel (passes.hpp) the instruction was inlined into.
#
#   profile_on_qemu.sh --plugin libspanlight_icount.so [--cpu CPU] [--top N] [--work DIR]
#                      ELF [APP_ARG]...
#
# Prints four Markdown tables: instructions per stage (innermost source file), per pass
# (code inlined into a pass's kernel; shared code that was not inlined is listed apart),
# per machine function (what the compiler kept out of line) and the N hottest source lines. The counts cover the measured regions only, like
# run_on_qemu.sh's total, and add up to it.
set -euo pipefail

usage() { sed -n '2,13s/^# \{0,1\}//p' "$0" >&2; exit 2; }

here=$(cd "$(dirname "$0")" && pwd)
cpu=cortex-m7
plugin=
top=25
work=
while [ $# -gt 0 ]; do
  case "$1" in
    --cpu) cpu=$2; shift 2 ;;
    --plugin) plugin=$2; shift 2 ;;
    --top) top=$2; shift 2 ;;
    --work) work=$2; shift 2 ;;
    -h|--help) usage ;;
    --*) echo "profile_on_qemu: unknown option $1" >&2; usage ;;
    *) break ;;
  esac
done
[ $# -ge 1 ] && [ -n "$plugin" ] || usage
elf=$1
shift
command -v arm-none-eabi-addr2line >/dev/null || { echo "profile_on_qemu: arm-none-eabi-addr2line is missing" >&2; exit 2; }
work=${work:-$(mktemp -d)}
mkdir -p "$work"

"$here/run_on_qemu.sh" --cpu "$cpu" --plugin "$plugin" --profile "$work/profile.txt" \
  --count-file "$work/count.txt" --timeout 600 "$elf" "$@" >"$work/run.log"
[ -s "$work/profile.txt" ] || { echo "profile_on_qemu: the plugin wrote no profile" >&2; exit 3; }

# One addr2line call for all addresses; -p -i prints the innermost frame first, then
# " (inlined by) ..." lines for each caller it was inlined into.
cut -d' ' -f1 "$work/profile.txt" | arm-none-eabi-addr2line -e "$elf" -a -f -i -p -C >"$work/lines.txt"

awk -v top="$top" -v total_file="$work/count.txt" '
  FNR == NR { count[$1] = $2; next }          # profile.txt: address -> executions
  /^0x[0-9a-f]+: / {                         # a new address: its innermost frame
    finish()
    sub(/ \(discriminator [0-9]+\)$/, "")
    address = $1; sub(/:$/, "", address); sub(/^0x0*/, "0x", address)
    if (address == "0x") address = "0x0"
    where = $NF; stage = where; sub(/:[0-9?]+.*$/, "", stage); sub(/^.*\//, "", stage)
    line = where; sub(/^.*\//, "", line); sub(/ .*$/, "", line)
    pass = ""; chain = $0; outer = $0
    next
  }
  { sub(/ \(discriminator [0-9]+\)$/, ""); chain = chain "\n" $0; outer = $0 }  # " (inlined by) ..." lines
  function finish(   n) {
    if (address == "") return
    n = count[address] + 0
    if (pass == "") pass = pass_of(chain)
    by_stage[stage] += n; by_pass[pass] += n; by_line[line] += n; by_function[short_name(outer)] += n; sum += n
    address = ""
  }
  function pass_of(text) {
    if (text ~ /ShadowDepthKernel/) return "shadow map"
    if (text ~ /DepthAmbientKernel/) return "depth + ambient"
    if (text ~ /LightKernel/) return "light"
    if (text ~ /ModulateKernel/) return "modulate"
    if (text ~ /FusedKernel/) return "fused"
    if (text ~ /clear|depth_clear|fill/) return "clears"
    if (text ~ /spanlight::/) return "shared, out of line (setup, subdivision points, clears)"
    return "other (libgcc, HAL, app)"
  }
  function short_name(frame,   f) {           # "void ns::f<...>(...) const at file:line" -> "ns::f"
    f = frame; sub(/^ *\(inlined by\) /, "", f); sub(/^0x[0-9a-f]+: /, "", f); sub(/ at [^ ]+$/, "", f)
    while (gsub(/<[^<>]*>/, "", f)) {}
    while (gsub(/\([^()]*\)/, "", f)) {}
    sub(/ const$/, "", f)                   # a const member function: its name is the word before
    sub(/^.* /, "", f)
    return f
  }
  function table(title, arr, limit,   k, keys, i, j, tmp, shown) {
    printf "| %s | instructions | share |\n|---|---:|---:|\n", title
    i = 0
    for (k in arr) keys[++i] = k
    for (a = 1; a <= i; ++a)                  # sort by count, descending (insertion sort)
      for (b = a; b > 1 && arr[keys[b]] > arr[keys[b - 1]]; --b) { tmp = keys[b]; keys[b] = keys[b - 1]; keys[b - 1] = tmp }
    shown = 0
    for (a = 1; a <= i && a <= limit; ++a) {
      printf "| `%s` | %d | %.1f %% |\n", keys[a], arr[keys[a]], 100.0 * arr[keys[a]] / sum
      shown += arr[keys[a]]
    }
    if (i > limit) printf "| (%d more) | %d | %.1f %% |\n", i - limit, sum - shown, 100.0 * (sum - shown) / sum
    printf "\n"
  }
  END {
    finish()
    while ((getline l < total_file) > 0) if (l ~ /^spanlight-instructions:/) { split(l, f, " "); measured = f[2] }
    printf "Instructions attributed: %d (measured: %d)\n\n", sum, measured
    table("stage (innermost source file)", by_stage, 1000)
    table("pass", by_pass, 1000)
    table("machine function", by_function, top)
    table("source line", by_line, top)
  }
' "$work/profile.txt" "$work/lines.txt"
