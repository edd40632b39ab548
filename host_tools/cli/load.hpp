// Loading a scene for a command: bad input becomes a message on stderr
// ("FILE: FIELD: what was expected") and std::nullopt, so the caller exits 2.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "io/output_check.hpp"
#include "prepare/prepare.hpp"
#include "scene/scene.hpp"

namespace spanlight::cli {

std::optional<scene::Scene> load_or_report(const std::string& file);
std::unique_ptr<prepare::PreparedStorage> prepare_or_report(const scene::Scene& scene);
// The scene file and every mesh and image it read: what no output may be.
io::RunInputs inputs_of(const scene::Scene& scene);

}  // namespace spanlight::cli
