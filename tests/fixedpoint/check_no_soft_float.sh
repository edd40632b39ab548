#!/usr/bin/env bash
# Fails if an object names (defines or calls) a floating-point or division routine of
# libgcc: the ARM EABI helpers __aeabi_f*, __aeabi_d*, __aeabi_*div*, and the generic
# soft-float (__addsf3, __muldf3, __fixdfsi, ...) and division (__udivdi3, ...) names.
# On Cortex-M0+ these are the calls integer-only code must not make.
#   check_no_soft_float.sh [--nm arm-none-eabi-nm] OBJECT...
set -euo pipefail

nm=arm-none-eabi-nm
if [ "${1:-}" = "--nm" ]; then
  nm=$2
  shift 2
fi
[ $# -ge 1 ] || { echo "usage: check_no_soft_float.sh [--nm NM] OBJECT..." >&2; exit 2; }

forbidden='^(__aeabi_[fd][a-z0-9]*|__aeabi_[a-z]*div[a-z]*|__aeabi_[a-z]*mod'
forbidden+='|__[a-z]+[sdtx]f[0-9]|__[a-z]+[sdtx]f[sdt]i[0-9]?|__[a-z]+[sdt]i[sdtx]f[0-9]?'
forbidden+='|__u?(div|mod)[sdt]i3|__udivmod[sdt]i4)$'

failed=0
for file in "$@"; do
  if [ ! -f "$file" ]; then
    echo "soft-float-check: FAIL $file: missing"
    failed=1
    continue
  fi
  found=$("$nm" -P "$file" | awk '{ print $1 }' | grep -E "$forbidden" | LC_ALL=C sort -u | tr '\n' ' ' || true)
  if [ -n "$found" ]; then
    echo "soft-float-check: FAIL $file: $found"
    failed=1
  else
    echo "soft-float-check: ok $file"
  fi
done
exit "$failed"
