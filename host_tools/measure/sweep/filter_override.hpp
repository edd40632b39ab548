// The texture-filter knob. A scene names each texture's filter; the sweep may
// force every texture (surfaces and projector images alike) to one filter,
// applied to the loaded Scene before prepare, so the fixed pipeline and the
// float model both see the forced filter.
#pragma once

#include <vector>

#include "scene/scene.hpp"
#include "sweep/grid.hpp"

namespace spanlight::sweep {

// A copy of `scene` with the filter applied (FilterChoice::scene: unchanged).
scene::Scene with_filter(const scene::Scene& scene, FilterChoice filter);

// `scene` first, then each forced filter that gives a different scene (a scene
// whose textures are all bilinear gets {scene, nearest}).
std::vector<FilterChoice> distinct_filter_choices(const scene::Scene& scene);

}  // namespace spanlight::sweep
