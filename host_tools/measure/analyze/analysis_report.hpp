// `spanlight analyze` output, section by section, as plain text.
#pragma once

#include <string>
#include <vector>

#include "analyze/format_choice.hpp"
#include "analyze/proposal.hpp"
#include "analyze/scene_ranges.hpp"
#include "scene/scene.hpp"
#include "sweep/sweep_result.hpp"

namespace spanlight::analyze {

std::string features_text(const scene::Scene& scene);
std::string ranges_text(const SceneRanges& ranges);
std::string formats_text(const std::vector<FormatChoice>& choices);
std::string proposal_text(const sweep::SweepResult& result, const Proposal& proposal, const AccuracyTarget& target);

// `spanlight bake SCENE --out DIR <knobs>` for a configuration.
std::string bake_command_line(const std::string& scene_file, const Knobs& knobs);

// The measured figures of a row as a JSON object (for the config file's "measured").
std::string measured_json(const sweep::SweepResult& result, const sweep::SweepRow& row, const AccuracyTarget& target);

}  // namespace spanlight::analyze
