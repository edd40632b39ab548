/* What runs between reset and main. Newlib's crt0 is not linked (-nostartfiles): it would
 * set up its own heap and exit path; this does only what spanlight needs. */
#include "startup/handlers.h"
#include "startup/linker_symbols.h"
#include "startup/semihosting.h"
#include "startup/stack_watermark.h"

#include <stddef.h>
#include <string.h>

#define SPANLIGHT_STR2(x) #x
#define SPANLIGHT_STR(x) SPANLIGHT_STR2(x)

__attribute__((noreturn, used)) void spanlight_start_c(void);

/* Naked and in assembly because two steps must happen before any compiled code runs:
 *  1. Painting the stack: only now is every byte of it unused (SP = __stack_top, nothing pushed).
 *  2. Enabling the FPU: with -mfloat-abi=hard the compiler may use FP registers anywhere,
 *     and the first FP instruction with CP10/CP11 disabled is a UsageFault.
 * Written with ARMv6-M instructions only, so the one source serves all three cores. */
__attribute__((naked, noreturn)) void Reset_Handler(void) {
  __asm__ volatile(
      ".syntax unified\n"
      "  ldr r0, =__stack_limit\n"
      "  ldr r1, =__stack_top\n"
      "  ldr r2, =" SPANLIGHT_STR(SPANLIGHT_STACK_PAINT) "\n"
      "1:\n"
      "  cmp r0, r1\n"
      "  bhs 2f\n"
      "  stmia r0!, {r2}\n"
      "  b 1b\n"
      "2:\n"
#if defined(__ARM_FP)
      /* CPACR (0xE000ED88) bits 20-23: full access to CP10 and CP11, the FPU. The barriers
       * make the new access rights apply to the very next instruction. */
      "  ldr r0, =0xE000ED88\n"
      "  ldr r1, [r0]\n"
      "  ldr r2, =0x00F00000\n"
      "  orrs r1, r1, r2\n"
      "  str r1, [r0]\n"
      "  dsb\n"
      "  isb\n"
#endif
      /* bl, not b: ARMv6-M's 16-bit b reaches only +-2 KiB. */
      "  bl spanlight_start_c\n"
      "  .ltorg\n");
}

static void run_init_functions(spanlight_init_fn *first, spanlight_init_fn *last) {
  for (spanlight_init_fn *fn = first; fn < last; ++fn) {
    (*fn)();
  }
}

void spanlight_start_c(void) {
  /* .data: the linker stored its initial values in flash after the code (LMA), but code
   * addresses it in RAM (VMA). newlib's memcpy/memset are plain loops, no heap and no state. */
  memcpy(__data_start, __data_load, (size_t)((char *)__data_end - (char *)__data_start));
  memset(__bss_start, 0, (size_t)((char *)__bss_end - (char *)__bss_start));
  /* Constructors of C++ static objects, in the order crtbegin would run them. */
  run_init_functions(__preinit_array_start, __preinit_array_end);
  run_init_functions(__init_array_start, __init_array_end);

  const int status = main();
  /* Static destructors never run: the run ends here, and QEMU reports this status. */
  spanlight_semihost_exit(status);
}
