// CMSDK APB timer 0 of the mps2 boards (0x40000000): a 32-bit down-counter clocked at 25 MHz.
// Under QEMU with -icount shift=0 every instruction takes 1 ns, so one tick is exactly
// 40 instructions and the readings repeat run to run. (DWT CYCCNT is not emulated.)
#pragma once

#include <cstdint>

namespace spanlight::hal::timer0 {

inline constexpr std::uintptr_t kBase = 0x40000000u;

inline volatile std::uint32_t& reg(std::uintptr_t offset) {
  return *reinterpret_cast<volatile std::uint32_t*>(kBase + offset);
}

inline constexpr std::uintptr_t kCtrl = 0x0;    // bit 0: enable
inline constexpr std::uintptr_t kValue = 0x4;   // current count
inline constexpr std::uintptr_t kReload = 0x8;  // loaded when the count passes 0

// Counts down from 2^32-1 and wraps: differences of readings are elapsed ticks modulo 2^32
// (about 170 s at 25 MHz, far above any measured region).
inline void start_free_running() {
  reg(kCtrl) = 0;
  reg(kReload) = 0xFFFFFFFFu;
  reg(kValue) = 0xFFFFFFFFu;
  reg(kCtrl) = 1;
}

inline std::uint32_t read() { return reg(kValue); }

}  // namespace spanlight::hal::timer0
