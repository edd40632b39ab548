#include "analyze/analysis_report.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

#include <nlohmann/json.hpp>

#include "sweep/report_tables.hpp"
#include "io/knob_text.hpp"
#include "io/number_text.hpp"

namespace spanlight::analyze {
namespace {

std::string num(double v) { return io::number_text("%.6g", v); }

std::string interval(const Interval& i) { return i.empty ? std::string("none") : std::string("[") + num(i.lo) + ", " + num(i.hi) + "]"; }

const char* filter_name(scene::Filter f) {
  return f == scene::Filter::nearest ? "nearest" : (f == scene::Filter::bilinear ? "bilinear" : "trilinear");
}
const char* wrap_name(scene::Wrap w) { return w == scene::Wrap::repeat ? "repeat" : w == scene::Wrap::clamp ? "clamp" : "border"; }

}  // namespace

std::string features_text(const scene::Scene& s) {
  std::ostringstream out;
  std::size_t triangles = 0;
  bool bilinear = false, trilinear = false, shadows = false, pcf = false, falloff = false, facing = false;
  for (const scene::Object& o : s.objects) triangles += o.mesh.triangles.size();
  for (const scene::Texture& t : s.textures) {
    bilinear |= t.filter == scene::Filter::bilinear;
    trilinear |= t.filter == scene::Filter::trilinear;
  }
  for (const scene::Projector& p : s.projectors) {
    shadows |= p.shadows.has_value();
    pcf |= p.shadows && p.shadows->filter == scene::ShadowFilter::pcf2x2;
    falloff |= p.falloff >= 0;
    facing |= p.facing_only;
  }
  out << "Features used\n"
      << "  frame " << s.width << "x" << s.height << ", " << s.objects.size() << " object(s), " << triangles << " triangle(s)\n"
      << "  projectors " << s.projectors.size() << ", shadows " << (shadows ? "yes" : "no") << (pcf ? " (pcf2x2)" : "")
      << ", bilinear " << (bilinear ? "yes" : "no") << ", trilinear " << (trilinear ? "yes" : "no")
      << ", falloff " << (falloff ? "yes" : "no") << ", facing_only " << (facing ? "yes" : "no") << "\n";
  for (const scene::Texture& t : s.textures)
    out << "  texture " << t.name << ": " << t.image.width << "x" << t.image.height << ", " << filter_name(t.filter) << ", "
        << wrap_name(t.wrap) << "\n";
  return out.str();
}

std::string ranges_text(const SceneRanges& r) {
  std::ostringstream out;
  out << "Numeric ranges\n"
      << "  object coordinates: max |x|, |y|, |z| " << num(r.largest_coordinate) << " units\n"
      << "  eye clip w (inside near/far): " << interval(r.clip_w) << "\n"
      << "  window x, y after clipping (px): " << interval(r.window_x) << ", " << interval(r.window_y)
      << " (the guard band holds +-8192 px; beyond it the clipper cuts)\n";
  for (const ObjectRanges& o : r.objects)
    if (o.textured) out << "  " << o.name << ": max |uv x size| " << num(o.largest_texel) << " texels\n";
  for (const ProjectorRanges& p : r.projectors) {
    out << "  projector " << p.name << ": q over vertices " << interval(p.q) << ", " << p.vertices_behind
        << " vertex(es) behind it (q <= 0); depth r/q " << interval(p.window_depth);
    if (p.shadows) out << "; shadow map " << p.map_size << "^2, bias " << num(p.bias);
    out << "\n";
  }
  const DepthRanges& d = r.depth;
  double smallest = INFINITY;
  for (double g : d.gaps) smallest = std::min(smallest, g);
  out << "  eye depth of visible surfaces: " << interval(d.visible) << ", " << d.covered << " covered pixels, "
      << d.gaps.size() << " with another object behind";
  if (!d.gaps.empty()) out << " (smallest gap " << num(smallest) << ")";
  out << "\n    pixels with another object within one depth step: 16 bits " << d.at_risk(16) << ", 24 bits " << d.at_risk(24) << "\n";
  return out.str();
}

std::string formats_text(const std::vector<FormatChoice>& choices) {
  std::ostringstream out;
  out << "Formats that hold these ranges (first that holds is chosen)\n";
  for (const FormatChoice& c : choices) {
    out << "  " << c.quantity << ": " << c.needed << "\n";
    for (std::size_t i = 0; i < c.candidates.size(); ++i) {
      const Candidate& k = c.candidates[i];
      out << "    " << (c.chosen && *c.chosen == i ? "-> " : "   ") << k.format << ": "
          << (k.holds ? std::string("holds") : "REJECTED (" + k.failure + ")") << ", " << k.why << (k.implemented ? "" : " [not in the pipeline]")
          << "\n";
    }
    if (!c.chosen) out << "    none of these holds the range\n";
    else if (!c.candidates[*c.chosen].implemented) out << "    the pipeline has no such format: prepare will refuse this scene\n";
    if (!c.pipeline.empty()) out << "    pipeline uses: " << c.pipeline << "\n";
  }
  return out.str();
}

std::string bake_command_line(const std::string& scene_file, const Knobs& knobs) {
  return "spanlight bake " + scene_file + " --out baked/ " + knob_command_line(knobs);
}

std::string measured_json(const sweep::SweepResult& r, const sweep::SweepRow& row, const AccuracyTarget& target) {
  nlohmann::json j;
  j["target"] = target.describe();
  j["psnr_db"] = std::isinf(row.psnr_db) ? nlohmann::json(nullptr) : nlohmann::json(row.psnr_db);
  j["max_lsb"] = row.max_lsb;
  j["mean_lsb"] = row.mean_lsb;
  j["psnr_vs_scene_db"] = std::isinf(row.psnr_vs_scene_db) ? nlohmann::json(nullptr) : nlohmann::json(row.psnr_vs_scene_db);
  j["texcoord_err_max_texels"] = row.texcoord_err_max();
  if (row.m7.instructions) j["m7_instructions"] = *row.m7.instructions;
  if (row.m0plus.instructions) j["m0plus_instructions"] = *row.m0plus.instructions;
  j["covered_pixels"] = r.covered_pixels;
  j["host_ratio_to_float"] = row.host_ratio();
  j["buffer_bytes"] = row.buffer_bytes;
  j["table_bytes"] = row.table_bytes;
  return j.dump();
}

std::string proposal_text(const sweep::SweepResult& r, const Proposal& p, const AccuracyTarget& target) {
  std::ostringstream out;
  out << "Cheapest configuration meeting " << target.describe() << " (cost: " << sweep::axis_name(p.axis)
      << (p.axis == sweep::CostAxis::host ? " time" : " instructions") << ", " << p.candidates << " candidate(s))\n";
  if (!p.row) {
    out << "  " << p.why_none << "\n";
    return out.str();
  }
  const sweep::SweepRow& row = r.rows[*p.row];
  char line[400];
  std::snprintf(line, sizeof line,
                "  %s\n  error: PSNR %s dB, max %.0f LSB, mean %.3f LSB, %.3f %% > 2 LSB, %.3f %% > 8 LSB, worst texel %.4f\n",
                sweep::label(row.point).c_str(), std::isinf(row.psnr_db) ? "inf" : num(row.psnr_db).c_str(), row.max_lsb,
                row.mean_lsb, row.pct_over_2, row.pct_over_8, row.texcoord_err_max());
  out << line;
  if (row.point.filter != FilterChoice::scene) {
    std::snprintf(line, sizeof line, "  against the scene as authored (filters as written): PSNR %s dB, max %.0f LSB\n",
                  std::isinf(row.psnr_vs_scene_db) ? "inf" : num(row.psnr_vs_scene_db).c_str(), row.max_vs_scene_lsb);
    out << line;
  }
  auto cost = [&](const char* cpu, const sweep::TargetCost& c) {
    out << "  " << cpu << ": "
        << (c.instructions ? sweep::millions(static_cast<double>(*c.instructions)) + " instructions/frame, " +
                                 num(std::round(static_cast<double>(*c.instructions) / static_cast<double>(r.covered_pixels))) +
                                 " per covered pixel (" + c.source + ")"
                           : c.source)
        << "\n";
  };
  cost("Cortex-M7", row.m7);
  cost("Cortex-M0+", row.m0plus);
  std::snprintf(line, sizeof line, "  host: %.2f x the float model's time; memory: %zu B tables, %zu B buffers\n",
                row.host_ratio(), row.table_bytes, row.buffer_bytes);
  out << line;
  if (const auto d = sweep::default_row(r)) {
    const sweep::SweepRow& def = r.rows[*d];
    const auto a = sweep::cost_of(row, p.axis), b = sweep::cost_of(def, p.axis);
    if (a && b && *p.row != *d)
      out << "  against the default (" << sweep::label(def.point) << "): " << num(std::round(100.0 * (1.0 - *a / *b)))
          << " % cheaper, PSNR " << (std::isinf(def.psnr_db) ? "inf" : num(def.psnr_db)) << " dB there\n";
    else if (*p.row == *d)
      out << "  this is the default configuration\n";
  }
  return out.str();
}

}  // namespace spanlight::analyze
