// `spanlight bake`: a prepared scene as C++ a firmware build links. It writes
//   baked_scene.cpp   const arrays (geometry, textures, the scene's pose) and the PreparedScene
//   baked_config.hpp  the scene's Features (only what it uses), its Knobs, buffer sizes
// so the firmware renders exactly what the host renders, from the same bytes.
#pragma once

#include <filesystem>
#include <string>

#include "prepare/prepare.hpp"
#include "spanlight/knobs.hpp"

namespace spanlight::bake {

// The two files as strings (tests read them without touching the disk).
std::string baked_config_source(const prepare::PreparedStorage& prepared, const Knobs& knobs,
                                const std::string& scene_name);
std::string baked_scene_source(const prepare::PreparedStorage& prepared, const std::string& scene_name);

// The two files a bake writes into out_dir.
struct BakedFiles {
  std::filesystem::path scene;   // baked_scene.cpp
  std::filesystem::path config;  // baked_config.hpp
};
BakedFiles baked_files(const std::filesystem::path& out_dir);

// Writes both into `out_dir` (created if missing), each through a temporary
// file and a rename. Throws std::runtime_error naming the file on failure.
void write_baked_scene(const prepare::PreparedStorage& prepared, const Knobs& knobs, const std::string& scene_name,
                       const std::filesystem::path& out_dir);

}  // namespace spanlight::bake
