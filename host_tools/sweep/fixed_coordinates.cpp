// A debug kernel for the eye pass: it interpolates uv and every projector at
// once (each group keeps its own span schedule, span.hpp, so the values are
// the ones the real passes see) and keeps the nearest surface's values.
#include <stdexcept>

#include "spanlight/render.hpp"
#include "sweep/coordinate_map.hpp"

namespace spanlight::sweep {
namespace {

template <int P>
struct CoordinateProbe {
  const PreparedScene* scene;
  CoordinateMap* map;
  std::vector<std::uint32_t>* depth;
  int depth_bits;
  const ObjectData* current = nullptr;
  double uv_scale = 0.0;
  int object_index = -1;

  SpanNeeds needs() const { return {current->texture >= 0, 0, scene->projector_count}; }
  void object(const ObjectData& o) {
    current = &o;
    object_index = static_cast<int>(&o - scene->objects);
    uv_scale = 1.0 / static_cast<double>(1u << o.uv_frac_bits);
  }
  void pixel(std::int32_t i, const PointValues<P>& v) {
    const auto p = static_cast<std::size_t>(i);
    const std::uint32_t d = depth_store(v.z, depth_bits);
    if (d >= (*depth)[p]) return;
    (*depth)[p] = d;
    map->object[p] = object_index;
    map->u[p] = v.u * uv_scale;
    map->v[p] = v.v * uv_scale;
    constexpr double to_unit = 1.0 / static_cast<double>(1 << proj_frac_bits);
    for (int j = 0; j < scene->projector_count; ++j) {
      const TextureData& image = scene->textures[scene->projectors[j].texture];
      ProjectorCoordinate& c = map->projector[p * static_cast<std::size_t>(map->projectors) + static_cast<std::size_t>(j)];
      c.lit = v.front[j];
      c.s = v.s[j] * to_unit * image.width;
      c.t = v.t[j] * to_unit * image.height;
    }
  }
};

template <int TableBits, int NewtonSteps>
CoordinateMap probe(const PreparedScene& scene, const Precision& precision) {
  using F = HostFeatures<PixelFormat::rgb888, TableBits, NewtonSteps>;
  CoordinateMap map;
  map.width = scene.width;
  map.height = scene.height;
  map.projectors = scene.projector_count;
  const std::size_t pixels = map.pixels();
  map.object.assign(pixels, -1);
  map.u.assign(pixels, 0.0);
  map.v.assign(pixels, 0.0);
  map.projector.assign(pixels * scene.projector_count, {});
  std::vector<std::uint32_t> depth(pixels, depth_clear(precision.depth_bits));
  CoordinateProbe<F::max_projectors> kernel{&scene, &map, &depth, precision.depth_bits};
  draw_pass<F>(scene, PassView{scene.width, scene.height, -1}, precision, kernel);
  return map;
}

template <int TableBits>
CoordinateMap probe_steps(const PreparedScene& scene, const prepare::FixedOptions& o) {
  switch (o.newton_steps) {
    case 0: return probe<TableBits, 0>(scene, o.precision);
    case 1: return probe<TableBits, 1>(scene, o.precision);
    case 2: return probe<TableBits, 2>(scene, o.precision);
    default: throw std::invalid_argument("newton steps must be 0, 1 or 2");
  }
}

}  // namespace

CoordinateMap fixed_coordinates(const prepare::PreparedStorage& prepared, const prepare::FixedOptions& o) {
  const PreparedScene& scene = prepared.scene;
  switch (o.table_bits) {
    case 6: return probe_steps<6>(scene, o);
    case 8: return probe_steps<8>(scene, o);
    case 10: return probe_steps<10>(scene, o);
    case 12: return probe_steps<12>(scene, o);
    default: throw std::invalid_argument("reciprocal table bits must be 6, 8, 10 or 12");
  }
}

}  // namespace spanlight::sweep
