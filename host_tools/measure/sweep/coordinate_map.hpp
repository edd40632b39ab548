// Texture coordinates as each renderer interpolated them, pixel by pixel, for
// the visible surface: the sweep's direct measure of interpolation error, with
// no texture or colour quantisation in between.
//   uv     the surface's coordinates in texels of its texture (u * width, v * height)
//   s, t   each projector's s/q, t/q in texels of its image
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "prepare/prepare.hpp"
#include "spanlight/knobs.hpp"
#include "scene/scene.hpp"

namespace spanlight::sweep {

struct ProjectorCoordinate {
  double s = 0.0, t = 0.0;  // texels of the projector's image
  bool lit = false;         // float: q > 0 and s/q, t/q, r/q in [0, 1]; fixed: q > 0 (the pipeline's `front`)
};

struct CoordinateMap {
  int width = 0, height = 0, projectors = 0;
  std::vector<int> object;              // visible object per pixel, -1 on background
  std::vector<std::int64_t> triangle;   // float model only: which mesh triangle, for the interior test
  std::vector<double> u, v;             // texels; only meaningful where the object is textured
  std::vector<ProjectorCoordinate> projector;  // pixel-major, `projectors` per pixel
  // Fixed pipeline only: per object, the texture size at which its uv wraps (0: no wrap).
  // A repeating texture is stepped modulo its size, so uv is compared modulo it.
  std::vector<int> wrap_width, wrap_height;

  std::size_t pixels() const { return static_cast<std::size_t>(width) * static_cast<std::size_t>(height); }
  const ProjectorCoordinate& at(std::size_t pixel, int j) const {
    return projector[pixel * static_cast<std::size_t>(projectors) + static_cast<std::size_t>(j)];
  }
};

// The float model's exact values (double, the exact divide at every pixel).
CoordinateMap float_coordinates(const scene::Scene& scene);

// The fixed pipeline's values: a probe kernel in the eye pass records what the
// span walk hands each pixel (depth test `less`, as the fused pass, so the
// same surface wins as in the real passes), with the knobs' reciprocal, span,
// tolerance and depth bits.
CoordinateMap fixed_coordinates(const prepare::PreparedStorage& prepared, const Knobs& knobs);

// Worst and mean |fixed - float| in texels (the larger of the two axes), over
// pixels where both show the same object and the float model's 3x3
// neighbourhood lies on one triangle (at a triangle edge the two renderers may
// legitimately interpolate different triangles). Projector values count where
// the float model says the pixel is lit and the fixed pipeline agrees q > 0.
struct CoordinateError {
  double uv_max = 0.0, uv_mean = 0.0;
  double st_max = 0.0, st_mean = 0.0;
  std::size_t uv_pixels = 0, st_pixels = 0;
  std::size_t edge_pixels_skipped = 0;  // covered, same object, but at a triangle edge
  std::size_t object_mismatches = 0;    // the renderers disagree on the visible object
  double worst() const { return uv_max > st_max ? uv_max : st_max; }
};

CoordinateError compare_coordinates(const CoordinateMap& fixed, const CoordinateMap& reference,
                                    const std::vector<bool>& textured_objects);

}  // namespace spanlight::sweep
