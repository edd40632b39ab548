#include <string>
#include <vector>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include "compare/compare.hpp"
#include "compare/rgb_image.hpp"
#include "io/atomic_write.hpp"

namespace spanlight::compare {

std::string png_bytes(Rgb8View image) {
  require_rgb8_size(image);
  std::vector<unsigned char> encoded;
  OIIO::Filesystem::IOVecOutput memory(encoded);
  auto output = OIIO::ImageOutput::create("png");  // by format name: there is no file name to go by
  if (!output) throw CompareError("no PNG writer: " + OIIO::geterror());
  const OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::UINT8);
  if (!output->set_ioproxy(&memory) || !output->open("memory.png", spec) ||
      !output->write_image(OIIO::TypeDesc::UINT8, image.rgb.data()) || !output->close()) {
    throw CompareError("PNG encoder: " + output->geterror());
  }
  return std::string(encoded.begin(), encoded.end());
}

bool write_png_atomically(const std::filesystem::path& path, int width, int height,
                          std::span<const std::uint8_t> rgb8, std::string* error) {
  try {
    io::write_file_atomically(path, png_bytes({width, height, rgb8}), "", {});
    return true;
  } catch (const std::runtime_error& e) {  // CompareError or io::OutputError
    if (error) *error = e.what();
    return false;
  }
}

}  // namespace spanlight::compare
