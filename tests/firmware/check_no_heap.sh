#!/usr/bin/env bash
# Fails if any given ELF (or object, or archive) names an allocator, C++ new/delete, the
# exception machinery or RTTI typeinfo, defined or merely referenced. A directory stands for
# every *.elf in it (so apps added later are checked without listing them).
#   check_no_heap.sh [--nm arm-none-eabi-nm] FILE|DIR...
set -euo pipefail

nm=arm-none-eabi-nm
if [ "${1:-}" = "--nm" ]; then
  nm=$2
  shift 2
fi
[ $# -ge 1 ] || { echo "usage: check_no_heap.sh [--nm NM] FILE|DIR..." >&2; exit 2; }

files=()
for path in "$@"; do
  if [ -d "$path" ]; then
    elfs=("$path"/*.elf)
    [ -e "${elfs[0]}" ] || { echo "heap-check: FAIL $path: no ELF files"; exit 1; }
    files+=("${elfs[@]}")
  else
    files+=("$path")
  fi
done

# malloc family and newlib's reentrant _r twins, the break that grows a heap, operator
# new/new[]/delete/delete[] in every overload (_Znw*, _Zna*, _Zdl*, _Zda*), exceptions, and
# typeinfo objects/names (_ZTI*, _ZTS*: RTTI, which -fno-rtti should leave none of).
forbidden='^(malloc|free|calloc|realloc|reallocarray|memalign|aligned_alloc|posix_memalign|valloc|pvalloc'
forbidden+='|_malloc_r|_free_r|_calloc_r|_realloc_r|_memalign_r|_sbrk|_sbrk_r|sbrk'
forbidden+='|_Znw.*|_Zna.*|_Zdl.*|_Zda.*'
forbidden+='|__cxa_allocate_exception|__cxa_free_exception|__cxa_throw|__cxa_rethrow|__gxx_personality_v0'
forbidden+='|_ZTI.*|_ZTS.*)$'

failed=0
for file in "${files[@]}"; do
  if [ ! -f "$file" ]; then
    echo "heap-check: FAIL $file: missing"
    failed=1
    continue
  fi
  # -P: "name type [value size]" per symbol, undefined ones included.
  found=$("$nm" -P "$file" | awk '{ print $1 }' | grep -E "$forbidden" | LC_ALL=C sort -u | tr '\n' ' ' || true)
  if [ -n "$found" ]; then
    echo "heap-check: FAIL $file: $found"
    failed=1
  else
    echo "heap-check: ok $file"
  fi
done
exit "$failed"
