// The selftest's picture: a deterministic RGB888 pattern in integer math only, so the host
// build and every Cortex-M build must produce the same bytes.
#pragma once

#include "hal/hal.hpp"

#include <cstdint>
#include <span>

namespace spanlight::selftest {

// Fills rgb (hal::frame_bytes(size) bytes) with horizontal/vertical ramps, rings and a checker.
void fill_test_pattern(std::span<std::uint8_t> rgb, hal::FrameSize size);

// FNV-1a over the bytes: a short fingerprint to log and compare by eye.
std::uint32_t fnv1a(std::span<const std::uint8_t> bytes);

}  // namespace spanlight::selftest
