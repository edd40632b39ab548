// Stage 1a, transform: object space to clip space and to each projector's
// (s, t, r, q). Matrices are block floating point (fixedpoint::Mat4Block:
// int32 mantissas, one shared exponent) prepared on the host; positions are
// Q15.16; results are int64 with 32 fraction bits, enough to keep 1/256 px
// after the divide even at w = 0.01 (a near plane of a centimetre).
#pragma once

#include <cstdint>

#include "fixedpoint/vec.hpp"

namespace spanlight {

using fixedpoint::Mat4Block;
using fixedpoint::Vec4Wide;

// Positions are stored as x, y, z triples of Q15.16 in the scene's arrays.
constexpr Vec4Wide transform(const Mat4Block& mat, const std::int32_t* position) {
  return fixedpoint::transform(mat, fixedpoint::Vec3Q16{position[0], position[1], position[2]});
}

}  // namespace spanlight
