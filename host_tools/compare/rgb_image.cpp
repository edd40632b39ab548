#include "compare/rgb_image.hpp"

#include <string>

#include "io/image_file.hpp"

namespace spanlight::compare {

OIIO::ImageBuf read_rgb(const std::filesystem::path& file) {
  try {
    const io::Rgb8Image image = io::read_rgb8_image(file, "image file");
    return to_image_buf({image.width, image.height, image.rgb});
  } catch (const io::ReadError& e) {
    throw CompareError(e.what());
  }
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
