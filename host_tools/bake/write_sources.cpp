// Emits the baked C++: plain aggregate initialisers, one array per line of data.
#include <cstdio>
#include <sstream>

#include "bake/bake.hpp"
#include "io/knob_text.hpp"
#include "spanlight/scene_features.hpp"

namespace spanlight::bake {
namespace {

template <typename T>
void write_array(std::ostream& out, const char* type, const std::string& name, const T* data, std::size_t count) {
  out << "alignas(4) const " << type << " " << name << "[" << (count ? count : 1) << "] = {";
  for (std::size_t i = 0; i < count; ++i) {
    if (i % 16 == 0) out << "\n  ";
    out << static_cast<long long>(data[i]) << ",";
  }
  if (count == 0) out << "0";
  out << "\n};\n";
}

void write_matrix(std::ostream& out, const Mat4Block& m) {
  out << "{{";
  for (int i = 0; i < 16; ++i) out << m.m[i] << (i < 15 ? ", " : "");
  out << "}, " << m.frac_bits << "}";
}

const char* filter_name(Filter f) {
  return f == Filter::nearest ? "Filter::nearest" : (f == Filter::bilinear ? "Filter::bilinear" : "Filter::trilinear");
}
const char* wrap_name(Wrap w) {
  return w == Wrap::repeat ? "Wrap::repeat" : (w == Wrap::clamp ? "Wrap::clamp" : "Wrap::border");
}
const char* boolean(bool b) { return b ? "true" : "false"; }

void write_matrices(std::ostream& out, const char* name, const std::vector<Mat4Block>& mats) {
  out << "const Mat4Block " << name << "[" << (mats.empty() ? 1 : mats.size()) << "] = {";
  for (const Mat4Block& m : mats) {
    out << "\n  ";
    write_matrix(out, m);
    out << ",";
  }
  if (mats.empty()) out << "{}";
  out << "\n};\n";
}

// The scene's name as a C++ string literal. A name is any JSON string: a quote,
// a backslash or a newline written as is would end the literal or the comment
// and put the rest of the name into the firmware's source as code.
std::string cpp_string_literal(const std::string& text) {
  std::string literal = "\"";
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      literal += '\\';
      literal += c;
    } else if (byte < 0x20 || byte == 0x7f) {  // control characters, a newline among them
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\%03o", byte);
      literal += escaped;
    } else {
      literal += c;  // printable ASCII and UTF-8 bytes
    }
  }
  return literal + "\"";
}

}  // namespace

std::string baked_config_source(const prepare::PreparedStorage& prepared, const Knobs& knobs,
                                const std::string& scene_name, const prepare::PreparedAnimation* animation) {
  const PreparedScene& s = prepared.scene;
  const Features f = features_of(s, knobs);
  std::uint32_t shadow_texels = 0;
  for (int j = 0; j < s.projector_count; ++j)
    if (s.projectors[j].shadows) shadow_texels += std::uint32_t{s.projectors[j].map_size} * s.projectors[j].map_size;
  std::ostringstream out;
  out << "// Baked by `spanlight bake` from scene " << cpp_string_literal(scene_name) << ". Do not edit: bake again.\n"
      << "// Only what the scene uses is switched on, so the rest is never compiled.\n"
      << "#pragma once\n\n#include <cstdint>\n\n#include \"spanlight/render.hpp\"\n"
      << (animation ? "#include \"spanlight/scene_animation.hpp\"\n" : "") << "\n"
      << "namespace baked {\n\n"
      << "inline constexpr spanlight::Features features{.max_projectors = " << int(f.max_projectors)
      << ", .shadows = " << boolean(f.shadows) << ", .pcf = " << boolean(f.pcf) << ",\n    .nearest = " << boolean(f.nearest)
      << ", .bilinear = " << boolean(f.bilinear) << ", .clamped = " << boolean(f.clamped) << ", .tinted = " << boolean(f.tinted)
      << ", .trilinear = " << boolean(f.trilinear) << ", .falloff = " << boolean(f.falloff) << ", .facing = " << boolean(f.facing)
      << ", .closed_solids = " << boolean(f.closed_solids)
      << ",\n    .format = spanlight::PixelFormat::" << (knobs.format == PixelFormat::rgb888 ? "rgb888" : (knobs.format == PixelFormat::rgb565 ? "rgb565" : "rgb565_be"))
      << ", .fused = " << boolean(f.fused) << ", .multipass = " << boolean(f.multipass)
      << ",\n    .table_bits = " << int(f.table_bits) << ", .newton = " << int(f.newton) << ", .depth_bits = " << int(f.depth_bits)
      << ",\n    .repeat_sizes = {" << int(f.repeat_sizes[0]) << ", " << int(f.repeat_sizes[1]) << ", " << int(f.repeat_sizes[2])
      << ", " << int(f.repeat_sizes[3]) << "}, .any_repeat_size = " << boolean(f.any_repeat_size) << "};\n"
      << "// As `spanlight render` takes them: " << knob_command_line(knobs) << "\n"
      << "inline constexpr spanlight::Knobs knobs{.span_log2 = " << int(knobs.span_log2) << ", .tolerance_log2 = "
      << int(knobs.tolerance_log2) << ", .table_bits = " << int(knobs.table_bits) << ", .newton = " << int(knobs.newton)
      << ", .depth_bits = " << int(knobs.depth_bits) << ",\n    .format = features.format, .passes = spanlight::Passes::"
      << (knobs.passes == Passes::fused ? "fused" : "multipass") << ",\n    .mip = spanlight::MipRule::" << knob_value(knobs, "mip") << "};\n"
      << "using Depth = " << (knobs.depth_bits <= 16 ? "std::uint16_t" : "std::uint32_t") << ";\n\n"
      << "inline constexpr const char* scene_name = " << cpp_string_literal(scene_name) << ";\n"
      << "inline constexpr std::uint16_t width = " << s.width << ";\n"
      << "inline constexpr std::uint16_t height = " << s.height << ";\n"
      << "inline constexpr int projector_count = " << int(s.projector_count) << ";\n"
      << "inline constexpr int texture_count = " << int(s.texture_count) << ";  // TextureData entries of the scene\n"
      << "inline constexpr std::uint16_t max_vertex_count = " << s.max_vertex_count << ";  // the vertex buffer a frame needs\n"
      << "inline constexpr std::uint32_t shadow_map_texels = " << shadow_texels << ";  // all maps together\n"
      << "// map_size of each projector, 0 where it casts no shadow.\n"
      << "inline constexpr std::uint16_t shadow_map_size[" << (s.projector_count ? s.projector_count : 1) << "] = {";
  for (int j = 0; j < s.projector_count; ++j) out << (s.projectors[j].shadows ? s.projectors[j].map_size : 0) << ", ";
  if (s.projector_count == 0) out << "0";
  out << "};\n\nextern const spanlight::PreparedScene scene;\n"
      << "extern const spanlight::FrameMatrices matrices;  // the scene file's own pose\n";
  if (animation) out << baked_animation_config(*animation);
  out << "\n}  // namespace baked\n";
  return out.str();
}

std::string baked_scene_source(const prepare::PreparedStorage& prepared, const std::string& scene_name,
                               const prepare::PreparedAnimation* animation) {
  const PreparedScene& s = prepared.scene;
  std::ostringstream out;
  out << "// Baked by `spanlight bake` from scene " << cpp_string_literal(scene_name) << ". Do not edit: bake again.\n"
      << "#include \"baked_config.hpp\"\n\nnamespace baked {\nnamespace {\n\nusing namespace spanlight;\n\n";
  for (std::size_t t = 0; t < prepared.texture_storage.size(); ++t) {
    const prepare::PreparedTexture& storage = prepared.texture_storage[t];
    out << "// texture " << t << ": " << prepared.texture_names[t] << "\n";
    for (std::size_t l = 0; l < storage.framed.size(); ++l)
      write_array(out, "std::uint32_t", "texels_" + std::to_string(t) + "_" + std::to_string(l), storage.framed[l].data(),
                  storage.framed[l].size());
    out << "const TextureLevel levels_" << t << "[" << storage.levels.size() << "] = {\n";
    for (std::size_t l = 0; l < storage.levels.size(); ++l) {
      const TextureLevel& level = storage.levels[l];
      out << "  {texels_" << t << "_" << l << " + " << (level.texels - storage.framed[l].data()) << ", " << level.width
          << ", " << level.height << ", " << level.stride << "},\n";
    }
    out << "};\n";
  }
  out << "\nconst TextureData textures[" << (prepared.textures.empty() ? 1 : prepared.textures.size()) << "] = {\n";
  for (std::size_t t = 0; t < prepared.textures.size(); ++t) {
    const TextureData& d = prepared.textures[t];
    out << "  {levels_" << t << ", " << int(d.level_count) << ", " << filter_name(d.filter) << ", " << wrap_name(d.wrap) << "},\n";
  }
  if (prepared.textures.empty()) out << "  {nullptr, 0, Filter::nearest, Wrap::border},\n";
  out << "};\n\n";

  for (std::size_t o = 0; o < prepared.objects.size(); ++o) {
    const std::string n = std::to_string(o);
    out << "// object " << o << ": " << prepared.object_names[o] << "\n";
    write_array(out, "std::int32_t", "positions_" + n, prepared.positions[o].data(), prepared.positions[o].size());
    write_array(out, "std::int32_t", "uvs_" + n, prepared.uvs[o].data(), prepared.uvs[o].size());
    write_array(out, "std::uint16_t", "indices_" + n, prepared.indices[o].data(), prepared.indices[o].size());
  }
  out << "\nconst ObjectData objects[" << (prepared.objects.empty() ? 1 : prepared.objects.size()) << "] = {\n";
  for (std::size_t o = 0; o < prepared.objects.size(); ++o) {
    const ObjectData& d = prepared.objects[o];
    const std::string n = std::to_string(o);
    out << "  {positions_" << n << ", uvs_" << n << ", indices_" << n << ", " << d.vertex_count << ", " << d.triangle_count
        << ", {{" << d.bounds.min[0] << ", " << d.bounds.min[1] << ", " << d.bounds.min[2] << "}, {" << d.bounds.max[0]
        << ", " << d.bounds.max[1] << ", " << d.bounds.max[2] << "}}, " << d.texture << ", " << int(d.uv_frac_bits) << ", "
        << (d.cull == Cull::back ? "Cull::back" : "Cull::none") << ", {" << int(d.color[0]) << ", " << int(d.color[1])
        << ", " << int(d.color[2]) << "}, TexgenSpace::none, " << boolean(d.closed) << "},\n";
  }
  out << "};\n\nconst ProjectorData projectors[" << (s.projector_count ? s.projector_count : 1) << "] = {\n";
  for (int j = 0; j < s.projector_count; ++j) {
    const ProjectorData& p = s.projectors[j];
    out << "  {" << p.texture << ", " << p.falloff << ", {" << p.color[0] << ", " << p.color[1] << ", " << p.color[2]
        << "}, " << boolean(p.facing_only) << ", " << boolean(p.shadows) << ", "
        << (p.filter == ShadowFilter::pcf2x2 ? "ShadowFilter::pcf2x2" : "ShadowFilter::nearest") << ", " << p.map_size
        << ", " << p.bias << "},\n";
  }
  if (s.projector_count == 0) out << "  {},\n";
  out << "};\n\n";
  write_matrices(out, "clip_from_object", prepared.clip_from_object);
  write_matrices(out, "projector_from_object", prepared.projector_from_object);
  write_matrices(out, "light_clip_from_object", prepared.light_clip_from_object);
  out << "\n}  // namespace\n\n"
      << "const PreparedScene scene{" << s.width << ", " << s.height << ", {" << int(s.ambient[0]) << ", "
      << int(s.ambient[1]) << ", " << int(s.ambient[2]) << "}, textures, " << int(s.texture_count) << ", objects, "
      << s.object_count << ", projectors, " << int(s.projector_count) << ", " << s.max_vertex_count << "};\n\n"
      << "const FrameMatrices matrices{clip_from_object, projector_from_object, light_clip_from_object};\n";
  if (animation) out << baked_animation_source(*animation);
  out << "\n}  // namespace baked\n";
  return out.str();
}

void write_baked_scene(const prepare::PreparedStorage& prepared, const Knobs& knobs, const std::string& scene_name,
                       io::OutputFolder& out, const prepare::PreparedAnimation* animation) {
  out.write(baked_config_file, baked_config_source(prepared, knobs, scene_name, animation));
  out.write(baked_scene_file, baked_scene_source(prepared, scene_name, animation));
}

}  // namespace spanlight::bake
