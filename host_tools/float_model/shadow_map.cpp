#include "float_model/shadow_map.hpp"

#include <algorithm>
#include <cmath>

#include "float_model/scene_geometry.hpp"

namespace spanlight::float_model {

double ShadowMap::at(long long column, long long row_from_bottom) const {
  const long long last = size - 1;
  column = std::clamp(column, 0LL, last);
  const long long row_from_top = last - std::clamp(row_from_bottom, 0LL, last);
  return depth[static_cast<std::size_t>(row_from_top * size + column)];
}

ShadowMap render_shadow_map(const scene::Scene& scene, const scene::Projector& projector) {
  const int size = projector.shadows ? projector.shadows->map_size : 0;
  ShadowMap map{size, std::vector<double>(static_cast<std::size_t>(size) * static_cast<std::size_t>(size), 1.0)};
  const Viewport viewport{size, size};
  const auto keep_nearest = [&](MeshTriangle, const ClipTriangle&, const Fragment& fragment) {
    double& stored = map.depth[static_cast<std::size_t>(fragment.y) * static_cast<std::size_t>(size) +
                               static_cast<std::size_t>(fragment.x)];
    if (fragment.depth < stored) stored = fragment.depth;
  };
  const auto from_projector = [&](const scene::Object& object) {
    return projector_depth_transform(scene.camera, projector, object);
  };
  for_each_fragment(scene, viewport, from_projector, keep_nearest);
  return map;
}

namespace {

// floor() as a texel index. Lookups only happen inside the frustum (0 <= s/q <= 1),
// so the limit never bites there; it keeps the cast defined for any input.
long long map_index(double x, int size) {
  return static_cast<long long>(std::floor(std::clamp(x, -1.0, static_cast<double>(size))));
}

}  // namespace

double shadow_factor(const ShadowMap& map, const scene::Shadows& shadows, glm::dvec3 projected) {
  const double receiver = projected.z - shadows.bias;
  const auto lit = [&](long long column, long long row_from_bottom) {
    return receiver <= map.at(column, row_from_bottom) ? 1.0 : 0.0;
  };
  if (shadows.filter == scene::ShadowFilter::nearest) {
    return lit(map_index(projected.x * map.size, map.size), map_index(projected.y * map.size, map.size));
  }
  const double x = projected.x * map.size - 0.5;
  const double y = projected.y * map.size - 0.5;  // from the bottom
  const long long x0 = map_index(x, map.size);
  const long long y0 = map_index(y, map.size);
  const double fx = std::clamp(x - static_cast<double>(x0), 0.0, 1.0);
  const double fy = std::clamp(y - static_cast<double>(y0), 0.0, 1.0);
  return (1.0 - fx) * (1.0 - fy) * lit(x0, y0) + fx * (1.0 - fy) * lit(x0 + 1, y0) +
         (1.0 - fx) * fy * lit(x0, y0 + 1) + fx * fy * lit(x0 + 1, y0 + 1);
}

}  // namespace spanlight::float_model
