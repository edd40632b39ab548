#include "analyze/knob_config.hpp"

#include <set>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "io/read_file.hpp"

namespace spanlight::analyze {
namespace {

using nlohmann::json;

int integer_in(const json& j, const std::string& file, const char* key, std::set<int> allowed) {
  const auto it = j.find(key);
  if (it == j.end()) throw std::runtime_error(file + ": " + key + ": missing");
  if (!it->is_number_integer() || !allowed.count(it->get<int>())) {
    std::string list;
    for (int v : allowed) list += (list.empty() ? "" : ", ") + std::to_string(v);
    throw std::runtime_error(file + ": " + key + ": expected one of " + list);
  }
  return it->get<int>();
}

std::string text_in(const json& j, const std::string& file, const char* key, std::set<std::string> allowed) {
  const auto it = j.find(key);
  if (it == j.end()) throw std::runtime_error(file + ": " + key + ": missing");
  if (!it->is_string() || !allowed.count(it->get<std::string>())) {
    std::string list;
    for (const std::string& v : allowed) list += (list.empty() ? "" : ", ") + v;
    throw std::runtime_error(file + ": " + key + ": expected one of " + list);
  }
  return it->get<std::string>();
}

}  // namespace

std::string to_json(const KnobConfig& c, const std::string& measured_json) {
  json j;
  j["spanlight_knobs"] = 1;
  j["span"] = c.knobs.span;
  j["tolerance"] = c.knobs.tolerance_log2;
  j["table_bits"] = c.knobs.table_bits;
  j["newton"] = c.knobs.newton;
  j["depth_bits"] = c.knobs.depth_bits;
  j["format"] = c.format == PixelFormat::rgb565 ? "rgb565" : "rgb888";
  j["fused"] = c.knobs.fused;
  j["texture_filter"] = sweep::to_string(c.knobs.filter);
  j["measured"] = json::parse(measured_json);
  return j.dump(2) + "\n";
}

KnobConfig read_knob_config(const std::filesystem::path& path) {
  const std::string file = path.string();
  const std::string text = io::read_regular_file(path, "knob config", io::mebibyte);  // a dozen fields
  json j;
  try {
    j = json::parse(text);
  } catch (const json::parse_error& e) {
    throw std::runtime_error(file + ": not JSON: " + e.what());
  }
  if (!j.is_object() || j.value("spanlight_knobs", 0) != 1)
    throw std::runtime_error(file + ": spanlight_knobs: expected 1 (a file written by `spanlight analyze --write-config`)");
  KnobConfig c;
  c.knobs.span = integer_in(j, file, "span", {1, 2, 4, 8, 16, 32, 64});
  c.knobs.tolerance_log2 = integer_in(j, file, "tolerance", {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10});
  c.knobs.table_bits = integer_in(j, file, "table_bits", {6, 8, 10, 12});
  c.knobs.newton = integer_in(j, file, "newton", {0, 1, 2});
  c.knobs.depth_bits = integer_in(j, file, "depth_bits", {16, 24});
  c.format = text_in(j, file, "format", {"rgb888", "rgb565"}) == "rgb565" ? PixelFormat::rgb565 : PixelFormat::rgb888;
  const auto fused = j.find("fused");
  if (fused == j.end() || !fused->is_boolean()) throw std::runtime_error(file + ": fused: expected true or false");
  c.knobs.fused = fused->get<bool>();
  c.knobs.filter = sweep::filter_from_string(text_in(j, file, "texture_filter", {"scene", "nearest", "bilinear"}));
  return c;
}

}  // namespace spanlight::analyze
