// Internal: the per-pixel difference both the figures and the heat map start from.
#pragma once

#include <OpenImageIO/imagebuf.h>

namespace spanlight::compare {

// One channel: for each pixel, max over R, G, B of |a - b|, in [0, 1] units (1 LSB = 1/255).
OIIO::ImageBuf max_channel_difference(const OIIO::ImageBuf& a, const OIIO::ImageBuf& b);

}  // namespace spanlight::compare
