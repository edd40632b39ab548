#include "sweep/filter_override.hpp"

namespace spanlight::sweep {

scene::Scene with_filter(const scene::Scene& s, FilterChoice filter) {
  scene::Scene out = s;
  if (filter == FilterChoice::scene) return out;
  for (scene::Texture& t : out.textures)
    t.filter = filter == FilterChoice::nearest ? scene::Filter::nearest : scene::Filter::bilinear;
  return out;
}

std::vector<FilterChoice> distinct_filter_choices(const scene::Scene& s) {
  bool any_nearest = false, any_bilinear = false;
  for (const scene::Texture& t : s.textures) (t.filter == scene::Filter::nearest ? any_nearest : any_bilinear) = true;
  std::vector<FilterChoice> out{FilterChoice::scene};
  if (any_bilinear) out.push_back(FilterChoice::nearest);
  if (any_nearest) out.push_back(FilterChoice::bilinear);
  return out;
}

}  // namespace spanlight::sweep
