// The texture-filter knob on target: the baked scene lives in flash, so a
// forced filter is applied to a RAM copy of its texture descriptors (the
// texels themselves stay in flash) and a PreparedScene that points at it.
#pragma once

#include "bench_request.hpp"
#include "spanlight/prepared_scene.hpp"

namespace bench {

// `baked` itself for FilterChoice::scene; nullptr when the scene has more
// textures than the copy holds.
const spanlight::PreparedScene* scene_with_filter(const spanlight::PreparedScene& baked, FilterChoice filter);

}  // namespace bench
