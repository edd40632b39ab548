// The scene as the fixed-point pipeline sees it: plain const arrays that a
// firmware image links from flash (written by `spanlight bake`) or that the
// host builds in memory (host_tools/prepare). Host and target run the same
// code on the same bytes.
//
// What moves from frame to frame (the camera, each object's model matrix, each
// projector's pose) is not here: it comes with every frame as FrameMatrices
// (frame_matrices.hpp), so firmware can animate a scene without re-baking it.
#pragma once

#include <cstdint>

namespace spanlight {

enum class Filter : std::uint8_t { nearest, bilinear, trilinear };
enum class Wrap : std::uint8_t { repeat, clamp, border };
enum class Cull : std::uint8_t { none, back };
enum class ShadowFilter : std::uint8_t { nearest, pcf2x2 };

// One image of a texture (a mip level), in the layout the sampler reads:
// 0x00RRGGBB words, rows from the bottom (t = 0) up, with a frame of one
// texel around the image that holds what the wrap mode reads there (repeat:
// the opposite edge; clamp: the edge itself; border: black). A bilinear fetch
// then reads texels (x0, y0) .. (x0 + 1, y0 + 1) for x0 in [-1, width - 1]
// without a test: the frame answers for the wrap.
struct TextureLevel {
  const std::uint32_t* texels;  // texel (0, 0) of the image; the frame starts one row and one texel before
  std::uint16_t width, height;  // the image, without the frame
  std::uint16_t stride;         // words from one row to the next: width + 2
};

inline constexpr int texture_frame = 1;  // texels of frame on each side of a level
constexpr std::uint32_t framed_texel_count(std::uint32_t width, std::uint32_t height) {
  return (width + 2 * texture_frame) * (height + 2 * texture_frame);
}

struct TextureData {
  const TextureLevel* levels;  // level 0 is the image; trilinear textures hold the whole chain
  std::uint8_t level_count;
  Filter filter;
  Wrap wrap;  // projectors ignore it: their images are baked with a black (border) frame
};

// An object-space axis-aligned box (Q15.16), for whole-object rejection.
struct Bounds {
  std::int32_t min[3], max[3];
};

// Generated texture coordinates (scene format 2): u = s . (x, y, z, 1), v = t . (x, y, z, 1),
// in object space, or in the camera's eye space (FrameMatrices::eye_from_object).
enum class TexgenSpace : std::uint8_t { none, object, eye };

struct ObjectData {
  const std::int32_t* positions;  // x, y, z per vertex, Q15.16 object space (|coord| < 2^14 units)
  const std::int32_t* uvs;        // u, v per vertex in level-0 texels * 2^uv_frac_bits (t = 0: bottom row)
  const std::uint16_t* indices;   // 3 per triangle, in the order bake chose (vertex reuse)
  std::uint16_t vertex_count;
  std::uint32_t triangle_count;
  Bounds bounds;
  std::int16_t texture;           // -1: none
  std::uint8_t uv_frac_bits;      // sub-texel bits chosen from the object's uv range (8..16)
  Cull cull;
  std::uint8_t color[3];          // object colour, round(255 * c)
  TexgenSpace texgen;             // none: uvs as given
  bool closed;                    // a closed solid (host_tools/prepare/closed_mesh.hpp): seen from outside, its
                                  // back faces are never the nearest surface, and draw_pass leaves them out
};

struct ProjectorData {
  std::int16_t texture;          // the projected image (border)
  std::int16_t falloff;          // scene format 2: light times falloff(r/q), a 1-row texture; -1: none
  std::uint16_t color[3];        // Q8.8, saturated at 255.996
  bool facing_only;              // scene format 2: lights only triangles facing it
  bool shadows;
  ShadowFilter filter;
  std::uint16_t map_size;
  std::int32_t bias;             // window-depth units, Q1.30, in [0, max_shadow_bias]
};

// The largest shadow bias, 1.99 in Q1.30 (round(1.99 * 2^30)): prepare clamps to it, render_frame
// refuses more, and shadow_need's one-word compare needs 4 r - bias to fit 32 bits.
inline constexpr std::int32_t max_shadow_bias = 2136746230;

struct PreparedScene {
  std::uint16_t width, height;
  std::uint8_t ambient[3];  // round(255 * a)
  const TextureData* textures;
  std::uint8_t texture_count;
  const ObjectData* objects;
  std::uint16_t object_count;
  const ProjectorData* projectors;
  std::uint8_t projector_count;
  std::uint16_t max_vertex_count;  // the largest object's: the vertex cache a frame needs
};

}  // namespace spanlight
