#!/usr/bin/env bash
# Fails if any given ELF, object or archive names a symbol matching REGEX (an extended
# regular expression; anchor it), defined or merely referenced. A directory stands for every
# *.elf in it (so apps added later are checked without listing them). Prints, per file,
# "LABEL: ok FILE" or "LABEL: FAIL FILE: NAME..." (the names sorted with LC_ALL=C).
#   check_forbidden_symbols.sh --label LABEL --forbidden REGEX [--nm arm-none-eabi-nm] FILE|DIR...
set -euo pipefail

usage() { echo "usage: check_forbidden_symbols.sh --label LABEL --forbidden REGEX [--nm NM] FILE|DIR..." >&2; exit 2; }
nm=arm-none-eabi-nm
label=
forbidden=
while [ $# -gt 0 ]; do
  case "$1" in
    --nm) nm=$2; shift 2 ;;
    --label) label=$2; shift 2 ;;
    --forbidden) forbidden=$2; shift 2 ;;
    --*) usage ;;
    *) break ;;
  esac
done
[ -n "$label" ] && [ -n "$forbidden" ] && [ $# -ge 1 ] || usage

files=()
for path in "$@"; do
  if [ -d "$path" ]; then
    elfs=("$path"/*.elf)
    [ -e "${elfs[0]}" ] || { echo "$label: FAIL $path: no ELF files"; exit 1; }
    files+=("${elfs[@]}")
  else
    files+=("$path")
  fi
done

failed=0
for file in "${files[@]}"; do
  if [ ! -f "$file" ]; then
    echo "$label: FAIL $file: missing"
    failed=1
    continue
  fi
  # -P: "name type [value size]" per symbol, undefined ones included.
  found=$("$nm" -P "$file" | awk '{ print $1 }' | grep -E "$forbidden" | LC_ALL=C sort -u | tr '\n' ' ' || true)
  if [ -n "$found" ]; then
    echo "$label: FAIL $file: $found"
    failed=1
  else
    echo "$label: ok $file"
  fi
done
exit "$failed"
