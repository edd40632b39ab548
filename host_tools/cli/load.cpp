#include "cli/load.hpp"

#include <cstdio>

namespace spanlight::cli {

std::optional<scene::Scene> load_or_report(const std::string& file) {
  try {
    return scene::load_scene(file);
  } catch (const scene::SceneError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return std::nullopt;
  }
}

std::unique_ptr<prepare::PreparedStorage> prepare_or_report(const scene::Scene& scene) {
  try {
    return prepare::prepare_scene(scene);
  } catch (const prepare::PrepareError& e) {
    std::fprintf(stderr, "%s: %s\n", scene.file.string().c_str(), e.what());
    return nullptr;
  }
}

}  // namespace spanlight::cli
