// The bench's instantiations: the baked scene's Features (projectors, shadows,
// pcf, pixel format) with bilinear always compiled in, so a forced filter works
// on any scene (a texture set to nearest then costs one extra branch per fetch),
// and the reciprocal chosen per run. Depth is stored in uint32 for both depth
// bit settings: the stored values are the same, only the buffer's size differs.
#pragma once

#include <cstdint>

#include "baked_config.hpp"

namespace bench {

template <int TableBits, int NewtonSteps>
using Features = spanlight::Features<baked::Features::max_projectors, baked::Features::shadows, baked::Features::pcf,
                                     true, baked::Features::format, spanlight::TableReciprocal<TableBits, NewtonSteps>>;
using Depth = std::uint32_t;
using Color = spanlight::ColorTraits<baked::Features::format>;
using Target = spanlight::FrameTarget<baked::Features::format, Depth>;

// The static buffers (bench_buffers.cpp).
Target frame_target();
// FNV-1a over the colour buffer's bytes as stored (little-endian RGB565 or RGB888),
// the same bytes as the host's FixedFrame::raw, so the sweep can check the run.
std::uint32_t frame_hash();

}  // namespace bench
