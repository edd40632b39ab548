/* The catch-all exception handler: report which exception hit and where, then exit
 * non-zero so the QEMU run (and its ctest test) fails instead of hanging. */
#include "startup/decimal.h"
#include "startup/handlers.h"
#include "startup/linker_symbols.h"
#include "startup/semihosting.h"

#include <stdint.h>

__attribute__((noreturn, used)) void spanlight_fault_report(uint32_t exception_number,
                                                            const uint32_t *faulting_sp);

/* Naked: the fault may be a stack overflow, so the handler must not push onto the old stack.
 * It passes IPSR (the exception number) and the old SP, then restarts SP at the top of the
 * stack so the report has room to run. */
__attribute__((naked, noreturn)) void spanlight_fault_handler(void) {
  __asm__ volatile(
      ".syntax unified\n"
      "  mrs r0, ipsr\n"
      "  mov r1, sp\n"
      "  ldr r2, =__stack_top\n"
      "  mov sp, r2\n"
      "  bl spanlight_fault_report\n"
      "  .ltorg\n");
}

/* The core pushed r0-r3, r12, lr, pc, xPSR on the old stack; pc is word 6. */
enum { kStackedPcIndex = 6, kStackedFrameWords = 8 };

static int frame_is_readable(const uint32_t *sp) {
  return sp >= __stack_limit && sp + kStackedFrameWords <= __stack_top;
}

void spanlight_fault_report(uint32_t exception_number, const uint32_t *faulting_sp) {
  char number[12];
  spanlight_semihost_write0("spanlight: unexpected exception ");
  spanlight_semihost_write0(spanlight_format_decimal(exception_number & 0x1FFu, number));
  if (frame_is_readable(faulting_sp)) {
    spanlight_semihost_write0(" at pc ");
    spanlight_semihost_write0(spanlight_format_hex(faulting_sp[kStackedPcIndex], number));
  } else {
    spanlight_semihost_write0(" (stack pointer outside the stack: overflow?)");
  }
  spanlight_semihost_write0("\n");
  /* 128 + exception number: 131 for a HardFault, distinct from any status an app returns. */
  spanlight_semihost_exit((int)(128u + (exception_number & 0x1FFu)));
}
