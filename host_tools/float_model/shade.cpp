#include "float_model/shade.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "float_model/sample.hpp"

namespace spanlight::float_model {

std::optional<glm::dvec3> project_into_frustum(glm::dvec4 strq) {
  const double q = strq.w;
  if (!(q > 0.0)) return std::nullopt;  // behind the projector: no back-projection
  const glm::dvec3 projected = glm::dvec3(strq) / q;  // the exact divide
  const auto inside = [](double v) { return 0.0 <= v && v <= 1.0; };
  if (!inside(projected.x) || !inside(projected.y) || !inside(projected.z)) return std::nullopt;
  return projected;
}

glm::dvec3 projector_light(const scene::Scene& scene, const scene::Projector& projector, const ShadowMap* shadow_map,
                           glm::dvec4 strq, bool facing) {
  if (!facing) return glm::dvec3(0.0);
  const auto projected = project_into_frustum(strq);
  if (!projected) return glm::dvec3(0.0);
  if (projector.image < 0) throw std::invalid_argument("float_model: projector '" + projector.name + "' has no image");
  const double shadow = (shadow_map && projector.shadows) ? shadow_factor(*shadow_map, *projector.shadows, *projected)
                                                          : 1.0;
  const scene::Texture& image = scene.textures[static_cast<std::size_t>(projector.image)];
  const glm::dvec3 falloff = projector.falloff < 0
                                 ? glm::dvec3(1.0)
                                 : sample_falloff(scene.textures[static_cast<std::size_t>(projector.falloff)], projected->z);
  return shadow * projector.color * sample_projector_image(image, glm::dvec2(*projected)) * falloff;
}

glm::dvec3 pixel_light(const scene::Scene& scene, const std::vector<ShadowMap>& shadow_maps,
                       const std::vector<glm::dvec4>& strq, const std::vector<std::uint8_t>& facing) {
  glm::dvec3 light = scene.ambient;
  for (std::size_t j = 0; j < scene.projectors.size(); ++j) {
    const ShadowMap* map = shadow_maps[j].size > 0 ? &shadow_maps[j] : nullptr;
    light += projector_light(scene, scene.projectors[j], map, strq[j], facing.empty() || facing[j] != 0);
  }
  return glm::min(light, glm::dvec3(1.0));
}

glm::dvec3 surface_color(const scene::Scene& scene, const scene::Object& object, glm::dvec2 uv, const MipChains& chains,
                         double lambda) {
  if (object.texture < 0) return object.color;
  const auto index = static_cast<std::size_t>(object.texture);
  const scene::Texture& texture = scene.textures[index];
  if (texture.filter == scene::Filter::trilinear && index >= chains.size()) {
    throw std::invalid_argument("float_model: trilinear texture '" + texture.name + "' without its mip chain");
  }
  static const std::vector<scene::Image> no_chain;
  return object.color * sample_texture(texture, index < chains.size() ? chains[index] : no_chain, uv, lambda);
}

std::uint8_t to_byte(double value) {
  return static_cast<std::uint8_t>(std::clamp(std::round(255.0 * value), 0.0, 255.0));
}

}  // namespace spanlight::float_model
