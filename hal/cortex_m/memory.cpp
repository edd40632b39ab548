// Stack high-water mark from the paint the reset code laid over the stack.
#include "hal/hal.hpp"
#include "startup/stack_watermark.h"

namespace spanlight::hal {

std::size_t stack_peak_bytes() { return spanlight_stack_peak_bytes(); }
std::size_t stack_mark() { return spanlight_stack_mark(); }

}  // namespace spanlight::hal
