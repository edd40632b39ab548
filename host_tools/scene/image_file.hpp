// Reads an image file with OpenImageIO into an 8-bit RGB Image, top row first.
#pragma once

#include <filesystem>
#include <string>

#include "scene/scene.hpp"

namespace spanlight::scene::detail {

// Errors name the image file and field_path, the scene field that named it.
Image load_image(const std::filesystem::path& image_file, const std::string& field_path);

}  // namespace spanlight::scene::detail
