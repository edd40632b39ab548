// projectors[]: view volume, projected image and colour, optional shadows; v2: falloff,
// facing_only and space.
#include "scene_readers.hpp"

namespace spanlight::scene::detail {
namespace {

constexpr std::int64_t min_shadow_map_size = 8;
constexpr std::int64_t max_shadow_map_size = 4096;

Shadows read_shadows(const JsonField& shadows) {
  shadows.expect_object_with_fields({"map_size", "bias", "filter"});
  Shadows loaded;
  loaded.map_size = static_cast<int>(shadows.required("map_size").integer(min_shadow_map_size, max_shadow_map_size));
  loaded.bias = shadows.required("bias").number(at_least(0.0));
  if (const auto filter = shadows.optional("filter")) {
    loaded.filter = filter->choice<ShadowFilter>({{"nearest", ShadowFilter::nearest}, {"pcf2x2", ShadowFilter::pcf2x2}});
  }
  return loaded;
}

Projector read_projector(const JsonField& projector, std::size_t index, const std::vector<Texture>& textures,
                         int version) {
  projector.expect_object_with_fields({"name", "eye", "target", "up", "fovy_deg", "aspect", "near", "far", "image",
                                       "color", "shadows", "falloff", "facing_only", "space"});
  refuse_version_2_fields(projector, version, {"falloff", "facing_only", "space"});
  Projector loaded;
  loaded.name = projector.has("name") ? projector.required("name").string()
                                      : "projectors[" + std::to_string(index) + "]";
  const ViewVolume view = read_view_volume(projector);
  loaded.eye = view.eye;
  loaded.target = view.target;
  loaded.up = view.up;
  loaded.fovy_deg = view.fovy_deg;
  loaded.near = view.near;
  loaded.far = view.far;
  if (const auto aspect = projector.optional("aspect")) loaded.aspect = aspect->number(greater_than(0.0));
  loaded.image = find_texture(projector.required("image"), textures);
  if (const auto color = projector.optional("color")) loaded.color = color->vec3(at_least(0.0));
  if (const auto shadows = projector.optional("shadows")) loaded.shadows = read_shadows(*shadows);
  if (const auto falloff = projector.optional("falloff")) loaded.falloff = find_texture(*falloff, textures);
  if (const auto facing_only = projector.optional("facing_only")) loaded.facing_only = facing_only->boolean();
  if (const auto space = projector.optional("space")) {
    loaded.space = space->choice<ProjectorSpace>({{"world", ProjectorSpace::world}, {"camera", ProjectorSpace::camera}});
  }
  return loaded;
}

}  // namespace

std::vector<Projector> read_projectors(const JsonField& projectors, const std::vector<Texture>& textures,
                                       int version) {
  std::vector<Projector> loaded;
  const auto elements = projectors.elements();
  for (std::size_t i = 0; i < elements.size(); ++i) loaded.push_back(read_projector(elements[i], i, textures, version));
  return loaded;
}

}  // namespace spanlight::scene::detail
