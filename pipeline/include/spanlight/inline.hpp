// The code that runs at every covered pixel is forced inline into the run
// loops, also in builds for size (-Os, the M0+ firmware): a call there costs
// its arguments, a register save and often a struct returned through memory at
// every pixel, more than the body of most of these functions.
#pragma once

// For the lambdas a run loop calls at each pixel: [&](...) SPANLIGHT_LAMBDA_INLINE_ATTR { ... }.
#define SPANLIGHT_LAMBDA_INLINE_ATTR __attribute__((always_inline))
// For a lambda kept out of line so that its locals are not in its caller's frame.
#define SPANLIGHT_LAMBDA_NOINLINE_ATTR __attribute__((noinline))
