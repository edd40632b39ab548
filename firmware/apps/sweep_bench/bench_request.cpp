#include "bench_request.hpp"

#include <string_view>

namespace bench {

bool parse_request(spanlight::hal::Args args, Request& out, const char*& error) {
  const char* knob_words[32];  // the HAL passes at most 32 words
  int knob_count = 0;
  for (std::size_t i = 1; i < args.size(); ++i) {
    const std::string_view word = args[i];
    error = args[i];
    if (word == "--per-pass") {
      out.per_pass = true;
    } else if (word == "--filter") {
      if (i + 1 >= args.size()) return false;
      error = args[++i];
      spanlight::FilterChoice choice = spanlight::FilterChoice::scene;
      if (!spanlight::parse_filter_choice(args[i], choice)) return false;
      out.force_filter = choice != spanlight::FilterChoice::scene;
      if (out.force_filter)
        out.filter = choice == spanlight::FilterChoice::nearest ? spanlight::Filter::nearest : spanlight::Filter::bilinear;
    } else {
      knob_words[knob_count++] = args[i];
    }
  }
  const spanlight::KnobParse parsed = spanlight::parse_knobs(out.knobs, knob_count, knob_words);
  if (parsed.error != spanlight::KnobError::ok) {
    error = parsed.at < knob_count ? knob_words[parsed.at] : "?";
    return false;
  }
  error = nullptr;
  return true;
}

}  // namespace bench
