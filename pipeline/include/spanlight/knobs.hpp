// The knobs: every speed-against-accuracy setting of the pipeline, with its
// allowed values, its default and its parser, in one place. The CLI (render,
// bake, sweep, analyze, cost), the firmware bench and the baked configuration
// all read and write this one type. Freestanding: the firmware parses its
// command line with it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <string_view>

namespace spanlight {

enum class PixelFormat : std::uint8_t { rgb888, rgb565, rgb565_be };  // rgb565_be: bytes swapped, as SPI panels take it
enum class Passes : std::uint8_t { fused, multipass };                 // multipass: the paper's passes, the same bytes
// How a trilinear texture picks its levels: the spec's two levels mixed per pixel, or one
// level per span segment (lambda at the segment's middle pixel, rounded) read bilinear.
enum class MipRule : std::uint8_t { trilinear, segment };

struct Knobs {
  std::uint8_t span_log2 = 6;       // segments of at most 2^span_log2 pixels between exact divides
  std::uint8_t tolerance_log2 = 5;  // linear stepping may drift at most 2^-N texel from the exact value; 0: never shorten
  std::uint8_t table_bits = 8;      // the reciprocal's table: 2^table_bits entries
  std::uint8_t newton = 1;          // Newton-Raphson steps after the table
  std::uint8_t depth_bits = 24;     // depth buffer and shadow maps: 16 or 24 bits
  PixelFormat format = PixelFormat::rgb888;
  Passes passes = Passes::fused;
  MipRule mip = MipRule::trilinear;

  friend constexpr bool operator==(const Knobs&, const Knobs&) = default;
};

// One knob as the command lines name it: `--name value`.
struct KnobInfo {
  const char* name;
  const char* help;
  const char* const* values;  // the allowed values, as typed
  std::uint8_t value_count;
};

namespace knob_values {
inline constexpr const char* span[] = {"1", "2", "4", "8", "16", "32", "64"};
inline constexpr const char* tolerance[] = {"0", "1", "2", "3", "4", "5", "6", "7", "8", "9", "10"};
inline constexpr const char* table_bits[] = {"6", "8", "10", "12"};
inline constexpr const char* newton[] = {"0", "1", "2"};
inline constexpr const char* depth_bits[] = {"16", "24"};
inline constexpr const char* format[] = {"rgb888", "rgb565", "rgb565-be"};
inline constexpr const char* passes[] = {"fused", "multipass"};
inline constexpr const char* mip[] = {"trilinear", "segment"};
}  // namespace knob_values

inline constexpr KnobInfo knob_table[] = {
    {"span", "most pixels between exact perspective divides", knob_values::span, std::size(knob_values::span)},
    {"tolerance", "shorten segments so linear stepping drifts at most 2^-N texel from the exact value (0: never)",
     knob_values::tolerance, std::size(knob_values::tolerance)},
    {"table-bits", "reciprocal table index bits (6 with --newton 0 renders at about 20 dB: see docs/reciprocal.md)",
     knob_values::table_bits, std::size(knob_values::table_bits)},
    {"newton", "Newton-Raphson steps after the reciprocal table", knob_values::newton, std::size(knob_values::newton)},
    {"depth-bits", "depth buffer and shadow map bits", knob_values::depth_bits, std::size(knob_values::depth_bits)},
    {"format", "framebuffer format (rgb565-be: RGB565 with its two bytes swapped, as SPI displays take it)",
     knob_values::format, std::size(knob_values::format)},
    {"passes", "fused: one pass per pixel; multipass: the paper's passes (the same bytes)", knob_values::passes,
     std::size(knob_values::passes)},
    {"mip", "trilinear: two mip levels mixed per pixel, as the scene format defines; segment: one level per span segment, read bilinear (cheaper, see docs/speed-accuracy.md)",
     knob_values::mip, std::size(knob_values::mip)},
};

enum class KnobError : std::uint8_t { ok, unknown_name, bad_value };

namespace detail {
constexpr int index_of(std::string_view value, const char* const* values, int count) {
  for (int i = 0; i < count; ++i)
    if (value == values[i]) return i;
  return -1;
}
}  // namespace detail

// Sets one knob from its name (without the dashes) and its value as typed.
constexpr KnobError set_knob(Knobs& knobs, std::string_view name, std::string_view value) {
  for (const KnobInfo& info : knob_table) {
    if (name != info.name) continue;
    const int i = detail::index_of(value, info.values, info.value_count);
    if (i < 0) return KnobError::bad_value;
    const auto n = static_cast<std::uint8_t>(i);
    if (name == "span") knobs.span_log2 = n;
    else if (name == "tolerance") knobs.tolerance_log2 = n;
    else if (name == "table-bits") knobs.table_bits = static_cast<std::uint8_t>(6 + 2 * n);
    else if (name == "newton") knobs.newton = n;
    else if (name == "depth-bits") knobs.depth_bits = n == 0 ? 16 : 24;
    else if (name == "format") knobs.format = static_cast<PixelFormat>(n);
    else if (name == "passes") knobs.passes = static_cast<Passes>(n);
    else knobs.mip = static_cast<MipRule>(n);
    return KnobError::ok;
  }
  return KnobError::unknown_name;
}

// The value of one knob as typed (the inverse of set_knob), for reports and baked configurations.
constexpr const char* knob_value(const Knobs& knobs, std::string_view name) {
  // An index past its list (a Knobs built by hand: knobs_valid says so) reads the first value.
  auto pick = [](const auto& values, unsigned index) { return values[index < std::size(values) ? index : 0]; };
  if (name == "span") return pick(knob_values::span, knobs.span_log2);
  if (name == "tolerance") return pick(knob_values::tolerance, knobs.tolerance_log2);
  if (name == "table-bits") return pick(knob_values::table_bits, (knobs.table_bits - 6u) / 2u);
  if (name == "newton") return pick(knob_values::newton, knobs.newton);
  if (name == "depth-bits") return knobs.depth_bits == 16 ? "16" : "24";
  if (name == "format") return pick(knob_values::format, static_cast<unsigned>(knobs.format));
  if (name == "passes") return pick(knob_values::passes, static_cast<unsigned>(knobs.passes));
  if (name == "mip") return pick(knob_values::mip, static_cast<unsigned>(knobs.mip));
  return "";
}

// Whether every field holds one of its allowed values (a Knobs built by hand may not): the
// field is an index into its value list (span, tolerance, newton, format, passes, mip), or
// table_bits = 6 + 2 * index, or depth 16 or 24. Checked per frame, so no string compares.
constexpr bool knobs_valid(const Knobs& k) {
  const unsigned table_index = (k.table_bits - 6u) / 2u;  // wraps to a large value below 6
  return k.span_log2 < std::size(knob_values::span) && k.tolerance_log2 < std::size(knob_values::tolerance) &&
         k.table_bits % 2 == 0 && table_index < std::size(knob_values::table_bits) &&
         k.newton < std::size(knob_values::newton) && (k.depth_bits == 16 || k.depth_bits == 24) &&
         static_cast<std::size_t>(k.format) < std::size(knob_values::format) &&
         static_cast<std::size_t>(k.passes) < std::size(knob_values::passes) &&
         static_cast<std::size_t>(k.mip) < std::size(knob_values::mip);
}

// Parses `--name value` pairs (argv style); stops at the first error and says where.
struct KnobParse {
  KnobError error;
  int at;  // index of the offending argument, or argc when all were read
};
constexpr KnobParse parse_knobs(Knobs& knobs, int argc, const char* const* argv) {
  for (int i = 0; i < argc; i += 2) {
    std::string_view name = argv[i];
    if (name.size() < 3 || name[0] != '-' || name[1] != '-') return {KnobError::unknown_name, i};
    if (i + 1 >= argc) return {KnobError::bad_value, i};
    const KnobError e = set_knob(knobs, name.substr(2), argv[i + 1]);
    if (e != KnobError::ok) return {e, e == KnobError::bad_value ? i + 1 : i};
  }
  return {KnobError::ok, argc};
}

// Not a knob but swept like one: the texture filter a sweep may force on every
// texture (the bench's `--filter`, a knob configuration's texture_filter);
// `scene` keeps each texture's own.
enum class FilterChoice : std::uint8_t { scene, nearest, bilinear };

namespace knob_values {
inline constexpr const char* filter[] = {"scene", "nearest", "bilinear"};
}  // namespace knob_values

constexpr const char* filter_choice_name(FilterChoice filter) {
  const auto i = static_cast<std::size_t>(filter);
  return knob_values::filter[i < std::size(knob_values::filter) ? i : 0];
}

// The choice a word names; false, leaving `out` as it was, for any other word.
constexpr bool parse_filter_choice(std::string_view word, FilterChoice& out) {
  const int i = detail::index_of(word, knob_values::filter, static_cast<int>(std::size(knob_values::filter)));
  if (i < 0) return false;
  out = static_cast<FilterChoice>(i);
  return true;
}

}  // namespace spanlight
