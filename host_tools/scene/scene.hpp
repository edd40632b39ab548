// The parsed, validated scene file (spec: docs/scene-format.md, versions 1 and 2).
// Host only: doubles and std::vector are fine here. Every error with file and
// field path comes from load_scene(), before anything is rendered.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace spanlight::scene {

enum class Filter { nearest, bilinear, trilinear };  // trilinear: v2, mipmapped (mip_chain.hpp)
enum class Wrap { repeat, clamp, border };
enum class Cull { none, back };
enum class ShadowFilter { nearest, pcf2x2 };
enum class TexgenSpace { object, eye };     // v2: planes applied to object or camera-eye coordinates
enum class ProjectorSpace { world, camera };  // v2: camera: eye/target/up given in the camera's eye space

// 8-bit RGB, top row first (as in the file). Grey is expanded, alpha dropped.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;  // width * height * 3
  std::array<std::uint8_t, 3> texel(int x, int y) const {
    const auto i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 3;
    return {rgb[i], rgb[i + 1], rgb[i + 2]};
  }
};

struct Texture {
  std::string name;
  std::filesystem::path path;  // as resolved against the scene's folder
  Filter filter = Filter::bilinear;
  Wrap wrap = Wrap::repeat;
  Image image;
};

struct Camera {
  glm::dvec3 eye{0.0}, target{0.0, 0.0, -1.0}, up{0.0, 1.0, 0.0};
  double fovy_deg = 60.0;
  double near = 0.1;
  double far = 100.0;
};

struct Mesh {
  std::vector<glm::dvec3> positions;
  std::vector<glm::dvec2> uvs;  // same count as positions (zeros where the file has none)
  std::vector<std::array<std::uint32_t, 3>> triangles;  // indices into positions, checked in range
  std::filesystem::path file;  // the OBJ file it was read from, resolved; empty for an inline mesh
};

// v2 objects[].texgen: u = s . (x, y, z, 1), v = t . (x, y, z, 1) of each vertex in object
// coordinates or in the camera's eye coordinates V_cam * M * v (vertex_uvs computes them).
struct Texgen {
  glm::dvec4 s{0.0}, t{0.0};
  TexgenSpace space = TexgenSpace::object;
};

struct Object {
  std::string name;
  Mesh mesh;  // with texgen, mesh.uvs are not used (an OBJ's vt is overridden; inline uvs are an error)
  glm::dvec3 color{1.0};
  int texture = -1;  // index into Scene::textures, -1: none
  Cull cull = Cull::none;
  glm::dmat4 model{1.0};  // M = T * Rz * Ry * Rx * S, or the given matrix
  std::optional<Texgen> texgen;  // v2; none: the mesh's uvs
};

struct Shadows {
  int map_size = 0;
  double bias = 0.0;
  ShadowFilter filter = ShadowFilter::nearest;
};

struct Projector {
  std::string name;
  glm::dvec3 eye{0.0}, target{0.0, 0.0, -1.0}, up{0.0, 1.0, 0.0};
  double fovy_deg = 60.0;
  double aspect = 1.0;
  double near = 0.1;
  double far = 100.0;
  int image = -1;  // index into Scene::textures
  glm::dvec3 color{1.0};
  std::optional<Shadows> shadows;
  int falloff = -1;           // v2: index into Scene::textures sampled at (r/q, 0.5), clamped; -1: none
  bool facing_only = false;   // v2: lights a triangle only when it faces the projector and the camera alike
  ProjectorSpace space = ProjectorSpace::world;  // v2: camera: eye, target, up in the camera's eye space
};

struct Scene {
  std::filesystem::path file;
  int version = 1;  // spanlight_scene: 1 or 2
  std::string name;
  int width = 0;
  int height = 0;
  Camera camera;
  glm::dvec3 ambient{0.0};
  std::vector<Texture> textures;
  std::vector<Object> objects;
  std::vector<Projector> projectors;
};

// Thrown by load_scene for any bad input. what() reads "FILE: FIELD: EXPECTED", or, when the
// fault is in a file the field names (an OBJ mesh, an image), "FILE: FIELD: ASSET: EXPECTED":
// FILE is always the scene file, so a message says which scene to fix even when assets are shared.
class SceneError : public std::runtime_error {
 public:
  SceneError(std::string file, std::string field, std::string expected, std::string asset = {})
      : std::runtime_error(file + ": " + field + ": " + (asset.empty() ? "" : asset + ": ") + expected),
        file_(std::move(file)), field_(std::move(field)), expected_(std::move(expected)), asset_(std::move(asset)) {}
  const std::string& file() const { return file_; }
  const std::string& field() const { return field_; }
  const std::string& expected() const { return expected_; }
  const std::string& asset() const { return asset_; }  // empty: the fault is in the scene file itself

 private:
  std::string file_, field_, expected_, asset_;
};

// Parses and validates a scene file; loads its meshes and images. Throws SceneError.
Scene load_scene(const std::filesystem::path& file);

// The matrices the spec defines, in double (GLM conventions, column-major); both backends
// take them from here. A projector's V_j is world-to-projector: for `space: camera` it is
// lookAt(eye_j, target_j, up_j) * V_cam, so these take the camera. Shadow maps are rendered
// with projector_view_projection, the same world-to-projector view.
glm::dmat4 camera_view(const Camera& camera);                    // V_cam = lookAt(eye, target, up)
glm::dmat4 camera_view_projection(const Scene& scene);           // perspective(fovy, w/h, n, f) * V_cam
glm::dmat4 projector_view(const Camera& camera, const Projector& projector);             // V_j
glm::dmat4 projector_view_projection(const Camera& camera, const Projector& projector);  // P_j * V_j
glm::dmat4 projector_texture_matrix(const Camera& camera, const Projector& projector);   // B * P_j * V_j, B: [-1,1] -> [0,1]
// The projector's eye in world coordinates: eye_j, or V_cam^-1 * eye_j for `space: camera`.
glm::dvec3 projector_eye_in_world(const Camera& camera, const Projector& projector);

// An object's uv per vertex: the mesh's, or with texgen u = s . p, v = t . p where p is the
// vertex (x, y, z, 1) in object coordinates or in eye coordinates V_cam * M * v.
std::vector<glm::dvec2> vertex_uvs(const Camera& camera, const Object& object);

}  // namespace spanlight::scene
