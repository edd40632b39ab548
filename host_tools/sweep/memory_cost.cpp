#include "sweep/memory_cost.hpp"

#include <array>
#include <cstdio>
#include <regex>
#include <sstream>

#include "spanlight/buffers.hpp"
#include "spanlight/project.hpp"

namespace spanlight::sweep {
namespace {

// project.hpp's VertexDivider has its own table, whose size is not exposed:
// find it by comparing its results with each candidate table (with two Newton
// steps the candidates agree to ~2^-29 but not bit for bit on every input).
template <int B>
constexpr bool vertex_divider_uses() {
  for (std::uint32_t i = 1; i < 200; ++i) {
    const std::int64_t w = std::int64_t{i} * 2654435761 % 4000000000 + 16;
    const VertexDivider d(w);
    if (d.rcp.mantissa != fixedpoint::reciprocal<B, 2>(static_cast<std::uint32_t>(w >> d.k)).mantissa) return false;
  }
  return true;
}
constexpr int vertex_table_bits = vertex_divider_uses<6>()    ? 6
                                  : vertex_divider_uses<8>()  ? 8
                                  : vertex_divider_uses<10>() ? 10
                                  : vertex_divider_uses<12>() ? 12
                                                              : 0;
static_assert(vertex_table_bits != 0, "project.hpp's vertex divide no longer uses reciprocal<B, 2>: update table_bytes");

}  // namespace

int vertex_table_bits_in_use() { return vertex_table_bits; }

std::size_t table_bytes(int table_bits) {
  const std::size_t span_table = std::size_t{2} << table_bits;
  const std::size_t vertex_table = std::size_t{2} << vertex_table_bits;
  return table_bits == vertex_table_bits ? vertex_table : span_table + vertex_table;
}

std::size_t buffer_bytes(const PreparedScene& s, PixelFormat format, const SweepConfig& c) {
  const std::size_t pixels = std::size_t{s.width} * s.height;
  const std::size_t depth_size = c.depth_bits <= 16 ? 2 : 4;
  std::size_t bytes = pixels * (format == PixelFormat::rgb565 ? 2 : 3) + pixels * depth_size;
  for (int j = 0; j < s.projector_count; ++j)
    if (s.projectors[j].shadows) bytes += std::size_t{s.projectors[j].map_size} * s.projectors[j].map_size * depth_size;
  if (!c.fused) bytes += tie_mask_bytes(s.width, s.height);
  return bytes;
}

std::string classify_symbol(const std::string& name, int& table_bits, int& newton) {
  static const std::regex reciprocal(R"(TableReciprocal<(\d+), (\d+)>)");
  static const std::regex measured(R"(bench::render_measured<(\d+), (\d+)>)");
  static const std::regex table(R"(^fixedpoint::reciprocal_table<(\d+)>$)");
  std::smatch m;
  if (name.find("render_by_pass") != std::string::npos) return "";  // the bench's own per-pass driver
  if (std::regex_search(name, m, measured) || std::regex_search(name, m, reciprocal)) {
    table_bits = std::stoi(m[1]);
    newton = std::stoi(m[2]);
    return "instantiation";
  }
  if (std::regex_search(name, m, table)) {
    table_bits = std::stoi(m[1]);
    return "table";
  }
  if (name.find("spanlight::hal") != std::string::npos || name.find("baked::") != std::string::npos ||
      name.find("bench::") != std::string::npos)
    return "";
  if (name.find("spanlight::") != std::string::npos || name.find("fixedpoint::") != std::string::npos) return "shared";
  static const std::regex helper(R"(^__(aeabi_(l|ul|ui|i)[a-z]*|u?divmoddi4|u?divdi3|u?moddi3|(ash|lsh)[lr]di3|muldi3|clz[sd]i2|ctzdi2))");
  if (std::regex_search(name, helper)) return "shared";
  return "";
}

std::optional<std::size_t> PipelineFlash::for_config(int table_bits, int n) const {
  const auto it = instantiation.find({table_bits, n});
  if (it == instantiation.end()) return std::nullopt;
  // The span table, and the vertex divide's table unless it is the same one.
  auto table_size = [&](int bits) {
    const auto t = table.find(bits);
    return t == table.end() ? std::size_t{0} : t->second;
  };
  const std::size_t tables = table_size(table_bits) + (table_bits == vertex_table_bits ? 0 : table_size(vertex_table_bits));
  return shared + it->second + tables;
}

std::optional<PipelineFlash> pipeline_flash(const std::filesystem::path& elf, const std::string& nm) {
  std::error_code ec;
  if (!std::filesystem::exists(elf, ec)) return std::nullopt;
  const std::string command = nm + " -C -S '" + elf.string() + "' 2>/dev/null";
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return std::nullopt;
  PipelineFlash flash;
  std::array<char, 8192> buffer{};
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
