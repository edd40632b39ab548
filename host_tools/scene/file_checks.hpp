// Files a scene names: where they are, and the first check on each (it must
// exist and be a file), so the error says "no such file" rather than a
// library's guess.
#pragma once

#include <filesystem>
#include <string_view>

namespace spanlight::scene::detail {

// Relative paths in a scene are relative to the scene file's own folder.
inline std::filesystem::path resolve_against_scene(const std::filesystem::path& scene_file,
                                                   const std::filesystem::path& named) {
  return (scene_file.parent_path() / named).lexically_normal();
}

// Throws SceneError(file, field, ...) unless file is an existing regular file.
// kind names it in the message: "scene file", "OBJ file", "image file".
void require_regular_file(const std::filesystem::path& file, std::string_view field, std::string_view kind);

}  // namespace spanlight::scene::detail
