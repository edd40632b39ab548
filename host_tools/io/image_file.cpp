#include "io/image_file.hpp"

#include <cstddef>
#include <string>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

namespace spanlight::io {
namespace {

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

Rgb8Image read_rgb8_image(const std::filesystem::path& file, std::string_view kind) {
  const std::string bytes = read_regular_file(file, kind, max_image_file_bytes);
  OIIO::Filesystem::IOMemReader memory(bytes.data(), bytes.size());

  // "Alpha ignored" means the stored RGB: by default OIIO would multiply RGB by alpha.
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  // open() reads the header only; the name picks the format (OIIO tries the others when it does not fit).
  auto input = OIIO::ImageInput::open(file.string(), &config, &memory);
  if (!input) throw ReadError(file, "expected " + with_article(kind) + " OpenImageIO can read, got: " + OIIO::geterror());

  const OIIO::ImageSpec& spec = input->spec();
  if (spec.width < 1 || spec.width > max_image_side || spec.height < 1 || spec.height > max_image_side) {
    throw ReadError(file, "expected an image of 1.." + std::to_string(max_image_side) + " texels a side, got " +
                    std::to_string(spec.width) + "x" + std::to_string(spec.height));
  }
  if (spec.nchannels < 1 || spec.nchannels > 4) {
    throw ReadError(file, "expected a grey, RGB or RGBA image, got " + std::to_string(spec.nchannels) + " channels");
  }

  // Within the side limit: at most 4096 * 4096 * 4 bytes (64 MiB).
  const auto texel_count = static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(spec.height);
  std::vector<std::uint8_t> pixels(texel_count * static_cast<std::size_t>(spec.nchannels));
  // UINT8 converts deeper formats with rounding; rows come top row first.
  if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, pixels.data())) {
    throw ReadError(file, "expected readable pixel data, got: " + input->geterror());
  }
  input->close();

  Rgb8Image image;
  image.width = spec.width;
  image.height = spec.height;
  image.rgb = to_rgb(pixels, spec.nchannels, texel_count);
  return image;
}

}  // namespace spanlight::io
