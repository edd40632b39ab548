// Host front-end of the fixed-point pipeline: owns the buffers a firmware
// build would declare statically and picks the kernel instantiation that
// matches the requested knobs.
#pragma once

#include <cstdint>
#include <vector>

#include "prepare/prepare.hpp"
#include "spanlight/features.hpp"

namespace spanlight::prepare {

struct FixedOptions {
  PixelFormat format = PixelFormat::rgb888;
  int table_bits = 8;    // 6, 8, 10 or 12
  int newton_steps = 1;  // 0, 1 or 2
  Precision precision{};
};

struct FixedFrame {
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb;       // 8 bits a channel (RGB565 expanded), top row first
  std::vector<std::uint8_t> raw;       // the framebuffer's own bytes (RGB888 or little-endian RGB565)
  std::vector<std::uint32_t> depth;    // as stored, depth_bits wide
};

// Throws std::invalid_argument for knob values outside the sets above.
FixedFrame render_fixed(const PreparedStorage& prepared, const FixedOptions& options);

const char* to_string(PixelFormat format);

}  // namespace spanlight::prepare
