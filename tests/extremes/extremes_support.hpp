// Helpers for the extreme-case tests: scenes built in memory, both renderers
// on the same scene, and the agreement measures the tests bound.
//
// The central measure is "unexplained" pixels. The fixed pipeline differs
// from the float model by sub-pixel amounts: its snapped vertices can sit one
// 1/256 px step away from the float model's (the divide is good to 2^-7
// subpixel before rounding, project.hpp), its texture coordinates by up to
// 2^-span_tolerance_log2 texel (3_span/segments.hpp), and its colour steps round in
// 8-bit levels (shade.hpp). Each of these moves an edge of the picture (a
// silhouette, a texel boundary, a shadow or frustum boundary) by less than a
// pixel, or changes a colour by a few levels. So a pixel may differ by more
// than a few levels only where the reference picture itself changes within a
// pixel or so: a pixel that differs while the reference is flat (every pixel
// within `radius` of it has the same coverage and a colour within
// `tolerance` levels of its own) is unexplained, and the tests require none.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "compare/compare.hpp"
#include "float_model/float_model.hpp"
#include "float_model/shade.hpp"
#include "prepare/prepare.hpp"
#include "prepare/render_fixed.hpp"
#include "scene/scene.hpp"
#include "spanlight/render.hpp"
#include "../support/scene_builders.hpp"

#if defined(__SANITIZE_ADDRESS__)
#define SPANLIGHT_XT_SANITIZED 1
#else
#define SPANLIGHT_XT_SANITIZED 0
#endif

namespace spanlight::xt {

namespace sc = spanlight::scene;
namespace fm = spanlight::float_model;
namespace pr = spanlight::prepare;

// The sanitizer twin runs the same cases; only the largest sizes are skipped there.
inline constexpr bool sanitized = SPANLIGHT_XT_SANITIZED != 0;

// ---- images ---------------------------------------------------------------------

using test_support::solid_image;

// Squares of `cell` texels, alternately `a` and `b`; texel (0, 0) (top-left) is `a`.
inline sc::Image checker_image(int width, int height, int cell, std::array<std::uint8_t, 3> a = {255, 255, 255},
                               std::array<std::uint8_t, 3> b = {40, 40, 40}) {
  sc::Image image{width, height, {}};
  image.rgb.reserve(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const auto& c = ((x / cell + y / cell) % 2 == 0) ? a : b;
      image.rgb.insert(image.rgb.end(), c.begin(), c.end());
    }
  return image;
}

using test_support::texture;

// ---- scenes -----------------------------------------------------------------------

inline sc::Scene make_scene(int width, int height, glm::dvec3 eye, glm::dvec3 target, glm::dvec3 up, double fovy_deg,
                            double near, double far) {
  return test_support::empty_scene("extremes", width, height, eye, target, up, fovy_deg, near, far);
}

// A quad a, b, c, d as triangles (a, b, c) and (a, c, d).
inline sc::Object quad(std::string name, std::array<glm::dvec3, 4> corners, glm::dvec3 color = glm::dvec3(1.0),
                       std::array<glm::dvec2, 4> uvs = {glm::dvec2(0, 0), glm::dvec2(1, 0), glm::dvec2(1, 1),
                                                        glm::dvec2(0, 1)}) {
  sc::Object object;
  object.name = std::move(name);
  object.mesh.positions.assign(corners.begin(), corners.end());
  object.mesh.uvs.assign(uvs.begin(), uvs.end());
  object.mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  object.color = color;
  return object;
}

inline sc::Object triangle(std::string name, std::array<glm::dvec3, 3> corners, glm::dvec3 color = glm::dvec3(1.0),
                           std::array<glm::dvec2, 3> uvs = {glm::dvec2(0, 0), glm::dvec2(1, 0), glm::dvec2(0, 1)}) {
  sc::Object object;
  object.name = std::move(name);
  object.mesh.positions.assign(corners.begin(), corners.end());
  object.mesh.uvs.assign(uvs.begin(), uvs.end());
  object.mesh.triangles = {{0, 1, 2}};
  object.color = color;
  return object;
}

// An axis-aligned box seen from inside (all faces wound to face inwards), one
// object per face so each face can carry its own colour.
inline std::vector<sc::Object> room(glm::dvec3 lo, glm::dvec3 hi) {
  const glm::dvec3 c[8] = {{lo.x, lo.y, lo.z}, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {lo.x, hi.y, lo.z},
                           {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}};
  const int faces[6][4] = {{0, 1, 2, 3}, {5, 4, 7, 6}, {4, 0, 3, 7}, {1, 5, 6, 2}, {4, 5, 1, 0}, {3, 2, 6, 7}};
  const glm::dvec3 colours[6] = {{0.9, 0.9, 0.9}, {0.8, 0.7, 0.6}, {0.6, 0.8, 0.7}, {0.7, 0.6, 0.8}, {1.0, 1.0, 1.0}, {0.5, 0.5, 0.9}};
  std::vector<sc::Object> out;
  for (int f = 0; f < 6; ++f) {
    out.push_back(quad("face" + std::to_string(f), {c[faces[f][0]], c[faces[f][1]], c[faces[f][2]], c[faces[f][3]]},
                       colours[f]));
  }
  return out;
}

using test_support::projector;

// Rounds every object-space position to the Q15.16 grid the fixed pipeline
// stores (spanlight/scene.hpp: positions are Q15.16), so both renderers draw
// the same geometry and a comparison measures the pipeline's arithmetic, not
// the input format. (What the format itself costs is bounded in docs/limits.md.)
inline void snap_positions_to_q16(sc::Scene& s) {
  for (sc::Object& o : s.objects)
    for (glm::dvec3& p : o.mesh.positions)
      for (int c = 0; c < 3; ++c) p[c] = std::round(p[c] * 65536.0) / 65536.0;
}

// ---- rendering both ------------------------------------------------------------------

struct Both {
  pr::FixedFrame fixed;
  fm::FloatFrame ref;
  std::uint32_t depth_clear = 0;
};

inline spanlight::Knobs default_options() {
  return spanlight::Knobs{};  // the CLI's defaults: RGB888, 8-bit table, one Newton step, 24-bit depth, fused
}

inline spanlight::Knobs with_passes(spanlight::Knobs k, bool fused) {
  k.passes = fused ? spanlight::Passes::fused : spanlight::Passes::multipass;
  return k;
}

inline Both render_both(const sc::Scene& s, const spanlight::Knobs& options = default_options()) {
  const auto prepared = pr::prepare_scene(s);
  Both b;
  b.fixed = pr::render_fixed(*prepared, options);
  b.ref = fm::render_float(s);
  b.depth_clear = depth_clear(options.depth_bits);
  return b;
}

// ---- agreement -----------------------------------------------------------------------------

struct Agreement {
  compare::CompareResult stats;
  int pixels = 0;
  int covered_fixed = 0, covered_ref = 0;
  int coverage_mismatch = 0;  // drawn by one renderer and not the other
  int over_tolerance = 0;     // largest channel difference > tolerance
  int unexplained = 0;        // over tolerance (or coverage differs) where the reference is flat
  int first_unexplained = -1;
};

inline int channel_diff(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b, std::size_t i,
                        std::size_t j) {
  int d = 0;
  for (std::size_t c = 0; c < 3; ++c) d = std::max(d, std::abs(int{a[i * 3 + c]} - int{b[j * 3 + c]}));
  return d;
}

inline Agreement agree(const Both& b, int radius, int tolerance) {
  const int w = b.ref.width, h = b.ref.height;
  Agreement a;
  a.pixels = w * h;
  a.stats = compare::compare_images(compare::Rgb8View{w, h, b.fixed.rgb}, compare::Rgb8View{w, h, b.ref.rgb});
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const auto i = static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x);
      const bool cov_fixed = b.fixed.depth[i] != b.depth_clear;
      const bool cov_ref = b.ref.object[i] >= 0;
      a.covered_fixed += cov_fixed;
      a.covered_ref += cov_ref;
      a.coverage_mismatch += cov_fixed != cov_ref;
      const bool off = channel_diff(b.fixed.rgb, b.ref.rgb, i, i) > tolerance;
      a.over_tolerance += off;
      if (!off && cov_fixed == cov_ref) continue;
      bool flat = true;
      for (int dy = -radius; dy <= radius && flat; ++dy) {
        for (int dx = -radius; dx <= radius && flat; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
          const auto j = static_cast<std::size_t>(ny) * static_cast<std::size_t>(w) + static_cast<std::size_t>(nx);
          flat = (b.ref.object[j] >= 0) == cov_ref && channel_diff(b.ref.rgb, b.ref.rgb, i, j) <= tolerance;
        }
      }
      if (flat) {
        if (a.unexplained == 0) a.first_unexplained = static_cast<int>(i);
        ++a.unexplained;
      }
    }
  }
  return a;
}

inline std::string describe(const Agreement& a, int width) {
  std::ostringstream out;
  out << compare::to_one_line(a.stats) << "; covered fixed " << a.covered_fixed << " / float " << a.covered_ref
      << ", coverage mismatches " << a.coverage_mismatch << ", over tolerance " << a.over_tolerance
      << ", unexplained " << a.unexplained;
  if (a.first_unexplained >= 0)
    out << " (first at x " << a.first_unexplained % width << ", y " << a.first_unexplained / width << ")";
  return out.str();
}

// With SPANLIGHT_XT_DUMP=folder in the environment, writes both pictures and
// their heat map there as NAME_fixed.png, NAME_float.png, NAME_diff.png.
inline void dump(const Both& b, const std::string& name) {
  const char* folder = std::getenv("SPANLIGHT_XT_DUMP");
  if (folder == nullptr) return;
  const std::string base = std::string(folder) + "/" + name;
  const compare::Rgb8View fixed{b.fixed.width, b.fixed.height, b.fixed.rgb}, ref{b.ref.width, b.ref.height, b.ref.rgb};
  compare::write_png_atomically(base + "_fixed.png", fixed.width, fixed.height, fixed.rgb);
  compare::write_png_atomically(base + "_float.png", ref.width, ref.height, ref.rgb);
  const io::Rgb8Image heat = compare::heat_map(fixed, ref);
  compare::write_png_atomically(base + "_diff.png", heat.width, heat.height, heat.rgb);
}

// Pixels whose largest channel differs by more than `tolerance` between two frames of one size.
inline int pixels_differing(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b, int tolerance) {
  int n = 0;
  for (std::size_t i = 0; i < a.size() / 3; ++i) n += channel_diff(a, b, i, i) > tolerance;
  return n;
}

}  // namespace spanlight::xt
