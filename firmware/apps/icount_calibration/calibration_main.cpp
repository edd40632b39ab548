// icount_calibration: proves the instruction count is exact. Each region below calls the
// measure markers directly from assembly around a body whose instruction count is known,
// so the plugin must report exactly body + 2 (the begin marker's `bx lr` and the `bl` into the
// end marker; see hal/cortex_m/measure_markers.cpp). tests/firmware checks the numbers.
// Cortex-M only: the regions are Thumb assembly (ARMv6-M subset, so all three cores run it).
#include "hal/hal.hpp"
#include "hal/log_line.hpp"

namespace {

// Registers a region may clobber: the markers follow the AAPCS, and bl writes lr.
#define SPANLIGHT_REGION_CLOBBERS "r0", "r1", "r2", "r3", "r12", "lr", "cc", "memory"

// Expected 2: no body at all.
__attribute__((noinline)) void empty_region() {
  __asm__ volatile(
      "bl spanlight_measure_begin\n"
      "bl spanlight_measure_end\n" ::: SPANLIGHT_REGION_CLOBBERS);
}

// Expected 1002: a straight line of 1000 instructions (longer than any translation block).
__attribute__((noinline)) void straight_line_region() {
  __asm__ volatile(
      "bl spanlight_measure_begin\n"
      ".rept 1000\n"
      "  nop\n"
      ".endr\n"
      "bl spanlight_measure_end\n" ::: SPANLIGHT_REGION_CLOBBERS);
}

// Expected 203: 1 + 100 iterations of 2 instructions (a loop re-executes one block).
__attribute__((noinline)) void loop_region() {
  __asm__ volatile(
      ".syntax unified\n"
      "bl spanlight_measure_begin\n"
      "  movs r2, #100\n"
      "1:\n"
      "  subs r2, r2, #1\n"
      "  bne 1b\n"
      "bl spanlight_measure_end\n" ::: SPANLIGHT_REGION_CLOBBERS);
}

// Expected 4: two loads from timer0, i.e. device I/O. Under -icount QEMU re-translates a block
// when an I/O access is not its last instruction; the count must not see that twice.
__attribute__((noinline)) void device_io_region() {
  __asm__ volatile(
      ".syntax unified\n"
      "ldr r0, =0x40000004\n"
      "bl spanlight_measure_begin\n"
      "  ldr r1, [r0]\n"
      "  ldr r1, [r0]\n"
      "bl spanlight_measure_end\n"
      "b 2f\n"
      ".ltorg\n"
      "2:\n" ::: SPANLIGHT_REGION_CLOBBERS);
}

}  // namespace

int spanlight::hal::app_main(Args /*args*/) {
  empty_region();
  straight_line_region();
  loop_region();
  device_io_region();
  log_line("icount_calibration: regions expect 2 1002 203 4 instructions");
  return 0;
}
