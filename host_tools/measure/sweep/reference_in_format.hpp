// What the float model's picture looks like in a framebuffer format: an RGB565
// frame is compared with the float picture rounded to RGB565 (each channel to
// the nearest 5- or 6-bit level, expanded back as the pipeline expands it), so
// the format's own quantisation (up to 4 LSB in red and blue) is not counted as
// the pipeline's error. RGB888 pictures are returned as they are. The one place
// where the sweep, its report and the accuracy figures round the reference.
#pragma once

#include <cstdint>
#include <vector>

#include "spanlight/knobs.hpp"

namespace spanlight::sweep {

std::vector<std::uint8_t> reference_in_format(const std::vector<std::uint8_t>& rgb, PixelFormat format);

}  // namespace spanlight::sweep
