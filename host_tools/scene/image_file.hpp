// Reads an image file into an 8-bit RGB Image, top row first (io::read_rgb8_image:
// grey expanded, alpha dropped, 16-bit rounded, 1..4096 texels a side).
#pragma once

#include <filesystem>
#include <string>

#include "scene/scene.hpp"

namespace spanlight::scene::detail {

// Errors name the image file and field_path, the scene field that named it.
Image load_image(const std::filesystem::path& image_file, const std::string& field_path);

}  // namespace spanlight::scene::detail
