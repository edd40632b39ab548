#include "analyze/knob_config.hpp"

#include <stdexcept>

#include <nlohmann/json.hpp>

#include "io/read_file.hpp"

namespace spanlight::analyze {

using nlohmann::json;

std::string to_json(const sweep::GridPoint& point, const std::string& measured_json) {
  json j;
  j["spanlight_knobs"] = knob_config_version;
  for (const KnobInfo& info : knob_table) {
    const std::string value = knob_value(point.knobs, info.name);
    if (value.find_first_not_of("0123456789") == std::string::npos) j[info.name] = std::stoi(value);
    else j[info.name] = value;
  }
  j["texture_filter"] = sweep::to_string(point.filter);
  j["measured"] = json::parse(measured_json);
  return j.dump(2) + "\n";
}

sweep::GridPoint read_knob_config(const std::filesystem::path& path) {
  const std::string file = path.string();
  const std::string text = io::read_regular_file(path, "knob config", io::mebibyte);  // a dozen fields
  json j;
  try {
    j = json::parse(text);
  } catch (const json::parse_error& e) {
    throw std::runtime_error(file + ": not JSON: " + e.what());
  }
  if (!j.is_object() || !j.contains("spanlight_knobs") || j["spanlight_knobs"] != knob_config_version)
    throw std::runtime_error(file + ": spanlight_knobs: expected " + std::to_string(knob_config_version) +
                             " (a file written by `spanlight analyze --write-config`)");
  sweep::GridPoint point;
  for (const KnobInfo& info : knob_table) {
    const auto it = j.find(info.name);
    const std::string expected = file + ": " + info.name + ": expected one of " + sweep::choice_list(info.name);
    if (it == j.end()) throw std::runtime_error(expected + " (missing)");
    std::string value;
    if (it->is_number_unsigned()) value = std::to_string(it->get<unsigned>());
    else if (it->is_string()) value = it->get<std::string>();
    else throw std::runtime_error(expected);
    if (set_knob(point.knobs, info.name, value) != KnobError::ok) throw std::runtime_error(expected + ", not \"" + value + "\"");
  }
  const std::string filter_expected = file + ": texture_filter: expected one of " + sweep::filter_choice_list();
  const auto filter = j.find("texture_filter");
  if (filter == j.end() || !filter->is_string()) throw std::runtime_error(filter_expected);
  if (!parse_filter_choice(filter->get<std::string>(), point.filter)) throw std::runtime_error(filter_expected);
  return point;
}

}  // namespace spanlight::analyze
