#include "compare/rgb_image.hpp"

#include <string>

#include <OpenImageIO/imagebufalgo.h>

namespace spanlight::compare {

OIIO::ImageBuf read_rgb(const std::filesystem::path& file) {
  OIIO::ImageBuf image(file.string());
  if (!image.read(0, 0, true, OIIO::TypeDesc::UINT8)) {
    throw CompareError("cannot read " + file.string() + ": " + image.geterror());
  }
  const int channels = image.nchannels();
  if (channels == 3) return image;
  // Grey: the one channel three times; RGBA (or more): the first three.
  const int order_grey[3] = {0, 0, 0};
  const int order_rgb[3] = {0, 1, 2};
  if (channels != 1 && channels < 3) {
    throw CompareError(file.string() + ": expected a grey, RGB or RGBA image, found " + std::to_string(channels) +
                       " channels");
  }
  OIIO::ImageBuf rgb = OIIO::ImageBufAlgo::channels(image, 3, channels == 1 ? order_grey : order_rgb);
  if (rgb.has_error()) throw CompareError(file.string() + ": " + rgb.geterror());
  return rgb;
}

OIIO::ImageBuf to_image_buf(Rgb8View view) {
  const auto expected = static_cast<std::size_t>(view.width) * static_cast<std::size_t>(view.height) * 3;
  if (view.width <= 0 || view.height <= 0 || view.rgb.size() != expected) {
    throw CompareError("RGB8 buffer of " + std::to_string(view.rgb.size()) + " bytes does not hold a " +
                       std::to_string(view.width) + " x " + std::to_string(view.height) + " RGB image");
  }
  OIIO::ImageBuf image(OIIO::ImageSpec(view.width, view.height, 3, OIIO::TypeDesc::UINT8));
  image.set_pixels(OIIO::ROI::All(), OIIO::TypeDesc::UINT8, view.rgb.data());
  return image;
}

void require_same_size(const OIIO::ImageBuf& a, const OIIO::ImageBuf& b) {
  const OIIO::ImageSpec& sa = a.spec();
  const OIIO::ImageSpec& sb = b.spec();
  if (sa.width != sb.width || sa.height != sb.height) {
    throw CompareError("images differ in size: " + std::to_string(sa.width) + " x " + std::to_string(sa.height) +
                       " and " + std::to_string(sb.width) + " x " + std::to_string(sb.height));
  }
}

}  // namespace spanlight::compare
