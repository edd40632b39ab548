#include "sweep/reference_in_format.hpp"

#include "spanlight/4_pixel/colour.hpp"

namespace spanlight::sweep {

std::vector<std::uint8_t> reference_in_format(const std::vector<std::uint8_t>& rgb, PixelFormat format) {
  if (format == PixelFormat::rgb888) return rgb;
  std::vector<std::uint8_t> out(rgb.size());
  for (std::size_t i = 0; i + 2 < rgb.size(); i += 3) {
    // Both RGB565 byte orders hold the same levels: the pipeline's own pack and unpack.
    const Colour c = ColorTraits<PixelFormat::rgb565>::quantize(colour_of(rgb[i], rgb[i + 1], rgb[i + 2]));
    out[i] = static_cast<std::uint8_t>(red(c));
    out[i + 1] = static_cast<std::uint8_t>(green(c));
    out[i + 2] = static_cast<std::uint8_t>(blue(c));
  }
  return out;
}

}  // namespace spanlight::sweep
