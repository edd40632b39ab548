#include <algorithm>

#include "bake/bake.hpp"

namespace spanlight::bake {

SceneFeatures features_of(const PreparedScene& scene) {
  SceneFeatures f;
  f.projectors = scene.projector_count;
  auto uses_bilinear = [&](std::int16_t texture) {
    return texture >= 0 && scene.textures[texture].filter == Filter::bilinear;
  };
  for (int j = 0; j < scene.projector_count; ++j) {
    const ProjectorData& p = scene.projectors[j];
    f.bilinear |= uses_bilinear(p.texture);
    if (!p.shadows) continue;
    f.shadows = true;
    f.pcf |= p.filter == ShadowFilter::pcf2x2;
    f.largest_shadow_map = std::max<int>(f.largest_shadow_map, p.map_size);
    f.shadow_map_texels += std::size_t{p.map_size} * p.map_size;
  }
  for (std::uint16_t o = 0; o < scene.object_count; ++o) f.bilinear |= uses_bilinear(scene.objects[o].texture);
  return f;
}

}  // namespace spanlight::bake
