#include "image_file.hpp"

#include "file_checks.hpp"
#include "io/image_file.hpp"

namespace spanlight::scene::detail {

Image load_image(const std::filesystem::path& image_file, const std::string& field_path) {
  io::Rgb8Image read = read_for_field(image_file, field_path, [&] { return io::read_rgb8_image(image_file, "image file"); });
  Image image;
  image.width = read.width;
  image.height = read.height;
  image.rgb = std::move(read.rgb);
  return image;
}

}  // namespace spanlight::scene::detail
