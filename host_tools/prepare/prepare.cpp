#include "prepare/prepare.hpp"

#include "prepare/closed_mesh.hpp"
#include "scene/mip_chain.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace spanlight::prepare {
namespace {

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

// Where texel coordinate i (in [-1, size]) of the frame reads from, or -1 for black.
int framed_index(int i, int size, Wrap wrap) {
  if (i >= 0 && i < size) return i;
  switch (wrap) {
    case Wrap::repeat: return (i + size) % size;
    case Wrap::clamp: return i < 0 ? 0 : size - 1;
    case Wrap::border: return -1;
  }
  return -1;
}

Bounds bounds_of(const std::vector<std::int32_t>& xyz) {
  Bounds b{{INT32_MAX, INT32_MAX, INT32_MAX}, {INT32_MIN, INT32_MIN, INT32_MIN}};
  for (std::size_t i = 0; i < xyz.size(); ++i) {
    const std::size_t c = i % 3;
    b.min[c] = std::min(b.min[c], xyz[i]);
    b.max[c] = std::max(b.max[c], xyz[i]);
  }
  if (xyz.empty()) b = Bounds{};
  return b;
}

}  // namespace

std::vector<std::uint32_t> framed_texels(const scene::Image& image, Wrap wrap) {
  const int w = image.width, h = image.height;
  std::vector<std::uint32_t> out(framed_texel_count(static_cast<std::uint32_t>(w), static_cast<std::uint32_t>(h)));
  std::size_t k = 0;
  for (int y = -texture_frame; y < h + texture_frame; ++y) {  // from the bottom row (t = 0) up
    for (int x = -texture_frame; x < w + texture_frame; ++x, ++k) {
      const int xi = framed_index(x, w, wrap), yi = framed_index(y, h, wrap);
      if (xi < 0 || yi < 0) continue;  // border: black
      const auto t = image.texel(xi, h - 1 - yi);  // the file's rows are top first
      out[k] = (std::uint32_t{t[0]} << 16) | (std::uint32_t{t[1]} << 8) | t[2];
    }
  }
  return out;
}

Mat4Block to_mat4_block(const glm::dmat4& m) {
  double col_major[16];
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) col_major[c * 4 + r] = m[c][r];
  const Mat4Block out = fixedpoint::mat4_block_from_doubles(col_major);
  if (out.frac_bits < min_matrix_frac_bits) throw PrepareError("a transform has an entry beyond the supported 2^13");
  return out;
}

int uv_frac_bits_for(double largest_texel_coordinate) {
  if (largest_texel_coordinate < 1.0) return 16;
  const int integer_bits = static_cast<int>(std::floor(std::log2(largest_texel_coordinate))) + 1;
  return std::clamp(uv_value_bits - integer_bits, 8, 16);
}

// A repeating image with a side of one texel, doubled along that side: the
// sampler finds a texel as the top log2(size) bits of a 32-bit fraction, and
// log2 1 = 0 would shift by 32. Both copies are the one row (or column), so
// nearest and bilinear read the same values as from the original.
scene::Image repeatable_image(const scene::Image& image) {
  if (image.width > 1 && image.height > 1) return image;
  scene::Image out;
  out.width = image.width == 1 ? 2 : image.width;
  out.height = image.height == 1 ? 2 : image.height;
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x)
      for (const std::uint8_t c : image.texel(x % image.width, y % image.height)) out.rgb.push_back(c);
  return out;
}

std::unique_ptr<PreparedStorage> prepare_scene(const scene::Scene& s) {
  auto out = std::make_unique<PreparedStorage>();
  const std::size_t projector_count = s.projectors.size();

  // Each (image, wrap, use) a pass reads gets its own TextureData: objects read a
  // texture with its wrap (a trilinear one with its whole mip chain), projectors
  // with a black frame (border) and falloff clamped to the edge, both at level 0
  // and never mipmapped (a trilinear image is sampled bilinearly there).
  struct Use {
    int index;
    Wrap wrap;
    bool mipmapped;
    auto operator<=>(const Use&) const = default;
  };
  std::map<Use, std::int16_t> baked;
  std::vector<Use> order;  // by id
  auto texture_for = [&](int index, Wrap wrap, bool object) -> std::int16_t {
    const scene::Texture& t = s.textures[static_cast<std::size_t>(index)];
    const Use use{index, wrap, object && t.filter == scene::Filter::trilinear};
    if (const auto found = baked.find(use); found != baked.end()) return found->second;
    PreparedTexture& storage = out->texture_storage.emplace_back();
    if (use.mipmapped) {  // the mipmap sampler takes a side of one texel at any level
      for (const scene::Image& level : scene::mip_chain(t.image)) storage.framed.push_back(framed_texels(level, wrap));
    } else {
      storage.framed.push_back(framed_texels(wrap == Wrap::repeat ? repeatable_image(t.image) : t.image, wrap));
    }
    const auto id = static_cast<std::int16_t>(out->texture_storage.size() - 1);
    baked.emplace(use, id);
    order.push_back(use);
    const char* suffix = wrap == to_wrap(t.wrap) ? "" : (wrap == Wrap::border ? "_border" : "_clamp");
    out->texture_names.push_back(t.name + suffix + (object || t.filter != scene::Filter::trilinear ? "" : "_level0"));
    return id;
  };
  std::vector<std::int16_t> object_texture(s.objects.size(), -1), projector_texture(projector_count, -1),
      falloff_texture(projector_count, -1);
  for (std::size_t i = 0; i < s.objects.size(); ++i)
    if (const int t = s.objects[i].texture; t >= 0)
      object_texture[i] = texture_for(t, to_wrap(s.textures[static_cast<std::size_t>(t)].wrap), true);
  for (std::size_t j = 0; j < projector_count; ++j) {
    projector_texture[j] = texture_for(s.projectors[j].image, Wrap::border, false);
    if (s.projectors[j].falloff >= 0) falloff_texture[j] = texture_for(s.projectors[j].falloff, Wrap::clamp, false);
  }

  // Level tables after all storage exists (their pointers must not move).
  for (std::size_t i = 0; i < out->texture_storage.size(); ++i) {
    PreparedTexture& storage = out->texture_storage[i];
    const Use& use = order[i];
    const scene::Texture& t = s.textures[static_cast<std::size_t>(use.index)];
    const bool doubled = use.wrap == Wrap::repeat && !use.mipmapped;  // as repeatable_image() bakes it
    const int width0 = doubled ? std::max(2, t.image.width) : t.image.width;
    const int height0 = doubled ? std::max(2, t.image.height) : t.image.height;
    for (std::size_t k = 0; k < storage.framed.size(); ++k) {
      const auto w = static_cast<std::uint16_t>(std::max(1, width0 >> k));
      const auto h = static_cast<std::uint16_t>(std::max(1, height0 >> k));
      const std::uint32_t stride = w + 2u * texture_frame;
      storage.levels.push_back(TextureLevel{storage.framed[k].data() + stride * texture_frame + texture_frame, w, h,
                                            static_cast<std::uint16_t>(stride)});
    }
    const Filter filter = use.mipmapped ? Filter::trilinear : to_filter(t.filter);
    out->textures.push_back(TextureData{storage.levels.data(), static_cast<std::uint8_t>(storage.levels.size()), filter, use.wrap});
  }

  for (std::size_t j = 0; j < projector_count; ++j) {
    const scene::Projector& p = s.projectors[j];
    ProjectorData d{};
    d.texture = projector_texture[j];
    d.falloff = falloff_texture[j];
    d.facing_only = p.facing_only;
    for (int c = 0; c < 3; ++c) d.color[c] = to_q8_8(p.color[c]);
    d.shadows = p.shadows.has_value();
    if (p.shadows) {
      d.filter = p.shadows->filter == scene::ShadowFilter::pcf2x2 ? ShadowFilter::pcf2x2 : ShadowFilter::nearest;
      d.map_size = static_cast<std::uint16_t>(p.shadows->map_size);
      // bias >= 0 (the loader's rule); above 1.99 the compare is the same, and the pipeline's word needs it there.
      d.bias = static_cast<std::int32_t>(std::min<long long>(std::llround(std::min(p.shadows->bias, 2.0) * 1073741824.0), max_shadow_bias));
    }
    out->projectors.push_back(d);
  }

  const glm::dmat4 view_projection = scene::camera_view_projection(s);
  const std::size_t n = s.objects.size();
  out->positions.resize(n);
  out->uvs.resize(n);
  out->indices.resize(n);
  std::uint16_t max_vertices = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const scene::Object& o = s.objects[i];
    const std::string where = s.file.string() + ": objects[" + std::to_string(i) + "]";
    if (o.mesh.positions.size() > vertex_limit) throw PrepareError(where + ": more than 65535 vertices");

    auto& pos = out->positions[i];
    for (const glm::dvec3& p : o.mesh.positions)
      for (int c = 0; c < 3; ++c) pos.push_back(to_q16(p[c], where + ".positions"));

    int frac = 8;
    if (o.texture >= 0) {
      const TextureLevel& img = out->textures[static_cast<std::size_t>(object_texture[i])].levels[0];  // as baked
      const std::vector<glm::dvec2> uvs = scene::vertex_uvs(s.camera, o);  // given, or from texgen
      double largest = 0.0;
      for (const glm::dvec2& uv : uvs)
        largest = std::max({largest, std::fabs(uv.x * img.width), std::fabs(uv.y * img.height)});
      if (!(largest < texel_coordinate_limit))
        throw PrepareError(where + ".uvs: texel coordinate " + std::to_string(largest) + " is beyond the supported 2^21");
      frac = uv_frac_bits_for(largest);
      for (const glm::dvec2& uv : uvs) {
        out->uvs[i].push_back(static_cast<std::int32_t>(std::llround(std::ldexp(uv.x * img.width, frac))));
        out->uvs[i].push_back(static_cast<std::int32_t>(std::llround(std::ldexp(uv.y * img.height, frac))));
      }
    } else {
      out->uvs[i].assign(o.mesh.positions.size() * 2, 0);
    }
    for (const auto& tri : o.mesh.triangles)
      for (std::uint32_t index : tri) out->indices[i].push_back(static_cast<std::uint16_t>(index));

    out->clip_from_object.push_back(to_mat4_block(view_projection * o.model));
    for (const scene::Projector& p : s.projectors) {
      out->projector_from_object.push_back(to_mat4_block(scene::projector_texture_matrix(s.camera, p) * o.model));
      out->light_clip_from_object.push_back(to_mat4_block(scene::projector_view_projection(s.camera, p) * o.model));
    }

    ObjectData d{};
    d.positions = pos.data();
    d.uvs = out->uvs[i].data();
    d.indices = out->indices[i].data();
    d.vertex_count = static_cast<std::uint16_t>(o.mesh.positions.size());
    d.triangle_count = static_cast<std::uint32_t>(o.mesh.triangles.size());
    d.bounds = bounds_of(pos);
    d.texture = object_texture[i];
    d.uv_frac_bits = static_cast<std::uint8_t>(frac);
    d.cull = o.cull == scene::Cull::back ? Cull::back : Cull::none;
    for (int c = 0; c < 3; ++c) d.color[c] = to_unorm8(o.color[c]);
    d.texgen = TexgenSpace::none;
    d.closed = closed_solid(pos, o.mesh.triangles);
    out->objects.push_back(d);
    out->object_names.push_back(o.name);
    max_vertices = std::max(max_vertices, d.vertex_count);
  }

  PreparedScene& ps = out->scene;
  ps.width = static_cast<std::uint16_t>(s.width);
  ps.height = static_cast<std::uint16_t>(s.height);
  for (int c = 0; c < 3; ++c) ps.ambient[c] = to_unorm8(s.ambient[c]);
  ps.textures = out->textures.data();
  ps.texture_count = static_cast<std::uint8_t>(out->textures.size());
  ps.objects = out->objects.data();
  ps.object_count = static_cast<std::uint16_t>(out->objects.size());
  ps.projectors = out->projectors.data();
  ps.projector_count = static_cast<std::uint8_t>(out->projectors.size());
  ps.max_vertex_count = max_vertices;
  out->matrices = FrameMatrices{out->clip_from_object.data(), out->projector_from_object.data(),
                                out->light_clip_from_object.data()};
  return out;
}

}  // namespace spanlight::prepare
