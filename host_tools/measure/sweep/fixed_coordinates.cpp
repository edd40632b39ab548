// A probe kernel for the eye pass: it asks the walk for uv (in the surface
// sampler's own stepping scale, so the segments are the ones the real passes
// get) and every projector, and keeps the nearest surface's values, turned back
// into texels.
#include <cmath>

#include "spanlight/render.hpp"
#include "sweep/coordinate_map.hpp"

namespace spanlight::sweep {
namespace {

constexpr Features probe_features = host_features(PixelFormat::rgb888);
constexpr int P = probe_features.max_projectors;

struct CoordinateProbe {
  static constexpr bool may_need_uv = true, may_need_projectors = true;
  const PreparedScene* scene;
  CoordinateMap* map;
  std::vector<std::uint32_t>* depth;
  DepthFormat<0> format;
  Surface surface{};
  int object_index = -1;
  double uv_unit = 0.0;  // texels per exact uv unit: 2^-uv_frac_bits

  SpanNeeds object(const ObjectData& o) {
    object_index = static_cast<int>(&o - scene->objects);
    surface = surface_of(o, scene->textures);
    uv_unit = std::ldexp(1.0, -o.uv_frac_bits);
    return {o.texture >= 0, surface.scale, 0, scene->projector_count};
  }
  // Every pixel a run covers is probed (run() keeps the nearest).
  PixelRange passing(std::uint32_t, std::int32_t count, std::uint32_t, std::int32_t) const { return {0, count}; }
  // A stepped value back in texels: exact = (value as int32 >> shift) - offset (modulo the
  // texture's size where the sampler wraps; compare_coordinates compares modulo it).
  double texels(std::uint32_t value, int c) const {
    const auto signed_value = static_cast<std::int32_t>(value);
    return static_cast<double>((signed_value >> surface.scale.shift[c]) - surface.scale.offset[c]) * uv_unit;
  }
  void run(std::uint32_t i, std::int32_t count, const PixelRun<P>& r) {
    Stepped u = r.u, v = r.v;
    Stepped s[projector_slots(P)], t[projector_slots(P)];
    for (int j = 0; j < scene->projector_count; ++j) s[j] = r.s[j], t[j] = r.t[j];
    std::uint32_t z = r.z;
    for (std::int32_t k = 0; k < count; ++k) {
      const std::size_t p = i + static_cast<std::size_t>(k);
      const std::uint32_t d = format.store(z);
      if (d < (*depth)[p]) {
        (*depth)[p] = d;
        map->object[p] = object_index;
        map->u[p] = texels(u.value, 0);
        map->v[p] = texels(v.value, 1);
        constexpr double to_unit = 1.0 / static_cast<double>(1 << proj_frac_bits);
        for (int j = 0; j < scene->projector_count; ++j) {
          const TextureLevel& image = scene->textures[scene->projectors[j].texture].levels[0];
          ProjectorCoordinate& c = map->projector[p * static_cast<std::size_t>(map->projectors) + static_cast<std::size_t>(j)];
          c.lit = r.front[j];
          c.s = static_cast<std::int32_t>(s[j].value) * to_unit * image.width;
          c.t = static_cast<std::int32_t>(t[j].value) * to_unit * image.height;
        }
      }
      z += static_cast<std::uint32_t>(r.dz);
      step(u);
      step(v);
      for (int j = 0; j < scene->projector_count; ++j) step(s[j]), step(t[j]);
    }
  }
};

}  // namespace

CoordinateMap fixed_coordinates(const prepare::PreparedStorage& prepared, const Knobs& knobs) {
  const PreparedScene& scene = prepared.scene;
  CoordinateMap map;
  map.width = scene.width;
  map.height = scene.height;
  map.projectors = scene.projector_count;
  map.wrap_width.resize(scene.object_count);
  map.wrap_height.resize(scene.object_count);
  for (std::uint16_t o = 0; o < scene.object_count; ++o) {  // a repeating texture's coordinates wrap at its size
    const ObjectData& object = scene.objects[o];
    if (object.texture < 0 || scene.textures[object.texture].wrap != Wrap::repeat) continue;
    map.wrap_width[o] = scene.textures[object.texture].levels[0].width;
    map.wrap_height[o] = scene.textures[object.texture].levels[0].height;
  }
  const std::size_t pixels = map.pixels();
  map.object.assign(pixels, -1);
  map.u.assign(pixels, 0.0);
  map.v.assign(pixels, 0.0);
  map.projector.assign(pixels * scene.projector_count, {});
  const DepthFormat<0> format(knobs.depth_bits);
  std::vector<std::uint32_t> depth(pixels, format.clear);
  std::vector<CachedVertex> vertices(scene.max_vertex_count);
  CoordinateProbe kernel{&scene, &map, &depth, format};
  NoHooks hooks;
  const PassView eye{scene.width, scene.height, -1, 0, scene.height};
  draw_pass<probe_features>(scene, prepared.matrices, eye, knobs, divide_for<probe_features>(knobs), format.z_limit,
                            vertices.data(), kernel, hooks);
  return map;
}

}  // namespace spanlight::sweep
