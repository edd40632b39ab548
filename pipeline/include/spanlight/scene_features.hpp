// Which Features a scene needs: what `spanlight bake` switches on for it, and
// what render_frame checks a build against before it draws. One function
// answers both, so they cannot disagree.
#pragma once

#include "spanlight/features.hpp"
#include "spanlight/scene.hpp"

namespace spanlight {

// A repeating texture's size as Features::repeat_sizes holds it: (log2 width << 4) | log2 height.
constexpr std::uint8_t repeat_size_of(const TextureLevel& level) {
  auto log2_of = [](std::uint32_t x) { int n = 0; while ((1u << n) < x) ++n; return n; };
  return static_cast<std::uint8_t>((log2_of(level.width) << 4) | log2_of(level.height));
}

// The least a build must compile to draw `scene` with `knobs`.
constexpr Features features_of(const PreparedScene& scene, const Knobs& knobs) {
  Features f{};
  f.max_projectors = scene.projector_count;
  f.shadows = f.pcf = f.nearest = f.bilinear = f.clamped = f.tinted = f.trilinear = f.falloff = f.facing = f.closed_solids = false;
  auto filter_of = [&](const TextureData& t) {
    if (t.filter == Filter::nearest) f.nearest = true;
    else f.bilinear = true;
  };
  int sizes = 0;
  f.any_repeat_size = false;
  for (std::uint16_t o = 0; o < scene.object_count; ++o) {
    const ObjectData& object = scene.objects[o];
    f.closed_solids |= object.closed && object.cull == Cull::none;
    if (object.texture < 0) continue;
    const TextureData& t = scene.textures[object.texture];
    filter_of(t);
    f.trilinear |= t.filter == Filter::trilinear && t.level_count > 1;
    f.clamped |= t.wrap != Wrap::repeat;
    f.tinted |= !(object.color[0] == 255 && object.color[1] == 255 && object.color[2] == 255);
    if (t.wrap != Wrap::repeat) continue;
    const std::uint8_t size = repeat_size_of(t.levels[0]);
    bool known = false;
    for (int i = 0; i < sizes; ++i) known |= f.repeat_sizes[i] == size;
    if (known) continue;
    if (sizes < 4) f.repeat_sizes[sizes++] = size;
    else f.any_repeat_size = true;
  }
  for (int j = 0; j < scene.projector_count; ++j) {
    const ProjectorData& p = scene.projectors[j];
    filter_of(scene.textures[p.texture]);
    if (p.falloff >= 0) filter_of(scene.textures[p.falloff]);
    f.falloff |= p.falloff >= 0;
    f.facing |= p.facing_only;
    f.shadows |= p.shadows;
    f.pcf |= p.shadows && p.filter == ShadowFilter::pcf2x2;
  }
  f.format = knobs.format;
  f.fused = knobs.passes == Passes::fused;
  f.multipass = knobs.passes == Passes::multipass;
  f.table_bits = knobs.table_bits;
  f.newton = knobs.newton;
  f.depth_bits = knobs.depth_bits;
  return f;
}

// Whether a build with features `built` has everything `needed` asks for.
constexpr bool covers(const Features& built, const Features& needed) {
  bool sizes = built.any_repeat_size || !needed.any_repeat_size;
  for (const std::uint8_t size : needed.repeat_sizes) {
    if (size == 0 || built.any_repeat_size) continue;
    bool found = false;
    for (const std::uint8_t b : built.repeat_sizes) found |= b == size;
    sizes &= found;
  }
  return built.max_projectors >= needed.max_projectors && (built.shadows || !needed.shadows) &&
         (built.pcf || !needed.pcf) && (built.nearest || !needed.nearest) && (built.bilinear || !needed.bilinear) &&
         (built.clamped || !needed.clamped) && (built.tinted || !needed.tinted) && (built.trilinear || !needed.trilinear) &&
         (built.falloff || !needed.falloff) && (built.facing || !needed.facing) &&
         (built.closed_solids || !needed.closed_solids) && sizes;
}

}  // namespace spanlight
