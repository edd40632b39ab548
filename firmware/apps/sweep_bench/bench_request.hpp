// What one sweep_bench run renders: the pipeline's knobs (parse_knobs, the one
// knob vocabulary), the texture filter the sweep may force, and whether each
// pass is measured as its own region.
#pragma once

#include <cstdint>

#include "hal/hal.hpp"
#include "spanlight/knobs.hpp"
#include "spanlight/scene.hpp"

namespace bench {

struct Request {
  spanlight::Knobs knobs{};  // parse_request changes only the knobs on the command line
  bool force_filter = false;  // false: each texture's filter as baked
  spanlight::Filter filter = spanlight::Filter::bilinear;
  bool per_pass = false;  // one measured region per pass instead of the whole frame
};

// Parses "[knob words as `spanlight render` takes them] [--filter scene|nearest|bilinear] [--per-pass]"
// (args[0] is the program). On a bad word returns false and points `error` at it.
bool parse_request(spanlight::hal::Args args, Request& out, const char*& error);

}  // namespace bench
