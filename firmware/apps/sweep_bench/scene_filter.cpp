#include "scene_filter.hpp"

namespace bench {
namespace {

constexpr int max_textures = 16;
spanlight::TextureData textures[max_textures];
spanlight::PreparedScene filtered;

// The scene does not store its texture count: one past the largest index used.
int texture_count(const spanlight::PreparedScene& s) {
  int count = 0;
  for (int o = 0; o < s.object_count; ++o)
    if (s.objects[o].texture + 1 > count) count = s.objects[o].texture + 1;
  for (int j = 0; j < s.projector_count; ++j)
    if (s.projectors[j].texture + 1 > count) count = s.projectors[j].texture + 1;
  return count;
}

}  // namespace

const spanlight::PreparedScene* scene_with_filter(const spanlight::PreparedScene& baked, FilterChoice filter) {
  if (filter == FilterChoice::scene) return &baked;
  const int count = texture_count(baked);
  if (count > max_textures) return nullptr;
  for (int t = 0; t < count; ++t) {
    textures[t] = baked.textures[t];
    textures[t].filter = filter == FilterChoice::nearest ? spanlight::Filter::nearest : spanlight::Filter::bilinear;
  }
  filtered = baked;
  filtered.textures = textures;
  return &filtered;
}

}  // namespace bench
