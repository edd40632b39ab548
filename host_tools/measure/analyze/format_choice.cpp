#include "analyze/format_choice.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "io/knob_text.hpp"
#include "io/number_text.hpp"
#include "prepare/prepare.hpp"

namespace spanlight::analyze {
namespace {

std::string num(double v) { return io::number_text("%.6g", v); }

void choose_first(FormatChoice& c) {
  for (std::size_t i = 0; i < c.candidates.size(); ++i)
    if (c.candidates[i].holds) {
      c.chosen = i;
      return;
    }
}

FormatChoice positions(const SceneRanges& r) {
  FormatChoice c{"object positions", "max |coordinate| " + num(r.largest_coordinate) + " units", {}, {}, "Q15.16"};
  for (int frac : {16, 12, 8}) {
    const double limit = std::ldexp(1.0, 31 - frac - 1);  // one bit of headroom, as prepare keeps for Q15.16
    c.candidates.push_back({q_format(frac), limit, r.largest_coordinate < limit, frac == 16, "overflow",
                            num(r.largest_coordinate) + (r.largest_coordinate < limit ? " < " : " >= ") + num(limit)});
  }
  choose_first(c);
  return c;
}

FormatChoice uv_of(const ObjectRanges& o) {
  const int frac = prepare::uv_frac_bits_for(o.largest_texel);
  FormatChoice c{"uv x texture size of " + o.name + " (" + std::to_string(o.texture_width) + "x" +
                     std::to_string(o.texture_height) + ")",
                 "max |uv x size| " + num(o.largest_texel) + " texels", {}, {}, q_format(frac) + " (prepare's choice)"};
  for (int f : {16, 12, 8}) {
    const double limit = uv_limit(f);
    c.candidates.push_back({q_format(f), limit, o.largest_texel < limit, true, "overflow",
                            num(o.largest_texel) + (o.largest_texel < limit ? " < " : " >= ") + num(limit)});
  }
  choose_first(c);
  return c;
}

// The depth bits the pipeline offers, smallest first: the depth-bits knob's values (knob_table).
std::vector<int> depth_candidates() {
  std::vector<int> bits;
  for (const std::string& value : knob_choices("depth-bits")) bits.push_back(std::stoi(value));
  return bits;
}

FormatChoice eye_depth(const SceneRanges& r) {
  const DepthRanges& d = r.depth;
  const std::string visible = d.visible.empty ? std::string("nothing visible")
                                               : "visible depth [" + num(d.visible.lo) + ", " + num(d.visible.hi) + "]";
  FormatChoice c{"eye depth buffer", visible + ", " + std::to_string(d.gaps.size()) + " pixels with a second object behind",
                 {}, {}, {}};
  const double allowed = depth_risk_threshold * static_cast<double>(d.covered);
  for (const int bits : depth_candidates()) {
    const std::size_t risk = d.at_risk(bits);
    c.candidates.push_back({std::to_string(bits) + " bits", std::ldexp(1.0, -bits), static_cast<double>(risk) <= allowed, true,
                            "too coarse", std::to_string(risk) + " of " + std::to_string(d.covered) +
                                " covered pixels have another object within one step (" + num(std::ldexp(1.0, -bits)) +
                                "); allowed " + num(allowed)});
  }
  choose_first(c);
  return c;
}

FormatChoice shadow_depth(const ProjectorRanges& p) {
  FormatChoice c{"shadow map of " + p.name + " (" + std::to_string(p.map_size) + "^2)",
                 "bias " + num(p.bias) + ", depth [" + num(p.window_depth.lo) + ", " + num(p.window_depth.hi) + "]", {}, {}, {}};
  for (const int bits : depth_candidates()) {
    const double steps = p.bias * std::ldexp(1.0, bits);
    c.candidates.push_back({std::to_string(bits) + " bits", std::ldexp(1.0, -bits), steps >= 2.0, true, "too coarse",
                            "bias = " + num(steps) + " steps (>= 2 wanted)"});
  }
  choose_first(c);
  return c;
}

}  // namespace

std::string q_format(int frac_bits) {
  char name[16];
  std::snprintf(name, sizeof name, "Q%d.%d", 31 - frac_bits, frac_bits);
  return name;
}

double uv_limit(int frac_bits) { return std::ldexp(1.0, 29 - frac_bits); }

std::vector<FormatChoice> choose_formats(const SceneRanges& r) {
  std::vector<FormatChoice> out{positions(r)};
  for (const ObjectRanges& o : r.objects)
    if (o.textured) out.push_back(uv_of(o));
  out.push_back(eye_depth(r));
  for (const ProjectorRanges& p : r.projectors)
    if (p.shadows) out.push_back(shadow_depth(p));
  return out;
}

int required_depth_bits(const std::vector<FormatChoice>& choices) {
  int bits = depth_candidates().front();
  for (const FormatChoice& c : choices) {
    if (c.quantity != "eye depth buffer" && c.quantity.rfind("shadow map", 0) != 0) continue;
    if (!c.chosen) return 0;  // no depth setting is enough
    bits = std::max(bits, std::stoi(c.candidates[*c.chosen].format));  // "24 bits"
  }
  return bits;
}

}  // namespace spanlight::analyze
