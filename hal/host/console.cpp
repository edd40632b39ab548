// Host log and exit: stderr keeps stdout free for a tool's own output.
#include "hal/hal.hpp"

#include <cstdio>
#include <cstdlib>

namespace spanlight::hal {

void log_line(const char* text) { std::fprintf(stderr, "%s\n", text); }

// std::exit flushes and closes open stdio files, as a returning main would.
void exit(int status) { std::exit(status); }

}  // namespace spanlight::hal
