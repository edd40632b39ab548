// Scene (double, validated) -> PreparedScene (fixed point), the data the
// pipeline reads, and the FrameMatrices of the scene's own pose. The host
// renders from them and `bake` writes them out as C++, so host and firmware
// consume the same bytes.
#pragma once

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.hpp"
#include "spanlight/frame_matrices.hpp"
#include "spanlight/scene.hpp"

namespace spanlight::prepare {

// A scene the fixed-point formats cannot hold (e.g. a coordinate beyond 2^14).
class PrepareError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The fixed formats' limits, each checked by prepare_scene.
inline constexpr double position_limit = 16384.0;       // |object coordinate| < 2^14 units (Q15.16 with headroom)
inline constexpr double texel_coordinate_limit = 2097152.0;  // |u * size| < 2^21 texels (8 sub-texel bits in 30)
inline constexpr std::size_t vertex_limit = 65535;      // 16-bit indices
inline constexpr int uv_value_bits = 29;               // |u * size| * 2^frac < 2^29: two uvs' difference fits int32 with a bit to spare
inline constexpr int min_matrix_frac_bits = 16;         // entries below 2^13: clip coordinates stay in Q31.32

// A texture's image in the sampler's layout (scene.hpp): its own storage and level table.
struct PreparedTexture {
  std::vector<std::vector<std::uint32_t>> framed;  // one framed image a level
  std::vector<TextureLevel> levels;
};

// Owns every array the PreparedScene and FrameMatrices point into. Not
// copyable: the pointers inside refer to this object's vectors.
struct PreparedStorage {
  PreparedScene scene{};
  FrameMatrices matrices{};
  std::vector<PreparedTexture> texture_storage;
  std::vector<TextureData> textures;
  std::vector<std::vector<std::int32_t>> positions, uvs;
  std::vector<std::vector<std::uint16_t>> indices;
  std::vector<ObjectData> objects;
  std::vector<ProjectorData> projectors;
  std::vector<Mat4Block> clip_from_object, projector_from_object, light_clip_from_object;
  std::vector<std::string> object_names;
  std::vector<std::string> texture_names;  // of each TextureData: the scene's name, plus the use when baked twice

  PreparedStorage() = default;
  PreparedStorage(const PreparedStorage&) = delete;
  PreparedStorage& operator=(const PreparedStorage&) = delete;
};

std::unique_ptr<PreparedStorage> prepare_scene(const scene::Scene& scene);

// A repeating image with a side of one texel, doubled along that side (both copies the
// one row or column: nearest and bilinear read the same values). The repeat sampler takes
// a texel index as the top log2(size) bits of a 32-bit coordinate, so a side of 1 would
// shift by 32; prepare_scene bakes every repeating level 0 through this.
scene::Image repeatable_image(const scene::Image& image);

// One image in the sampler's layout: 0x00RRGGBB, rows from the bottom, with a
// one-texel frame holding what `wrap` reads beyond the edges.
std::vector<std::uint32_t> framed_texels(const scene::Image& image, Wrap wrap);

// Block floating point for a matrix: int32 mantissas below 2^29, one shared exponent.
Mat4Block to_mat4_block(const glm::dmat4& m);

// Sub-texel bits that keep every |uv * size| * 2^bits below 2^29: 8 to 16.
int uv_frac_bits_for(double largest_texel_coordinate);

}  // namespace spanlight::prepare
