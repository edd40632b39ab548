// The host has no painted stack to read; report "not measured".
#include "hal/hal.hpp"

namespace spanlight::hal {

std::size_t stack_peak_bytes() { return 0; }
std::size_t stack_mark() { return 0; }

}  // namespace spanlight::hal
