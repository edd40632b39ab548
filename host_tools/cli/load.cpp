#include "cli/load.hpp"

#include <cstdio>

#include "scene/scene_files.hpp"

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

io::RunInputs inputs_of(const scene::Scene& scene) {
  io::RunInputs inputs;
  inputs.add(scene::files_read(scene));
  return inputs;
}

}  // namespace spanlight::cli
