// Scene (double, validated) -> PreparedScene (fixed point), the data the
// pipeline reads. The host renders from it and `bake` writes it out as C++,
// so host and firmware consume the same bytes.
#pragma once

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "spanlight/prepared_scene.hpp"

namespace spanlight::prepare {

// A scene the fixed-point formats cannot hold (e.g. a coordinate beyond 2^14).
class PrepareError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Owns every array the PreparedScene points into. Not copyable: the pointers
// inside `scene` refer to this object's vectors.
struct PreparedStorage {
  PreparedScene scene{};
  std::vector<std::vector<std::uint8_t>> texels;
  std::vector<TextureData> textures;
  std::vector<std::vector<std::int32_t>> positions, uvs;
  std::vector<std::vector<std::uint16_t>> indices;
  std::vector<std::vector<Mat4Block>> projector_from_object, light_clip_from_object;
  std::vector<ObjectData> objects;
  std::vector<ProjectorData> projectors;
  std::vector<std::string> object_names;

  PreparedStorage() = default;
  PreparedStorage(const PreparedStorage&) = delete;
  PreparedStorage& operator=(const PreparedStorage&) = delete;
};

std::unique_ptr<PreparedStorage> prepare_scene(const scene::Scene& scene);

// Block floating point for a matrix: int32 mantissas below 2^29, one shared exponent.
Mat4Block to_mat4_block(const glm::dmat4& m);

// Sub-texel bits that keep every |uv * size| * 2^bits below 2^30 (at most 16).
int uv_frac_bits_for(double largest_texel_coordinate);

}  // namespace spanlight::prepare
