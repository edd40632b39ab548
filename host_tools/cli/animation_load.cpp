#include "cli/animation_load.hpp"

#include <cstdio>

namespace spanlight::cli {

std::optional<scene::Animation> load_animation_or_report(const std::string& file, const scene::Scene& scene) {
  try {
    return scene::load_animation(file, scene);
  } catch (const scene::SceneError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return std::nullopt;
  }
}

std::unique_ptr<prepare::PreparedAnimation> prepare_animation_or_report(const scene::Animation& animation,
                                                                        const scene::Scene& scene,
                                                                        const prepare::PreparedStorage& prepared) {
  try {
    auto out = prepare::prepare_animation(scene, animation);
    prepare::check_every_frame(prepared, *out, scene);
    return out;
  } catch (const prepare::PrepareError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return nullptr;
  }
}

}  // namespace spanlight::cli
