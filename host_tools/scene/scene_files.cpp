#include "scene/scene_files.hpp"

#include <algorithm>

namespace spanlight::scene {

std::vector<std::filesystem::path> files_read(const Scene& scene) {
  std::vector<std::filesystem::path> files{scene.file};
  const auto add = [&](const std::filesystem::path& file) {
    if (!file.empty() && std::find(files.begin(), files.end(), file) == files.end()) files.push_back(file);
  };
  for (const Object& object : scene.objects) add(object.mesh.file);
  for (const Texture& texture : scene.textures) add(texture.path);
  return files;
}

}  // namespace spanlight::scene
