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

void require_rgb8_size(Rgb8View view) {
  const auto expected = static_cast<std::size_t>(view.width > 0 ? view.width : 0) *
                        static_cast<std::size_t>(view.height > 0 ? view.height : 0) * 3;
  if (view.width <= 0 || view.height <= 0 || view.rgb.size() != expected) {
    throw CompareError("RGB8 buffer of " + std::to_string(view.rgb.size()) + " bytes does not hold a " +
                       std::to_string(view.width) + " x " + std::to_string(view.height) + " RGB image");
  }
}

OIIO::ImageBuf to_image_buf(Rgb8View view) {
  require_rgb8_size(view);
  OIIO::ImageBuf image(OIIO::ImageSpec(view.width, view.height, 3, OIIO::TypeDesc::UINT8));
  image.set_pixels(OIIO::ROI::All(), OIIO::TypeDesc::UINT8, view.rgb.data());
  return image;
}

io::Rgb8Image to_rgb8(const OIIO::ImageBuf& image) {
  const OIIO::ImageSpec& spec = image.spec();
  io::Rgb8Image rgb8;
  rgb8.width = spec.width;
  rgb8.height = spec.height;
  rgb8.rgb.resize(static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(spec.height) * 3);
  image.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::UINT8, rgb8.rgb.data());
  return rgb8;
}

void require_same_size(const OIIO::ImageBuf& a, const OIIO::ImageBuf& b) {
  const OIIO::ImageSpec& sa = a.spec();
  const OIIO::ImageSpec& sb = b.spec();
  if (sa.width != sb.width || sa.height != sb.height) {
    throw CompareError("images differ in size: " + std::to_string(sa.width) + " x " + std::to_string(sa.height) +
                       " and " + std::to_string(sb.width) + " x " + std::to_string(sb.height));
  }
}

ImagePair read_same_size(const std::filesystem::path& a, const std::filesystem::path& b) {
  ImagePair pair{read_rgb(a), read_rgb(b)};  // braces: a is read first
  try {
    require_same_size(pair.a, pair.b);
  } catch (const CompareError& e) {
    throw CompareError(a.string() + " and " + b.string() + ": " + e.what());
  }
  return pair;
}

}  // namespace spanlight::compare
