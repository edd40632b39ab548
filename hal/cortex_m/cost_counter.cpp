// Cortex-M cost: the marker calls bracket the region for the exact instruction count; timer0
// is read outside the markers so its reads are not part of the counted region.
#include "hal/hal.hpp"
#include "timer0.hpp"

extern "C" void spanlight_measure_begin();
extern "C" void spanlight_measure_end();

namespace spanlight::hal {

void CostCounter::begin() {
  start_ = timer0::read();
  spanlight_measure_begin();
}

void CostCounter::end() {
  spanlight_measure_end();
  const std::uint32_t now = timer0::read();
  // The timer counts down; unsigned subtraction handles the wrap.
  elapsed_ += static_cast<std::uint32_t>(static_cast<std::uint32_t>(start_) - now);
}

const char* CostCounter::unit() { return "timer0-ticks"; }

}  // namespace spanlight::hal
