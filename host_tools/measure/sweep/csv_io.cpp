#include "sweep/csv_io.hpp"

#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <stdexcept>

#include "io/read_file.hpp"

namespace spanlight::sweep {
namespace {

std::string num(double v, int decimals) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, v);
  return buffer;
}

template <typename T>
std::string opt(const std::optional<T>& v) {
  return v ? std::to_string(*v) : "n/a";
}

std::string per_pixel(const std::optional<std::uint64_t>& instructions, std::size_t covered) {
  return instructions && covered ? num(static_cast<double>(*instructions) / static_cast<double>(covered), 1) : "n/a";
}

std::string no_commas(std::string text) {
  for (char& c : text)
    if (c == ',' || c == '\n') c = ';';
  return text;
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream in(line);
  std::string field;
  while (std::getline(in, field, ',')) fields.push_back(field);
  if (!line.empty() && line.back() == ',') fields.emplace_back();
  return fields;
}

double to_double(const std::string& text) {
  if (text == "inf") return INFINITY;
  return std::stod(text);
}

template <typename T>
std::optional<T> to_optional(const std::string& text) {
  if (text == "n/a") return std::nullopt;
  return static_cast<T>(std::stoull(text));
}

// The knobs' columns: each knob of knob_table by its name, but the format, which is the sweep's own column.
std::vector<std::string> knob_columns() {
  std::vector<std::string> names;
  for (const KnobInfo& info : knob_table)
    if (std::string_view(info.name) != "format") names.emplace_back(info.name);
  return names;
}

}  // namespace

std::vector<std::string> csv_columns() {
  std::vector<std::string> columns{"scene", "format", "covered_pixels", "label"};
  for (const std::string& knob : knob_columns()) columns.push_back(knob);
  columns.insert(columns.end(), {"filter", "psnr_db", "rms_lsb", "max_lsb", "mean_lsb", "pct_over_2_lsb", "pct_over_8_lsb",
          "psnr_vs_scene_db", "rms_vs_scene_lsb", "max_vs_scene_lsb", "uv_err_max_texels", "uv_err_mean_texels", "st_err_max_texels", "st_err_mean_texels",
          "texcoord_err_max_texels", "visibility_mismatches", "host_ms", "float_ms", "host_ratio",
          "m7_instructions", "m7_per_covered_pixel", "m7_source", "m0plus_instructions", "m0plus_per_covered_pixel",
          "m0plus_source", "hash_checked", "table_bytes", "buffer_bytes", "flash_m7", "flash_m0plus", "is_default",
          "front_m7", "front_m0plus", "front_host"});
  return columns;
}

std::string to_csv(const SweepResult& r) {
  std::ostringstream out;
  const std::vector<std::string> columns = csv_columns();
  for (std::size_t i = 0; i < columns.size(); ++i) out << (i ? "," : "") << columns[i];
  out << "\n";
  for (const SweepRow& row : r.rows) {
    const GridPoint& c = row.point;
    out << no_commas(r.scene_name) << "," << r.format << "," << r.covered_pixels << "," << label(c) << ",";
    for (const std::string& knob : knob_columns()) out << knob_value(c.knobs, knob) << ",";
    out << to_string(c.filter) << "," << num(row.psnr_db, 3) << "," << num(row.rms_lsb, 4) << ","
        << num(row.max_lsb, 0) << "," << num(row.mean_lsb, 4) << "," << num(row.pct_over_2, 4) << ","
        << num(row.pct_over_8, 4) << "," << num(row.psnr_vs_scene_db, 3) << "," << num(row.rms_vs_scene_lsb, 4) << ","
        << num(row.max_vs_scene_lsb, 0) << "," << num(row.uv_err_max, 5) << "," << num(row.uv_err_mean, 5) << ","
        << num(row.st_err_max, 5) << "," << num(row.st_err_mean, 5) << "," << num(row.texcoord_err_max(), 5) << ","
        << row.visibility_mismatches << "," << num(row.host_ms, 3) << "," << num(row.float_ms, 3) << ","
        << num(row.host_ratio(), 4) << "," << opt(row.m7.instructions) << "," << per_pixel(row.m7.instructions, r.covered_pixels)
        << "," << no_commas(row.m7.source) << "," << opt(row.m0plus.instructions) << ","
        << per_pixel(row.m0plus.instructions, r.covered_pixels) << "," << no_commas(row.m0plus.source) << ","
        << (row.hash_checked ? 1 : 0) << "," << row.table_bytes << "," << row.buffer_bytes << "," << opt(row.flash_m7)
        << "," << opt(row.flash_m0plus) << "," << (row.is_default ? 1 : 0) << "," << (row.front_m7 ? 1 : 0) << ","
        << (row.front_m0plus ? 1 : 0) << "," << (row.front_host ? 1 : 0) << "\n";
  }
  return out.str();
}

SweepResult read_csv(const std::filesystem::path& file) {
  std::istringstream in(io::read_regular_file(file, "sweep CSV", 16 * io::mebibyte));  // ~300 KB for the default grid
  std::string line;
  if (!std::getline(in, line) || split(line) != csv_columns())
    throw std::runtime_error(file.string() + ": line 1: not a `spanlight sweep` CSV (the header differs)");
  const std::vector<std::string> columns = csv_columns();
  SweepResult r;
  int line_number = 1;
  while (std::getline(in, line)) {
    ++line_number;
    if (line.empty()) continue;
    const std::vector<std::string> fields = split(line);
    if (fields.size() != columns.size())
      throw std::runtime_error(file.string() + ": line " + std::to_string(line_number) + ": " +
                               std::to_string(fields.size()) + " fields, expected " + std::to_string(columns.size()));
    std::map<std::string, std::string> f;
    for (std::size_t i = 0; i < columns.size(); ++i) f[columns[i]] = fields[i];
    try {
      r.scene_name = f["scene"];
      r.format = f["format"];
      r.covered_pixels = std::stoull(f["covered_pixels"]);
      SweepRow row;
      GridPoint& c = row.point;
      for (const std::string& knob : knob_columns()) {
        if (set_knob(c.knobs, knob, f[knob]) != KnobError::ok)
          throw std::invalid_argument(knob + ": expected one of " + choice_list(knob) + ", not \"" + f[knob] + "\"");
      }
      if (set_knob(c.knobs, "format", f["format"]) != KnobError::ok)
        throw std::invalid_argument("format: expected one of " + choice_list("format") + ", not \"" + f["format"] + "\"");
      c.filter = filter_from_string(f["filter"]);
      row.psnr_db = to_double(f["psnr_db"]);
      row.rms_lsb = to_double(f["rms_lsb"]);
      row.max_lsb = to_double(f["max_lsb"]);
      row.mean_lsb = to_double(f["mean_lsb"]);
      row.pct_over_2 = to_double(f["pct_over_2_lsb"]);
      row.pct_over_8 = to_double(f["pct_over_8_lsb"]);
      row.psnr_vs_scene_db = to_double(f["psnr_vs_scene_db"]);
      row.rms_vs_scene_lsb = to_double(f["rms_vs_scene_lsb"]);
      row.max_vs_scene_lsb = to_double(f["max_vs_scene_lsb"]);
      row.uv_err_max = to_double(f["uv_err_max_texels"]);
      row.uv_err_mean = to_double(f["uv_err_mean_texels"]);
      row.st_err_max = to_double(f["st_err_max_texels"]);
      row.st_err_mean = to_double(f["st_err_mean_texels"]);
      row.visibility_mismatches = std::stoull(f["visibility_mismatches"]);
      row.host_ms = to_double(f["host_ms"]);
      row.float_ms = to_double(f["float_ms"]);
      row.m7 = {to_optional<std::uint64_t>(f["m7_instructions"]), f["m7_source"]};
      row.m0plus = {to_optional<std::uint64_t>(f["m0plus_instructions"]), f["m0plus_source"]};
      row.hash_checked = f["hash_checked"] == "1";
      row.table_bytes = std::stoull(f["table_bytes"]);
      row.buffer_bytes = std::stoull(f["buffer_bytes"]);
      row.flash_m7 = to_optional<std::size_t>(f["flash_m7"]);
      row.flash_m0plus = to_optional<std::size_t>(f["flash_m0plus"]);
      row.is_default = f["is_default"] == "1";
      row.front_m7 = f["front_m7"] == "1";
      row.front_m0plus = f["front_m0plus"] == "1";
      row.front_host = f["front_host"] == "1";
      r.rows.push_back(row);
    } catch (const std::exception& e) {
      throw std::runtime_error(file.string() + ": line " + std::to_string(line_number) + ": " + e.what());
    }
  }
  return r;
}

}  // namespace spanlight::sweep
