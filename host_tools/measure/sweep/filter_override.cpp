#include "sweep/filter_override.hpp"

namespace spanlight::sweep {

scene::Scene with_filter(const scene::Scene& s, FilterChoice filter) {
  scene::Scene out = s;
  if (filter == FilterChoice::scene) return out;
  for (scene::Texture& t : out.textures)
    t.filter = filter == FilterChoice::nearest ? scene::Filter::nearest : scene::Filter::bilinear;
  return out;
}

// Each forced filter that changes some texture: a trilinear scene gets a bilinear variant too,
// the trade the mip chain makes.
std::vector<FilterChoice> distinct_filter_choices(const scene::Scene& s) {
  bool any_not_nearest = false, any_not_bilinear = false;
  for (const scene::Texture& t : s.textures) {
    any_not_nearest |= t.filter != scene::Filter::nearest;
    any_not_bilinear |= t.filter != scene::Filter::bilinear;
  }
  std::vector<FilterChoice> out{FilterChoice::scene};
  if (any_not_nearest) out.push_back(FilterChoice::nearest);
  if (any_not_bilinear) out.push_back(FilterChoice::bilinear);
  return out;
}

}  // namespace spanlight::sweep
