#include "float_model/visibility.hpp"

#include <limits>

#include "float_model/facing.hpp"
#include "float_model/sample.hpp"
#include "float_model/scene_geometry.hpp"

namespace spanlight::float_model {

namespace {

// The object's texture when it is filtered trilinearly, the one case that needs a level of detail.
const scene::Texture* mipmapped_texture(const scene::Scene& scene, const scene::Object& object) {
  if (object.texture < 0) return nullptr;
  const scene::Texture& texture = scene.textures[static_cast<std::size_t>(object.texture)];
  return texture.filter == scene::Filter::trilinear ? &texture : nullptr;
}

}  // namespace

VisibleSurfaces resolve_visibility(const scene::Scene& scene) {
  const std::size_t pixels = static_cast<std::size_t>(scene.width) * static_cast<std::size_t>(scene.height);
  const std::size_t projectors = scene.projectors.size();
  VisibleSurfaces visible{projectors,
                          std::vector<double>(pixels, 1.0),
                          std::vector<int>(pixels, -1),
                          std::vector<std::int64_t>(pixels, -1),
                          std::vector<glm::dvec2>(pixels),
                          std::vector<double>(pixels, -std::numeric_limits<double>::infinity()),
                          std::vector<glm::dvec4>(pixels * projectors),
                          std::vector<std::uint8_t>(pixels * projectors, 1)};
  const Viewport viewport{scene.width, scene.height};

  std::int64_t scene_triangle = -1;
  // Per triangle rather than for_each_fragment: facing is a property of the whole triangle.
  for_each_triangle(scene, eye_transforms(scene), [&](MeshTriangle which, const ClipTriangle& transformed) {
    ++scene_triangle;
    const scene::Object& object = scene.objects[which.object];
    const scene::Texture* mipmapped = mipmapped_texture(scene, object);
    const std::vector<std::uint8_t> facing = projectors_facing(scene, object, which.index);
    const auto keep_nearest = [&](const ClipTriangle& triangle, const Fragment& fragment) {
      const std::size_t pixel = static_cast<std::size_t>(fragment.y) * static_cast<std::size_t>(scene.width) +
                                static_cast<std::size_t>(fragment.x);
      if (!(fragment.depth < visible.depth[pixel])) return;
      visible.depth[pixel] = fragment.depth;
      visible.object[pixel] = static_cast<int>(which.object);
      visible.triangle[pixel] = scene_triangle;
      visible.uv[pixel] = interpolate_uv(triangle, fragment);
      if (mipmapped) {
        const UvDerivatives d = uv_derivatives(triangle, fragment);
        visible.lambda[pixel] = level_of_detail(d.d_dx, d.d_dy, mipmapped->image.width, mipmapped->image.height);
      }
      for (std::size_t j = 0; j < projectors; ++j) {
        visible.strq[pixel * projectors + j] = interpolate_projector(triangle, fragment, j);
        visible.facing[pixel * projectors + j] = facing[j];
      }
    };
    draw_triangle(transformed, viewport, object.cull, keep_nearest);
  });
  return visible;
}

}  // namespace spanlight::float_model
