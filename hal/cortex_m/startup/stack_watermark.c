#include "startup/stack_watermark.h"

#include "startup/linker_symbols.h"

#include <stdint.h>

size_t spanlight_stack_peak_bytes(void) {
  /* The stack grows down, so the lowest word that lost its paint marks the peak. */
  const uint32_t *word = __stack_limit;
  while (word < __stack_top && *word == SPANLIGHT_STACK_PAINT) {
    ++word;
  }
  return (size_t)((uintptr_t)__stack_top - (uintptr_t)word);
}

size_t spanlight_stack_mark(void) {
  uint32_t *sp;
  __asm volatile("mov %0, sp" : "=r"(sp));
  /* Below sp nothing is in use (this leaf function keeps its loop in registers): paint it again. */
  for (uint32_t *word = __stack_limit; word < sp; ++word) {
    *word = SPANLIGHT_STACK_PAINT;
  }
  return (size_t)((uintptr_t)__stack_top - (uintptr_t)sp);
}

size_t spanlight_stack_size_bytes(void) {
  return (size_t)((uintptr_t)__stack_top - (uintptr_t)__stack_limit);
}
