#include "sweep/memory_cost.hpp"

#include <array>
#include <cstdio>
#include <regex>
#include <sstream>

#include "spanlight/1_vertex/project.hpp"
#include "spanlight/render.hpp"

namespace spanlight::sweep {
namespace {

// The fields of a demangled Features literal ("spanlight::Features{(unsigned char)4, true, ...}")
// come in the struct's order, trailing zero fields left out: symbol names are all a linked image
// tells of which instantiation a function belongs to. table_bits and newton follow the pixel
// format and the two pass flags (features.hpp), so they are found from the format's field;
// sweep_units_test reads names the compiler itself makes, so a reordered Features fails there.
constexpr std::size_t table_bits_after_format = 3, newton_after_format = 4;

int field_value(const std::string& text) {
  const std::size_t close = text.rfind(')');
  return std::stoi(close == std::string::npos ? text : text.substr(close + 1));
}

}  // namespace

std::size_t table_bytes(int table_bits) {
  const std::size_t span_table = std::size_t{2} << table_bits;
  const std::size_t vertex_table = std::size_t{2} << vertex_divide_table_bits;
  return table_bits == vertex_divide_table_bits ? vertex_table : span_table + vertex_table;
}

std::size_t buffer_bytes(const PreparedScene& s, const Knobs& knobs) {
  const std::size_t pixels = std::size_t{s.width} * s.height;
  const std::size_t depth_size = knobs.depth_bits <= 16 ? 2 : 4;
  const std::size_t colour_size = knobs.format == PixelFormat::rgb888 ? 3 : 2;
  std::size_t bytes = pixels * (colour_size + depth_size) + std::size_t{s.max_vertex_count} * sizeof(CachedVertex);
  for (int j = 0; j < s.projector_count; ++j)
    if (s.projectors[j].shadows) bytes += std::size_t{s.projectors[j].map_size} * s.projectors[j].map_size * depth_size;
  if (knobs.passes == Passes::multipass) bytes += tie_mask_bytes(static_cast<std::uint32_t>(pixels));
  return bytes;
}

std::string classify_symbol(const std::string& name, int& table_bits, int& newton) {
  static const std::regex features(R"(spanlight::Features\{([^}]*))");
  static const std::regex table(R"(^fixedpoint::reciprocal_table<(\d+)>$)");
  std::smatch m;
  // The HAL, the scene's data, and the bench's own code (its driver and its per-pass hooks
  // live in an anonymous namespace; the pipeline's headers have none).
  if (name.find("spanlight::hal") != std::string::npos || name.find("baked::") != std::string::npos ||
      name.find("(anonymous namespace)") != std::string::npos || name.find("bench::") != std::string::npos)
    return "";
  if (std::regex_search(name, m, features)) {
    std::vector<std::string> fields;
    std::stringstream list(m[1].str());
    for (std::string f; std::getline(list, f, ',');) fields.push_back(f);
    std::size_t format = 0;
    while (format < fields.size() && fields[format].find("PixelFormat)") == std::string::npos) ++format;
    const std::size_t table_bits_field = format + table_bits_after_format, newton_field = format + newton_after_format;
    if (format < fields.size() && fields.size() > table_bits_field) {  // trailing zero fields are left out
      table_bits = field_value(fields[table_bits_field]);
      newton = fields.size() > newton_field ? field_value(fields[newton_field]) : 0;
      return "instantiation";
    }
  }
  if (std::regex_search(name, m, table)) {
    table_bits = std::stoi(m[1]);
    return "table";
  }
  if (name.find("spanlight::") != std::string::npos || name.find("fixedpoint::") != std::string::npos) return "shared";
  static const std::regex helper(R"(^__(aeabi_(l|ul|ui|i)[a-z]*|u?divmoddi4|u?divdi3|u?moddi3|(ash|lsh)[lr]di3|muldi3|clz[sd]i2|ctzdi2))");
  if (std::regex_search(name, helper)) return "shared";
  return "";
}

std::optional<std::size_t> PipelineFlash::for_knobs(const Knobs& knobs) const {
  const auto it = instantiation.find({knobs.table_bits, knobs.newton});
  if (it == instantiation.end()) return std::nullopt;
  // The span table, and the vertex divide's table unless it is the same one.
  auto table_size = [&](int bits) {
    const auto t = table.find(bits);
    return t == table.end() ? std::size_t{0} : t->second;
  };
  const std::size_t tables = table_size(knobs.table_bits) +
                             (knobs.table_bits == vertex_divide_table_bits ? 0 : table_size(vertex_divide_table_bits));
  return shared + it->second + tables;
}

std::optional<PipelineFlash> pipeline_flash(const std::filesystem::path& elf, const std::string& nm) {
  std::error_code ec;
  if (!std::filesystem::exists(elf, ec)) return std::nullopt;
  const std::string command = nm + " -C -S '" + elf.string() + "' 2>/dev/null";
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return std::nullopt;
  PipelineFlash flash;
  std::array<char, 16384> buffer{};
  bool any = false;
  while (std::fgets(buffer.data(), static_cast<int>(buffer.size()), pipe) != nullptr) {
    // "address size type name...": only symbols with a size, in flash (code or read-only data).
    std::istringstream line(buffer.data());
    std::string address, size_hex, type, name;
    if (!(line >> address >> size_hex >> type)) continue;
    std::getline(line, name);
    if (name.empty() || type.size() != 1 || std::string("tTwWrRvV").find(type[0]) == std::string::npos) continue;
    name.erase(0, name.find_first_not_of(' '));
    while (!name.empty() && (name.back() == '\n' || name.back() == '\r')) name.pop_back();
    std::size_t size = 0;
    try {
      size = std::stoul(size_hex, nullptr, 16);
    } catch (const std::exception&) {
      continue;
    }
    any = true;
    int table_bits = 0, newton = 0;
    const std::string kind = classify_symbol(name, table_bits, newton);
    if (kind == "shared") flash.shared += size;
    else if (kind == "instantiation") flash.instantiation[{table_bits, newton}] += size;
    else if (kind == "table") flash.table[table_bits] += size;
  }
  const int status = pclose(pipe);
  if (status != 0 || !any) return std::nullopt;
  return flash;
}

}  // namespace spanlight::sweep
