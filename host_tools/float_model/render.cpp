// The frame, in the order of Segal et al.'s passes: a depth map per shadowed
// projector; the eye's depth pass, which settles the visible surface of every
// pixel (depth test `less`, objects and triangles in file order); then light and
// surface for that one surface. Shading once after visibility is the paper's
// z-equal passes fused; it also means two surfaces at exactly equal depth never
// both add light: the first one drawn wins, as the depth test says.
#include <cstddef>
#include <utility>

#include "float_model/float_model.hpp"
#include "float_model/sample.hpp"
#include "float_model/shade.hpp"
#include "float_model/shadow_map.hpp"
#include "float_model/visibility.hpp"

namespace spanlight::float_model {

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
