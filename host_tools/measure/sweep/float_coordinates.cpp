// The float model's own eye depth pass (float_model/visibility.hpp), its
// interpolated coordinates turned into texels.
#include "float_model/visibility.hpp"
#include "sweep/coordinate_map.hpp"

namespace spanlight::sweep {

namespace {

// s/q, t/q in texels of the projector's image; lit inside the projector's frustum.
ProjectorCoordinate projector_texels(glm::dvec4 strq, const scene::Image& image) {
  ProjectorCoordinate c;
  if (!(strq.w > 0.0)) return c;
  const double sq = strq.x / strq.w, tq = strq.y / strq.w, rq = strq.z / strq.w;
  c.s = sq * image.width;
  c.t = tq * image.height;
  c.lit = sq >= 0.0 && sq <= 1.0 && tq >= 0.0 && tq <= 1.0 && rq >= 0.0 && rq <= 1.0;
  return c;
}

}  // namespace

CoordinateMap float_coordinates(const scene::Scene& s) {
  const float_model::VisibleSurfaces visible = float_model::resolve_visibility(s);
  CoordinateMap map;
  map.width = s.width;
  map.height = s.height;
  map.projectors = static_cast<int>(s.projectors.size());
  const std::size_t pixels = map.pixels();
  map.object = visible.object;
  map.triangle = visible.triangle;
  map.u.assign(pixels, 0.0);
  map.v.assign(pixels, 0.0);
  map.projector.assign(pixels * s.projectors.size(), {});
  for (std::size_t p = 0; p < pixels; ++p) {
    if (visible.object[p] < 0) continue;
    const scene::Object& object = s.objects[static_cast<std::size_t>(visible.object[p])];
    if (object.texture >= 0) {
      const scene::Image& image = s.textures[static_cast<std::size_t>(object.texture)].image;
      map.u[p] = visible.uv[p].x * image.width;
      map.v[p] = visible.uv[p].y * image.height;
    }
    for (std::size_t j = 0; j < s.projectors.size(); ++j) {
      const scene::Image& image = s.textures[static_cast<std::size_t>(s.projectors[j].image)].image;
      map.projector[p * s.projectors.size() + j] = projector_texels(visible.strq[p * s.projectors.size() + j], image);
    }
  }
  return map;
}

}  // namespace spanlight::sweep
