// Shared by the live tests: the example scenes and animations, and a host render of
// a prepared scene at given matrices into buffers of `band_rows` rows, collecting
// each finished band (Hooks::band_done) into one frame as a display would.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <vector>

#include "prepare/prepare.hpp"
#include "prepare/prepare_animation.hpp"
#include "scene/animation.hpp"
#include "spanlight/dispatch.hpp"
#include "spanlight/render.hpp"

namespace live_test {

inline std::filesystem::path source_dir() { return SPANLIGHT_SOURCE_DIR; }
inline std::filesystem::path scene_file(const char* name) { return source_dir() / "scenes" / name; }
inline std::filesystem::path animation_file(const char* name) { return source_dir() / "scenes" / "animations" / name; }

// A scene, its prepared form and (optionally) its animation, kept together.
struct Loaded {
  spanlight::scene::Scene scene;
  std::unique_ptr<spanlight::prepare::PreparedStorage> prepared;
  spanlight::scene::Animation animation;
  std::unique_ptr<spanlight::prepare::PreparedAnimation> prepared_animation;
};

inline Loaded load(const char* scene, const char* animation = nullptr, int width = 0, int height = 0) {
  Loaded out;
  out.scene = spanlight::scene::load_scene(scene_file(scene));
  if (width > 0) {  // a smaller frame of the same scene
    out.scene.width = width;
    out.scene.height = height;
  }
  out.prepared = spanlight::prepare::prepare_scene(out.scene);
  if (animation != nullptr) {
    out.animation = spanlight::scene::load_animation(animation_file(animation), out.scene);
    out.prepared_animation = spanlight::prepare::prepare_animation(out.scene, out.animation);
  }
  return out;
}

// Whole-frame colour bytes as band_done hands them over.
struct BandCollector : spanlight::NoHooks {
  std::vector<std::uint8_t>* frame;
  std::uint32_t row_bytes;
  int bands = 0;
  template <typename Storage>
  void band_done(std::uint16_t first_row, std::uint16_t rows, const Storage* colour) {
    const auto* bytes = reinterpret_cast<const std::uint8_t*>(colour);
    for (std::uint32_t i = 0; i < std::uint32_t{rows} * row_bytes; ++i) (*frame)[first_row * row_bytes + i] = bytes[i];
    ++bands;
  }
};

// The frame's colour bytes rendered in bands of band_rows (0: the whole frame at once).
inline std::vector<std::uint8_t> render_in_bands(const spanlight::PreparedScene& scene, const spanlight::FrameMatrices& matrices,
                                                 const spanlight::Knobs& knobs, std::uint16_t band_rows) {
  using namespace spanlight;
  return dispatch<host_features(PixelFormat::rgb888), true, false>(knobs, [&]<Features F>() {
    using Color = ColorTraits<F.format>;
    const std::uint32_t rows = band_rows == 0 ? scene.height : band_rows;
    const std::size_t band_pixels = std::size_t{scene.width} * rows;
    std::vector<typename Color::Storage> color(band_pixels * Color::per_pixel);
    std::vector<std::uint32_t> depth(band_pixels);
    std::vector<std::vector<std::uint32_t>> maps(scene.projector_count);
    std::vector<std::span<std::uint32_t>> map_spans(scene.projector_count);
    for (std::size_t j = 0; j < scene.projector_count; ++j) {
      if (!scene.projectors[j].shadows) continue;
      maps[j].resize(std::size_t{scene.projectors[j].map_size} * scene.projectors[j].map_size);
      map_spans[j] = maps[j];
    }
    std::vector<std::uint8_t> tie_mask(tie_mask_bytes(static_cast<std::uint32_t>(band_pixels)));
    std::vector<CachedVertex> vertices(scene.max_vertex_count);
    const FrameTarget<F.format, std::uint32_t> target{color, depth, map_spans, tie_mask, vertices, band_rows};
    const std::uint32_t row_bytes = scene.width * Color::per_pixel * sizeof(typename Color::Storage);
    std::vector<std::uint8_t> frame(std::size_t{row_bytes} * scene.height);
    BandCollector collect{{}, &frame, row_bytes};
    // An empty result when the frame is refused or a band never arrives (the frame would stay zero).
    const int expected_bands = static_cast<int>((scene.height + rows - 1) / rows);
    if (render_frame<F>(scene, matrices, target, knobs, collect) != RenderStatus::ok || collect.bands != expected_bands) frame.clear();
    return frame;
  });
}

}  // namespace live_test
