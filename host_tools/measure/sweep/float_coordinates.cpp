// The float model's own stages (transform, clip, setup, raster) with a visitor
// that keeps the nearest fragment's interpolated coordinates, as the model's
// visibility pass does (depth test `less`, objects and triangles in file order).
#include <limits>

#include "float_model/float_model.hpp"
#include "float_model/transform.hpp"
#include "sweep/coordinate_map.hpp"

namespace spanlight::sweep {

CoordinateMap float_coordinates(const scene::Scene& s) {
  CoordinateMap map;
  map.width = s.width;
  map.height = s.height;
  map.projectors = static_cast<int>(s.projectors.size());
  const std::size_t pixels = map.pixels();
  map.object.assign(pixels, -1);
  map.triangle.assign(pixels, -1);
  map.u.assign(pixels, 0.0);
  map.v.assign(pixels, 0.0);
  map.projector.assign(pixels * s.projectors.size(), {});
  std::vector<double> depth(pixels, std::numeric_limits<double>::infinity());
  const float_model::Viewport viewport{s.width, s.height};

  std::int64_t triangle_id = 0;
  for (std::size_t o = 0; o < s.objects.size(); ++o) {
    const scene::Object& object = s.objects[o];
    const float_model::ObjectTransform transform = float_model::eye_transform(s, object);
    double tex_w = 0.0, tex_h = 0.0;
    if (object.texture >= 0) {
      const scene::Image& image = s.textures[static_cast<std::size_t>(object.texture)].image;
      tex_w = image.width;
      tex_h = image.height;
    }
    for (std::size_t i = 0; i < object.mesh.triangles.size(); ++i, ++triangle_id) {
      const auto keep_nearest = [&](const float_model::ClipTriangle& tri, const float_model::Fragment& f) {
        const std::size_t p = static_cast<std::size_t>(f.y) * static_cast<std::size_t>(s.width) + static_cast<std::size_t>(f.x);
        if (!(f.depth < depth[p])) return;
        depth[p] = f.depth;
        map.object[p] = static_cast<int>(o);
        map.triangle[p] = triangle_id;
        const glm::dvec2 uv = float_model::interpolate_uv(tri, f);
        map.u[p] = uv.x * tex_w;
        map.v[p] = uv.y * tex_h;
        for (std::size_t j = 0; j < s.projectors.size(); ++j) {
          const glm::dvec4 strq = float_model::interpolate_projector(tri, f, j);
          const scene::Image& image = s.textures[static_cast<std::size_t>(s.projectors[j].image)].image;
          ProjectorCoordinate& c = map.projector[p * s.projectors.size() + j];
          c = {};
          if (!(strq.w > 0.0)) continue;
          const double sq = strq.x / strq.w, tq = strq.y / strq.w, rq = strq.z / strq.w;
          c.s = sq * image.width;
          c.t = tq * image.height;
          c.lit = sq >= 0.0 && sq <= 1.0 && tq >= 0.0 && tq <= 1.0 && rq >= 0.0 && rq <= 1.0;
        }
      };
      float_model::draw_triangle(float_model::transform_triangle(transform, object.mesh, i), viewport, object.cull,
                                 keep_nearest);
    }
  }
  return map;
}

}  // namespace spanlight::sweep
