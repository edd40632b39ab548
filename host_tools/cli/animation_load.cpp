#include "cli/animation_load.hpp"

#include <cstdio>

namespace spanlight::cli {

std::unique_ptr<prepare::PreparedAnimation> prepare_animation_or_report(const std::string& file, const scene::Scene& scene,
                                                                        const prepare::PreparedStorage& prepared) {
  try {
    auto animation = prepare::prepare_animation(scene, scene::load_animation(file, scene));
    prepare::check_every_frame(prepared, *animation, scene);
    return animation;
  } catch (const scene::SceneError& e) {
    std::fprintf(stderr, "%s\n", e.what());
  } catch (const prepare::PrepareError& e) {
    std::fprintf(stderr, "%s\n", e.what());
  }
  return nullptr;
}

}  // namespace spanlight::cli
