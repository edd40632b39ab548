// Reads a scene or animation file into a JSON tree, turning every way that can fail
// (missing file, bad syntax, a number too large for a double, a key given
// twice) into a SceneError naming the file and, where known, the field.
#pragma once

#include <filesystem>
#include <string_view>

#include <nlohmann/json.hpp>

namespace spanlight::scene::detail {

// ordered_json keeps the file's order, so textures and messages follow it.
using Json = nlohmann::ordered_json;

// kind names the file in messages: "scene file", "animation file".
Json read_json_document(const std::filesystem::path& file, std::string_view kind = "scene file");

}  // namespace spanlight::scene::detail
