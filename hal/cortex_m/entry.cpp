// Cortex-M entry: the reset code calls main() once C/C++ state is ready; main fetches the
// command line QEMU was given (-semihosting-config ...,arg=...), starts timer0 and runs the app.
// The reset code exits with main's return value.
#include "hal/hal.hpp"
#include "startup/semihosting.h"
#include "timer0.hpp"

#include <cstddef>
#include <iterator>

namespace {

// Static storage, not stack or heap: the command line outlives app_main's arguments.
char command_line[256];
const char* arg_pointers[32];  // the sweep bench takes 18 words: its name, seven knobs, --filter and --per-pass
const char* const kUnnamedProgram = "firmware";

// Splits text at spaces in place (QEMU joins its arg= values with single spaces).
std::size_t split_at_spaces(char* text) {
  std::size_t count = 0;
  char* cursor = text;
  while (*cursor != '\0' && count < std::size(arg_pointers)) {
    while (*cursor == ' ') {
      *cursor++ = '\0';
    }
    if (*cursor == '\0') {
      break;
    }
    arg_pointers[count++] = cursor;
    while (*cursor != ' ' && *cursor != '\0') {
      ++cursor;
    }
  }
  return count;
}

}  // namespace

int main() {
  spanlight::hal::timer0::start_free_running();
  std::size_t count = 0;
  if (spanlight_semihost_get_cmdline(command_line, sizeof command_line) == 0) {
    count = split_at_spaces(command_line);
  }
  if (count == 0) {
    arg_pointers[count++] = kUnnamedProgram;
  }
  return spanlight::hal::app_main(spanlight::hal::Args(arg_pointers, count));
}
