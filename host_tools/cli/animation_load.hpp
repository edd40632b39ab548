// Loading an animation for a command (render, bake): bad input, or a frame whose pose
// the pipeline cannot build, becomes a message on stderr ("FILE: FIELD: expected ...")
// and nullptr, so the caller exits 2 before it writes anything.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "prepare/prepare_animation.hpp"

namespace spanlight::cli {

// Before the scene is prepared: the animation's own errors come first (also those naming
// a scene pose it keeps, which prepare would only report without a field).
std::optional<scene::Animation> load_animation_or_report(const std::string& file, const scene::Scene& scene);
std::unique_ptr<prepare::PreparedAnimation> prepare_animation_or_report(const scene::Animation& animation,
                                                                        const scene::Scene& scene,
                                                                        const prepare::PreparedStorage& prepared);

}  // namespace spanlight::cli
