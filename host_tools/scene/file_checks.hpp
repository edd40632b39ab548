// Files a scene names: where they are, and reading them through host_tools/io
// (regular files only, within a size limit), so the error says "no such file"
// or "got a FIFO" rather than a library's guess, and errors that name both
// the scene and the file.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "io/read_file.hpp"
#include "scene/scene.hpp"

namespace spanlight::scene::detail {

// Relative paths in a scene are relative to the scene file's own folder.
inline std::filesystem::path resolve_against_scene(const std::filesystem::path& scene_file,
                                                   const std::filesystem::path& named) {
  return (scene_file.parent_path() / named).lexically_normal();
}

// Runs load(), a reader of one file the scene names, whose SceneErrors name that file as theirs,
// and puts the scene file in front: "SCENE: FIELD: ASSET: expected ..." (scene.hpp).
template <typename Load>
auto load_asset(const std::filesystem::path& scene_file, Load&& load) -> decltype(load()) {
  try {
    return load();
  } catch (const SceneError& in_asset) {
    throw SceneError(scene_file.string(), in_asset.field(), in_asset.expected(), in_asset.file());
  }
}

// Runs read(), an io reader of `file`, turning its io::ReadError into a SceneError
// naming the file and `field`: "FILE: FIELD: expected ..., got ...".
template <typename Read>
auto read_for_field(const std::filesystem::path& file, std::string_view field, Read&& read) -> decltype(read()) {
  try {
    return read();
  } catch (const io::ReadError& error) {
    throw SceneError(file.string(), std::string(field), error.expected());
  }
}

}  // namespace spanlight::scene::detail
