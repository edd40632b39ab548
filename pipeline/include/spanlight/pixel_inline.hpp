// SPANLIGHT_PIXEL_INLINE marks the functions that run at every covered pixel.
#pragma once

// They are forced inline into the span loop, also in builds for size (-Os, the
// M0+ firmware): a call there costs its arguments, a register save and often a
// struct returned through memory at every pixel, more than the body of most of
// them. The bilinear fetch is the exception (sample.hpp): inlined it makes the
// loop spill more than the call costs.
#define SPANLIGHT_PIXEL_INLINE [[gnu::always_inline]] inline

// The same for the lambdas a run loop calls at each pixel: [&](...) SPANLIGHT_LAMBDA_INLINE { ... }.
#define SPANLIGHT_LAMBDA_INLINE __attribute__((always_inline))
