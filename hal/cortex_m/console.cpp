// Cortex-M log and exit through semihosting: QEMU prints the text and exits with the status.
#include "hal/hal.hpp"
#include "startup/semihosting.h"

namespace spanlight::hal {

void log_line(const char* text) {
  spanlight_semihost_write0(text);
  spanlight_semihost_write0("\n");
}

void exit(int status) { spanlight_semihost_exit(status); }

}  // namespace spanlight::hal
