// Knob settings known to render badly get a warning on stderr (the command
// still runs: a sweep or a user may want exactly that picture).
#pragma once

#include <optional>
#include <string>

#include "spanlight/knobs.hpp"

namespace spanlight::cli {

// The warning for `knobs`, if any: when the reciprocal's proven relative
// error (fixedpoint/reciprocal_bound.hpp) exceeds 2^-11, which at a texel
// coordinate of 256 is more than 1/8 texel. That is no Newton step with a 6-,
// 8- or 10-bit table.
std::optional<std::string> accuracy_warning(const Knobs& knobs);

// Prints accuracy_warning(knobs), if any, to stderr.
void warn_if_inaccurate(const Knobs& knobs);

}  // namespace spanlight::cli
