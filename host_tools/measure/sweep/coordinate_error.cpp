#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "sweep/coordinate_map.hpp"

namespace spanlight::sweep {
namespace {

// True when every float-model neighbour inside the image shows the same triangle.
bool interior(const CoordinateMap& m, int x, int y) {
  const std::int64_t id = m.triangle[static_cast<std::size_t>(y) * static_cast<std::size_t>(m.width) + static_cast<std::size_t>(x)];
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const int nx = x + dx, ny = y + dy;
      if (nx < 0 || ny < 0 || nx >= m.width || ny >= m.height) continue;
      if (m.triangle[static_cast<std::size_t>(ny) * static_cast<std::size_t>(m.width) + static_cast<std::size_t>(nx)] != id)
        return false;
    }
  return true;
}

double axis_error(double fu, double fv, double ru, double rv) { return std::max(std::fabs(fu - ru), std::fabs(fv - rv)); }

// The difference of two coordinates on a circle of `period` texels (0: on the line).
double wrapped(double difference, int period) {
  if (period <= 0) return difference;
  return difference - period * std::round(difference / period);
}

}  // namespace

CoordinateError compare_coordinates(const CoordinateMap& fixed, const CoordinateMap& ref,
                                    const std::vector<bool>& textured_objects) {
  if (fixed.width != ref.width || fixed.height != ref.height || fixed.projectors != ref.projectors)
    throw std::invalid_argument("coordinate maps of different shapes");
  CoordinateError e;
  double uv_sum = 0.0, st_sum = 0.0;
  for (int y = 0; y < ref.height; ++y) {
    for (int x = 0; x < ref.width; ++x) {
      const std::size_t p = static_cast<std::size_t>(y) * static_cast<std::size_t>(ref.width) + static_cast<std::size_t>(x);
      const int o = ref.object[p];
      if (o < 0 && fixed.object[p] < 0) continue;
      if (o != fixed.object[p]) {
        ++e.object_mismatches;
        continue;
      }
      if (!interior(ref, x, y)) {
        ++e.edge_pixels_skipped;
        continue;
      }
      if (textured_objects[static_cast<std::size_t>(o)]) {
        const auto object = static_cast<std::size_t>(o);
        const int wrap_u = object < fixed.wrap_width.size() ? fixed.wrap_width[object] : 0;
        const int wrap_v = object < fixed.wrap_height.size() ? fixed.wrap_height[object] : 0;
        const double d = std::max(std::fabs(wrapped(fixed.u[p] - ref.u[p], wrap_u)),
                                  std::fabs(wrapped(fixed.v[p] - ref.v[p], wrap_v)));
        e.uv_max = std::max(e.uv_max, d);
        uv_sum += d;
        ++e.uv_pixels;
      }
      for (int j = 0; j < ref.projectors; ++j) {
        const ProjectorCoordinate& r = ref.at(p, j);
        const ProjectorCoordinate& f = fixed.at(p, j);
        if (!r.lit || !f.lit) continue;
        const double d = axis_error(f.s, f.t, r.s, r.t);
        e.st_max = std::max(e.st_max, d);
        st_sum += d;
        ++e.st_pixels;
      }
    }
  }
  if (e.uv_pixels) e.uv_mean = uv_sum / static_cast<double>(e.uv_pixels);
  if (e.st_pixels) e.st_mean = st_sum / static_cast<double>(e.st_pixels);
  return e;
}

}  // namespace spanlight::sweep
