// Host cost: wall time from steady_clock. Only indicative; the exact figure is the
// instruction count of the Cortex-M build under QEMU.
#include "hal/hal.hpp"

#include <chrono>

namespace spanlight::hal {
namespace {

std::uint64_t now_ns() {
  const auto since_epoch = std::chrono::steady_clock::now().time_since_epoch();
  return static_cast<std::uint64_t>(std::chrono::duration_cast<std::chrono::nanoseconds>(since_epoch).count());
}

}  // namespace

void CostCounter::begin() { start_ = now_ns(); }

void CostCounter::end() { elapsed_ += now_ns() - start_; }

const char* CostCounter::unit() { return "ns"; }

}  // namespace spanlight::hal
