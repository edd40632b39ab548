#!/usr/bin/env bash
# Fails if an object names (defines or calls) a floating-point or division routine of
# libgcc: the ARM EABI helpers __aeabi_f*, __aeabi_d*, __aeabi_*div*, and the generic
# soft-float (__addsf3, __muldf3, __fixdfsi, ...) and division (__udivdi3, ...) names.
# On Cortex-M0+ these are the calls integer-only code must not make.
#   check_no_soft_float.sh [--nm arm-none-eabi-nm] OBJECT...
set -euo pipefail

forbidden='^(__aeabi_[fd][a-z0-9]*|__aeabi_[a-z]*div[a-z]*|__aeabi_[a-z]*mod'
forbidden+='|__[a-z]+[sdtx]f[0-9]|__[a-z]+[sdtx]f[sdt]i[0-9]?|__[a-z]+[sdt]i[sdtx]f[0-9]?'
forbidden+='|__u?(div|mod)[sdt]i3|__udivmod[sdt]i4)$'

# Options (--nm) and files go to the shared check as they are.
exec bash "$(dirname "$0")/../check_forbidden_symbols.sh" --label soft-float-check --forbidden "$forbidden" "$@"
