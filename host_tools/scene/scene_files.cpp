#include "scene/scene_files.hpp"

#include <algorithm>

namespace spanlight::scene {

std::vector<std::filesystem::path> files_read(const Scene& scene) {
  std::vector<std::filesystem::path> files{scene.file};
  const auto same = [](const std::filesystem::path& a, const std::filesystem::path& b) {
    return std::filesystem::absolute(a).lexically_normal() == std::filesystem::absolute(b).lexically_normal();
  };
  const auto add = [&](const std::filesystem::path& file) {
    if (file.empty()) return;
    if (std::none_of(files.begin(), files.end(), [&](const std::filesystem::path& f) { return same(f, file); }))
      files.push_back(file);
  };
  for (const Texture& texture : scene.textures) add(texture.path);
  for (const Object& object : scene.objects) add(object.mesh.file);
  return files;
}

}  // namespace spanlight::scene
