// The scene as the fixed-point pipeline sees it: plain const arrays a firmware
// image links from flash, or the host builds in memory. The host renders from
// the same structure, so host and target run the same code on the same bytes.
#pragma once

#include <cstdint>

#include "spanlight/transform.hpp"

namespace spanlight {

enum class Filter : std::uint8_t { nearest, bilinear };
enum class Wrap : std::uint8_t { repeat, clamp, border };
enum class Cull : std::uint8_t { none, back };
enum class ShadowFilter : std::uint8_t { nearest, pcf2x2 };

struct TextureData {
  const std::uint8_t* rgb;  // RGB888, top row first
  std::uint16_t width, height;
  Filter filter;
  Wrap wrap;  // projectors ignore it: always border
};

struct ObjectData {
  const std::int32_t* positions;  // x, y, z per vertex, Q15.16 object space (|coord| < 2^14 units)
  const std::int32_t* uvs;        // u, v per vertex in texels * 2^uv_frac_bits of its texture (t = 0: bottom row)
  const std::uint16_t* indices;   // 3 per triangle
  std::uint32_t triangle_count;
  std::int16_t texture;           // -1: none
  std::uint8_t uv_frac_bits;      // sub-texel bits chosen from the object's uv range (>= 8 wanted)
  Cull cull;
  std::uint8_t color[3];          // object colour, round(255 * c)
  Mat4Block clip_from_object;     // P * V * M
  const Mat4Block* projector_from_object;     // B * P_j * V_j * M, one per projector
  const Mat4Block* light_clip_from_object;    // P_j * V_j * M, one per projector (shadow maps)
};

struct ProjectorData {
  std::int16_t texture;
  std::uint16_t color[3];  // Q8.8, saturated at 255.996
  bool shadows;
  ShadowFilter filter;
  std::uint16_t map_size;
  std::int32_t bias;       // window-depth units, Q1.30
};

struct PreparedScene {
  std::uint16_t width, height;
  std::uint8_t ambient[3];  // round(255 * a)
  const TextureData* textures;
  const ObjectData* objects;
  std::uint16_t object_count;
  const ProjectorData* projectors;
  std::uint8_t projector_count;
};

}  // namespace spanlight
