// `spanlight bake`: a prepared scene as C++ a firmware build links. It writes
//   baked_scene.cpp   const arrays (geometry, textures, matrices) and the PreparedScene
//   baked_config.hpp  the scene's Features (only what it uses), buffer sizes, Precision
// so the firmware renders exactly what the host renders, from the same bytes.
#pragma once

#include <filesystem>
#include <string>

#include "prepare/prepare.hpp"
#include "prepare/render_fixed.hpp"

namespace spanlight::bake {

// What the scene uses, decided from the prepared data: each flag switches code on.
struct SceneFeatures {
  int projectors = 0;
  bool shadows = false;
  bool pcf = false;
  bool bilinear = false;
  int largest_shadow_map = 0;
  std::size_t shadow_map_texels = 0;  // sum over shadowed projectors
};

SceneFeatures features_of(const PreparedScene& scene);

// The two files as strings (tests read them without touching the disk).
std::string baked_config_source(const prepare::PreparedStorage& prepared, const prepare::FixedOptions& options,
                                const std::string& scene_name);
std::string baked_scene_source(const prepare::PreparedStorage& prepared, const std::string& scene_name);

// Writes both into `out_dir` (created if missing), each through a temporary
// file and a rename. Throws std::runtime_error naming the file on failure.
void write_baked_scene(const prepare::PreparedStorage& prepared, const prepare::FixedOptions& options,
                       const std::string& scene_name, const std::filesystem::path& out_dir);

}  // namespace spanlight::bake
