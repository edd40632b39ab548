// Reads a scene file into a JSON tree, turning every way that can fail
// (missing file, bad syntax, a number too large for a double, a key given
// twice) into a SceneError naming the file and, where known, the field.
#pragma once

#include <filesystem>

#include <nlohmann/json.hpp>

namespace spanlight::scene::detail {

// ordered_json keeps the file's order, so textures and messages follow it.
using Json = nlohmann::ordered_json;

Json read_json_document(const std::filesystem::path& file);

}  // namespace spanlight::scene::detail
