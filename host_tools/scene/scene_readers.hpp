// One reader per part of the scene file; load_scene() calls them in order.
// Each takes the part's JsonField and throws SceneError on any bad input.
#pragma once

#include <initializer_list>
#include <string_view>
#include <vector>

#include <glm/mat4x4.hpp>

#include "json_field.hpp"
#include "scene/scene.hpp"

namespace spanlight::scene::detail {

// What a camera and a projector share: where it is, where it looks, its frustum.
struct ViewVolume {
  glm::dvec3 eye{0.0}, target{0.0}, up{0.0};
  double fovy_deg = 0.0;
  double near = 0.0;
  double far = 0.0;
};

// The format version, 1 or 2 (format_version.cpp).
int read_version(const JsonField& root);
// In a version-1 file, refuses each of `fields` that `owner` holds: they are new in version 2.
void refuse_version_2_fields(const JsonField& owner, int version, std::initializer_list<std::string_view> fields);
void read_output(const JsonField& output, Scene& scene);
Camera read_camera(const JsonField& camera);
ViewVolume read_view_volume(const JsonField& owner);  // reads owner.eye ... owner.far
std::vector<Texture> read_textures(const JsonField& textures, int version);
int find_texture(const JsonField& name, const std::vector<Texture>& textures);
std::vector<Object> read_objects(const JsonField& objects, const std::vector<Texture>& textures, int version);
Texgen read_texgen(const JsonField& texgen);
Mesh read_inline_mesh(const JsonField& object);
glm::dmat4 read_transform(const JsonField& transform);
std::vector<Projector> read_projectors(const JsonField& projectors, const std::vector<Texture>& textures, int version);

}  // namespace spanlight::scene::detail
