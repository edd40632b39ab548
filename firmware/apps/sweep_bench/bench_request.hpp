// What one sweep_bench run renders: the knobs from its command line.
#pragma once

#include <cstdint>

#include "hal/hal.hpp"
#include "spanlight/features.hpp"

namespace bench {

enum class FilterChoice : std::uint8_t { scene, nearest, bilinear };

struct Request {
  int table_bits = 8;
  int newton = 1;
  spanlight::Precision precision{};
  FilterChoice filter = FilterChoice::scene;
  bool passes = false;  // measure each pass as its own region instead of the whole frame
};

// Parses "--table-bits B --newton N --span S --tolerance T --depth-bits D --fused 0|1
// --filter scene|nearest|bilinear [--passes]" (any order, all optional). On a bad
// argument returns false and points `error` at the offending word.
bool parse_request(spanlight::hal::Args args, Request& out, const char*& error);

const char* to_string(FilterChoice filter);

}  // namespace bench
