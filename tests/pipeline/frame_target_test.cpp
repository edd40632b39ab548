// Issue 17, the target side: render_frame takes every buffer with its size
// (FrameTarget) and refuses a mismatch with the scene with the RenderStatus
// that names it, before it writes a byte; and a frame that fits writes nothing
// outside its buffers. Each caller buffer sits between guard bytes, so any
// write before or past it shows (and the _asan twin reports it at once: the
// guards are inside the same allocation, so the check here is what sees them).
#include <catch2/catch.hpp>

#include <cstdint>
#include <cstring>
#include <span>
#include <utility>
#include <vector>

#include "pipeline_support.hpp"

namespace pt = spanlight::ptest;
using spanlight::Passes;
using spanlight::PixelFormat;
using spanlight::RenderStatus;

namespace {

constexpr std::size_t guard = 64;        // elements of guard on each side
constexpr unsigned char pattern = 0xA5;  // what the guards and a fresh buffer hold

// `size` elements of T between guards, all bytes set to the pattern.
template <typename T>
struct Guarded {
  std::vector<T> storage;
  std::size_t size;
  explicit Guarded(std::size_t n) : storage(n + 2 * guard), size(n) {
    std::memset(static_cast<void*>(storage.data()), pattern, storage.size() * sizeof(T));
  }
  std::span<T> inner() { return {storage.data() + guard, size}; }
  bool all_bytes_are(unsigned char v, std::size_t begin, std::size_t end) const {
    const auto* bytes = reinterpret_cast<const unsigned char*>(storage.data());
    for (std::size_t i = begin * sizeof(T); i < end * sizeof(T); ++i)
      if (bytes[i] != v) return false;
    return true;
  }
  bool guards_intact() const {
    return all_bytes_are(pattern, 0, guard) && all_bytes_are(pattern, guard + size, storage.size());
  }
  bool untouched() const { return all_bytes_are(pattern, 0, storage.size()); }
};

// A scene that uses every buffer: one shadowed projector (its map), multipass
// (the tie mask), two objects (the vertex cache holds the larger).
spanlight::scene::Scene shadowed_scene() {
  auto s = pt::empty_scene(40, 30, {0, 4, 6}, {0, 0, 0}, {0, 1, 0}, 60.0, 0.5, 30.0);
  s.ambient = glm::dvec3(0.2);
  s.textures.push_back(pt::texture("white", pt::solid_image(2, 2, {255, 255, 255}), spanlight::scene::Filter::nearest,
                                   spanlight::scene::Wrap::clamp));
  s.objects.push_back(pt::quad("floor", {glm::dvec3(-5, 0, 5), glm::dvec3(5, 0, 5), glm::dvec3(5, 0, -5),
                                         glm::dvec3(-5, 0, -5)}));
  auto box = pt::quad("card", {glm::dvec3(-1, 1, 0), glm::dvec3(1, 1, 0), glm::dvec3(1, 2, 0), glm::dvec3(-1, 2, 0)});
  box.mesh.positions.push_back(glm::dvec3(0, 2.5, 0));
  box.mesh.uvs.push_back(glm::dvec2(0.0));
  box.mesh.triangles.push_back({2, 4, 3});
  s.objects.push_back(box);
  auto p = pt::projector({0, 6, 2}, {0, 0, 0}, {0, 1, 0}, 60.0, 0.5, 30.0, 0, glm::dvec3(0.6));
  p.shadows = spanlight::scene::Shadows{32, 0.01, spanlight::scene::ShadowFilter::nearest};
  s.projectors.push_back(p);
  return s;
}

// The buffers a frame of `rows` rows (per band) needs, each resizable by a delta, between guards.
template <PixelFormat Format, typename DepthT>
struct Buffers {
  using Color = spanlight::ColorTraits<Format>;
  Guarded<typename Color::Storage> color;
  Guarded<DepthT> depth;
  Guarded<DepthT> map;
  Guarded<std::uint8_t> tie;
  Guarded<spanlight::CachedVertex> vertices;
  std::vector<std::span<DepthT>> maps;

  struct Deltas {
    std::ptrdiff_t color = 0, depth = 0, map = 0, tie = 0, vertices = 0;
  };
  static std::size_t plus(std::size_t n, std::ptrdiff_t d) { return static_cast<std::size_t>(static_cast<std::ptrdiff_t>(n) + d); }
  Buffers(const spanlight::PreparedScene& scene, std::uint32_t rows, Deltas d)
      : color(plus(std::size_t{scene.width} * rows * Color::per_pixel, d.color)),
        depth(plus(std::size_t{scene.width} * rows, d.depth)),
        map(plus(std::size_t{scene.projectors[0].map_size} * scene.projectors[0].map_size, d.map)),
        tie(plus(spanlight::tie_mask_bytes(scene.width * rows), d.tie)),
        vertices(plus(scene.max_vertex_count, d.vertices)) {
    maps.push_back(map.inner());
  }
  spanlight::FrameTarget<Format, DepthT> target(std::uint16_t band_rows = 0) {
    return {color.inner(), depth.inner(), maps, tie.inner(), vertices.inner(), band_rows};
  }
  bool guards_intact() const {
    return color.guards_intact() && depth.guards_intact() && map.guards_intact() && tie.guards_intact() &&
           vertices.guards_intact();
  }
  bool untouched() const {
    return color.untouched() && depth.untouched() && map.untouched() && tie.untouched() && vertices.untouched();
  }
};

template <PixelFormat Format, typename DepthT, spanlight::Features F = spanlight::host_features(Format)>
RenderStatus render(const spanlight::prepare::PreparedStorage& p, Buffers<Format, DepthT>& b, const spanlight::Knobs& k,
                    std::uint16_t band_rows = 0) {
  return spanlight::render_frame<F>(p.scene, p.matrices, b.target(band_rows), k, spanlight::NoHooks{});
}

template <PixelFormat Format, typename DepthT>
void check_every_mismatch(std::uint8_t depth_bits) {
  const auto prepared = spanlight::prepare::prepare_scene(shadowed_scene());
  const spanlight::PreparedScene& scene = prepared->scene;
  REQUIRE(scene.projector_count == 1);
  REQUIRE(scene.projectors[0].shadows);
  REQUIRE(scene.max_vertex_count == 5);
  const spanlight::Knobs multipass = pt::knobs_with(Passes::multipass, depth_bits, Format);
  const spanlight::Knobs fused = pt::knobs_with(Passes::fused, depth_bits, Format);
  using B = Buffers<Format, DepthT>;
  using D = typename B::Deltas;

  SECTION("buffers of exactly the frame's sizes: ok, and nothing written outside them") {
    for (const spanlight::Knobs& k : {multipass, fused}) {
      B b(scene, scene.height, {});
      CHECK(render(*prepared, b, k) == RenderStatus::ok);
      CHECK(b.guards_intact());
      CHECK_FALSE(b.color.untouched());  // it did draw
      CHECK_FALSE(b.map.untouched());
    }
  }
  SECTION("in bands: buffers for one band of 7 rows (the last band shorter): ok, guards intact") {
    B b(scene, 7, {});
    CHECK(render(*prepared, b, multipass, 7) == RenderStatus::ok);
    CHECK(b.guards_intact());
  }
  // Each mismatch: the status that names it, and not one byte written anywhere.
  auto refused = [&](D d, const spanlight::Knobs& k, RenderStatus expected, std::uint32_t rows, std::uint16_t band) {
    B b(scene, rows, d);
    CHECK(render(*prepared, b, k, band) == expected);
    CHECK(b.untouched());
  };
  SECTION("a colour buffer one element short") { refused({.color = -1}, multipass, RenderStatus::colour_too_small, scene.height, 0); }
  SECTION("a depth buffer one pixel short") { refused({.depth = -1}, fused, RenderStatus::depth_too_small, scene.height, 0); }
  SECTION("a vertex buffer one short of the largest object") {
    refused({.vertices = -1}, fused, RenderStatus::vertices_too_small, scene.height, 0);
  }
  SECTION("a tie mask one byte short, multipass") { refused({.tie = -1}, multipass, RenderStatus::tie_mask_too_small, scene.height, 0); }
  SECTION("a shadow map one texel short or one too many") {
    refused({.map = -1}, fused, RenderStatus::shadow_map_missing, scene.height, 0);
    refused({.map = +1}, fused, RenderStatus::shadow_map_missing, scene.height, 0);
  }
  SECTION("a shadow bias outside [0, max_shadow_bias], and the limit itself") {
    auto with_bias = [&](std::int32_t bias) {
      spanlight::ProjectorData projector = scene.projectors[0];
      projector.bias = bias;
      spanlight::PreparedScene altered = scene;
      altered.projectors = &projector;
      B b(scene, scene.height, {});
      const RenderStatus status = spanlight::render_frame<spanlight::host_features(Format)>(altered, prepared->matrices, b.target(), fused);
      CHECK(b.guards_intact());
      return std::pair{status, b.untouched()};
    };
    for (const std::int32_t bias : {-1, spanlight::max_shadow_bias + 1, INT32_MAX}) {
      const auto [status, untouched] = with_bias(bias);
      CHECK(status == RenderStatus::shadow_bias_out_of_range);
      CHECK(untouched);
    }
    for (const std::int32_t bias : {0, spanlight::max_shadow_bias}) CHECK(with_bias(bias).first == RenderStatus::ok);
  }
  SECTION("band buffers too small for the band, and a band taller than the frame") {
    refused({.color = -1}, fused, RenderStatus::colour_too_small, 7, 7);
    refused({}, fused, RenderStatus::bad_band, scene.height, static_cast<std::uint16_t>(scene.height + 1));
  }
  SECTION("no shadow map span at all for the shadowed projector") {
    B b(scene, scene.height, {});
    auto t = b.target();
    t.shadow_maps = {};
    CHECK(spanlight::render_frame<spanlight::host_features(Format)>(scene, prepared->matrices, t, fused) ==
          RenderStatus::shadow_map_missing);
    CHECK(b.untouched());
  }
  SECTION("knobs outside their values, or of another format than the build") {
    spanlight::Knobs bad = fused;
    bad.span_log2 = 7;
    refused({}, bad, RenderStatus::bad_knobs, scene.height, 0);
    bad = fused;
    bad.format = Format == PixelFormat::rgb888 ? PixelFormat::rgb565 : PixelFormat::rgb888;
    refused({}, bad, RenderStatus::bad_knobs, scene.height, 0);
  }
  SECTION("a build without projectors or without shadows") {
    constexpr spanlight::Features no_projectors = [] {
      spanlight::Features f = spanlight::host_features(Format);
      f.max_projectors = 0;
      return f;
    }();
    constexpr spanlight::Features no_shadows = [] {
      spanlight::Features f = spanlight::host_features(Format);
      f.shadows = false;
      return f;
    }();
    B b(scene, scene.height, {});
    CHECK(render<Format, DepthT, no_projectors>(*prepared, b, fused) == RenderStatus::too_many_projectors);
    CHECK(render<Format, DepthT, no_shadows>(*prepared, b, fused) == RenderStatus::scene_needs_feature);
    CHECK(b.untouched());
  }
}

}  // namespace

TEST_CASE("render_frame refuses every buffer that does not fit the scene before writing, rgb888, 32-bit depth",
          "[frame_target]") {
  check_every_mismatch<PixelFormat::rgb888, std::uint32_t>(24);
}

TEST_CASE("render_frame refuses every buffer that does not fit the scene before writing, rgb565, 16-bit depth",
          "[frame_target]") {
  check_every_mismatch<PixelFormat::rgb565, std::uint16_t>(16);
}

TEST_CASE("render_frame refuses 24-bit depth in 16-bit storage before writing", "[frame_target]") {
  const auto prepared = spanlight::prepare::prepare_scene(shadowed_scene());
  Buffers<PixelFormat::rgb888, std::uint16_t> b(prepared->scene, prepared->scene.height, {});
  CHECK(render(*prepared, b, pt::knobs_with(Passes::fused, 24)) == RenderStatus::depth_type_too_narrow);
  CHECK(b.untouched());
}
