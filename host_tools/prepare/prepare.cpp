#include "prepare/prepare.hpp"

#include <algorithm>
#include <cmath>

namespace spanlight::prepare {
namespace {

constexpr double position_limit = 16384.0;  // Q15.16 with headroom: |coord| < 2^14

std::int32_t to_q16(double value, const std::string& what) {
  if (!(std::fabs(value) < position_limit)) {
    throw PrepareError(what + ": coordinate " + std::to_string(value) + " is beyond the supported +-16384 units");
  }
  return static_cast<std::int32_t>(std::llround(value * 65536.0));
}

std::uint8_t to_unorm8(double value) { return static_cast<std::uint8_t>(std::lround(std::clamp(value, 0.0, 1.0) * 255.0)); }

std::uint16_t to_q8_8(double value) { return static_cast<std::uint16_t>(std::lround(std::clamp(value, 0.0, 65535.0 / 256.0) * 256.0)); }

Filter to_filter(scene::Filter f) { return f == scene::Filter::nearest ? Filter::nearest : Filter::bilinear; }

Wrap to_wrap(scene::Wrap w) {
  switch (w) {
    case scene::Wrap::repeat: return Wrap::repeat;
    case scene::Wrap::clamp: return Wrap::clamp;
    case scene::Wrap::border: return Wrap::border;
  }
  return Wrap::border;
}

}  // namespace

Mat4Block to_mat4_block(const glm::dmat4& m) {
  double col_major[16];
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) col_major[c * 4 + r] = m[c][r];
  const Mat4Block out = fixedpoint::mat4_block_from_doubles(col_major);
  // Below 16 fraction bits an entry is >= 2^13 and clip coordinates could leave Q31.32.
  if (out.frac_bits < 16) throw PrepareError("a transform has an entry beyond the supported 2^13");
  return out;
}

int uv_frac_bits_for(double largest_texel_coordinate) {
  if (largest_texel_coordinate < 1.0) return 16;
  const int integer_bits = static_cast<int>(std::floor(std::log2(largest_texel_coordinate))) + 1;
  return std::clamp(29 - integer_bits, 0, 16);
}

std::unique_ptr<PreparedStorage> prepare_scene(const scene::Scene& s) {
  auto out = std::make_unique<PreparedStorage>();
  const std::size_t projector_count = s.projectors.size();

  out->texels.reserve(s.textures.size());
  for (const scene::Texture& t : s.textures) {
    out->texels.push_back(t.image.rgb);
    out->textures.push_back(TextureData{out->texels.back().data(), static_cast<std::uint16_t>(t.image.width),
                                        static_cast<std::uint16_t>(t.image.height), to_filter(t.filter), to_wrap(t.wrap)});
  }

  for (const scene::Projector& p : s.projectors) {
    ProjectorData d{};
    d.texture = static_cast<std::int16_t>(p.image);
    for (int c = 0; c < 3; ++c) d.color[c] = to_q8_8(p.color[c]);
    d.shadows = p.shadows.has_value();
    if (p.shadows) {
      d.filter = p.shadows->filter == scene::ShadowFilter::pcf2x2 ? ShadowFilter::pcf2x2 : ShadowFilter::nearest;
      d.map_size = static_cast<std::uint16_t>(p.shadows->map_size);
      d.bias = static_cast<std::int32_t>(std::llround(std::min(p.shadows->bias, 1.99) * 1073741824.0));
    }
    out->projectors.push_back(d);
  }

  const glm::dmat4 view_projection = scene::camera_view_projection(s);
  const std::size_t n = s.objects.size();
  out->positions.resize(n);
  out->uvs.resize(n);
  out->indices.resize(n);
  out->projector_from_object.resize(n);
  out->light_clip_from_object.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const scene::Object& o = s.objects[i];
    const std::string where = s.file.string() + ": objects[" + std::to_string(i) + "]";
    if (o.mesh.positions.size() > 65535) throw PrepareError(where + ": more than 65535 vertices");

    auto& pos = out->positions[i];
    for (const glm::dvec3& p : o.mesh.positions)
      for (int c = 0; c < 3; ++c) pos.push_back(to_q16(p[c], where + ".positions"));

    int frac = 0;
    if (o.texture >= 0) {
      const scene::Image& img = s.textures[static_cast<std::size_t>(o.texture)].image;
      double largest = 0.0;
      for (const glm::dvec2& uv : o.mesh.uvs)
        largest = std::max({largest, std::fabs(uv.x * img.width), std::fabs(uv.y * img.height)});
      if (!(largest < 536870912.0))  // 2^29: the pipeline's |u| bound (perspective.hpp)
        throw PrepareError(where + ".uvs: texel coordinate " + std::to_string(largest) + " is beyond the supported 2^29");
      frac = uv_frac_bits_for(largest);
      for (const glm::dvec2& uv : o.mesh.uvs) {
        out->uvs[i].push_back(static_cast<std::int32_t>(std::llround(std::ldexp(uv.x * img.width, frac))));
        out->uvs[i].push_back(static_cast<std::int32_t>(std::llround(std::ldexp(uv.y * img.height, frac))));
      }
    } else {
      out->uvs[i].assign(o.mesh.positions.size() * 2, 0);
    }
    for (const auto& tri : o.mesh.triangles)
      for (std::uint32_t index : tri) out->indices[i].push_back(static_cast<std::uint16_t>(index));

    for (const scene::Projector& p : s.projectors) {
      out->projector_from_object[i].push_back(to_mat4_block(scene::projector_texture_matrix(p) * o.model));
      out->light_clip_from_object[i].push_back(to_mat4_block(scene::projector_view_projection(p) * o.model));
    }

    ObjectData d{};
    d.positions = pos.data();
    d.uvs = out->uvs[i].data();
    d.indices = out->indices[i].data();
    d.triangle_count = static_cast<std::uint32_t>(o.mesh.triangles.size());
    d.texture = static_cast<std::int16_t>(o.texture);
    d.uv_frac_bits = static_cast<std::uint8_t>(frac);
    d.cull = o.cull == scene::Cull::back ? Cull::back : Cull::none;
    for (int c = 0; c < 3; ++c) d.color[c] = to_unorm8(o.color[c]);
    d.clip_from_object = to_mat4_block(view_projection * o.model);
    d.projector_from_object = projector_count ? out->projector_from_object[i].data() : nullptr;
    d.light_clip_from_object = projector_count ? out->light_clip_from_object[i].data() : nullptr;
    out->objects.push_back(d);
    out->object_names.push_back(o.name);
  }

  PreparedScene& ps = out->scene;
  ps.width = static_cast<std::uint16_t>(s.width);
  ps.height = static_cast<std::uint16_t>(s.height);
  for (int c = 0; c < 3; ++c) ps.ambient[c] = to_unorm8(s.ambient[c]);
  ps.textures = out->textures.data();
  ps.objects = out->objects.data();
  ps.object_count = static_cast<std::uint16_t>(out->objects.size());
  ps.projectors = out->projectors.data();
  ps.projector_count = static_cast<std::uint8_t>(out->projectors.size());
  return out;
}

}  // namespace spanlight::prepare
