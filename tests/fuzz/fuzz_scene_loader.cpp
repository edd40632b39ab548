// libFuzzer harness: arbitrary bytes as a scene file.
//
// The bytes are written to scene.json in a private temporary folder that also
// holds the example scenes' assets (scenes/assets, scenes/extremes/assets, and
// tests/scene/bad/assets for the malformed ones), so fuzzed scenes can name
// real meshes and images.
// Contract under test (spec: docs/scene-format.md; scene.hpp):
//   load_scene returns a Scene or throws SceneError; nothing else, no crash,
//   no sanitizer report.
// A scene that loads is then prepared (PrepareError is the documented refusal
// of values the fixed formats cannot hold) and, when it is small enough to
// stay fast (<= 64x64 pixels, <= 2000 triangles, shadow maps <= 256), drawn by
// both renderers: no crash, no sanitizer report, and the two pictures the
// same size. The float model may refuse a vertex beyond 2^53 px with
// std::range_error (float_model/setup.hpp), also documented.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <unistd.h>

#include "float_model/float_model.hpp"
#include "prepare/prepare.hpp"
#include "prepare/render_fixed.hpp"
#include "scene/scene.hpp"

namespace fs = std::filesystem;
namespace sl = spanlight;

namespace {

fs::path folder;

void copy_tree(const fs::path& from, const fs::path& to) {
  fs::create_directories(to);
  fs::copy(from, to, fs::copy_options::recursive | fs::copy_options::overwrite_existing);
}

bool small_enough(const sl::scene::Scene& s) {
  if (static_cast<long>(s.width) * s.height > 64 * 64) return false;
  std::size_t triangles = 0;
  for (const auto& o : s.objects) triangles += o.mesh.triangles.size();
  if (triangles > 2000) return false;
  for (const auto& p : s.projectors)
    if (p.shadows && p.shadows->map_size > 256) return false;
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  folder = fs::temp_directory_path() / ("spanlight_fuzz_scene_" + std::to_string(::getpid()));
  fs::remove_all(folder);
  copy_tree(fs::path(SPANLIGHT_SOURCE_DIR) / "scenes" / "assets", folder / "assets");
  copy_tree(fs::path(SPANLIGHT_SOURCE_DIR) / "tests" / "scene" / "bad" / "assets", folder / "assets");
  copy_tree(fs::path(SPANLIGHT_SOURCE_DIR) / "scenes" / "extremes" / "assets", folder / "assets");
  std::atexit([] {
    std::error_code ignored;
    fs::remove_all(folder, ignored);
  });
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const fs::path file = folder / "scene.json";
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  sl::scene::Scene scene;
  try {
    scene = sl::scene::load_scene(file);
  } catch (const sl::scene::SceneError&) {
    return 0;  // the documented outcome for bad input
  }
  // Loaded: the validated scene must be one the renderers can take or refuse cleanly.
  std::unique_ptr<sl::prepare::PreparedStorage> prepared;
  try {
    prepared = sl::prepare::prepare_scene(scene);
  } catch (const sl::prepare::PrepareError&) {
    return 0;
  }
  if (!small_enough(scene)) return 0;
  const sl::prepare::FixedFrame fixed = sl::prepare::render_fixed(*prepared, sl::Knobs{});
  try {
    const sl::float_model::FloatFrame ref = sl::float_model::render_float(scene);
    if (ref.width != fixed.width || ref.height != fixed.height || ref.rgb.size() != fixed.rgb.size()) std::abort();
  } catch (const std::range_error&) {
    // float_model::snap: a vertex beyond 2^53 px (documented).
  }
  return 0;
}
