// Emits the baked C++: plain aggregate initialisers, one array per line of data.
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "bake/bake.hpp"

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

const char* filter_name(Filter f) { return f == Filter::nearest ? "Filter::nearest" : "Filter::bilinear"; }
const char* wrap_name(Wrap w) {
  return w == Wrap::repeat ? "Wrap::repeat" : (w == Wrap::clamp ? "Wrap::clamp" : "Wrap::border");
}

void write_atomically(const std::filesystem::path& file, const std::string& text) {
  const std::filesystem::path temp = file.string() + ".partial";
  {
    std::ofstream out(temp, std::ios::binary);
    out << text;
    if (!out.flush()) {
      std::error_code ignored;
      std::filesystem::remove(temp, ignored);
      throw std::runtime_error(file.string() + ": cannot write");
    }
  }
  std::filesystem::rename(temp, file);
}

}  // namespace

std::string baked_config_source(const prepare::PreparedStorage& prepared, const prepare::FixedOptions& options,
                                const std::string& scene_name) {
  const PreparedScene& s = prepared.scene;
  const SceneFeatures f = features_of(s);
  const bool rgb565 = options.format == PixelFormat::rgb565;
  std::ostringstream out;
  out << "// Baked by `spanlight bake` from scene \"" << scene_name << "\". Do not edit: bake again.\n"
      << "// Only what the scene uses is switched on, so the rest is never compiled.\n"
      << "#pragma once\n\n#include <cstdint>\n\n#include \"spanlight/render.hpp\"\n\n"
      << "namespace baked {\n\n"
      << "using Features = spanlight::Features<" << f.projectors << ", " << (f.shadows ? "true" : "false") << ", "
      << (f.pcf ? "true" : "false") << ", " << (f.bilinear ? "true" : "false") << ", spanlight::PixelFormat::"
      << (rgb565 ? "rgb565" : "rgb888") << ",\n    spanlight::TableReciprocal<" << options.table_bits << ", "
      << options.newton_steps << ">>;\n"
      << "using Depth = " << (options.precision.depth_bits <= 16 ? "std::uint16_t" : "std::uint32_t") << ";\n\n"
      << "inline constexpr const char* scene_name = \"" << scene_name << "\";\n"
      << "inline constexpr std::uint16_t width = " << s.width << ";\n"
      << "inline constexpr std::uint16_t height = " << s.height << ";\n"
      << "inline constexpr int projector_count = " << f.projectors << ";\n"
      << "inline constexpr std::uint32_t shadow_map_texels = " << f.shadow_map_texels << ";  // all maps together\n"
      << "inline constexpr spanlight::Precision precision{" << int(options.precision.span_log2) << ", "
      << int(options.precision.span_tolerance_log2) << ", " << int(options.precision.depth_bits) << ", "
      << (options.precision.fused ? "true" : "false") << "};\n"
      << "// map_size of each projector, 0 where it casts no shadow.\n"
      << "inline constexpr std::uint16_t shadow_map_size[" << (f.projectors ? f.projectors : 1) << "] = {";
  for (int j = 0; j < s.projector_count; ++j) out << (s.projectors[j].shadows ? s.projectors[j].map_size : 0) << ", ";
  if (s.projector_count == 0) out << "0";
  out << "};\n\nextern const spanlight::PreparedScene scene;\n\n}  // namespace baked\n";
  return out.str();
}

std::string baked_scene_source(const prepare::PreparedStorage& prepared, const std::string& scene_name) {
  const PreparedScene& s = prepared.scene;
  std::ostringstream out;
  out << "// Baked by `spanlight bake` from scene \"" << scene_name << "\". Do not edit: bake again.\n"
      << "#include \"baked_config.hpp\"\n\nnamespace baked {\nnamespace {\n\nusing namespace spanlight;\n\n";
  for (std::size_t t = 0; t < prepared.texels.size(); ++t)
    write_array(out, "std::uint8_t", "texels_" + std::to_string(t), prepared.texels[t].data(), prepared.texels[t].size());
  out << "\nconst TextureData textures[" << (s.projector_count + s.object_count > 0 && !prepared.textures.empty() ? prepared.textures.size() : 1) << "] = {\n";
  for (std::size_t t = 0; t < prepared.textures.size(); ++t) {
    const TextureData& d = prepared.textures[t];
    out << "  {texels_" << t << ", " << d.width << ", " << d.height << ", " << filter_name(d.filter) << ", "
        << wrap_name(d.wrap) << "},\n";
  }
  if (prepared.textures.empty()) out << "  {nullptr, 0, 0, Filter::nearest, Wrap::border},\n";
  out << "};\n\n";

  for (std::size_t o = 0; o < prepared.objects.size(); ++o) {
    const std::string n = std::to_string(o);
    out << "// object " << o << ": " << prepared.object_names[o] << "\n";
    write_array(out, "std::int32_t", "positions_" + n, prepared.positions[o].data(), prepared.positions[o].size());
    write_array(out, "std::int32_t", "uvs_" + n, prepared.uvs[o].data(), prepared.uvs[o].size());
    write_array(out, "std::uint16_t", "indices_" + n, prepared.indices[o].data(), prepared.indices[o].size());
    for (const char* kind : {"projector_from_object_", "light_clip_from_object_"}) {
      const auto& mats = std::string(kind) == "projector_from_object_" ? prepared.projector_from_object[o]
                                                                         : prepared.light_clip_from_object[o];
      out << "const Mat4Block " << kind << n << "[" << (mats.empty() ? 1 : mats.size()) << "] = {";
      for (const Mat4Block& m : mats) {
        out << "\n  ";
        write_matrix(out, m);
        out << ",";
      }
      if (mats.empty()) out << "{}";
      out << "\n};\n";
    }
  }
  out << "\nconst ObjectData objects[" << (prepared.objects.empty() ? 1 : prepared.objects.size()) << "] = {\n";
  for (std::size_t o = 0; o < prepared.objects.size(); ++o) {
    const ObjectData& d = prepared.objects[o];
    const std::string n = std::to_string(o);
    out << "  {positions_" << n << ", uvs_" << n << ", indices_" << n << ", " << d.triangle_count << ", " << d.texture
        << ", " << int(d.uv_frac_bits) << ", " << (d.cull == Cull::back ? "Cull::back" : "Cull::none") << ", {"
        << int(d.color[0]) << ", " << int(d.color[1]) << ", " << int(d.color[2]) << "}, ";
    write_matrix(out, d.clip_from_object);
    out << ", projector_from_object_" << n << ", light_clip_from_object_" << n << "},\n";
  }
  out << "};\n\nconst ProjectorData projectors[" << (s.projector_count ? s.projector_count : 1) << "] = {\n";
  for (int j = 0; j < s.projector_count; ++j) {
    const ProjectorData& p = s.projectors[j];
    out << "  {" << p.texture << ", {" << p.color[0] << ", " << p.color[1] << ", " << p.color[2] << "}, "
        << (p.shadows ? "true" : "false") << ", "
        << (p.filter == ShadowFilter::pcf2x2 ? "ShadowFilter::pcf2x2" : "ShadowFilter::nearest") << ", " << p.map_size
        << ", " << p.bias << "},\n";
  }
  if (s.projector_count == 0) out << "  {},\n";
  out << "};\n\n}  // namespace\n\n"
      << "const PreparedScene scene{" << s.width << ", " << s.height << ", {" << int(s.ambient[0]) << ", "
      << int(s.ambient[1]) << ", " << int(s.ambient[2]) << "}, textures, objects, " << s.object_count
      << ", projectors, " << int(s.projector_count) << "};\n\n}  // namespace baked\n";
  return out.str();
}

void write_baked_scene(const prepare::PreparedStorage& prepared, const prepare::FixedOptions& options,
                       const std::string& scene_name, const std::filesystem::path& out_dir) {
  std::error_code error;
  std::filesystem::create_directories(out_dir, error);
  if (error) throw std::runtime_error(out_dir.string() + ": cannot create: " + error.message());
  write_atomically(out_dir / "baked_config.hpp", baked_config_source(prepared, options, scene_name));
  write_atomically(out_dir / "baked_scene.cpp", baked_scene_source(prepared, scene_name));
}

}  // namespace spanlight::bake
