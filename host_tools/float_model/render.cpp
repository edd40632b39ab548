// The frame, in the order of Segal et al.'s passes: a depth map per shadowed
// projector; the eye's depth pass, which settles the visible surface of every
// pixel (depth test `less`, objects and triangles in file order); then light and
// surface for that one surface. Shading once after visibility is the paper's
// z-equal passes fused; it also means two surfaces at exactly equal depth never
// both add light: the first one drawn wins, as the depth test says.
#include <cstddef>
#include <limits>
#include <utility>

#include "float_model/facing.hpp"
#include "float_model/float_model.hpp"
#include "float_model/sample.hpp"
#include "float_model/shade.hpp"
#include "float_model/shadow_map.hpp"
#include "float_model/transform.hpp"

namespace spanlight::float_model {

namespace {

// What the eye's depth pass keeps per pixel: the nearest surface and its
// interpolated attributes (one (s, t, r, q) per projector), its texture's level
// of detail, and which projectors its triangle faces (facing.hpp).
struct VisibleSurfaces {
  std::size_t projectors = 0;
  std::vector<double> depth;
  std::vector<int> object;
  std::vector<glm::dvec2> uv;
  std::vector<double> lambda;          // trilinear textures only
  std::vector<glm::dvec4> strq;        // pixel-major, `projectors` entries per pixel
  std::vector<std::uint8_t> facing;    // pixel-major like strq
};

VisibleSurfaces resolve_visibility(const scene::Scene& scene) {
  const std::size_t pixels = static_cast<std::size_t>(scene.width) * static_cast<std::size_t>(scene.height);
  const std::size_t projectors = scene.projectors.size();
  VisibleSurfaces visible{projectors,
                          std::vector<double>(pixels, 1.0),
                          std::vector<int>(pixels, -1),
                          std::vector<glm::dvec2>(pixels),
                          std::vector<double>(pixels, -std::numeric_limits<double>::infinity()),
                          std::vector<glm::dvec4>(pixels * projectors),
                          std::vector<std::uint8_t>(pixels * projectors, 1)};
  const Viewport viewport{scene.width, scene.height};

  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    const scene::Object& object = scene.objects[o];
    const scene::Texture* mipmapped = nullptr;
    if (object.texture >= 0 && scene.textures[static_cast<std::size_t>(object.texture)].filter == scene::Filter::trilinear) {
      mipmapped = &scene.textures[static_cast<std::size_t>(object.texture)];
    }
    std::vector<std::uint8_t> facing;  // of the triangle being drawn
    const auto keep_nearest = [&](const ClipTriangle& triangle, const Fragment& fragment) {
      const std::size_t pixel = static_cast<std::size_t>(fragment.y) * static_cast<std::size_t>(scene.width) +
                                static_cast<std::size_t>(fragment.x);
      if (!(fragment.depth < visible.depth[pixel])) return;
      visible.depth[pixel] = fragment.depth;
      visible.object[pixel] = static_cast<int>(o);
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
    const ObjectTransform transform = eye_transform(scene, object);
    for (std::size_t i = 0; i < object.mesh.triangles.size(); ++i) {
      facing = projectors_facing(scene, object, i);
      draw_triangle(transform_triangle(transform, object.mesh, i), viewport, object.cull, keep_nearest);
    }
  }
  return visible;
}

}  // namespace

FloatFrame render_float(const scene::Scene& scene) {
  std::vector<ShadowMap> shadow_maps;  // an empty map for a projector without shadows
  for (const scene::Projector& projector : scene.projectors) {
    shadow_maps.push_back(projector.shadows ? render_shadow_map(scene, projector) : ShadowMap{});
  }

  VisibleSurfaces visible = resolve_visibility(scene);
  const MipChains chains = mip_chains(scene);

  const std::size_t pixels = visible.depth.size();
  FloatFrame frame{scene.width, scene.height, std::vector<std::uint8_t>(pixels * 3, 0), std::move(visible.depth),
                   std::vector<float>(pixels * 3, 0.0f), visible.object};
  std::vector<glm::dvec4> strq(visible.projectors);
  std::vector<std::uint8_t> facing(visible.projectors);
  for (std::size_t pixel = 0; pixel < pixels; ++pixel) {
    const int o = visible.object[pixel];
    if (o < 0) continue;  // background stays black
    for (std::size_t j = 0; j < visible.projectors; ++j) {
      strq[j] = visible.strq[pixel * visible.projectors + j];
      facing[j] = visible.facing[pixel * visible.projectors + j];
    }
    const glm::dvec3 light = pixel_light(scene, shadow_maps, strq, facing);
    const glm::dvec3 surface =
        surface_color(scene, scene.objects[static_cast<std::size_t>(o)], visible.uv[pixel], chains, visible.lambda[pixel]);
    const glm::dvec3 color = light * surface;
    for (int c = 0; c < 3; ++c) {
      frame.rgb[pixel * 3 + static_cast<std::size_t>(c)] = to_byte(color[c]);
      frame.light_rgb[pixel * 3 + static_cast<std::size_t>(c)] = static_cast<float>(light[c]);
    }
  }
  return frame;
}

}  // namespace spanlight::float_model
