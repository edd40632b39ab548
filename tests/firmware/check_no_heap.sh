#!/usr/bin/env bash
# Fails if any given ELF (or object, or archive) names an allocator, C++ new/delete, the
# exception machinery or RTTI typeinfo, defined or merely referenced. A directory stands for
# every *.elf in it (so apps added later are checked without listing them).
#   check_no_heap.sh [--nm arm-none-eabi-nm] FILE|DIR...
set -euo pipefail

# malloc family and newlib's reentrant _r twins, the break that grows a heap, operator
# new/new[]/delete/delete[] in every overload (_Znw*, _Zna*, _Zdl*, _Zda*), exceptions, and
# typeinfo objects/names (_ZTI*, _ZTS*: RTTI, which -fno-rtti should leave none of).
forbidden='^(malloc|free|calloc|realloc|reallocarray|memalign|aligned_alloc|posix_memalign|valloc|pvalloc'
forbidden+='|_malloc_r|_free_r|_calloc_r|_realloc_r|_memalign_r|_sbrk|_sbrk_r|sbrk'
forbidden+='|_Znw.*|_Zna.*|_Zdl.*|_Zda.*'
forbidden+='|__cxa_allocate_exception|__cxa_free_exception|__cxa_throw|__cxa_rethrow|__gxx_personality_v0'
forbidden+='|_ZTI.*|_ZTS.*)$'

# Options (--nm) and files go to the shared check as they are.
exec bash "$(dirname "$0")/../check_forbidden_symbols.sh" --label heap-check --forbidden "$forbidden" "$@"
