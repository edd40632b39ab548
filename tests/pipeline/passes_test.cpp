// The multipass algorithm's invariants (Segal et al.'s z-equal passes):
// each light pass and the modulate pass touch exactly the pixels the depth +
// ambient pass left visible, each exactly once; and the fused single pass
// gives the same bytes as the multipass.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "pipeline_support.hpp"

namespace pt = spanlight::ptest;
using spanlight::PixelFormat;

namespace {

struct PassCheck {
  std::size_t visible = 0;
  int depth_pass_mismatches = 0;   // touched by the depth pass xor visible
  int light_pass_mismatches = 0;   // per light pass: pixels not touched exactly once when visible, or touched when not
  int modulate_mismatches = 0;
  bool light_events_count_ok = true;
};

// Splits the log by pass; each light pass's events carry its projector (Hooks::pass_begin).
PassCheck check_passes(const pt::ObservedFrame& frame, int projectors, int depth_bits) {
  const std::size_t pixels = frame.depth.size();
  const std::uint32_t clear = spanlight::depth_clear(depth_bits);
  std::vector<std::uint8_t> visible(pixels);
  PassCheck out;
  for (std::size_t i = 0; i < pixels; ++i) {
    visible[i] = frame.depth[i] != clear;
    out.visible += visible[i];
  }
  std::vector<int> depth_touches(pixels, 0), modulate_touches(pixels, 0);
  std::vector<std::vector<int>> light_touches(static_cast<std::size_t>(projectors), std::vector<int>(pixels, 0));
  std::size_t light_events = 0;
  for (const pt::PassEvent& e : frame.log.events) {
    const auto i = static_cast<std::size_t>(e.index);
    REQUIRE(i < pixels);
    if (e.pass == spanlight::Pass::depth_ambient) ++depth_touches[i];
    if (e.pass == spanlight::Pass::light) {
      ++light_events;
      REQUIRE(e.projector >= 0);
      REQUIRE(e.projector < projectors);
      ++light_touches[static_cast<std::size_t>(e.projector)][i];
    }
    if (e.pass == spanlight::Pass::modulate) ++modulate_touches[i];
  }
  for (std::size_t i = 0; i < pixels; ++i) {
    out.depth_pass_mismatches += (depth_touches[i] > 0) != (visible[i] != 0);
    out.modulate_mismatches += modulate_touches[i] != visible[i];
  }
  out.light_events_count_ok = light_events == out.visible * static_cast<std::size_t>(projectors);
  for (int j = 0; j < projectors; ++j)
    for (std::size_t i = 0; i < pixels; ++i)
      out.light_pass_mismatches += light_touches[static_cast<std::size_t>(j)][i] != visible[i];
  return out;
}

void require_invariant(const spanlight::prepare::PreparedStorage& prepared, std::uint8_t depth_bits) {
  const spanlight::PreparedScene& scene = prepared.scene;
  const pt::ObservedFrame multipass = pt::render_observed(prepared, pt::knobs_with(spanlight::Passes::multipass, depth_bits));
  const PassCheck check = check_passes(multipass, scene.projector_count, depth_bits);
  INFO("visible pixels " << check.visible << ", projectors " << int{scene.projector_count});
  CHECK(check.visible > 0);
  CHECK(check.depth_pass_mismatches == 0);
  CHECK(check.light_events_count_ok);
  CHECK(check.light_pass_mismatches == 0);
  CHECK(check.modulate_mismatches == 0);

  // The fused pass resolves the same depth and touches the same pixels.
  const pt::ObservedFrame fused = pt::render_observed(prepared, pt::knobs_with(spanlight::Passes::fused, depth_bits));
  CHECK(fused.depth == multipass.depth);
  std::vector<int> fused_touched(fused.depth.size(), 0);
  int not_fused = 0;
  for (const pt::PassEvent& e : fused.log.events) {
    if (e.pass == spanlight::Pass::shadow_depth) continue;  // a shadow map's texel, not a pixel
    not_fused += e.pass != spanlight::Pass::fused;
    REQUIRE(e.index < fused_touched.size());
    fused_touched[e.index] = 1;
  }
  CHECK(not_fused == 0);
  int fused_mismatches = 0;
  const std::uint32_t clear = spanlight::depth_clear(depth_bits);
  for (std::size_t i = 0; i < fused.depth.size(); ++i) fused_mismatches += fused_touched[i] != (multipass.depth[i] != clear);
  CHECK(fused_mismatches == 0);
}

// The floor of a camera looking down at it crosses the far plane: near the
// far line, window depths round to the cleared value (all ones) in the depth
// buffer, so the depth pass does not keep those fragments.
//
// Width of that band, to make sure it holds pixel centres: window depth is
// z_w(d) = f (d - n) / (d (f - n)) at eye depth d, so 1 - z_w = n (f - d) / (d (f - n)),
// and a fragment stores the clear value when 1 - z_w < 2^-bits, i.e.
// (f - d) / d < 2^-bits (f - n) / n. With n = 0.01, f = 20 and 16 bits that
// is d > 20 / 1.0305 = 19.41: 0.6 units of eye depth, which the camera (5
// units up, looking 14 degrees down) sees across about 0.5 degrees: a row
// of pixels in a 120-row, 60-degree view. At 24 bits the band is 256 times
// thinner and usually holds no pixel centre.
spanlight::scene::Scene far_plane_scene() {
  auto s = pt::empty_scene(160, 120, {0, 5, 0}, {0, 0, -20}, {0, 1, 0}, 60.0, 0.01, 20.0);
  s.ambient = glm::dvec3(0.25);
  s.textures.push_back(pt::texture("white", pt::solid_image(1, 1, {255, 255, 255}), spanlight::scene::Filter::nearest,
                                   spanlight::scene::Wrap::clamp));
  s.objects.push_back(pt::quad("floor", {glm::dvec3(-60, 0, 2), glm::dvec3(60, 0, 2), glm::dvec3(60, 0, -60),
                                         glm::dvec3(-60, 0, -60)},
                               glm::dvec3(0.8)));
  s.projectors.push_back(pt::projector({0, 5, 0}, {0, 0, -20}, {0, 1, 0}, 70.0, 0.5, 100.0, 0, glm::dvec3(0.5)));
  return s;
}

}  // namespace

TEST_CASE("z-equal light and modulate passes touch exactly the visible pixels once, on every shared scene",
          "[passes]") {
  for (const char* name : pt::shared_scene_names()) {
    INFO("scene " << name);
    const auto loaded = spanlight::scene::load_scene(pt::scene_file(name));
    const auto prepared = spanlight::prepare::prepare_scene(loaded);
    require_invariant(*prepared, 24);
  }
}

TEST_CASE("z-equal passes touch no pixel whose depth stayed cleared, for geometry crossing the far plane",
          "[passes]") {
  const auto prepared = spanlight::prepare::prepare_scene(far_plane_scene());
  for (const std::uint8_t bits : {std::uint8_t{24}, std::uint8_t{16}}) {
    INFO("depth bits " << int{bits});
    require_invariant(*prepared, bits);
  }
}

namespace {

void require_fused_equals_multipass(const spanlight::prepare::PreparedStorage& prepared, PixelFormat format,
                                    std::uint8_t depth_bits) {
  const auto multipass = spanlight::prepare::render_fixed(prepared, pt::knobs_with(spanlight::Passes::multipass, depth_bits, format));
  const auto fused = spanlight::prepare::render_fixed(prepared, pt::knobs_with(spanlight::Passes::fused, depth_bits, format));
  std::size_t differing = 0;
  for (std::size_t i = 0; i < fused.raw.size(); ++i) differing += fused.raw[i] != multipass.raw[i];
  INFO("format " << spanlight::prepare::to_string(format) << ", depth bits " << int{depth_bits} << ": "
                 << differing << " of " << fused.raw.size() << " framebuffer bytes differ");
  REQUIRE(fused.raw.size() == multipass.raw.size());
  CHECK(differing == 0);
  CHECK(fused.depth == multipass.depth);
}

}  // namespace

TEST_CASE("the fused pass gives the multipass's bytes on every shared scene in rgb888 and rgb565", "[passes]") {
  for (const char* name : pt::shared_scene_names()) {
    INFO("scene " << name);
    const auto loaded = spanlight::scene::load_scene(pt::scene_file(name));
    const auto prepared = spanlight::prepare::prepare_scene(loaded);
    for (const PixelFormat format : {PixelFormat::rgb888, PixelFormat::rgb565}) {
      require_fused_equals_multipass(*prepared, format, 24);
    }
  }
}

TEST_CASE("the fused pass gives the multipass's bytes with 16-bit depth, also where geometry meets the far plane",
          "[passes]") {
  const auto prepared = spanlight::prepare::prepare_scene(far_plane_scene());
  for (const PixelFormat format : {PixelFormat::rgb888, PixelFormat::rgb565}) {
    require_fused_equals_multipass(*prepared, format, 24);
    require_fused_equals_multipass(*prepared, format, 16);
  }
  // The shared scenes at 16 bits too (rgb888 only: the format does not touch depth).
  for (const char* name : pt::shared_scene_names()) {
    INFO("scene " << name);
    const auto loaded = spanlight::scene::load_scene(pt::scene_file(name));
    const auto prepared_shared = spanlight::prepare::prepare_scene(loaded);
    require_fused_equals_multipass(*prepared_shared, PixelFormat::rgb888, 16);
  }
}

TEST_CASE("on the mesh scenes, whose small triangles hand each pass only a row's pixels from the first its depth test takes, "
          "the z-equal passes touch the visible pixels once and the fused pass gives the multipass's bytes",
          "[passes]") {
  for (const char* name : {"mesh_bear", "checks/mesh_terrain", "checks/mesh_torus_knot"}) {
    INFO("scene " << name);
    const auto prepared = spanlight::prepare::prepare_scene(spanlight::scene::load_scene(pt::scene_file(name)));
    for (const std::uint8_t bits : {std::uint8_t{24}, std::uint8_t{16}}) {
      require_invariant(*prepared, bits);
      require_fused_equals_multipass(*prepared, PixelFormat::rgb565, bits);
    }
  }
}

namespace {

// Records which pixels a kernel's run touched (the small path trims runs to `passing`).
struct TouchLog : spanlight::NoHooks {
  std::vector<std::uint32_t>* pixels;
  void touched(spanlight::Pass, std::uint32_t i) const { pixels->push_back(i); }
};

}  // namespace

TEST_CASE("the fused and modulate passes' passing range starts at the first pixel their depth test takes, and their "
          "runs write nothing before it, and the fused pass hides a box only where every pixel is nearer",
          "[passes]") {
  using spanlight::Features;
  constexpr Features F = [] {
    Features f{};
    f.max_projectors = 0;
    f.depth_bits = 16;
    return f;
  }();
  using Depth = std::uint16_t;
  const spanlight::DepthFormat<F.depth_bits> depth(16);
  std::mt19937 rng(20261207);
  std::uniform_int_distribution<std::uint32_t> word;
  const int cases = pt::sanitized ? 2000 : 20000;
  for (int n = 0; n < cases; ++n) {
    const auto count = static_cast<std::int32_t>(1 + word(rng) % 40);
    const std::uint32_t z = 0x80000000u + (word(rng) % (6u << 24));
    const auto dz = static_cast<std::int32_t>(word(rng) % (1u << 22)) - (1 << 21);
    // Each stored depth equal to the run's there, behind it, in front of it or cleared, so that
    // both tests pass and fail in every pattern.
    std::vector<Depth> buffer(static_cast<std::size_t>(count));
    std::int32_t first_nearer = -1, first_equal = -1;
    for (std::int32_t k = 0; k < count; ++k) {
      const std::uint32_t stored = depth.store(z + static_cast<std::uint32_t>(k) * static_cast<std::uint32_t>(dz));
      const std::uint32_t kind = word(rng) % 4, by = 1 + word(rng) % 64;
      const std::uint32_t d = kind == 0 ? stored : kind == 1 ? stored + by : kind == 2 ? stored - by : depth.clear;
      buffer[static_cast<std::size_t>(k)] = static_cast<Depth>(d);
      if (first_nearer < 0 && stored < d) first_nearer = k;
      if (first_equal < 0 && d == stored) first_equal = k;
    }
    INFO("case " << n << ", count " << count);
    // passing() against the brute-force first pixel, then the whole run: its first write is there.
    auto check = [&](auto& kernel, std::vector<std::uint32_t>& touched, std::int32_t first) {
      const spanlight::PixelRange range = kernel.passing(0, count, z, dz);
      if (first < 0) {
        REQUIRE(range.first == range.end);
      } else {
        REQUIRE(range.first == first);
        REQUIRE(range.end == count);
      }
      spanlight::PixelRun<0> run{};
      run.z = z;
      run.dz = dz;
      kernel.run(0, count, run);
      if (first < 0) REQUIRE(touched.empty());
      else REQUIRE((!touched.empty() && touched.front() == static_cast<std::uint32_t>(first)));
    };
    std::vector<std::uint8_t> colour(static_cast<std::size_t>(count) * 3), tie_mask(spanlight::tie_mask_bytes(static_cast<std::uint32_t>(count)));
    {
      std::vector<std::uint32_t> touched;
      TouchLog log{{}, &touched};
      spanlight::ModulateKernel<F, Depth, TouchLog> modulate{{colour.data(), buffer.data(), tie_mask.data()}, nullptr, depth, log};
      check(modulate, touched, first_equal);
    }
    {
      std::vector<std::uint32_t> touched;
      TouchLog log{{}, &touched};
      spanlight::FusedKernel<F, Depth, TouchLog> fused{{colour.data(), buffer.data(), tie_mask.data()}, nullptr, nullptr, 0, spanlight::white,
                                                       depth, log};
      // hides() against brute force at the run's first depth, on the buffer as rows of `columns`
      // pixels `stride` apart (the last row ends at (rows - 1) stride + columns <= count).
      const std::int32_t columns = 1 + static_cast<std::int32_t>(word(rng) % 6), stride = columns + 1;
      const std::int32_t rows = (count + 1) / stride;
      bool hidden = true;
      for (std::int32_t r = 0; r < rows; ++r)
        for (std::int32_t c = 0; c < columns; ++c)
          hidden = hidden && !(depth.store(z) < buffer[static_cast<std::size_t>(r * stride + c)]);
      REQUIRE(fused.hides(0, columns, rows, stride, z) == hidden);
      check(fused, touched, first_nearer);  // last: it writes depth
    }
  }
}
