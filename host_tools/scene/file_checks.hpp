// Files a scene names: where they are, the first check on each (it must
// exist and be a file), so the error says "no such file" rather than a
// library's guess, and errors that name both the scene and the file.
#pragma once

#include <filesystem>
#include <string_view>

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

// Throws SceneError(file, field, ...) unless file is an existing regular file.
// kind names it in the message: "scene file", "OBJ file", "image file".
void require_regular_file(const std::filesystem::path& file, std::string_view field, std::string_view kind);

}  // namespace spanlight::scene::detail
