#include "analyze/proposal.hpp"

#include <cstdio>

namespace spanlight::analyze {

std::string AccuracyTarget::describe() const {
  char text[120];
  if (max_error_lsb && min_psnr_db) std::snprintf(text, sizeof text, "max error <= %g LSB and PSNR >= %g dB", *max_error_lsb, *min_psnr_db);
  else if (max_error_lsb) std::snprintf(text, sizeof text, "max error <= %g LSB", *max_error_lsb);
  else if (min_psnr_db) std::snprintf(text, sizeof text, "PSNR >= %g dB", *min_psnr_db);
  else std::snprintf(text, sizeof text, "RMS error no worse than the default configuration's");
  return text;
}

// Against the scene as authored, so a forced filter counts as error.
bool meets(const sweep::SweepRow& row, const AccuracyTarget& t, double default_rms) {
  if (t.max_error_lsb && row.max_vs_scene_lsb > *t.max_error_lsb) return false;
  if (t.min_psnr_db && row.psnr_vs_scene_db < *t.min_psnr_db) return false;
  if (!t.max_error_lsb && !t.min_psnr_db && row.rms_vs_scene_lsb > default_rms) return false;
  return true;
}

Proposal cheapest_meeting(const sweep::SweepResult& r, const AccuracyTarget& target, const Constraints& c) {
  Proposal p;
  p.axis = sweep::has_cost(r, sweep::CostAxis::m7)       ? sweep::CostAxis::m7
           : sweep::has_cost(r, sweep::CostAxis::m0plus) ? sweep::CostAxis::m0plus
                                                         : sweep::CostAxis::host;
  const std::optional<std::size_t> d = sweep::default_row(r);
  const double default_rms = d ? r.rows[*d].rms_vs_scene_lsb : 0.0;
  for (std::size_t i = 0; i < r.rows.size(); ++i) {
    const sweep::SweepRow& row = r.rows[i];
    if (row.point.knobs.depth_bits < c.min_depth_bits) continue;
    if (!c.allow_filter_change && row.point.filter != FilterChoice::scene) continue;
    if (!meets(row, target, default_rms)) continue;
    const std::optional<double> cost = sweep::cost_of(row, p.axis);
    if (!cost) continue;
    ++p.candidates;
    if (!p.row) {
      p.row = i;
      continue;
    }
    const sweep::SweepRow& best = r.rows[*p.row];
    const double best_cost = *sweep::cost_of(best, p.axis);
    const std::size_t memory = row.buffer_bytes + row.table_bytes, best_memory = best.buffer_bytes + best.table_bytes;
    if (*cost < best_cost || (*cost == best_cost && memory < best_memory)) p.row = i;
  }
  if (!p.row) p.why_none = "no configuration of the sweep meets " + target.describe() + " with depth bits >= " + std::to_string(c.min_depth_bits);
  return p;
}

}  // namespace spanlight::analyze
