// Where the mesh tests find the repository's scenes/ folder and its mesh scenes.
#pragma once

#include <algorithm>
#include <filesystem>
#include <vector>

namespace spanlight::mesh_generator::test {

inline std::filesystem::path scenes_folder() { return std::filesystem::path(SPANLIGHT_SOURCE_DIR) / "scenes"; }

// scenes/mesh_*.json (the shared mesh scenes) and scenes/checks/mesh_*.json (check
// scenes), sorted: every mesh scene a file adds is tested without listing it here.
inline std::vector<std::filesystem::path> mesh_scene_files(const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    if (name.starts_with("mesh_") && entry.path().extension() == ".json") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// The shared ones, then the checks.
inline std::vector<std::filesystem::path> all_mesh_scene_files() {
  std::vector<std::filesystem::path> files = mesh_scene_files(scenes_folder());
  for (const auto& check : mesh_scene_files(scenes_folder() / "checks")) files.push_back(check);
  return files;
}

}  // namespace spanlight::mesh_generator::test
