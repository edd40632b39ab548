// fault_check: executes an undefined instruction, which must end in the startup's catch-all
// handler: it logs the exception and the faulting pc, and QEMU exits with status 131
// (128 + 3, HardFault; UsageFault is not enabled, so it escalates). tests/firmware checks
// that a crash fails the run instead of hanging it.
#include "hal/hal.hpp"

int spanlight::hal::app_main(Args /*args*/) {
  log_line("fault_check: executing udf");
  __asm__ volatile("udf #0");
  log_line("fault_check: still running after udf");
  return 0;
}
