#include "image_file.hpp"

#include <cstddef>

#include <OpenImageIO/imageio.h>

#include "file_checks.hpp"

namespace spanlight::scene::detail {
namespace {

constexpr int max_image_side = 4096;

// Spec: grey, RGB or RGBA, alpha ignored; grey with alpha is grey.
bool has_supported_channels(int channels) { return channels >= 1 && channels <= 4; }
bool is_grey(int channels) { return channels <= 2; }

std::vector<std::uint8_t> to_rgb(const std::vector<std::uint8_t>& pixels, int channels, std::size_t texel_count) {
  std::vector<std::uint8_t> rgb(texel_count * 3);
  const auto stride = static_cast<std::size_t>(channels);
  for (std::size_t i = 0; i < texel_count; ++i) {
    const std::uint8_t* texel = &pixels[i * stride];
    for (std::size_t c = 0; c < 3; ++c) rgb[i * 3 + c] = is_grey(channels) ? texel[0] : texel[c];
  }
  return rgb;
}

}  // namespace

Image load_image(const std::filesystem::path& image_file, const std::string& field_path) {
  const auto fail = [&](const std::string& message) { throw SceneError(image_file.string(), field_path, message); };
  require_regular_file(image_file, field_path, "image file");

  // "Alpha ignored" means the stored RGB: by default OIIO would multiply RGB by alpha.
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto input = OIIO::ImageInput::open(image_file.string(), &config);
  if (!input) fail("expected an image file OpenImageIO can read, got: " + OIIO::geterror());

  const OIIO::ImageSpec& spec = input->spec();
  if (spec.width < 1 || spec.width > max_image_side || spec.height < 1 || spec.height > max_image_side) {
    fail("expected an image of 1..4096 texels a side, got " + std::to_string(spec.width) + "x" +
         std::to_string(spec.height));
  }
  if (!has_supported_channels(spec.nchannels)) {
    fail("expected a grey, RGB or RGBA image, got " + std::to_string(spec.nchannels) + " channels");
  }

  const auto texel_count = static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(spec.height);
  std::vector<std::uint8_t> pixels(texel_count * static_cast<std::size_t>(spec.nchannels));
  // UINT8 converts deeper formats with rounding; rows come top row first.
  if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, pixels.data())) {
    fail("expected readable pixel data, got: " + input->geterror());
  }
  input->close();

  Image image;
  image.width = spec.width;
  image.height = spec.height;
  image.rgb = to_rgb(pixels, spec.nchannels, texel_count);
  return image;
}

}  // namespace spanlight::scene::detail
