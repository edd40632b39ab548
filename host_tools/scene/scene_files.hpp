// The files a loaded scene was read from, for the commands' output checks
// (host_tools/io/output_check.hpp: an output must not be one of them).
#pragma once

#include <filesystem>
#include <vector>

#include "scene/scene.hpp"

namespace spanlight::scene {

// The scene file, then every image and OBJ mesh it names, each once (by normalised absolute path).
std::vector<std::filesystem::path> files_read(const Scene& scene);

}  // namespace spanlight::scene
