// `spanlight bake`: a prepared scene as C++ a firmware build links. It writes
//   baked_scene.cpp   const arrays (geometry, textures, the scene's pose) and the PreparedScene
//   baked_config.hpp  the scene's Features (only what it uses), its Knobs, buffer sizes
// so the firmware renders exactly what the host renders, from the same bytes.
#pragma once

#include <string>

#include "io/output_folder.hpp"
#include "prepare/prepare.hpp"
#include "prepare/prepare_animation.hpp"
#include "spanlight/knobs.hpp"

namespace spanlight::bake {

// The two files as strings (tests read them without touching the disk). With an
// animation (bake --animation) they also hold baked::animation, frame_count and object_count.
std::string baked_config_source(const prepare::PreparedStorage& prepared, const Knobs& knobs,
                                const std::string& scene_name, const prepare::PreparedAnimation* animation = nullptr);
std::string baked_scene_source(const prepare::PreparedStorage& prepared, const std::string& scene_name,
                               const prepare::PreparedAnimation* animation = nullptr);

// The animation's parts of the two files (write_animation.cpp).
std::string baked_animation_config(const prepare::PreparedAnimation& animation);
std::string baked_animation_source(const prepare::PreparedAnimation& animation);

// The two files a bake writes, relative to its output folder.
inline constexpr const char* baked_scene_file = "baked_scene.cpp";
inline constexpr const char* baked_config_file = "baked_config.hpp";

// Writes both into `out` (io::OutputFolder: created if missing, each file
// atomic, listed in the folder's manifest). Throws io::OutputError.
void write_baked_scene(const prepare::PreparedStorage& prepared, const Knobs& knobs, const std::string& scene_name,
                       io::OutputFolder& out, const prepare::PreparedAnimation* animation = nullptr);

}  // namespace spanlight::bake
