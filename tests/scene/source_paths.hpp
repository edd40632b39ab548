// Where the tests find the example scenes and the malformed-scene corpus.
#pragma once

#include <filesystem>

namespace spanlight::scene::test {

inline std::filesystem::path source_dir() { return SPANLIGHT_SOURCE_DIR; }
inline std::filesystem::path example_scene(const char* file_name) { return source_dir() / "scenes" / file_name; }
inline std::filesystem::path bad_scene_dir() { return source_dir() / "tests" / "scene" / "bad"; }

}  // namespace spanlight::scene::test
