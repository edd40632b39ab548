// Which fixed-point formats hold a scene's ranges without overflow. For each
// stored quantity the candidates go from the most fraction bits to the most
// integer bits; the chosen one is the first that holds the range (the most
// precision that does not overflow).
//
//   object positions   Q15.16 (the pipeline's), Q19.12, Q23.8; prepare keeps one
//                      bit of headroom: |x| < 2^(integer bits - 1)
//   uv * texture size  Q15.16, Q19.12, Q23.8 texels; the span code needs
//                      |u| * 2^frac < 2^29 (deltas and sums stay inside int32);
//                      prepare picks its own fraction bits per object
//   depth buffer       16 or 24 bits: enough when at most 1 in 10,000 covered
//                      pixels has another object within one depth step
//   shadow maps        16 or 24 bits: enough when the bias is >= 2 depth steps
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "analyze/scene_ranges.hpp"

namespace spanlight::analyze {

struct Candidate {
  std::string format;      // "Q15.16", "24 bits"
  double limit = 0.0;      // the largest magnitude it holds (or the finest step it resolves)
  bool holds = false;
  bool implemented = true; // the pipeline has it
  std::string failure;     // when it does not hold: "overflow" or "too coarse"
  std::string why;         // one line: the comparison made
};

struct FormatChoice {
  std::string quantity;   // "object positions", "uv of room (texels)", ...
  std::string needed;     // the measured range, in words
  std::vector<Candidate> candidates;
  std::optional<std::size_t> chosen;  // index of the first candidate that holds
  std::string pipeline;   // what the pipeline actually uses for this scene, when it decides itself
};

// A Q<int>.<frac> name for a 32-bit signed format with `frac` fraction bits.
std::string q_format(int frac_bits);

// The largest |uv * size| a format with `frac` fraction bits holds in the span code.
double uv_limit(int frac_bits);

std::vector<FormatChoice> choose_formats(const SceneRanges& ranges);

// The smallest depth bits the eye's depth buffer and every shadow map need, from the choices.
int required_depth_bits(const std::vector<FormatChoice>& choices);

inline constexpr double depth_risk_threshold = 1e-4;  // share of covered pixels

}  // namespace spanlight::analyze
